/* The convex hull of points in 3D, by quickhull (Barber, Dobkin and
 * Huhdanpaa, "The Quickhull Algorithm for Convex Hulls", ACM TOMS 1996)
 * with exact orientation tests.
 *
 * The hull is a closed surface of triangles, each wound counter-clockwise
 * seen from outside, each knowing its three neighbours. It starts as a
 * tetrahedron of four extreme points. Every other point is kept in the
 * outside set of one triangle it lies strictly above. Then, while some
 * triangle has an outside set, its farthest point p (by floating-point
 * distance, a heuristic only) is added: the triangles p sees form a
 * connected patch, found by a search from that triangle over neighbours;
 * the patch's boundary (the horizon) is one closed loop of edges; each
 * horizon edge a -> b gets the new triangle (a, b, p), and the patch is
 * removed. The points of the removed triangles go to the first new
 * triangle they lie above, or are dropped: a point above a removed
 * triangle that is outside the new hull must see one of the new
 * triangles (the segment from it to the removed triangle enters the new
 * hull through one of them), so nothing outside is lost.
 *
 * "Sees" is the sign of orient(a, b, c, p) = (b - a) x (c - a) . (p - a),
 * and it is exact: a floating-point determinant with Shewchuk's error bound
 * decides when it can ("Adaptive Precision Floating-Point Arithmetic and
 * Fast Robust Geometric Predicates", 1997: |det| > (7 + 56 eps) eps times
 * the permanent), and otherwise the determinant is summed exactly as a
 * floating-point expansion: the 4x4 determinant of the rows (x, y, z, 1)
 * of a, b, c, p is a sum of 24 signed triple products of coordinates, each
 * exact as a product expansion (fma gives the rounding error of a product
 * exactly), and the expansions add exactly. With exact signs the visible
 * patch is always a topological disc and its horizon one simple loop, so
 * the combinatorics cannot fail on duplicate, coplanar or nearly coplanar
 * points: a point on a triangle's plane is not above it and adds nothing.
 * (Coordinates are limited to HULL3_MAX_COORD so that triple products do
 * not overflow; products of tiny coordinates may underflow, which only
 * matters below 1e-100.)
 *
 * Output: the vertices used by the final triangles, the triangles, and one
 * plane per set of adjacent, exactly coplanar triangles: its normal is the
 * sum of the triangles' area vectors (normalised), its offset the largest
 * n . v over the set's vertices, so every vertex, and with it every input
 * point, is inside every plane up to the rounding of n; where that rounding
 * can tilt n (a sliver of nearly collinear corners), the largest n . v over
 * all the vertices.
 */
#include "csg/hull3.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define NONE UINT32_MAX

/* ---- exact orientation ---- */

/* x + y = a + b exactly, |y| <= ulp(x) / 2. */
static void two_sum(double a, double b, double *x, double *y)
{
    double s = a + b;
    double bv = s - a;
    double av = s - bv;
    *x = s;
    *y = (a - av) + (b - bv);
}

/* Adds b to the nonoverlapping expansion e[0 .. n) (increasing magnitude)
 * in place; returns the new length (at most n + 1), zeros dropped. */
static int grow(double *e, int n, double b)
{
    double q = b;
    int k = 0;
    for (int i = 0; i < n; i++) {
        double hh;
        two_sum(q, e[i], &q, &hh);
        if (hh != 0)
            e[k++] = hh;
    }
    if (q != 0 || k == 0)
        e[k++] = q;
    return k;
}

/* The 24 permutations of 4 columns with their signs: row r takes column
 * perm[r]; column 3 is the constant 1. */
static const unsigned char perms[24][5] = {
    {0, 1, 2, 3, 0}, {0, 1, 3, 2, 1}, {0, 2, 1, 3, 1}, {0, 2, 3, 1, 0}, {0, 3, 1, 2, 0},
    {0, 3, 2, 1, 1}, {1, 0, 2, 3, 1}, {1, 0, 3, 2, 0}, {1, 2, 0, 3, 0}, {1, 2, 3, 0, 1},
    {1, 3, 0, 2, 1}, {1, 3, 2, 0, 0}, {2, 0, 1, 3, 0}, {2, 0, 3, 1, 1}, {2, 1, 0, 3, 1},
    {2, 1, 3, 0, 0}, {2, 3, 0, 1, 0}, {2, 3, 1, 0, 1}, {3, 0, 1, 2, 1}, {3, 0, 2, 1, 0},
    {3, 1, 0, 2, 0}, {3, 1, 2, 0, 1}, {3, 2, 0, 1, 1}, {3, 2, 1, 0, 0},
};

static int exact_det4_sign(const vec3 rows[4])
{
    double e[128];
    int n = 0;
    for (int k = 0; k < 24; k++) {
        double f[3];
        int m = 0;
        for (int r = 0; r < 4; r++) {
            int col = perms[k][r];
            if (col < 3)
                f[m++] = v3_get(rows[r], col);
        }
        /* f0 f1 = hi + lo exactly; times f2, each exactly. */
        double hi = f[0] * f[1];
        double lo = fma(f[0], f[1], -hi);
        double terms[4];
        terms[0] = hi * f[2];
        terms[1] = fma(hi, f[2], -terms[0]);
        terms[2] = lo * f[2];
        terms[3] = fma(lo, f[2], -terms[2]);
        double s = perms[k][4] ? -1.0 : 1.0;
        for (int i = 0; i < 4; i++) {
            if (terms[i] != 0)
                n = grow(e, n, s * terms[i]);
        }
    }
    if (n == 0)
        return 0; /* every product was zero */
    /* A nonoverlapping expansion has the sign of its largest component. */
    double top = e[n - 1];
    return top > 0 ? 1 : top < 0 ? -1 : 0;
}

int hull3_orient(vec3 a, vec3 b, vec3 c, vec3 p)
{
    /* Shewchuk's orient3d(a, b, c, p), which is -orient here. */
    double adx = a.x - p.x, bdx = b.x - p.x, cdx = c.x - p.x;
    double ady = a.y - p.y, bdy = b.y - p.y, cdy = c.y - p.y;
    double adz = a.z - p.z, bdz = b.z - p.z, cdz = c.z - p.z;
    double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
    double cdxady = cdx * ady, adxcdy = adx * cdy;
    double adxbdy = adx * bdy, bdxady = bdx * ady;
    double det =
        adz * (bdxcdy - cdxbdy) + bdz * (cdxady - adxcdy) + cdz * (adxbdy - bdxady);
    double permanent = (fabs(bdxcdy) + fabs(cdxbdy)) * fabs(adz) +
                       (fabs(cdxady) + fabs(adxcdy)) * fabs(bdz) +
                       (fabs(adxbdy) + fabs(bdxady)) * fabs(cdz);
    const double eps = DBL_EPSILON / 2;
    double bound = (7.0 + 56.0 * eps) * eps * permanent;
    if (det > bound)
        return -1;
    if (-det > bound)
        return 1;
    vec3 rows[4] = {a, b, c, p};
    return -exact_det4_sign(rows);
}

/* ---- quickhull ---- */

typedef struct face {
    uint32_t v[3];    /* counter-clockwise seen from outside */
    uint32_t nb[3];   /* the face across edge v[i] -> v[i + 1] */
    uint32_t outside; /* first point of its outside set, or NONE */
    uint32_t mark;    /* the round that found it visible */
    int alive;
    vec3 n; /* (v1 - v0) x (v2 - v0), for the distance heuristic */
} face;

typedef struct qh {
    const vec3 *p;
    uint32_t count;
    uint32_t *next; /* outside-set links, per point */
    face *faces;
    uint32_t face_count, face_cap;
    uint32_t *stack, *visible; /* scratch, face indices */
    uint32_t *horizon;         /* scratch: (face, edge) pairs */
    uint32_t *start_of;        /* per point: new face starting there */
} qh;

static int add_face(qh *q, uint32_t a, uint32_t b, uint32_t c, uint32_t *index)
{
    if (q->face_count == q->face_cap) {
        uint32_t cap = q->face_cap ? 2 * q->face_cap : 64;
        if (cap > UINT32_MAX / 4)
            return 0;
        face *grown = realloc(q->faces, (size_t)cap * sizeof *grown);
        uint32_t *stack = realloc(q->stack, (size_t)cap * sizeof *stack);
        if (stack)
            q->stack = stack;
        uint32_t *visible = realloc(q->visible, (size_t)cap * sizeof *visible);
        if (visible)
            q->visible = visible;
        uint32_t *horizon = realloc(q->horizon, (size_t)cap * 6 * sizeof *horizon);
        if (horizon)
            q->horizon = horizon;
        if (grown)
            q->faces = grown;
        if (!grown || !stack || !visible || !horizon)
            return 0;
        q->face_cap = cap;
    }
    face *f = &q->faces[q->face_count];
    memset(f, 0, sizeof *f);
    f->v[0] = a;
    f->v[1] = b;
    f->v[2] = c;
    f->nb[0] = f->nb[1] = f->nb[2] = NONE;
    f->outside = NONE;
    f->alive = 1;
    f->n = v3_cross(v3_sub(q->p[b], q->p[a]), v3_sub(q->p[c], q->p[a]));
    *index = q->face_count++;
    return 1;
}

static int above(const qh *q, const face *f, uint32_t point)
{
    return hull3_orient(q->p[f->v[0]], q->p[f->v[1]], q->p[f->v[2]], q->p[point]) > 0;
}

/* Puts point into the outside set of the first face of faces[0 .. n) it
 * lies above; returns 0 when there is none. */
static int assign(qh *q, const uint32_t *faces, uint32_t n, uint32_t point)
{
    for (uint32_t i = 0; i < n; i++) {
        face *f = &q->faces[faces[i]];
        if (above(q, f, point)) {
            q->next[point] = f->outside;
            f->outside = point;
            return 1;
        }
    }
    return 0;
}

/* The edge index of face f that runs a -> b, or 3. */
static int edge_of(const face *f, uint32_t a, uint32_t b)
{
    for (int i = 0; i < 3; i++) {
        if (f->v[i] == a && f->v[(i + 1) % 3] == b)
            return i;
    }
    return 3;
}

/* Four points spanning a tetrahedron, or 0 when the set is flat. Lengths
 * are compared by their largest coordinate, which does not underflow as
 * squares would. */
static int initial_simplex(const qh *q, uint32_t s[4])
{
    uint32_t ext[6] = {0, 0, 0, 0, 0, 0};
    for (uint32_t i = 1; i < q->count; i++) {
        for (int k = 0; k < 3; k++) {
            if (v3_get(q->p[i], k) < v3_get(q->p[ext[2 * k]], k))
                ext[2 * k] = i;
            if (v3_get(q->p[i], k) > v3_get(q->p[ext[2 * k + 1]], k))
                ext[2 * k + 1] = i;
        }
    }
    double best = -1;
    s[0] = s[1] = 0;
    for (int i = 0; i < 6; i++) {
        for (int j = i + 1; j < 6; j++) {
            double d = v3_max_abs(v3_sub(q->p[ext[i]], q->p[ext[j]]));
            if (d > best) {
                best = d;
                s[0] = ext[i];
                s[1] = ext[j];
            }
        }
    }
    if (!(best > 0))
        return 0;
    vec3 axis = v3_sub(q->p[s[1]], q->p[s[0]]);
    best = 0;
    s[2] = NONE;
    for (uint32_t i = 0; i < q->count; i++) {
        double d = v3_max_abs(v3_cross(axis, v3_sub(q->p[i], q->p[s[0]])));
        if (d > best) {
            best = d;
            s[2] = i;
        }
    }
    if (s[2] == NONE)
        return 0;
    vec3 nrm = v3_cross(axis, v3_sub(q->p[s[2]], q->p[s[0]]));
    best = -1;
    s[3] = NONE;
    for (uint32_t i = 0; i < q->count; i++) {
        double d = fabs(v3_dot(nrm, v3_sub(q->p[i], q->p[s[0]])));
        if (d > best && hull3_orient(q->p[s[0]], q->p[s[1]], q->p[s[2]], q->p[i]) != 0) {
            best = d;
            s[3] = i;
        }
    }
    return s[3] != NONE;
}

/* Links faces[0 .. n) to each other by their shared edges. */
static void link_faces(qh *q, const uint32_t *faces, uint32_t n)
{
    for (uint32_t i = 0; i < n; i++) {
        face *f = &q->faces[faces[i]];
        for (int e = 0; e < 3; e++) {
            for (uint32_t j = 0; j < n; j++) {
                if (edge_of(&q->faces[faces[j]], f->v[(e + 1) % 3], f->v[e]) < 3)
                    f->nb[e] = faces[j];
            }
        }
    }
}

/* Adds the farthest point of face f's outside set. Returns 0 on failure
 * (out of memory; or a broken horizon, which exact tests rule out). */
static int add_point(qh *q, uint32_t fi, uint32_t round)
{
    face *f = &q->faces[fi];
    uint32_t apex = NONE;
    double best = -INFINITY;
    for (uint32_t i = f->outside; i != NONE; i = q->next[i]) {
        double d = v3_dot(f->n, v3_sub(q->p[i], q->p[f->v[0]]));
        if (d > best) {
            best = d;
            apex = i;
        }
    }
    /* The visible patch, by depth-first search. */
    uint32_t nvis = 0, top = 0;
    q->stack[top++] = fi;
    q->faces[fi].mark = round;
    while (top) {
        uint32_t g = q->stack[--top];
        q->visible[nvis++] = g;
        for (int e = 0; e < 3; e++) {
            uint32_t h = q->faces[g].nb[e];
            face *hf = &q->faces[h];
            if (hf->mark == round)
                continue;
            if (above(q, hf, apex)) {
                hf->mark = round;
                q->stack[top++] = h;
            }
        }
    }
    /* Horizon edges: a visible face's edge whose neighbour is not visible. */
    uint32_t nh = 0;
    for (uint32_t i = 0; i < nvis; i++) {
        face *g = &q->faces[q->visible[i]];
        for (int e = 0; e < 3; e++) {
            if (q->faces[g->nb[e]].mark != round) {
                q->horizon[nh++] = q->visible[i];
                q->horizon[nh++] = (uint32_t)e;
            }
        }
    }
    uint32_t first_new = q->face_count;
    for (uint32_t i = 0; i < nh; i += 2) {
        face g = q->faces[q->horizon[i]];
        int e = (int)q->horizon[i + 1];
        uint32_t a = g.v[e], b = g.v[(e + 1) % 3], other = g.nb[e], idx;
        if (q->start_of[a] != NONE)
            return 0;
        if (!add_face(q, a, b, apex, &idx))
            return 0;
        q->start_of[a] = idx;
        q->faces[idx].nb[0] = other;
        face *of = &q->faces[other];
        int oe = edge_of(of, b, a);
        if (oe == 3)
            return 0;
        of->nb[oe] = idx;
    }
    uint32_t created = q->face_count - first_new;
    int ok = 1;
    for (uint32_t i = first_new; i < q->face_count; i++) {
        face *g = &q->faces[i];
        uint32_t after = q->start_of[g->v[1]];
        if (after == NONE) {
            ok = 0;
            continue;
        }
        g->nb[1] = after;          /* b -> apex: the face starting at b */
        q->faces[after].nb[2] = i; /* its apex -> b */
    }
    for (uint32_t i = first_new; i < q->face_count; i++)
        q->start_of[q->faces[i].v[0]] = NONE;
    if (!ok)
        return 0;
    /* The removed faces' points go to the new faces. */
    for (uint32_t i = 0; i < nvis; i++) {
        face *g = &q->faces[q->visible[i]];
        g->alive = 0;
        uint32_t pt = g->outside;
        g->outside = NONE;
        while (pt != NONE) {
            uint32_t following = q->next[pt];
            if (pt != apex) {
                for (uint32_t k = 0; k < created; k++) {
                    face *nf = &q->faces[first_new + k];
                    if (above(q, nf, pt)) {
                        q->next[pt] = nf->outside;
                        nf->outside = pt;
                        break;
                    }
                }
            }
            pt = following;
        }
    }
    return 1;
}

static uint32_t find(uint32_t *parent, uint32_t x)
{
    while (parent[x] != x) {
        parent[x] = parent[parent[x]];
        x = parent[x];
    }
    return x;
}

/* Fills out from the live faces. */
static hull3_status finish(qh *q, hull3 *out)
{
    uint32_t *vmap = malloc((size_t)q->count * sizeof *vmap);
    uint32_t *parent = malloc((size_t)q->face_count * sizeof *parent);
    uint32_t *group = malloc((size_t)q->face_count * sizeof *group);
    uint32_t live = 0;
    for (uint32_t i = 0; i < q->face_count; i++)
        live += q->faces[i].alive ? 1u : 0u;
    out->tris = malloc((size_t)live * 3 * sizeof *out->tris);
    out->vertices = malloc((size_t)(live + 4) * sizeof *out->vertices);
    out->planes = malloc((size_t)live * sizeof *out->planes);
    vec3 *sum = calloc(live, sizeof *sum);
    double *err = calloc(live ? live : 1, sizeof *err); /* per plane: sum's rounding */
    if (!vmap || !parent || !group || !out->tris || !out->vertices || !out->planes ||
        !sum || !err) {
        free(vmap);
        free(parent);
        free(group);
        free(sum);
        free(err);
        hull3_free(out);
        return HULL3_NOMEM;
    }
    for (uint32_t i = 0; i < q->count; i++)
        vmap[i] = NONE;
    out->bounds = bbox_empty();
    /* Coplanar neighbours share a plane. */
    for (uint32_t i = 0; i < q->face_count; i++)
        parent[i] = i;
    for (uint32_t i = 0; i < q->face_count; i++) {
        const face *f = &q->faces[i];
        if (!f->alive)
            continue;
        for (int e = 0; e < 3; e++) {
            const face *g = &q->faces[f->nb[e]];
            uint32_t opposite = g->v[(edge_of(g, f->v[(e + 1) % 3], f->v[e]) + 2) % 3];
            if (hull3_orient(q->p[f->v[0]], q->p[f->v[1]], q->p[f->v[2]],
                             q->p[opposite]) == 0) {
                uint32_t a = find(parent, i), b = find(parent, f->nb[e]);
                parent[a] = b;
            }
        }
    }
    for (uint32_t i = 0; i < q->face_count; i++)
        group[i] = NONE;
    uint32_t t = 0;
    for (uint32_t i = 0; i < q->face_count; i++) {
        const face *f = &q->faces[i];
        if (!f->alive)
            continue;
        uint32_t root = find(parent, i);
        if (group[root] == NONE)
            group[root] = out->plane_count++;
        sum[group[root]] = v3_add(sum[group[root]], f->n);
        for (int k = 0; k < 3; k++) {
            uint32_t v = f->v[k];
            if (vmap[v] == NONE) {
                vmap[v] = out->vertex_count;
                out->vertices[out->vertex_count++] = q->p[v];
                out->bounds = bbox_add_point(out->bounds, q->p[v]);
            }
            out->tris[3 * t + (uint32_t)k] = vmap[v];
        }
        t++;
    }
    out->tri_count = t;
    for (uint32_t g = 0; g < out->plane_count; g++) {
        out->planes[g].n = v3_normalize(sum[g]);
        out->planes[g].d = -INFINITY;
    }
    for (uint32_t i = 0; i < q->face_count; i++) {
        const face *f = &q->faces[i];
        if (!f->alive)
            continue;
        uint32_t g = group[find(parent, i)];
        plane *pl = &out->planes[g];
        for (int k = 0; k < 3; k++)
            pl->d = fmax(pl->d, v3_dot(pl->n, q->p[f->v[k]]));
        /* the rounding of f's area vector, summed into err */
        vec3 u = v3_sub(q->p[f->v[1]], q->p[f->v[0]]);
        vec3 v = v3_sub(q->p[f->v[2]], q->p[f->v[0]]);
        err[g] += 16 * DBL_EPSILON * v3_max_abs(u) * v3_max_abs(v);
    }
    /* A plane whose rounded normal may be tilted by more than about 1e-13
     * (a sliver: corners nearly collinear, so that its area vector is
     * mostly rounding and may point anywhere) takes its offset from every
     * vertex: from its own corners alone, the rest of the hull could lie
     * outside it and the plane would cut the solid. Each component of a
     * triangle's rounded cross product is off by at most 16 eps |u| |v|
     * (max norms of its edges; differences, products and their difference
     * each round once), so a group's normal tilts by about err / |sum| at
     * most. Such a plane still holds every vertex, and the sliver has next
     * to no area: its neighbours' planes bound the solid across it. */
    for (uint32_t g = 0; g < out->plane_count; g++) {
        if (!(err[g] > 1e-13 * v3_length(sum[g])))
            continue;
        for (uint32_t k = 0; k < out->vertex_count; k++)
            out->planes[g].d =
                fmax(out->planes[g].d, v3_dot(out->planes[g].n, out->vertices[k]));
    }
    free(vmap);
    free(parent);
    free(group);
    free(sum);
    free(err);
    return HULL3_OK;
}

hull3_status hull3_compute(const vec3 *points, uint32_t count, hull3 *out)
{
    memset(out, 0, sizeof *out);
    if (count > HULL3_MAX_POINTS)
        return HULL3_RANGE;
    for (uint32_t i = 0; i < count; i++) {
        if (!v3_is_finite(points[i]) || !(v3_max_abs(points[i]) <= HULL3_MAX_COORD))
            return HULL3_RANGE;
    }
    if (count < 4)
        return HULL3_FLAT;
    qh q;
    memset(&q, 0, sizeof q);
    q.p = points;
    q.count = count;
    uint32_t s[4] = {0, 0, 0, 0};
    if (!initial_simplex(&q, s))
        return HULL3_FLAT;
    q.next = malloc((size_t)count * sizeof *q.next);
    q.start_of = malloc((size_t)count * sizeof *q.start_of);
    hull3_status st = HULL3_NOMEM;
    if (!q.next || !q.start_of)
        goto done;
    for (uint32_t i = 0; i < count; i++)
        q.start_of[i] = NONE;
    if (hull3_orient(points[s[0]], points[s[1]], points[s[2]], points[s[3]]) > 0) {
        uint32_t t = s[1];
        s[1] = s[2];
        s[2] = t;
    }
    uint32_t tet[4];
    if (!add_face(&q, s[0], s[1], s[2], &tet[0]) ||
        !add_face(&q, s[1], s[0], s[3], &tet[1]) ||
        !add_face(&q, s[2], s[1], s[3], &tet[2]) ||
        !add_face(&q, s[0], s[2], s[3], &tet[3]))
        goto done;
    link_faces(&q, tet, 4);
    for (uint32_t i = 0; i < count; i++) {
        if (i != s[0] && i != s[1] && i != s[2] && i != s[3])
            assign(&q, tet, 4, i);
    }
    uint32_t round = 0;
    for (uint32_t i = 0; i < q.face_count; i++) {
        if (!q.faces[i].alive || q.faces[i].outside == NONE)
            continue;
        if (!add_point(&q, i, ++round))
            goto done; /* only memory can fail here with exact tests */
    }
    st = finish(&q, out);
done:
    free(q.next);
    free(q.start_of);
    free(q.faces);
    free(q.stack);
    free(q.visible);
    free(q.horizon);
    return st;
}

void hull3_free(hull3 *h)
{
    free(h->vertices);
    free(h->tris);
    free(h->planes);
    memset(h, 0, sizeof *h);
}

double hull3_volume(const hull3 *h)
{
    double v = 0;
    vec3 o = h->vertex_count ? h->vertices[0] : v3(0, 0, 0);
    for (uint32_t t = 0; t < h->tri_count; t++) {
        vec3 a = v3_sub(h->vertices[h->tris[3 * t]], o);
        vec3 b = v3_sub(h->vertices[h->tris[3 * t + 1]], o);
        vec3 c = v3_sub(h->vertices[h->tris[3 * t + 2]], o);
        v += v3_dot(a, v3_cross(b, c));
    }
    return v / 6;
}
