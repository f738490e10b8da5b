/* Watching model files for changes (watch.c): what `spancast view` and
 * `spancast render --watch` reload on. */
#ifndef SPANCAST_CLI_WATCH_H
#define SPANCAST_CLI_WATCH_H

#include <signal.h>

#include "spancast/spancast.h"

/* Quiet time after the last change before a reload starts, in milliseconds:
 * an editor's save is often several writes and a rename. */
#define WATCH_SETTLE_MS 100

typedef struct watch_set watch_set;

/* A new, empty set; NULL (with error filled) when inotify is unavailable. */
watch_set *watch_open(sc_error *error);

/* Frees the set; NULL is ignored. */
void watch_close(watch_set *set);

/* Adds a file to the set (its folder is watched, so an editor that saves by
 * writing a new file and renaming it over the old one is seen too). A file
 * already in the set is not added again. Returns SC_OK, or SC_ERR_IO when
 * the folder cannot be watched. */
sc_status watch_add(watch_set *set, const char *path, sc_error *error);

/* The callback form of watch_add for scad_load_files: errors are ignored
 * (the file is then simply not watched). */
void watch_add_file(void *set, const char *path);

/* The inotify descriptor, for poll(). */
int watch_fd(const watch_set *set);

/* Reads the pending events without blocking; returns 1 when one of them
 * concerns a file of the set, else 0. */
int watch_changed(watch_set *set);

/* Blocks until a file of the set changes and then stays quiet for
 * WATCH_SETTLE_MS; returns 1. Returns 0 when *stop becomes non-zero (a
 * signal handler sets it; the signal interrupts the wait) or when the
 * descriptor fails. */
int watch_wait(watch_set *set, const volatile sig_atomic_t *stop);

/* The file of the set the last change seen was to, as it was added; NULL
 * when none was seen, or events were lost. */
const char *watch_last_change(const watch_set *set);

#endif
