/* The 2D builder (build_twod.c): OpenSCAD's 2D subtrees evaluated into
 * regions of the 2D engine (twod/twod.h), as OpenSCAD 2021.01 evaluates
 * them, for the extrusions, revolutions, hulls and imports that take 2D
 * children.
 */
#ifndef SPANCAST_BUILD_BUILD_TWOD_H
#define SPANCAST_BUILD_BUILD_TWOD_H

#include "build/build_ctx.h"
#include "twod/twod.h"

/* The union of parent's 2D children, as OpenSCAD 2021.01 evaluates them:
 * circle, square, polygon, group/union/render/color, difference,
 * intersection, multmatrix (its xy part), offset, hull and minkowski.
 * '%' and '*' children are left out. out must be initialised; it is
 * replaced. Errors (bad arguments, nodes that are not 2D, limits) are set
 * at their position. */
sc_status build_twod_children(const build_ctx *c, const model_node *parent,
                              twod_region *out);
/* The region of the 2D node n itself (circle, offset, ...), evaluated the
 * same way; outer names the node that asked, for messages. */
sc_status build_twod_node(const build_ctx *c, const model_node *n, const char *outer,
                          twod_region *out);

/* The main-model node n (a 2D shape, or an operation whose first child
 * with a dimension is 2D), evaluated as OpenSCAD evaluates it. */
sc_status build_twod_main(const build_ctx *c, const model_node *n, twod_region *out);
/* The 2D node n read through the 2D engine (build_twod_main) only for its
 * errors and warnings, where a 3D operation or a projection leaves it out;
 * *empty (when empty is not NULL) tells whether its outline is empty. */
sc_status build_twod_check(const build_ctx *c, const model_node *n, int *empty);
/* The top level of a file from first on, a 2D model: the union of its
 * nodes, 3D ones ignored as a 2D operation ignores them. */
sc_status build_twod_top(const build_ctx *c, const model_node *first, twod_region *out);
/* A '%' child k of a 2D operation, lowered in the 2D context: no operand,
 * but evaluated for the warnings of its subtree (and its errors), as
 * OpenSCAD 2021.01's render evaluates a background child before it leaves
 * it out; its parent says nothing of it. A 3D subtree gives what OpenSCAD
 * says as it evaluates it: its 2D parts' warnings, its operations' check
 * of their children's dimensions, a removed multmatrix, a polyhedron's
 * indices, not what needs its geometry. */
sc_status build_twod_background(const build_ctx *c, const model_node *k,
                                const char *outer);

/* The dimension OpenSCAD 2021.01 gives node n: 2 or 3, 0 when nothing
 * below it has one (an empty group, a light). A shape has its own; an
 * operation (group, union, difference, intersection, multmatrix, color,
 * and hull and minkowski in the 2D context) has that of its first child
 * with one ('%' and '*' children do not count; nor a projection without
 * a 3D child, which OpenSCAD makes no geometry: build_projects). in_2d: n
 * was lowered in
 * the 2D context (model.h). build_list_dim: the same over a list of
 * nodes from first on, the top level of a file. */
int build_dim(const model_node *n, int in_2d);
int build_list_dim(const model_node *first, int in_2d);
/* Whether projection n has a child that is 3D, so that OpenSCAD 2021.01
 * makes geometry of it. */
int build_projects(const model_node *n);
/* Whether 3D node n's geometry is empty as its nodes already say, as
 * OpenSCAD 2021.01 makes it: a shape of no size, an extrusion of nothing,
 * an operation of such. One that only CGAL finds empty (a difference that
 * removes all) is not. */
int build_node_empty(const model_node *n);
/* How many of the nodes from first on, the children of an operation of
 * this kind, OpenSCAD 2021.01 takes as operands: 0, 1, or 2 for two or
 * more (its applyToChildren3D is a no-op for one). Not '%' or '*', nor
 * shading nodes; a difference or intersection takes every other child
 * (a 2D one as an empty operand); a union (a group, transform, colour,
 * render or minkowski) leaves out 2D children and empty ones
 * (build_node_empty). */
int build_operands(model_kind kind, const model_node *first);

/* The one walk over a 2D model subtree, for every builder of 2D children:
 * the exact region of linear_extrude (build_region.c), the revolve
 * profile (build_revolve.c), the text outlines (build_text.c) and
 * OpenSCAD's evaluation here. The walk owns what they share: which
 * children count ('%' and '*' do not), the depth limit and its message,
 * and the xy part of a multmatrix; the visitor owns what a node means. */
enum { TWOD_WALK_MAX_DEPTH = 1000 };

typedef struct twod_walker twod_walker;
struct twod_walker {
    const build_ctx *c;
    const char *outer;  /* the node that asked, for messages */
    const char *nested; /* what the depth limit counts, for its message */
    /* Visits node n at depth under the transform m into the caller's
     * result out (the visitor's type, or NULL). */
    sc_status (*visit)(twod_walker *w, const model_node *n, const affine2 *m, int depth,
                       void *out);
};

/* The children of n that count, in order: not '%' or '*'. */
const model_node *twod_walk_first(const model_node *n);
const model_node *twod_walk_next(const model_node *k);
/* Visits n at depth: past TWOD_WALK_MAX_DEPTH an error at n, else
 * w->visit. */
sc_status twod_walk(twod_walker *w, const model_node *n, const affine2 *m, int depth,
                    void *out);
/* Visits the children of n that count at depth + 1, without results, and
 * gives the warnings of its '%' children (build_twod_background) in their
 * place; then, for a multmatrix removed for a nan or inf entry, OpenSCAD
 * 2021.01's warning that it is removed (build_xform_not_finite), after its
 * children's, as OpenSCAD evaluates them first. */
sc_status twod_walk_children(twod_walker *w, const model_node *n, const affine2 *m,
                             int depth);
/* The transform under multmatrix n: m times the xy part of its matrix (its
 * argument error, if any, first). A visitor that walks the children itself
 * says that a removed one is removed after them (build_xform_not_finite). */
sc_status twod_walk_fold(const twod_walker *w, const model_node *n, const affine2 *m,
                         affine2 *inner);

/* The one reader of polygon(points, paths) n: its contours moved by m,
 * added to out (the caller's contours kept): one per path, or one through
 * all the points without paths, and, with empty_is_all (OpenSCAD's rule),
 * with an empty vector of them; from the outline OpenSCAD's clipper
 * refuses on (model_polygon.range_bad), none. The caller gives the
 * polygon's warnings first (build_bad_indices), also for one without
 * points. */
sc_status build_twod_polygon(const build_ctx *c, const model_node *n, const affine2 *m,
                             int empty_is_all, twod_region *out);

/* The error of a failed twod_add_point into r for node n: the limit of
 * TWOD_MAX_POINTS points of every 2D shape when r is full, else memory. */
sc_status build_twod_add_error(const build_ctx *c, const model_node *n,
                               const twod_region *r);

#endif
