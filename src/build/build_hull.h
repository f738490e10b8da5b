/* Builders of hull(), minkowski(), resize() (build_hull.c) and surface()
 * (build_surface.c). See docs/hull.md.
 */
#ifndef SPANCAST_BUILD_BUILD_HULL_H
#define SPANCAST_BUILD_BUILD_HULL_H

#include <stdint.h>

#include "build/build_ctx.h"
#include "build/build_mesh.h"
#include "build/nef.h"
#include "math/vec.h"
#include "twod/twod.h"

/* Nesting below a hull, minkowski or resize node that their walks follow. */
#define BUILD_HULL_MAX_DEPTH 1000

/* The most convex parts a minkowski() result may have (the product of its
 * children's part counts). */
#define BUILD_MINKOWSKI_MAX_PARTS 4096

/* The most grid points a surface() height map may have. */
#define BUILD_SURFACE_MAX_POINTS (1024u * 1024u)

/* The largest .dat file surface() reads, in bytes. */
#define BUILD_SURFACE_MAX_FILE (64u * 1024u * 1024u)

/* Leaves one node builds: items is malloc'd (free it), count may be 0. */
typedef struct build_prims {
    prim *items;
    uint32_t count, cap;
} build_prims;

/* The matrices of the resize nodes measured so far in one build (owned by
 * the caller, created on first use; free with build_resize_cache_free). */
typedef struct build_resize_cache build_resize_cache;

void build_resize_cache_free(build_resize_cache *cache);

/* The convex hull of count points as one leaf of node n (a plane set, or a
 * mesh of its triangles when it has many faces) appended to out; nothing
 * when the points span no volume. */
sc_status build_hull_points(const build_ctx *c, const model_node *n, const vec3 *points,
                            uint32_t count, build_prims *out);

/* hull() of its 3D children (booleans among them evaluated with CGAL's Nef
 * polyhedra, as OpenSCAD does): one convex leaf (a plane set, or a mesh of the
 * hull's triangles when it has many faces), in the hull node's frame. A
 * hull without volume sets *empty to a warning. With emit clear, the
 * children are only checked. */
sc_status build_hull(const build_ctx *c, const model_node *n, int emit,
                     build_resize_cache **cache, build_prims *out, const char **empty);

/* minkowski() of its children, each a union of convex parts (non-convex
 * ones split by CGAL's convex decomposition): one convex leaf per
 * combination of parts, to be united. */

sc_status build_minkowski(const build_ctx *c, const model_node *n, int emit,
                          build_resize_cache **cache, build_prims *out,
                          const char **empty);

/* The solid of 3D subtree n as OpenSCAD 2021.01 evaluates it with CGAL (its
 * booleans, hulls and minkowski sums as Nef polyhedra), in n's parent's
 * frame: *tris gets 3 * *tri_count corners, each triangle turned away from
 * the solid (malloc'd; NULL and 0 for the empty solid). Loads the CGAL
 * plugin; messages begin with owner ("projection"). With own (n is the
 * projection's own child), n's solid is looked for in c->nefs but not
 * kept there, as OpenSCAD caches a child only where its parent collects
 * its children, which projection does not. */
sc_status build_nef_triangles(const build_ctx *c, const model_node *n, const char *owner,
                              build_resize_cache **cache, int own, vec3 **tris,
                              uint32_t *tri_count);

/* projection(cut = true) n's section as OpenSCAD 2021.01 computes it with
 * CGAL (GeometryEvaluator's projectionCut): the union of n's 3D children
 * as a Nef polyhedron (their warnings not given again: c's notes are
 * muted), cut by the plane z = 0 and flattened (nef.h's section), its
 * loops added to out. *missed is 1 where the cut is empty, 2 where CGAL
 * failed to flatten it (its message given here, as OpenSCAD logs it; the
 * error with --strict). Loads the CGAL plugin. */
sc_status build_nef_section(const build_ctx *c, const model_node *n,
                            build_resize_cache **cache, twod_region *out, int *missed);
/* Whether the triangles (3 * tri_count corners) pass through themselves
 * (nef.h's self_crossing), in *crossing; through the CGAL plugin nef,
 * loaded here if it is not yet (the caller closes it), with at in the
 * messages. */
sc_status build_self_crossing(const build_ctx *c, const sc_location *at, nef_plugin *nef,
                              const vec3 *tris, uint32_t tri_count, int *crossing);

/* Whether leaf n may pass through itself: a twisted or scaled
 * linear_extrude, a polyhedron, an import. */
int build_may_cross(const model_node *n);

/* Faithful mode: whether OpenSCAD 2021.01's CGAL evaluation of n (a
 * boolean, or a union of several, which OpenSCAD makes a Nef polyhedron
 * of) takes a mesh that passes through itself (build_may_cross, then
 * nef.h's self_crossing): the Nef polyhedron CGAL makes of it, and whether
 * its booleans with it fail, follow no rule on the mesh, so n is then drawn
 * as CGAL's solid (build_nef_triangles). A subtree with a node CGAL does
 * not take (spancast's own leaves) is not. Loads the CGAL plugin only
 * where a leaf may cross. */
sc_status build_cgal_crossing(const build_ctx *c, const model_node *n, int *crossing);

/* What OpenSCAD 2021.01's CGAL evaluation makes of a 3D subtree
 * (build_nef_evaluate). */
typedef struct build_nef_state {
    int walked;      /* 0: not evaluated (a node CGAL does not take here, or
                      * no plugin) */
    int empty;       /* the solid has no volume */
    int first_empty; /* the first operand of n (a boolean) has none */
    int later_empty; /* another operand has none */
} build_nef_state;

/* Evaluates 3D subtree n as OpenSCAD 2021.01 does with CGAL (its booleans,
 * hulls and minkowski sums as Nef polyhedra), for its warnings (a mesh that
 * is not closed: c->notes, or the error with --strict) and what *out says,
 * where OpenSCAD evaluates a subtree it then leaves out. A subtree with a
 * node the walk does not take, or a build without the CGAL plugin, is not
 * evaluated (walked 0, SC_OK). */
sc_status build_nef_evaluate(const build_ctx *c, const model_node *n,
                             build_nef_state *out);

/* Whether OpenSCAD 2021.01 evaluates the union of the children of n (a
 * multmatrix, resize or other operation) to a CGAL Nef polyhedron, not to
 * a mesh (PolySet) or nothing: a transform then applies to the Nef
 * polyhedron (CGAL_Nef_polyhedron::transform, which removes it under a
 * singular matrix) rather than to the mesh's points (PolySet::transform,
 * which flattens them). */
int build_nef_result(const model_node *n);

/* OpenSCAD 2021.01's transform of the children of n by a singular matrix:
 * 1 where they are a Nef polyhedron (build_nef_result), which it removes,
 * with *warning set to its own warning where that polyhedron is not empty
 * (else NULL); 0 where they are a mesh, whose points it flattens
 * (*warning NULL). */
int build_singular_removes(const model_node *n, const char **warning);

/* resize(newsize, auto): the scale (a diagonal matrix in *out) that
 * OpenSCAD 2021.01 applies to the children, from their bounding box in the
 * resize node's frame. *warning is set (and *out the identity) when a
 * non-zero size is asked of a flat child. */
sc_status build_resize(const build_ctx *c, const model_node *n,
                       build_resize_cache **cache, affine *out, const char **warning);

/* surface(file, center, invert) (its arguments read by the lowering
 * pass): the closed mesh OpenSCAD 2021.01 builds from a .dat height map or
 * a PNG image (build_surface.c). */
sc_status build_surface(const build_ctx *c, const model_surface *s, prim *out,
                        const char **empty);
/* The same mesh as its faces, for CGAL (free with build_mesh_faces_free);
 * errors and *empty as for build_surface. */
sc_status build_surface_faces(const build_ctx *c, const model_surface *s,
                              build_mesh_faces *faces, const char **empty);

#endif
