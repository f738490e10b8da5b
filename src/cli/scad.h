/* Loading OpenSCAD source (.scad) by converting it with OpenSCAD (scad.c). */
#ifndef SPANCAST_CLI_SCAD_H
#define SPANCAST_CLI_SCAD_H

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

/* The same, and when depend is not NULL, calls depend(user, file) for each
 * file the conversion read (the source and what it includes, uses or
 * imports: OpenSCAD's -d dependency file), so that a watcher can reload on
 * a change to any of them. Not called when OpenSCAD fails. */
sc_status scad_load_files(const char *path, const sc_load_options *options,
                          sc_scene **scene, sc_error *error,
                          void (*depend)(void *user, const char *file), void *user);

/* scad_load at OpenSCAD's animation time $t = t: the model as OpenSCAD's
 * --animate evaluates it for that frame. */
sc_status scad_load_at(const char *path, const sc_load_options *options, double t,
                       sc_scene **scene, sc_error *error);

#endif
