/* A mesh file as a model: the one-line model import(file = "PATH") that
 * sc_scene_load, sc_scene_load_mesh and sc_objects_load read in place of
 * a .stl, .off, .amf or .3mf file (compare.c). */
#ifndef SPANCAST_API_MESH_MODEL_H
#define SPANCAST_API_MESH_MODEL_H

#include <stddef.h>

#include "spancast/spancast.h"

/* 1 when path ends in .stl, .off, .amf or .3mf, in any case, as OpenSCAD's import()
 * tells a mesh by its name. */
int mesh_model_is_mesh(const char *path);

/* The model that imports the mesh at path by its absolute path, as a
 * string of the grammar (quote and backslash escaped): malloc'd into
 * *text, *length bytes and a NUL. SC_ERR_IO when path cannot be resolved,
 * SC_ERR_NOMEM. */
sc_status mesh_model_text(const char *path, char **text, size_t *length, sc_error *error);

/* sc_scene_load_string of text, mesh_model_text's model of the mesh file
 * name: a file that an import in a model leaves out with a warning, as
 * OpenSCAD imports nothing from it (not STL at all, a line OpenSCAD's
 * reader cannot parse), is the error (BUILD_MESH_MODEL). */
sc_status mesh_model_load(const char *name, const char *text, size_t length,
                          const sc_load_options *options, sc_scene **scene,
                          sc_error *error);

/* Drops the position of e when it points into the one-line model named
 * path (its line 1, past column 1), which is no place in a file the user
 * has: the error or warning is about the mesh file as a whole. A position
 * at column 1 is the mesh file's own line (a reader's error on its line
 * 1), and is kept. */
void mesh_model_unplace(sc_error *e, const char *path);

#endif
