/* Builder of mesh leaves (build_mesh.c): non-convex polyhedra and
 * import("file.stl" | "file.off").
 */
#ifndef SPANCAST_BUILD_BUILD_MESH_H
#define SPANCAST_BUILD_BUILD_MESH_H

#include <stdint.h>

#include "build/build_ctx.h"
#include "model/model.h"

/* The largest mesh file import reads, in bytes (docs/meshes.md). */
#define BUILD_MAX_MESH_FILE (512u * 1024u * 1024u)

/* A mesh leaf from face_count polygons (face f is indices[face_start[f] ..
 * face_start[f + 1]) into points). what names the node in messages;
 * numbered says the points are a polyhedron's own, numbered in the file
 * (an edge is named by its point numbers, else by its ends' coordinates,
 * and a mesh without volume is "polyhedron without volume"). The
 * mesh must be closed (every edge in exactly two faces) and consistently
 * oriented (the two faces run along it in opposite directions); inward or
 * outward winding are both taken (the signed volume decides). Polygons are
 * split into fans of triangles. A mesh without volume sets *empty to a
 * warning and fills nothing. */
sc_status build_mesh_prim(const build_ctx *c, const sc_location *loc, const char *what,
                          int numbered, const vec3 *points, uint32_t point_count,
                          const uint32_t *indices, const uint32_t *face_start,
                          uint32_t face_count, prim *out, const char **empty);

/* The path of a file a model names: relative names are relative to the
 * directory of the file being read (c->file). malloc'd; NULL when memory
 * runs out. */
char *build_file_path(const build_ctx *c, const char *name);
/* import(file) (its name checked by the lowering pass): an STL (ASCII or
 * binary) or OFF file, its path relative to the directory of the file
 * being read. */
sc_status build_import(const build_ctx *c, const model_import *import, prim *out,
                       const char **empty);

/* linear_extrude (build_extrude.c): exact in default mode without twist or
 * scale over the 2D nodes build_region.h reads, else OpenSCAD's mesh of it
 * (build_extrude_faithful.h). */
sc_status build_linear_extrude(const build_ctx *c, const model_node *n, int emit,
                               prim *out, const char **empty);

#endif
