/* The scene builder: typed model in, CSG tree out.
 *
 * It gives each node name its meaning, as OpenSCAD 2021.01 does:
 *   group, union, render, color, multmatrix   union of the children
 *   difference                                first child minus the others
 *   intersection                              intersection of the children
 *   cube, sphere, cylinder, polyhedron        leaves (polyhedron: convex ones as
 *                                             planes, others as meshes)
 *   import                                    a mesh; the union of an AMF or 3MF
 *                                             file's objects (build_mesh.h)
 *   linear_extrude                            a prism of its 2D children (build_mesh.h)
 *   hull, minkowski, surface, resize          build_hull.h
 *   material                                  union; sets its children's material
 *   light, camera, background                 no geometry (build_shading.h)
 *   torus, quadric, implicit                  spancast's curved leaves
 *                                             (model/lower_curved.c)
 * Transforms (multmatrix, row-major 4x4) nest and accumulate into each
 * leaf's to_world; an outer colour wins over an inner one (OpenSCAD's
 * preview); leaves without a
 * colour get OpenSCAD's default face colour (Cornfield, #f9d72c).
 *
 * Modifiers: '*' drops the node (its subtree is not looked at); '%' keeps
 * the subtree out of the solid, and out of its parent's operation, but still
 * checks it; '#' changes nothing in the solid; the first '!' in file order
 * (outside dropped subtrees) makes its subtree the whole design, without
 * its ancestors' transforms or colours, as OpenSCAD's root modifier does.
 * Each '#' and '%' subtree inside the design is also built on its own, with
 * its ancestors' transforms and colours, into the shading record's trees of
 * highlighted and background parts (shading.overlay), which only the
 * preview draws (build.c).
 *
 * Every node OpenSCAD can write is known by name; those spancast cannot
 * render yet, and spancast's own geometry extension nodes, are SC_ERR_UNSUPPORTED
 * at their name; any other name is an error too. Unknown arguments are
 * ignored and the last of repeated ones wins, as in OpenSCAD.
 *
 * Things OpenSCAD turns into no geometry (a zero or negative size, a
 * singular transform) become the empty solid with a warning at their
 * position. The walk over the model uses an explicit stack.
 */
#ifndef SPANCAST_BUILD_BUILD_H
#define SPANCAST_BUILD_BUILD_H

#include <stddef.h>

#include "csg/csg.h"
#include "model/shading.h"
#include "spancast/spancast.h"
#include "model/model.h"

/* The largest polyhedron the convex plane-set path takes, as faces times
 * points (its cost): 100000000 is about 10000 faces over 10000 points, a
 * fraction of a second. */
#define BUILD_MAX_POLYHEDRON_WORK 100000000

/* OpenSCAD's default face colour, Cornfield #f9d72c, alpha 1. */
#define BUILD_DEFAULT_COLOR                                                              \
    {                                                                                    \
        249 / 255.0f, 215 / 255.0f, 44 / 255.0f, 1.0f                                    \
    }

/* The default of sc_load_options.max_triangles (build_scene's
 * max_triangles 0): the mesh triangles of one model, all meshes together. */
#define BUILD_MAX_TRIANGLES ((size_t)1 << 26)

/* How far from the origin a model may reach, in every coordinate of its
 * bounds (past it the load is SC_ERR_LIMIT): products of a few
 * coordinates stay within double's range, and OpenSCAD's triangulation,
 * which faithful mode follows, works in float. */
#define BUILD_MAX_EXTENT 1e30

/* build_scene's flags. */
#define BUILD_FAITHFUL 1   /* OpenSCAD's polygons and polyhedra (--faithful) */
#define BUILD_STRICT 2     /* bad meshes are errors (--strict) */
#define BUILD_NO_PREVIEW 4 /* not the preview's parts and solid (sc_load_options) */
/* the model is a mesh file's one-line import (sc_scene_load_mesh): a file
 * OpenSCAD would import nothing from, which an import in a model leaves
 * out with a warning, is the error */
#define BUILD_MESH_MODEL 8

/* Builds the CSG tree of the model m and the scene's shading record
 * (lights, materials, camera, background: build_shading.h); with
 * BUILD_FAITHFUL in flags, spheres and cylinders become OpenSCAD's polyhedra for their
 * $fn, $fa, $fs (faithful.h). On success *out owns the tree (free with csg_tree_free),
 * *look the shading record (free with shading_free; not made when look is NULL), and
 * *warnings is a malloc'd array of *warning_count warnings in source order (NULL when
 * there are none; free with free()). On failure nothing is returned and error says where
 * and why: the first error in file order, which may be one the lowering found (a
 * MODEL_ERROR node). With BUILD_STRICT, a polyhedron or imported mesh that is not closed
 * is an error rather than a warning (build_mesh.h). With BUILD_NO_PREVIEW, *look has
 * neither the preview's parts (shading.overlay) nor its solid (shading.preview_solid).
 * The meshes the build makes have at
 * most max_triangles triangles in all (0: BUILD_MAX_TRIANGLES); past it the build
 * fails with SC_ERR_LIMIT at the mesh that passes it (build_charge_triangles), as
 * it does for a model whose bounds reach past BUILD_MAX_EXTENT. */
sc_status build_scene(const model *m, int flags, size_t max_triangles, csg_tree **out,
                      shading **look, sc_error **warnings, size_t *warning_count,
                      sc_error *error);

/* build_scene that takes m and frees it in every case, as soon as the walk
 * over it is done and before the tree is compiled, so that the typed model
 * and the compiled leaves never take memory at once (a million positioned
 * spheres: 350 MB of model, 330 MB of leaves). It takes spare too, spare_size
 * bytes from malloc (or NULL) that the caller is done with, the text the
 * model was read from: the leaves' array is made of it where that saves
 * touching fresh memory (csg_builder_give), else it is freed first. */
sc_status build_scene_take(model *m, void *spare, size_t spare_size, int flags,
                           size_t max_triangles, csg_tree **out, shading **look,
                           sc_error **warnings, size_t *warning_count, sc_error *error);

#endif
