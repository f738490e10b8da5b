/* Loading OpenSCAD source (.scad) by converting it with OpenSCAD (scad.c). */
#ifndef SPANCAST_CLI_SCAD_H
#define SPANCAST_CLI_SCAD_H

#include <signal.h>

#include "spancast/spancast.h"

/* 1 when path names an OpenSCAD source file (ends in .scad, any case). */
int scad_is_source(const char *path);

/* Converts path with `openscad -o` into a temporary .csg (removed again in
 * every case) and loads it as if it were DIR/NAME.csg beside the source, so
 * that relative imports resolve as OpenSCAD resolves them. On failure
 * *scene is NULL and error says why (OpenSCAD missing, its conversion
 * failing, with the last line it printed, or the .csg not loading). */
sc_status scad_load(const char *path, const sc_load_options *options, sc_scene **scene,
                    sc_error *error);

/* How a conversion is stopped early (both may be NULL): when *stop
 * becomes non-zero, OpenSCAD is killed (SIGTERM, then SIGKILL after a
 * second), its temporary files removed, and the call returns
 * SC_ERR_CANCELLED; *loading is 1 while the converted text is loaded,
 * once no temporary file is left. */
typedef struct scad_stop {
    const volatile sig_atomic_t *stop;
    volatile sig_atomic_t *loading;
} scad_stop;

/* The same, and when depend is not NULL, calls depend(user, file) for each
 * file the conversion read (the source and what it includes, uses or
 * imports: OpenSCAD's -d dependency file), so that a watcher can reload on
 * a change to any of them. Not called when OpenSCAD fails. stop: NULL, or
 * as scad_stop says. */
sc_status scad_load_files(const char *path, const sc_load_options *options,
                          sc_scene **scene, sc_error *error,
                          void (*depend)(void *user, const char *file), void *user,
                          const scad_stop *stop);

/* The conversion alone: OpenSCAD's CSG text for path into *text
 * (malloc'd and NUL-terminated, *size bytes; the caller frees it) and the
 * name to load it under (DIR/NAME.csg) into name; depend and stop as above. On
 * failure *text is NULL and error says why. (spancast-mpi converts once
 * and sends the text to its other ranks.) */
sc_status scad_convert(const char *path, char **text, size_t *size, char *name,
                       size_t name_size, sc_error *error,
                       void (*depend)(void *user, const char *file), void *user,
                       const scad_stop *stop);

/* scad_load at OpenSCAD's animation time $t = t: the model as OpenSCAD's
 * --animate evaluates it for that frame; stop as for scad_load_files. */
sc_status scad_load_at(const char *path, const sc_load_options *options, double t,
                       sc_scene **scene, sc_error *error, const scad_stop *stop);

#endif
