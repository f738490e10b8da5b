/* Builder of rotate_extrude (build_revolve.c). */
#ifndef SPANCAST_BUILD_BUILD_REVOLVE_H
#define SPANCAST_BUILD_BUILD_REVOLVE_H

#include "build/build_ctx.h"
#include "build/build_mesh.h"

/* Most points of the mesh faithful mode builds for one rotate_extrude
 * (profile points times rings). */
#define BUILD_REVOLVE_MAX_MESH_POINTS 4000000u

/* rotate_extrude(angle, convexity, $fn, $fa, $fs) of circle, square and
 * polygon children under group, union, render, color and multmatrix: the
 * exact solid of revolution (PRIM_REVOLVE), or with c->faithful OpenSCAD
 * 2021.01's mesh of it (PRIM_MESH). Other 2D nodes are SC_ERR_UNSUPPORTED
 * at their position; a profile on both sides of the axis is OpenSCAD's
 * error. A profile without area, or angle = 0, sets *empty to a warning. */
sc_status build_rotate_extrude(const build_ctx *c, const model_node *n, int emit,
                               prim *out, const char **empty);

/* OpenSCAD 2021.01's mesh of a rotate_extrude (as build_rotate_extrude
 * builds it in faithful mode, whatever c->faithful says) as faces that do
 * not overlap, for CGAL: each side triangle one face, and with an angle
 * below 360 each end cap one face of all the profile's outlines and holes
 * (the leaf's mesh has a face per contour, which overlap). Errors, warnings
 * and *empty as for build_rotate_extrude (faces then empty); free faces
 * with build_mesh_faces_free. */
sc_status build_rotate_extrude_faces(const build_ctx *c, const model_node *n,
                                     build_mesh_faces *faces, const char **empty);

#endif
