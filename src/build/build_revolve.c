/* rotate_extrude(angle, convexity, $fn, $fa, $fs) of 2D children.
 *
 * The children are gathered into a profile in OpenSCAD's 2D coordinates
 * (x, y): regions, each a set of closed paths read even-odd (a polygon
 * with its paths, a square) or a circle, under group, union, render, color
 * and multmatrix (its xy part). The profile is their union. Every region
 * also keeps the polygon OpenSCAD makes of it (a circle's points for its
 * $fn, $fa, $fs), which gives OpenSCAD's checks and the faithful mesh.
 * Other 2D nodes (difference, intersection, offset, text, hull, ...) are
 * "not supported yet" at their position; a 2D engine that turns such a
 * node into paths plugs in at gather_other, adding one region.
 *
 * OpenSCAD 2021.01 (GeometryEvaluator.cc, rotatePolygon), whose rules this
 * follows:
 *   - angle: 360 when absent or not finite, and when <= -360 or > 360; 0
 *     gives nothing. Positive angles sweep counter-clockwise from +x,
 *     negative ones clockwise.
 *   - all x must have one sign: min_x and max_x start at 0 and follow the
 *     points in order; when max_x - min_x exceeds both max_x and |min_x|
 *     (points strictly on both sides) it stops with "all points for
 *     rotate_extrude() must have the same X coordinate sign (range is
 *     min_x -> max_x)", the range so far, two decimals. A profile wholly at
 *     x <= 0 is allowed: a point (x, y) goes to (x cos a, x sin a, y), so
 *     it sweeps the mirrored profile from 180 degrees.
 *   - fragments: get_fragments_from_r(max_x - min_x, $fn, $fs, $fa)
 *     * |angle| / 360, at least 1, truncated.
 *   - rings: for 360, ring k at a = -90 + k * 360 / f (k = 0 .. f - 1,
 *     the last quad strip closing onto ring 0); otherwise f + 1 rings,
 *     ring 0 at a = 90 and ring k at 90 - k * angle / f. A profile point
 *     goes to (x sin a, x cos a, y). Each profile edge between two rings is
 *     two triangles, and a partial angle closes with the profile itself as
 *     the start and end caps.
 *
 * Exact mode builds PRIM_REVOLVE (prim_revolve.c): edges in (r, z) =
 * (|x|, y), each path wound so that its region lies on its left (outlines
 * counter-clockwise, holes clockwise, holes found by nesting within their
 * polygon as linear_extrude does), and circles as discs (a torus each). A
 * circle under a transform that is not a similarity (an ellipse, whose
 * revolution is a quartic that is no torus) and a circle whose exact disc
 * would reach across the axis (its polygon does not) are their OpenSCAD
 * polygon. A profile with a point past the clipper's range is OpenSCAD's
 * 2D union of the children, which decides what is drawn there. Faithful
 * mode builds OpenSCAD's mesh through build_mesh_prim.
 * The walk over the children recurses with a depth guard.
 */
#include "build/build_revolve.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "base/grow.h"
#include "build/build_mesh.h"
#include "build/build_twod.h"
#include "csg/prim_revolve.h"
#include "model/faithful.h"

/* An exact circle: centre, radius, and the path holding its polygon. */
typedef struct profile_circle {
    double cx, cy, r;
    uint32_t path;
    int exact; /* the transform was a similarity */
} profile_circle;

typedef struct profile {
    twod_region pts;  /* the paths, under the transforms */
    uint32_t *region; /* per path: the region it belongs to */
    int *hole;        /* per path: a hole of its region */
    uint32_t paths_cap;
    uint32_t noted; /* paths with their region and hole mark */
    uint32_t regions;
    profile_circle *circles;
    uint32_t circle_count, circle_cap;
} profile;

static void profile_free(profile *p)
{
    twod_free(&p->pts);
    free(p->region);
    free(p->hole);
    free(p->circles);
}

/* Opens a new region; the paths that follow belong to it. */
static void begin_region(profile *p)
{
    p->regions++;
}

/* Gives the paths added since the last call their region (the last one
 * opened) and no hole mark; 0 when memory runs out. */
static int note_paths(profile *p)
{
    uint32_t count = p->pts.contour_count;
    if (count > p->paths_cap) {
        uint32_t cap = p->paths_cap;
        if (!grow_array32((void **)&p->region, &cap, count, sizeof *p->region))
            return 0;
        int *hole = realloc(p->hole, (size_t)cap * sizeof *hole);
        if (!hole)
            return 0;
        p->hole = hole;
        p->paths_cap = cap;
    }
    for (uint32_t k = p->noted; k < count; k++) {
        p->hole[k] = 0;
        p->region[k] = p->regions - 1;
    }
    p->noted = count;
    return 1;
}

static int begin_path(profile *p)
{
    return twod_begin_contour(&p->pts) && note_paths(p);
}

/* Even-odd: is (x, y) inside path k? */
static int in_path(const profile *p, uint32_t k, double x, double y)
{
    int in = 0;
    uint32_t s = p->pts.start[k], e = p->pts.start[k + 1];
    for (uint32_t i = s; i < e; i++) {
        uint32_t j = i + 1 < e ? i + 1 : s;
        double xi = p->pts.xy[2 * i], yi = p->pts.xy[2 * i + 1];
        double xj = p->pts.xy[2 * j], yj = p->pts.xy[2 * j + 1];
        if ((yi > y) != (yj > y) && x < xi + (y - yi) * (xj - xi) / (yj - yi))
            in = !in;
    }
    return in;
}

/* Marks the holes among paths first .. p->pts.contour_count - 1 (one polygon): a path
 * whose first point lies inside an odd number of the others.
 *
 * Each path j is measured once, and only the points in its box (widened by
 * the rounding of in_path's crossing abscissa, a few ulps of the largest
 * |x|) are tested against its edges: a point above or below the box meets
 * no edge of j, and one left or right of it meets every edge's crossing on
 * the same side, an even count. So the marks are in_path's, and a profile of
 * many small contours (text) costs about paths^2 box tests instead of
 * paths x points edge tests (a fuzzed text profile of 141863 points took
 * 13 s). */
static void mark_holes(profile *p, uint32_t first)
{
    for (uint32_t k = first; k < p->pts.contour_count; k++)
        p->hole[k] = 0;
    for (uint32_t j = first; j < p->pts.contour_count; j++) {
        uint32_t s = p->pts.start[j], e = p->pts.start[j + 1];
        if (e - s < 3)
            continue;
        double x0 = p->pts.xy[2 * s], x1 = x0, y0 = p->pts.xy[2 * s + 1], y1 = y0;
        for (uint32_t i = s + 1; i < e; i++) {
            x0 = fmin(x0, p->pts.xy[2 * i]);
            x1 = fmax(x1, p->pts.xy[2 * i]);
            y0 = fmin(y0, p->pts.xy[2 * i + 1]);
            y1 = fmax(y1, p->pts.xy[2 * i + 1]);
        }
        double slack = 8 * DBL_EPSILON * fmax(fabs(x0), fabs(x1));
        for (uint32_t k = first; k < p->pts.contour_count; k++) {
            if (k == j || p->pts.start[k + 1] - p->pts.start[k] < 3)
                continue;
            double x = p->pts.xy[2 * p->pts.start[k]],
                   y = p->pts.xy[2 * p->pts.start[k] + 1];
            if (y < y0 || y > y1 || x < x0 - slack || x > x1 + slack)
                continue;
            if (in_path(p, j, x, y))
                p->hole[k] ^= 1;
        }
    }
}

static sc_status read_square(const build_ctx *c, const model_node *n, const affine2 *m,
                             profile *p)
{
    if (n->pending)
        return build_pending(c, n);
    double sx = n->u.square->sx, sy = n->u.square->sy;
    int center = n->u.square->center;
    if (!(sx > 0 && sy > 0 && isfinite(sx) && isfinite(sy)))
        return SC_OK; /* no area */
    double x0 = center ? -sx / 2 : 0, y0 = center ? -sy / 2 : 0;
    begin_region(p);
    twod_region *r = &p->pts;
    if (!begin_path(p) || !twod_add_moved(r, m, x0, y0) ||
        !twod_add_moved(r, m, x0 + sx, y0) || !twod_add_moved(r, m, x0 + sx, y0 + sy) ||
        !twod_add_moved(r, m, x0, y0 + sy))
        return build_twod_add_error(c, n, r);
    return SC_OK;
}

/* Is the 2x2 part of m a rotation or reflection times a uniform scale? */
static int similarity(const affine2 *m)
{
    double a = m->m[0][0], b = m->m[0][1], cc = m->m[1][0], d = m->m[1][1];
    double size = fmax(fmax(fabs(a), fabs(b)), fmax(fabs(cc), fabs(d)));
    double tol = 1e-9 * size;
    return (fabs(a - d) <= tol && fabs(b + cc) <= tol) ||
           (fabs(a + d) <= tol && fabs(b - cc) <= tol);
}

static sc_status read_circle(const build_ctx *c, const model_node *n, const affine2 *m,
                             profile *p)
{
    if (n->pending)
        return build_pending(c, n);
    const model_circle *args = n->u.circle;
    double r = isnan(args->d) ? args->r : args->d / 2, fn = args->res.fn,
           fa = args->res.fa, fs = args->res.fs;
    if (!(r > 0 && isfinite(r)))
        return SC_OK;
    long f = faithful_fragments(r, fn, fs, fa);
    if (f < 0)
        return err_set(c->error, SC_ERR_LIMIT, &n->loc,
                       "circle has too many fragments (limit is %d)",
                       FAITHFUL_MAX_FRAGMENTS);
    if (!grow_array32((void **)&p->circles, &p->circle_cap, p->circle_count + 1,
                      sizeof *p->circles))
        return err_nomem(c->error, &n->loc);
    begin_region(p);
    if (!begin_path(p))
        return err_nomem(c->error, &n->loc);
    double det = m->m[0][0] * m->m[1][1] - m->m[0][1] * m->m[1][0];
    p->circles[p->circle_count++] =
        (profile_circle){m->m[0][2], m->m[1][2], r * sqrt(fabs(det)),
                         p->pts.contour_count - 1, similarity(m)};
    for (long k = 0; k < f; k++) {
        double a = 360.0 * (double)k / (double)f;
        if (!twod_add_moved(&p->pts, m, r * faithful_cos_deg(a), r * faithful_sin_deg(a)))
            return build_twod_add_error(c, n, &p->pts);
    }
    return SC_OK;
}

static sc_status read_polygon(const build_ctx *c, const model_node *n, const affine2 *m,
                              profile *p)
{
    if (n->pending)
        return build_pending(c, n);
    sc_status st = build_bad_indices(c, n);
    if (st != SC_OK || !n->u.polygon->has_points)
        return st;
    begin_region(p);
    uint32_t first = p->pts.contour_count;
    /* an empty vector of paths is no path here */
    st = build_twod_polygon(c, n, m, 0, &p->pts);
    if (st != SC_OK)
        return st;
    if (!note_paths(p))
        return err_nomem(c->error, &n->loc);
    mark_holes(p, first);
    return SC_OK;
}

/* Adds the contours of a region the 2D engine (src/twod/) computed as one
 * region of the profile, holes found by nesting as for a polygon's paths. */
static sc_status add_twod(const build_ctx *c, const model_node *n, const twod_region *r,
                          const affine2 *m, profile *p)
{
    if (r->contour_count == 0)
        return SC_OK;
    uint32_t first = p->pts.contour_count;
    begin_region(p);
    for (uint32_t k = 0; k < r->contour_count; k++) {
        if (!begin_path(p))
            return err_nomem(c->error, &n->loc);
        for (uint32_t i = r->start[k]; i < r->start[k + 1]; i++) {
            if (!twod_add_moved(&p->pts, m, r->xy[2 * i], r->xy[2 * i + 1]))
                return build_twod_add_error(c, n, &p->pts);
        }
    }
    mark_holes(p, first);
    return SC_OK;
}

/* The 2D nodes without a reader here (difference, intersection, offset,
 * hull, minkowski): the 2D engine evaluates the node as OpenSCAD does. */
static sc_status gather_other(const build_ctx *c, const model_node *n, const affine2 *m,
                              profile *p)
{
    twod_region r;
    twod_init(&r);
    sc_status st = build_twod_node(c, n, "rotate_extrude", &r);
    if (st == SC_OK)
        st = add_twod(c, n, &r, m, p);
    twod_free(&r);
    return st;
}

/* The profile gathered by the one 2D walk (build_twod.h). */
typedef struct gatherer {
    twod_walker walk; /* first: the visitor is the walker */
    profile *p;
} gatherer;

/* The walk's visitor: n's paths added to the profile. */
static sc_status gather(twod_walker *walk, const model_node *n, const affine2 *m,
                        int depth, void *out)
{
    (void)out;
    const build_ctx *c = walk->c;
    profile *p = ((gatherer *)walk)->p;
    model_kind kind = n->kind;
    if (kind == MODEL_SQUARE)
        return read_square(c, n, m, p);
    if (kind == MODEL_CIRCLE)
        return read_circle(c, n, m, p);
    if (kind == MODEL_POLYGON)
        return read_polygon(c, n, m, p);
    /* removed for a nan or inf entry, or 3D (a union of a cube and a
     * square): the 2D engine says what OpenSCAD says of it and of its
     * children (no geometry) */
    if ((kind == MODEL_XFORM && n->not_finite) || build_dim(n, 1) == 3)
        return gather_other(c, n, m, p);
    affine2 inner = *m;
    if (kind == MODEL_XFORM) {
        sc_status st = twod_walk_fold(walk, n, m, &inner);
        if (st != SC_OK)
            return st;
    } else if (kind != MODEL_UNION && kind != MODEL_COLOR) {
        return gather_other(c, n, m, p);
    }
    return twod_walk_children(walk, n, &inner, depth);
}

/* Does path k go the way its region needs (outline counter-clockwise,
 * hole clockwise) in the plane (sign * x, y)? */
static int path_reversed(const profile *p, uint32_t k, double sign)
{
    return (sign * twod_contour_area(&p->pts, k) > 0) == p->hole[k];
}

/* Index of the i-th point of path k, oriented. */
static uint32_t oriented(const profile *p, uint32_t k, int reverse, uint32_t i)
{
    uint32_t s = p->pts.start[k], len = p->pts.start[k + 1] - s;
    return s + (reverse ? len - 1 - i : i);
}

/* OpenSCAD's mesh (see the top) through build_mesh_prim; or, when faces is
 * not NULL, in *faces (out unused), each end cap one face of all the
 * contours. */
static sc_status build_faithful(const build_ctx *c, const model_node *n, const profile *p,
                                double angle, long fragments, prim *out,
                                const char **empty, build_mesh_faces *faces)
{
    int full = angle == 360;
    uint32_t f = (uint32_t)fragments;
    uint32_t rings = full ? f : f + 1;
    if ((uint64_t)rings * p->pts.point_count > BUILD_REVOLVE_MAX_MESH_POINTS)
        return err_set(c->error, SC_ERR_LIMIT, &n->loc,
                       "rotate_extrude: %u rings of %u points are too many (limit is %u "
                       "points)",
                       rings, p->pts.point_count, BUILD_REVOLVE_MAX_MESH_POINTS);
    size_t np = (size_t)rings * p->pts.point_count;
    size_t ntri = (size_t)2 * f * p->pts.point_count;
    size_t nfaces = ntri + (full ? 0 : 2 * (size_t)p->pts.contour_count);
    vec3 *pts = malloc((np ? np : 1) * sizeof *pts);
    uint32_t *idx = malloc((3 * ntri + 2 * (size_t)p->pts.point_count + 1) * sizeof *idx);
    uint32_t *fs = malloc((nfaces + 1) * sizeof *fs);
    uint32_t *face_loops = faces ? malloc((ntri + 3) * sizeof *face_loops) : NULL;
    uint8_t *cap_of = faces ? NULL : calloc(nfaces + 1, 1); /* build_mesh_checks */
    sc_status st = SC_OK;
    if (!pts || !idx || !fs || (faces && !face_loops) || (!faces && !cap_of)) {
        st = err_nomem(c->error, &n->loc);
        goto done;
    }
    for (uint32_t k = 0; k < rings; k++) {
        double a = full ? -90 + (double)k * 360.0 / (double)f
                        : (k == 0 ? 90 : 90 - (double)k * angle / (double)f);
        double sa = faithful_sin_deg(a), ca = faithful_cos_deg(a);
        for (uint32_t i = 0; i < p->pts.point_count; i++) {
            double x = p->pts.xy[2 * i], y = p->pts.xy[2 * i + 1];
            pts[(size_t)k * p->pts.point_count + i] = v3(x * sa, x * ca, y);
        }
    }
    uint32_t ni = 0, nf = 0;
    for (uint32_t k = 0; k < p->pts.contour_count; k++) {
        uint32_t len = p->pts.start[k + 1] - p->pts.start[k];
        if (len < 3)
            continue;
        int rev = path_reversed(p, k, 1);
        for (uint32_t j = 0; j < f; j++) {
            size_t r0 = (size_t)j * p->pts.point_count,
                   r1 = (size_t)((j + 1) % rings) * p->pts.point_count;
            for (uint32_t i = 0; i < len; i++) {
                uint32_t a = oriented(p, k, rev, i),
                         b = oriented(p, k, rev, (i + 1) % len);
                /* OpenSCAD's two triangles of the quad */
                fs[nf++] = ni;
                idx[ni++] = (uint32_t)(r0 + a);
                idx[ni++] = (uint32_t)(r1 + b);
                idx[ni++] = (uint32_t)(r0 + b);
                fs[nf++] = ni;
                idx[ni++] = (uint32_t)(r0 + a);
                idx[ni++] = (uint32_t)(r1 + a);
                idx[ni++] = (uint32_t)(r1 + b);
            }
        }
        if (!full && !faces) {
            /* start cap: the path as oriented on ring 0; end cap: reversed on
             * ring f (opposite to the strips' edges there) */
            cap_of[nf] = 1;
            fs[nf++] = ni;
            for (uint32_t i = 0; i < len; i++)
                idx[ni++] = oriented(p, k, rev, i);
            cap_of[nf] = 2;
            fs[nf++] = ni;
            for (uint32_t i = 0; i < len; i++)
                idx[ni++] = (uint32_t)((size_t)f * p->pts.point_count) +
                            oriented(p, k, rev, len - 1 - i);
        }
    }
    if (!faces) {
        fs[nf] = ni;
        build_mesh_checks openscad = {idx, fs, nf, cap_of};
        st = build_mesh_prim_checked(c, &n->loc, "rotate_extrude", 0, pts, (uint32_t)np,
                                     idx, fs, nf, &openscad, out, empty);
        goto done;
    }
    /* faces: the side triangles, then each cap as one face of the loops of
     * all the contours, wound as above */
    uint32_t sides = nf, face_count = 0;
    for (uint32_t i = 0; i <= sides; i++)
        face_loops[face_count++] = i;
    for (uint32_t end = 0; !full && end < 2; end++) {
        for (uint32_t k = 0; k < p->pts.contour_count; k++) {
            uint32_t len = p->pts.start[k + 1] - p->pts.start[k];
            if (len < 3)
                continue;
            int rev = path_reversed(p, k, 1);
            fs[nf++] = ni;
            for (uint32_t i = 0; i < len; i++)
                idx[ni++] = end ? (uint32_t)((size_t)f * p->pts.point_count) +
                                      oriented(p, k, rev, len - 1 - i)
                                : oriented(p, k, rev, i);
        }
        face_loops[face_count++] = nf;
    }
    fs[nf] = ni;
    *faces = (build_mesh_faces){.points = pts,
                                .point_count = (uint32_t)np,
                                .indices = idx,
                                .face_start = fs,
                                .face_loops = face_loops,
                                .face_count = face_count - 1};
    pts = NULL;
    idx = fs = face_loops = NULL;
done:
    free(pts);
    free(idx);
    free(fs);
    free(face_loops);
    free(cap_of);
    return st;
}

/* The exact leaf (prim_revolve.c). sign is -1 for a profile at x <= 0. */
static sc_status build_exact(const build_ctx *c, const model_node *n, const profile *p,
                             double angle, double sign, prim *out)
{
    /* which paths a disc replaces, and the size of the result */
    uint32_t edges = 0, discs = 0;
    uint8_t *replaced = calloc(p->pts.contour_count ? p->pts.contour_count : 1, 1);
    uint32_t *region_map = malloc((p->regions ? p->regions : 1) * sizeof *region_map);
    sc_status st = SC_OK;
    if (!replaced || !region_map) {
        st = err_nomem(c->error, &n->loc);
        goto done;
    }
    for (uint32_t k = 0; k < p->circle_count; k++) {
        const profile_circle *ci = &p->circles[k];
        if (ci->exact && ci->r <= sign * ci->cx) {
            replaced[ci->path] = 1;
            discs++;
        }
    }
    for (uint32_t k = 0; k < p->pts.contour_count; k++) {
        uint32_t len = p->pts.start[k + 1] - p->pts.start[k];
        if (!replaced[k] && len >= 3)
            edges += len;
    }
    if ((uint64_t)edges + 2 * (uint64_t)discs > PRIM_REVOLVE_MAX_EDGES) {
        st =
            err_set(c->error, SC_ERR_LIMIT, &n->loc,
                    "rotate_extrude profile has %llu edges (limit is %d; a circle counts "
                    "2)",
                    (unsigned long long)edges + 2 * (unsigned long long)discs,
                    PRIM_REVOLVE_MAX_EDGES);
        goto done;
    }
    for (uint32_t k = 0; k < p->regions; k++)
        region_map[k] = UINT32_MAX;
    prim_revolve *rv = csg_builder_alloc(c->csg, sizeof *rv);
    prim_revolve_edge *ev = csg_builder_alloc(c->csg, (edges ? edges : 1) * sizeof *ev);
    prim_revolve_disc *dv = csg_builder_alloc(c->csg, (discs ? discs : 1) * sizeof *dv);
    if (!rv || !ev || !dv) {
        st = err_nomem(c->error, &n->loc);
        goto done;
    }
    memset(rv, 0, sizeof *rv);
    uint32_t regions = 0;
    double r_lo = INFINITY, r_hi = -INFINITY, z_lo = INFINITY, z_hi = -INFINITY;
    uint32_t ne = 0, nd = 0;
    for (uint32_t k = 0; k < p->pts.contour_count; k++) {
        uint32_t len = p->pts.start[k + 1] - p->pts.start[k];
        if (replaced[k] || len < 3)
            continue;
        uint32_t *reg = &region_map[p->region[k]];
        if (*reg == UINT32_MAX)
            *reg = regions++;
        int rev = path_reversed(p, k, sign);
        for (uint32_t i = 0; i < len; i++) {
            uint32_t a = oriented(p, k, rev, i), b = oriented(p, k, rev, (i + 1) % len);
            prim_revolve_edge *e = &ev[ne++];
            e->r0 = sign * p->pts.xy[2 * a];
            e->z0 = p->pts.xy[2 * a + 1];
            e->r1 = sign * p->pts.xy[2 * b];
            e->z1 = p->pts.xy[2 * b + 1];
            e->region = *reg;
            r_lo = fmin(r_lo, e->r0);
            r_hi = fmax(r_hi, e->r0);
            z_lo = fmin(z_lo, e->z0);
            z_hi = fmax(z_hi, e->z0);
        }
    }
    for (uint32_t k = 0; k < p->circle_count; k++) {
        const profile_circle *ci = &p->circles[k];
        if (!replaced[ci->path])
            continue;
        uint32_t *reg = &region_map[p->region[ci->path]];
        if (*reg == UINT32_MAX)
            *reg = regions++;
        prim_revolve_disc *d = &dv[nd++];
        d->rc = sign * ci->cx;
        d->zc = ci->cy;
        d->a = ci->r;
        d->region = *reg;
        r_lo = fmin(r_lo, d->rc - d->a);
        r_hi = fmax(r_hi, d->rc + d->a);
        z_lo = fmin(z_lo, d->zc - d->a);
        z_hi = fmax(z_hi, d->zc + d->a);
    }
    rv->edges = ev;
    rv->discs = dv;
    rv->edge_count = ne;
    rv->disc_count = nd;
    rv->region_count = regions;
    rv->r_lo = fmax(0, r_lo);
    rv->r_hi = r_hi;
    rv->z_lo = z_lo;
    rv->z_hi = z_hi;
    if (angle != 360) {
        /* The wedge from phi0 over |angle| degrees, counter-clockwise. */
        double phi0 = angle > 0 ? 0 : angle;
        if (sign < 0)
            phi0 += 180;
        double sweep = fabs(angle);
        rv->partial = 1;
        rv->sweep = sweep;
        rv->start[0] = faithful_cos_deg(phi0);
        rv->start[1] = faithful_sin_deg(phi0);
        rv->end[0] = faithful_cos_deg(phi0 + sweep);
        rv->end[1] = faithful_sin_deg(phi0 + sweep);
    }
    memset(out, 0, sizeof *out);
    out->kind = PRIM_REVOLVE;
    out->u.revolve.rev = rv;
done:
    free(replaced);
    free(region_map);
    return st;
}

/* build_rotate_extrude, or with faces build_rotate_extrude_faces. */
/* Adds to p the children of n as OpenSCAD's 2D union makes them. */
static sc_status united_profile(const build_ctx *c, const model_node *n, profile *p)
{
    affine2 id = affine2_identity();
    twod_region r;
    twod_init(&r);
    sc_status st = build_twod_children(c, n, &r);
    if (st == SC_OK)
        st = add_twod(c, n, &r, &id, p);
    twod_free(&r);
    return st;
}

static sc_status rotate_extrude(const build_ctx *c, const model_node *n, int emit,
                                prim *out, const char **empty, build_mesh_faces *faces)
{
    if (n->pending)
        return build_pending(c, n);
    const model_rotate_extrude *args = n->u.rotate_extrude;
    double angle = args->angle, fn = args->res.fn, fa = args->res.fa, fs = args->res.fs;
    if (!isfinite(angle) || angle <= -360 || angle > 360)
        angle = 360;
    sc_status st = SC_OK;
    profile p;
    memset(&p, 0, sizeof p);
    affine2 id = affine2_identity();
    if (c->faithful) {
        /* OpenSCAD unites the children in 2D first: its rings follow the
         * united outline's points. */
        st = united_profile(c, n, &p);
    } else {
        build_notes_place notes = build_notes_here(c);
        gatherer g = {{c, "rotate_extrude", "nodes", gather}, &p};
        st = twod_walk_children(&g.walk, n, &id, 0);
        int far = 0;
        for (uint32_t i = 0; st == SC_OK && i < 2 * p.pts.point_count; i++)
            far |= !twod_in_range(p.pts.xy[i]);
        if (far) {
            /* past the clipper's range, OpenSCAD's 2D union decides what
             * it draws, refuses or leaves out (and says so again) */
            build_notes_rewind(c, notes);
            profile_free(&p);
            memset(&p, 0, sizeof p);
            st = united_profile(c, n, &p);
        }
    }
    /* OpenSCAD's check, in its order, with its running range: it logs the
     * error and the extrusion is empty, the rest rendered */
    double min_x = 0, max_x = 0;
    int crossed = 0;
    for (uint32_t i = 0; st == SC_OK && !crossed && i < p.pts.point_count; i++) {
        min_x = fmin(min_x, p.pts.xy[2 * i]);
        max_x = fmax(max_x, p.pts.xy[2 * i]);
        crossed = max_x - min_x > max_x && max_x - min_x > fabs(min_x);
    }
    static const char crossing[] =
        "all points for rotate_extrude() must have the same X coordinate sign (range is "
        "%.2f -> %.2f)";
    if (st == SC_OK && crossed && c->strict)
        st = err_set(c->error, SC_ERR_SEMANTIC, &n->loc, crossing, min_x, max_x);
    else if (st == SC_OK && crossed) {
        char why[160];
        snprintf(why, sizeof why, crossing, min_x, max_x);
        st =
            build_note(c, &n->loc,
                       "%s; the rotate_extrude is empty, as OpenSCAD leaves it out", why);
        *empty = "";
    }
    if (st == SC_OK && emit && !crossed) {
        double area = 0;
        for (uint32_t k = 0; k < p.pts.contour_count; k++)
            if (p.pts.start[k + 1] - p.pts.start[k] >= 3)
                area += fabs(twod_contour_area(&p.pts, k));
        if (angle == 0) {
            *empty = "rotate_extrude with angle 0 is empty";
        } else if (!(area > 0)) {
            *empty = "rotate_extrude without area is empty";
        } else if (c->faithful) {
            long f = faithful_fragments(max_x - min_x, fn, fs, fa);
            if (f < 0)
                st = err_set(c->error, SC_ERR_LIMIT, &n->loc,
                             "faithful mode: $fn, $fa and $fs of radius %g give too many "
                             "fragments (limit is %d)",
                             max_x - min_x, FAITHFUL_MAX_FRAGMENTS);
            else
                st = build_faithful(c, n, &p, angle,
                                    (long)fmax((double)f * fabs(angle) / 360, 1), out,
                                    empty, faces);
        } else {
            st = build_exact(c, n, &p, angle, min_x < 0 ? -1 : 1, out);
        }
    }
    profile_free(&p);
    return st;
}

sc_status build_rotate_extrude(const build_ctx *c, const model_node *n, int emit,
                               prim *out, const char **empty)
{
    return rotate_extrude(c, n, emit, out, empty, NULL);
}

sc_status build_rotate_extrude_faces(const build_ctx *c, const model_node *n,
                                     build_mesh_faces *faces, const char **empty)
{
    build_ctx fc = *c;
    fc.faithful = 1;
    memset(faces, 0, sizeof *faces);
    return rotate_extrude(&fc, n, 1, NULL, empty, faces);
}
