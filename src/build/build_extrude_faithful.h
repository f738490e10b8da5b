/* linear_extrude as OpenSCAD 2021.01 builds it, with twist and scale
 * (build_extrude_faithful.c). build_extrude.c routes twisted and scaled
 * extrusions, and every extrusion in --faithful mode, here.
 */
#ifndef SPANCAST_BUILD_BUILD_EXTRUDE_FAITHFUL_H
#define SPANCAST_BUILD_BUILD_EXTRUDE_FAITHFUL_H

#include "build/build_ctx.h"
#include "build/build_mesh.h"
#include "build/nef.h"
#include "twod/twod.h"

/* Most side quads (slices times outline points) of one extrusion. */
#define BUILD_EXTRUDE_MAX_QUADS 2000000u

/* linear_extrude(height, center, twist, slices, scale, $fn, $fa, $fs) of
 * n's 2D children (build_twod_children): OpenSCAD's slices as a closed
 * mesh leaf. Arguments are checked always; *out is filled only when emit
 * is set, and an extrusion without height or area sets *empty instead. */
sc_status build_linear_extrude_faithful(const build_ctx *c, const model_node *n, int emit,
                                        prim *out, const char **empty);

/* The mesh of build_linear_extrude_faithful as faces that do not overlap,
 * for CGAL: each side triangle one face, and each cap one face of all the
 * outlines and holes of the region (the leaf's mesh has a face per contour,
 * fanned, which the winding rule of a leaf fills right but CGAL does not
 * take), or with cdt (the CGAL plugin) the caps as OpenSCAD 2021.01
 * triangulates them and every face as its PolySet reaches CGAL's builder:
 * caps first, wound inward, each face with corners of its own, which a
 * grid or from_mesh merges (an extrusion that crosses itself makes the Nef
 * polyhedron OpenSCAD's makes only so). Warnings and *empty as for
 * build_linear_extrude_faithful (faces then empty); free faces with
 * build_mesh_faces_free. */
sc_status build_linear_extrude_faces(const build_ctx *c, const model_node *n,
                                     build_mesh_faces *faces, const char **empty,
                                     const nef_plugin *cdt);

/* A 2D model as OpenSCAD 2021.01 draws a 2D result (its
 * PolySet::render_surface, in the preview and the render alike): the
 * region r between z = -height / 2 and height / 2 (1, or 1.1 for the
 * preview's subtracted 2D objects), as a closed mesh leaf; a region
 * without area sets *empty instead. loc is the model's position. */
sc_status build_flat_slab(const build_ctx *c, const sc_location *loc,
                          const twod_region *r, double height, prim *out,
                          const char **empty);

#endif
