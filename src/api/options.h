/* The public calls' options, read once at the API's edge: a caller's sized
 * struct (base/sized.h), which may be shorter (an older header) or NULL
 * (the defaults), becomes the library's full struct, which is what the
 * code behind the call sees. */
#ifndef SPANCAST_API_OPTIONS_H
#define SPANCAST_API_OPTIONS_H

#include "spancast/spancast.h"

/* *out: the defaults, then as much of *in as it holds (in NULL: the
 * defaults alone). SC_ERR_ARGUMENT for a struct never set up or from a
 * newer header. */
sc_status options_load(const sc_load_options *in, sc_load_options *out, sc_error *error);
sc_status options_measure(const sc_measure_options *in, sc_measure_options *out,
                          sc_error *error);
sc_status options_ray_query(const sc_ray_query *in, sc_ray_query *out, sc_error *error);

/* build_scene's BUILD_* flags for the load options o. */
int options_build_flags(const sc_load_options *o);

/* Runs the calling thread's parallel regions (the builds of a large
 * model's hierarchies) on threads threads, 0 leaving them as they are, until
 * options_threads_end(the value returned). Only the calling thread's
 * setting changes (OpenMP's nthreads-var is per thread). */
int options_threads_begin(int threads);
/* The threads a stage given `threads` (0: the default) runs on. */
int options_thread_count(int threads);
void options_threads_end(int saved);

#endif
