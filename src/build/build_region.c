/* The exact linear_extrude: linear_extrude(height, center) without twist
 * or scale, its 2D children read into a region tree (prim_extrusion.h)
 * whose leaves are exact:
 *   circle(r | d)           an ellipse: the circle under the 2D part of the
 *                           transforms above it (a true circle, not
 *                           OpenSCAD's polygon: $fn, $fa, $fs are checked
 *                           and not used)
 *   square(size, center)    a polygon set of one path
 *   polygon(points, paths)  a polygon set, inside by the even-odd rule
 *                           over its paths (OpenSCAD's reading); no paths,
 *                           or an empty vector of them, is one path
 *                           through all the points
 * and whose inner nodes are OpenSCAD's 2D operations:
 *   group, union, render, color   union of the children
 *   multmatrix                    union, under the matrix's xy part
 *                                 (its rows and columns 0, 1 and the
 *                                 translation); a singular one is empty
 *   difference                    the first child minus the others
 *   intersection                  the intersection of the children
 * A child without area (a zero radius or size, no points) is empty as in
 * OpenSCAD's 2D evaluator: a union drops it, an intersection with it and a
 * difference from it are empty. '%' and '*' children are left out ('%'
 * ones give their warnings: build_twod_background).
 *
 * build_region_covers says beforehand whether a linear_extrude is this
 * path's; anything else (twist, scale, offset, text, 3D nodes, ...) goes
 * to the prism path in build_extrude.c. The walk over the 2D nodes is the
 * one 2D walk (build_twod.h), with its depth guard; bad arguments are
 * errors at the value, with the messages of the prism path.
 */
#include "build/build_region.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "build/build_twod.h"
#include "csg/prim_extrusion.h"

typedef struct walker {
    twod_walker walk; /* first: the visitor is the walker */
    const build_ctx *c;
    prim_region region;
    twod_region poly; /* the polygon being read, under the transforms */
    int far;          /* a square or circle reaches past the clipper's range */
} walker;

/* The 2D leaves the walk reads. */
static int is_leaf(model_kind kind)
{
    return kind == MODEL_CIRCLE || kind == MODEL_SQUARE || kind == MODEL_POLYGON;
}

/* The operations it reads: group, union, render, color, multmatrix,
 * difference, intersection. */
static int is_op(model_kind kind)
{
    return kind == MODEL_UNION || kind == MODEL_COLOR || kind == MODEL_XFORM ||
           kind == MODEL_DIFFERENCE || kind == MODEL_INTERSECTION;
}

/* The first node below n (n included) the walk cannot read, or NULL. */
static const model_node *uncovered(const model_node *n, int depth)
{
    if (depth > TWOD_WALK_MAX_DEPTH ||
        (n->modifiers & (MODEL_MOD_DISABLE | MODEL_MOD_BACKGROUND)))
        return NULL; /* the walk reports the depth; '%' and '*' are not built */
    model_kind kind = n->kind;
    if (is_leaf(kind))
        return NULL;
    if (!is_op(kind))
        return n;
    for (const model_node *k = n->first_child; k; k = k->next) {
        const model_node *miss = uncovered(k, depth + 1);
        if (miss)
            return miss;
    }
    return NULL;
}

int build_region_covers(const model_node *n, const model_node **miss)
{
    *miss = NULL;
    for (const model_node *k = n->first_child; k && !*miss; k = k->next)
        *miss = uncovered(k, 1);
    if (*miss)
        return 0;
    return n->u.linear_extrude->plain;
}

/* Adds the polygon read into w->poly to the region tree. */
static sc_status add_poly(walker *w, const model_node *n, int *pushed)
{
    twod_region *p = &w->poly;
    return prim_region_add_polygon(&w->region, p->xy, p->start, p->contour_count, pushed)
               ? SC_OK
               : err_nomem(w->c->error, &n->loc);
}

/* square(size = s | [x, y], center = false) */
static sc_status read_square(walker *w, const model_node *n, const affine2 *m,
                             int *pushed)
{
    if (n->pending)
        return build_pending(w->c, n);
    double sx = n->u.square->sx, sy = n->u.square->sy;
    int center = n->u.square->center;
    if (!(sx > 0 && sy > 0 && isfinite(sx) && isfinite(sy)))
        return SC_OK; /* no area */
    double x0 = center ? -sx / 2 : 0, y0 = center ? -sy / 2 : 0;
    twod_region *p = &w->poly;
    twod_clear(p);
    if (!twod_begin_contour(p) || !twod_add_moved(p, m, x0, y0) ||
        !twod_add_moved(p, m, x0 + sx, y0) || !twod_add_moved(p, m, x0 + sx, y0 + sy) ||
        !twod_add_moved(p, m, x0, y0 + sy))
        return build_twod_add_error(w->c, n, p);
    for (uint32_t i = 0; i < 2 * p->point_count; i++)
        w->far |= !twod_in_range(p->xy[i]);
    return add_poly(w, n, pushed);
}

/* circle(r = 1 | d) */
static sc_status read_circle(walker *w, const model_node *n, const affine2 *m,
                             int *pushed)
{
    if (n->pending)
        return build_pending(w->c, n);
    /* $fn, $fa, $fs checked, not used: the circle is exact */
    const model_circle *args = n->u.circle;
    double r = isnan(args->d) ? args->r : args->d / 2;
    if (!(r > 0 && isfinite(r)))
        return SC_OK;
    /* the ellipse's box: its centre, plus r times each row's length */
    for (int a = 0; a < 2; a++) {
        double reach = r * hypot(m->m[a][0], m->m[a][1]);
        w->far |=
            !twod_in_range(m->m[a][2] - reach) || !twod_in_range(m->m[a][2] + reach);
    }
    return prim_region_add_ellipse(&w->region, m->m, r, pushed)
               ? SC_OK
               : err_nomem(w->c->error, &n->loc);
}

/* polygon(points = [[x, y], ...], paths = [[i, j, ...], ...] | undef) */
static sc_status read_polygon(walker *w, const model_node *n, const affine2 *m,
                              int *pushed)
{
    const build_ctx *c = w->c;
    if (n->pending)
        return build_pending(c, n);
    twod_region *poly = &w->poly;
    twod_clear(poly);
    sc_status st = build_bad_indices(c, n);
    if (st != SC_OK || !n->u.polygon->has_points)
        return st;
    st = build_twod_polygon(c, n, m, 1, poly);
    if (st != SC_OK)
        return st;
    st = add_poly(w, n, pushed);
    if (st == SC_OK && w->region.edge_count > PRIM_EXTRUSION_MAX_EDGES)
        return err_set(c->error, SC_ERR_LIMIT, &n->loc,
                       "linear_extrude has too many polygon edges (limit is %d)",
                       PRIM_EXTRUSION_MAX_EDGES);
    return st;
}

/* The children of n combined by op; *pushed says whether a region was
 * pushed (an empty result pushes nothing and leaves no trace). */
static sc_status walk_children(walker *w, const model_node *n, const affine2 *m,
                               prim_region_op op, int depth, int *pushed)
{
    prim_region *r = &w->region;
    uint32_t nodes = r->node_count, edges = r->edge_count, ellipses = r->ellipse_count;
    int operands = 0, seen = 0, empty = 0;
    for (const model_node *k = n->first_child; k; k = k->next) {
        if (k->modifiers & MODEL_MOD_DISABLE)
            continue;
        int p = 0;
        sc_status st = k->modifiers & MODEL_MOD_BACKGROUND
                           ? build_twod_background(w->c, k, "linear_extrude")
                           : twod_walk(&w->walk, k, m, depth + 1, &p);
        if (st != SC_OK)
            return st;
        if (k->modifiers & MODEL_MOD_BACKGROUND)
            continue; /* no operand, only its warnings */
        if (!p && (op == PRIM_REGION_INTERSECTION ||
                   (op == PRIM_REGION_DIFFERENCE && seen == 0)))
            empty = 1;
        seen++;
        if (p && !empty && ++operands >= 2 && !prim_region_add_op(r, op))
            return err_nomem(w->c->error, &n->loc);
    }
    if (empty) {
        r->node_count = nodes;
        r->edge_count = edges;
        r->ellipse_count = ellipses;
        operands = 0;
    }
    *pushed = operands > 0;
    return SC_OK;
}

/* The walk's visitor: *pushed (out) says whether n pushed a region. */
static sc_status walk(twod_walker *walk, const model_node *n, const affine2 *m, int depth,
                      void *out)
{
    walker *w = (walker *)walk;
    int *pushed = out;
    *pushed = 0;
    model_kind kind = n->kind;
    if (kind == MODEL_SQUARE)
        return read_square(w, n, m, pushed);
    if (kind == MODEL_CIRCLE)
        return read_circle(w, n, m, pushed);
    if (kind == MODEL_POLYGON)
        return read_polygon(w, n, m, pushed);
    if (kind == MODEL_XFORM) {
        affine2 inner;
        sc_status st = twod_walk_fold(walk, n, m, &inner);
        if (st != SC_OK)
            return st;
        prim_region *r = &w->region;
        uint32_t nodes = r->node_count, edges = r->edge_count,
                 ellipses = r->ellipse_count;
        st = walk_children(w, n, &inner, PRIM_REGION_UNION, depth, pushed);
        if (st == SC_OK) /* removed for a nan or inf entry: said after its children */
            st = build_xform_not_finite(w->c, n);
        double det = inner.m[0][0] * inner.m[1][1] - inner.m[0][1] * inner.m[1][0];
        if (st == SC_OK && *pushed && !(det != 0)) {
            /* flattened onto a line or a point: no area (the children were
             * still read, for their errors), with OpenSCAD's warning */
            r->node_count = nodes;
            r->edge_count = edges;
            r->ellipse_count = ellipses;
            *pushed = 0;
            if (!n->not_finite)
                st = build_xform_flat_2d(w->c, n);
        }
        return st;
    }
    if (kind == MODEL_DIFFERENCE)
        return walk_children(w, n, m, PRIM_REGION_DIFFERENCE, depth, pushed);
    if (kind == MODEL_INTERSECTION)
        return walk_children(w, n, m, PRIM_REGION_INTERSECTION, depth, pushed);
    if (is_op(kind))
        return walk_children(w, n, m, PRIM_REGION_UNION, depth, pushed);
    return err_set(w->c->error, SC_ERR_UNSUPPORTED, &n->loc,
                   "'%s' inside linear_extrude is not supported yet", n->name);
}

sc_status build_region_extrude(const build_ctx *c, const model_node *n, int emit,
                               prim *out, const char **empty, int *far)
{
    *far = 0;
    const model_linear_extrude *args = n->u.linear_extrude;
    if (args->exact_error) {
        *c->error = *args->exact_error;
        return args->exact_error->status;
    }
    double height = args->height;
    int center = args->center;
    walker w;
    memset(&w, 0, sizeof w);
    w.walk = (twod_walker){c, "linear_extrude", "nodes", walk};
    w.c = c;
    twod_init(&w.poly);
    affine2 id = affine2_identity();
    int pushed = 0;
    sc_status st = walk_children(&w, n, &id, PRIM_REGION_UNION, 0, &pushed);
    *far = st == SC_OK && w.far;
    if (st == SC_OK && emit && !w.far) {
        double z0 = center ? -height / 2 : 0, z1 = z0 + height;
        if (!(height > 0 && isfinite(height)) || !pushed || !(z0 < z1)) {
            *empty = "linear_extrude without height or area is empty";
        } else {
            const prim_extrusion *e = prim_extrusion_create(c->csg, &w.region, z0, z1);
            if (!e) {
                st = err_nomem((&w)->c->error, &n->loc);
            } else {
                memset(out, 0, sizeof *out);
                out->kind = PRIM_EXTRUSION;
                out->u.extrusion.ext = e;
            }
        }
    }
    prim_region_free(&w.region);
    twod_free(&w.poly);
    return st;
}
