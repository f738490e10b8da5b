/* Loading OpenSCAD source (.scad) by converting it with OpenSCAD (scad.c). */
#ifndef SPANCAST_CLI_SCAD_H
#define SPANCAST_CLI_SCAD_H

#include <signal.h>

#include "spancast/spancast.h"

/* 1 when path names an OpenSCAD source file (ends in .scad, any case). */
int scad_is_source(const char *path);

/* 1 when path names a mesh file (ends in .stl, .off, .amf or .3mf, any case), which
 * the commands take as the model import(file = path). */
int scad_is_mesh(const char *path);

/* Registers the font files the OpenSCAD source at path uses (use
 * <NAME.ttf> or .otf, in it or in a file it uses or includes, named from
 * that file's folder) with sc_font_register, as OpenSCAD registers them,
 * for every later load of the process; each conversion does it. A font
 * fontconfig cannot read is a warning on stderr. */
void scad_register_fonts(const char *path);

/* Takes every -D NAME=VALUE (or -DNAME=VALUE) out of argv, before the
 * command reads it, for every conversion with OpenSCAD of this process
 * (OpenSCAD's -D, passed on in order). Called once, before any command
 * runs. 0 or a usage exit status. */
int scad_take_defines(int *argc, char **argv);

/* The number of -D settings taken, and the index-th (NAME=VALUE). */
int scad_define_count(void);
const char *scad_define(int index);

/* How a conversion is stopped early (both may be NULL): when *stop
 * becomes non-zero, OpenSCAD is killed (SIGTERM, then SIGKILL after a
 * second), its temporary files removed, and the call returns
 * SC_ERR_CANCELLED; *loading is 1 while the converted text is loaded,
 * once no temporary file is left. */
typedef struct scad_stop {
    const volatile sig_atomic_t *stop;
    volatile sig_atomic_t *loading;
} scad_stop;

/* Converts path with `openscad -o` into a temporary .csg (removed again in
 * every case) and loads it as if it were DIR/NAME.csg beside the source, so
 * that relative imports resolve as OpenSCAD resolves them. On failure
 * *scene is NULL and error says why (OpenSCAD missing, its conversion
 * failing, with the last line it printed, or the .csg not loading). When depend is not
 * NULL, calls depend(user, file) for each file the conversion read (the source and what
 * it includes, uses or imports: OpenSCAD's -d dependency file), so that a watcher can
 * reload on a change to any of them. Not called when OpenSCAD fails. stop: NULL, or as
 * scad_stop says. */
sc_status scad_load_files(const char *path, const sc_load_options *options,
                          sc_scene **scene, sc_error *error,
                          void (*depend)(void *user, const char *file), void *user,
                          const scad_stop *stop);

/* scad_load at OpenSCAD's animation time $t = t: the model as OpenSCAD's
 * --animate evaluates it for that frame; stop as for scad_load_files. */
sc_status scad_load_at(const char *path, const sc_load_options *options, double t,
                       sc_scene **scene, sc_error *error, const scad_stop *stop);

/* The model at path, as every command takes MODEL:
 *   .scad         converted with OpenSCAD (scad_load_files);
 *   .stl, .off    the mesh, as the model import(file = path) would load it
 *                 (sc_scene_load_mesh; its errors at the mesh's positions);
 *   anything else the .csg grammar (sc_scene_load), except that a file
 *                 whose parse stops at OpenSCAD's language beyond the CSG
 *                 export (parse_error_is_language) is converted with
 *                 OpenSCAD like a .scad, after a note on stderr naming the
 *                 line.
 * depend, user and stop as for scad_load_files (stop->loading is also set
 * while a file is loaded). *converted (when not NULL) is set when the text
 * loaded came from OpenSCAD: the scene's warnings at that text name
 * scad_converted_name, to be put on path with scad_blame. */
sc_status scad_load_model(const char *path, const sc_load_options *options,
                          sc_scene **scene, sc_error *error,
                          void (*depend)(void *user, const char *file), void *user,
                          const scad_stop *stop, int *converted);

/* The top-level objects of path (sc_objects_load), from the same forms of
 * MODEL as scad_load_model and with its notes; *converted is set when the
 * text came from OpenSCAD (object positions then name
 * scad_converted_name). stop as for scad_load_files. */
sc_status scad_load_objects(const char *path, const sc_load_options *options,
                            sc_objects **objects, sc_error *error, const scad_stop *stop,
                            int *converted);

/* The text scad_load_model would load, and the name to load it under
 * (spancast-mpi's rank 0, which sends them to the other ranks): OpenSCAD's
 * conversion, the one-line import of a mesh, or the .csg file itself,
 * after a streamed parse that finds OpenSCAD's language in it (then
 * converted, with the note). Errors other than that one are left to the
 * load of the text. options (may be NULL) as scad_load_model reads them
 * for the conversion: strict makes OpenSCAD's first warning its error,
 * and $preview is true only where no_preview is not set. *text is
 * malloc'd; NULL on failure. */
sc_status scad_read_model(const char *path, const sc_load_options *options, char **text,
                          size_t *size, char *name, size_t name_size, sc_error *error,
                          const scad_stop *stop);

/* The name the converted text of path is loaded under (DIR/NAME.csg, DIR
 * the source's real directory) into name: 1, or 0 when path cannot be
 * resolved or name is too small. */
int scad_converted_name(const char *path, char *name, size_t name_size);

/* Puts an error or warning at a position in the converted text (named
 * name) on path, with the line of OpenSCAD's export in its message;
 * others are left as they are. */
void scad_blame(sc_error *error, const char *name, const char *path);

#endif
