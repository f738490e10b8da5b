/* Triangle meshes: spans of a ray through a closed mesh, by watertight
 * ray-triangle tests over a hierarchy of boxes.
 *
 * Ray-triangle test (Woop, Benthin and Wald, "Watertight Ray/Triangle
 * Intersection", JCGT 2013). The axis kz where |d| is largest becomes the
 * ray's axis; kx, ky follow cyclically and are swapped when d_kz < 0, so
 * the map below keeps orientation. Each corner p goes to the ray's frame
 *   P = p - o,  x = P_kx - S_x P_kz,  y = P_ky - S_y P_kz,  z = S_z P_kz
 * with S_x = d_kx / d_kz, S_y = d_ky / d_kz, S_z = 1 / d_kz: a shear that
 * sends the ray to the +z axis through (0, 0). The ray meets the triangle
 * ABC when the origin lies in its projection, i.e. the three edge functions
 *   e(p, q) = p_x q_y - p_y q_x   (the orientation of p, q and the origin)
 * for the edges BC, CA, AB all have the sign of the triangle's area
 * det = e(B, C) + e(C, A) + e(A, B); the crossing is at
 *   t = (e(B, C) A_z + e(C, A) B_z + e(A, B) C_z) / det.
 * The corners' sheared coordinates depend only on the corner and the ray,
 * so two triangles sharing an edge see the same two points. Each e is
 * computed with Kahan's fused difference of products, whose sign is the
 * exact sign of the determinant of those points, so the two triangles get
 * e of opposite signs, or both zero. A zero is resolved by simulation of
 * simplicity: the origin is moved by an infinitesimal eps (1, eta), which
 * turns e(p, q) = 0 into the sign of -(q_y - p_y), or of q_x - p_x when
 * q_y = p_y. The perturbed origin lies in exactly one of the triangles
 * around a shared edge or vertex of a surface the ray crosses, and in both
 * or neither of two that fold over an edge the ray grazes: a ray through an
 * edge or a vertex is counted once, and no ray slips between faces.
 *
 * Facing: the shear keeps orientation and sends the ray to +z, so det > 0
 * means the outward normal (b - a) x (c - a) points along the ray: an exit;
 * det < 0 an entry.
 *
 * Spans: the crossings are sorted by t and walked with a winding number
 * (+1 at an entry, -1 at an exit); the line is inside where it is
 * positive. For a closed, consistently oriented mesh this is the parity
 * rule; faces split into fans of triangles (a non-convex face) cancel
 * where the fan overlaps itself. At most PRIM_MESH_MAX_CROSSINGS crossings
 * are kept, the smallest t first, and the largest t of all is remembered;
 * at most prim_max_spans spans are written. Past either bound the last
 * span written is stretched to the largest crossing: the spans before it
 * and every first hit stay exact, the far side of a very intricate mesh is
 * filled (documented in docs/meshes.md).
 *
 * Membership: the winding number of q, from the crossings of the ray
 * q + t (1, sqrt 2, sqrt 3) / 2 with t > 0 (exits minus entries); a
 * crossing at t = 0 puts q on the surface, which is inside (closed).
 *
 * Hierarchy: median splits of the triangle centroids along the widest axis
 * down to 4 triangles a leaf, so its depth is at most log2(n) + 1 < 64. A
 * box test that rounds the wrong way must not drop a triangle the ray
 * touches, so every box is padded by 1e-9 of the mesh's extent, far more
 * than the rounding of the slab test and far less than anything visible.
 *
 * Normals: a span end's part is the triangle's index modulo 65536 (parts
 * are 16 bits); a mesh with more triangles is asked which of the triangles
 * with that residue has its plane closest to the point.
 */
#include "csg/prim_mesh.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "csg/csg.h"

enum { LEAF_SIZE = 4, STACK = 64 };

/* ---- building ---- */

typedef struct builder_state {
    const vec3 *points;
    const uint32_t *tris;
    uint32_t *order; /* triangle ids, permuted into leaf order */
    double *key;     /* scratch: centroid coordinate per position */
    vec3 *centre;    /* per triangle id */
    prim_mesh_node *nodes;
    uint32_t node_count;
    double pad;
} builder_state;

static bbox tri_box(const builder_state *s, uint32_t id)
{
    bbox b = bbox_empty();
    for (int k = 0; k < 3; k++)
        b = bbox_add_point(b, s->points[s->tris[3 * id + k]]);
    return b;
}

static double axis_of(vec3 v, int axis)
{
    return axis == 0 ? v.x : axis == 1 ? v.y : v.z;
}

/* Moves the k-th smallest key of order[lo .. hi) to position k, smaller
 * ones before it (Hoare's selection, iterative). */
static void select_kth(builder_state *s, uint32_t lo, uint32_t hi, uint32_t k)
{
    while (hi - lo > 1) {
        double pivot = s->key[lo + (hi - lo) / 2];
        uint32_t i = lo, j = hi - 1;
        while (i <= j) {
            while (s->key[i] < pivot)
                i++;
            while (s->key[j] > pivot)
                j--;
            if (i <= j) {
                double tk = s->key[i];
                s->key[i] = s->key[j];
                s->key[j] = tk;
                uint32_t to = s->order[i];
                s->order[i] = s->order[j];
                s->order[j] = to;
                i++;
                if (j == 0)
                    break;
                j--;
            }
        }
        if (k <= j)
            hi = j + 1;
        else if (k >= i)
            lo = i;
        else
            return;
    }
}

/* Builds the subtree over order[lo .. hi); depth is bounded by the median
 * split (log2 of the count). Returns its node index. */
static uint32_t build_node(builder_state *s, uint32_t lo, uint32_t hi)
{
    uint32_t index = s->node_count++;
    prim_mesh_node *n = &s->nodes[index];
    bbox box = bbox_empty(), centres = bbox_empty();
    for (uint32_t i = lo; i < hi; i++) {
        bbox t = tri_box(s, s->order[i]);
        box = bbox_add_point(bbox_add_point(box, t.lo), t.hi);
        centres = bbox_add_point(centres, s->centre[s->order[i]]);
    }
    vec3 pad = v3(s->pad, s->pad, s->pad);
    n->box.lo = v3_sub(box.lo, pad);
    n->box.hi = v3_add(box.hi, pad);
    if (hi - lo <= LEAF_SIZE) {
        n->start = lo;
        n->count = hi - lo;
        return index;
    }
    vec3 ext = v3_sub(centres.hi, centres.lo);
    int axis = ext.x >= ext.y && ext.x >= ext.z ? 0 : ext.y >= ext.z ? 1 : 2;
    for (uint32_t i = lo; i < hi; i++)
        s->key[i] = axis_of(s->centre[s->order[i]], axis);
    uint32_t mid = lo + (hi - lo) / 2;
    select_kth(s, lo, hi, mid);
    n->count = 0;
    build_node(s, lo, mid);
    uint32_t right = build_node(s, mid, hi);
    s->nodes[index].start = right;
    return index;
}

const prim_mesh *prim_mesh_create(struct csg_builder *b, const vec3 *points,
                                  const uint32_t *tris, uint32_t tri_count)
{
    builder_state s;
    memset(&s, 0, sizeof s);
    s.points = points;
    s.tris = tris;
    const prim_mesh *result = NULL;
    s.order = malloc((size_t)(tri_count ? tri_count : 1) * sizeof *s.order);
    s.key = malloc((size_t)(tri_count ? tri_count : 1) * sizeof *s.key);
    s.centre = malloc((size_t)(tri_count ? tri_count : 1) * sizeof *s.centre);
    if (!s.order || !s.key || !s.centre)
        goto done;
    bbox bounds = bbox_empty();
    uint32_t kept = 0;
    for (uint32_t i = 0; i < tri_count; i++) {
        vec3 a = points[tris[3 * i]], bb = points[tris[3 * i + 1]],
             c = points[tris[3 * i + 2]];
        vec3 n = v3_cross(v3_sub(bb, a), v3_sub(c, a));
        if (!(v3_dot(n, n) > 0))
            continue; /* no area: no ray crosses it */
        s.order[kept++] = i;
        s.centre[i] = v3_scale(v3_add(v3_add(a, bb), c), 1.0 / 3);
        bounds = bbox_add_point(bbox_add_point(bbox_add_point(bounds, a), bb), c);
    }
    if (kept == 0)
        goto done;
    vec3 ext = v3_sub(bounds.hi, bounds.lo);
    s.pad = 1e-9 * fmax(fmax(ext.x, ext.y), fmax(ext.z, v3_max_abs(bounds.lo))) + 1e-300;
    s.pad = fmax(s.pad, 1e-9 * v3_max_abs(bounds.hi));
    /* A binary tree over kept leaves of at least one triangle has fewer
     * than 2 kept nodes. */
    s.nodes = malloc((size_t)2 * kept * sizeof *s.nodes);
    if (!s.nodes)
        goto done;
    build_node(&s, 0, kept);
    prim_mesh *m = csg_builder_alloc(b, sizeof *m);
    vec3 *v = csg_builder_alloc(b, (size_t)3 * kept * sizeof *v);
    vec3 *nrm = csg_builder_alloc(b, (size_t)kept * sizeof *nrm);
    prim_mesh_node *nodes = csg_builder_alloc(b, (size_t)s.node_count * sizeof *nodes);
    if (!m || !v || !nrm || !nodes)
        goto done;
    for (uint32_t i = 0; i < kept; i++) {
        const uint32_t *t = &tris[3 * s.order[i]];
        for (int k = 0; k < 3; k++)
            v[3 * i + k] = points[t[k]];
        nrm[i] = v3_cross(v3_sub(v[3 * i + 1], v[3 * i]), v3_sub(v[3 * i + 2], v[3 * i]));
    }
    memcpy(nodes, s.nodes, (size_t)s.node_count * sizeof *nodes);
    m->v = v;
    m->n = nrm;
    m->nodes = nodes;
    m->tri_count = kept;
    m->node_count = s.node_count;
    m->bounds = bounds;
    result = m;
done:
    free(s.order);
    free(s.key);
    free(s.centre);
    free(s.nodes);
    return result;
}

/* ---- crossings ---- */

typedef struct ray_frame {
    vec3 o;
    int kx, ky, kz;
    double sx, sy, sz;
} ray_frame;

typedef struct crossing {
    double t;
    uint32_t tri;
    int exit; /* 1: the ray leaves the solid here */
} crossing;

static double comp(vec3 v, int k)
{
    return k == 0 ? v.x : k == 1 ? v.y : v.z;
}

static ray_frame frame_of(vec3 o, vec3 d)
{
    ray_frame f;
    f.o = o;
    double ax = fabs(d.x), ay = fabs(d.y), az = fabs(d.z);
    f.kz = ax >= ay && ax >= az ? 0 : ay >= az ? 1 : 2;
    f.kx = (f.kz + 1) % 3;
    f.ky = (f.kx + 1) % 3;
    double dz = comp(d, f.kz);
    if (dz < 0) {
        int t = f.kx;
        f.kx = f.ky;
        f.ky = t;
    }
    f.sx = comp(d, f.kx) / dz;
    f.sy = comp(d, f.ky) / dz;
    f.sz = 1.0 / dz;
    return f;
}

/* a b - c d with the sign of the exact result (Kahan: the rounding of c d
 * is recovered by a fused multiply-add and added back). */
static double diff_of_products(double a, double b, double c, double d)
{
    double w = c * d;
    double e = fma(-c, d, w);
    double f = fma(a, b, -w);
    return f + e;
}

/* The edge function e(p, q) with its zero resolved: > 0 or < 0 as the
 * origin, moved by eps (1, eta), lies left or right of p -> q. Returns +1,
 * -1, or 0 for a degenerate edge (p = q). */
static int edge_sign(double px, double py, double qx, double qy)
{
    double e = diff_of_products(px, qy, py, qx);
    if (e > 0)
        return 1;
    if (e < 0)
        return -1;
    if (qy != py)
        return qy < py ? 1 : -1;
    if (qx != px)
        return qx > px ? 1 : -1;
    return 0;
}

/* Crosses triangle i; returns 1 and fills *c when the line meets it. */
static int cross_triangle(const prim_mesh *m, const ray_frame *f, uint32_t i, crossing *c)
{
    double x[3], y[3], z[3];
    for (int k = 0; k < 3; k++) {
        vec3 p = v3_sub(m->v[3 * i + k], f->o);
        double pz = comp(p, f->kz);
        x[k] = comp(p, f->kx) - f->sx * pz;
        y[k] = comp(p, f->ky) - f->sy * pz;
        z[k] = f->sz * pz;
    }
    int su = edge_sign(x[1], y[1], x[2], y[2]); /* BC */
    int sv = edge_sign(x[2], y[2], x[0], y[0]); /* CA */
    int sw = edge_sign(x[0], y[0], x[1], y[1]); /* AB */
    if (su == 0 || sv == 0 || sw == 0 || su != sv || sv != sw)
        return 0;
    double u = diff_of_products(x[1], y[2], y[1], x[2]);
    double v = diff_of_products(x[2], y[0], y[2], x[0]);
    double w = diff_of_products(x[0], y[1], y[0], x[1]);
    double det = u + v + w;
    if (det == 0 || (det > 0) != (su > 0))
        return 0; /* no area in projection: a ray in the triangle's plane */
    double t = (u * z[0] + v * z[1] + w * z[2]) / det;
    if (!isfinite(t))
        return 0;
    c->t = t;
    c->tri = i;
    c->exit = det > 0;
    return 1;
}

/* Where the line meets the node's box: the slab test over the whole line;
 * an axis the ray does not move along is decided by the origin. */
static int hits_box(const bbox *b, vec3 o, vec3 d)
{
    double t0 = -INFINITY, t1 = INFINITY;
    for (int k = 0; k < 3; k++) {
        double ok = comp(o, k), dk = comp(d, k), lo = comp(b->lo, k), hi = comp(b->hi, k);
        if (dk == 0) {
            if (ok < lo || ok > hi)
                return 0;
            continue;
        }
        double ta = (lo - ok) / dk, tb = (hi - ok) / dk;
        t0 = fmax(t0, fmin(ta, tb));
        t1 = fmin(t1, fmax(ta, tb));
    }
    return t0 <= t1;
}

typedef struct crossings {
    crossing v[PRIM_MESH_MAX_CROSSINGS];
    uint32_t n;
    int overflow;
    crossing last; /* the largest t of all */
    int any;
    int count_only; /* membership: only the winding of t > 0 is wanted */
    int wind;       /* count_only: exits minus entries */
    int on_surface; /* count_only: a crossing at t = 0 */
} crossings;

static void keep(crossings *cs, const crossing *c)
{
    if (cs->count_only) {
        if (c->t == 0)
            cs->on_surface = 1;
        else if (c->t > 0)
            cs->wind += c->exit ? 1 : -1;
        return;
    }
    if (!cs->any || c->t > cs->last.t)
        cs->last = *c;
    cs->any = 1;
    if (cs->n == PRIM_MESH_MAX_CROSSINGS) {
        cs->overflow = 1;
        if (c->t >= cs->v[cs->n - 1].t)
            return;
        cs->n--; /* the largest kept one makes way */
    }
    /* insertion in t order; at equal t, exits first, so touching pieces
     * fuse and grazes leave no gap */
    uint32_t i = cs->n;
    while (i > 0 && (cs->v[i - 1].t > c->t ||
                     (cs->v[i - 1].t == c->t && cs->v[i - 1].exit < c->exit))) {
        cs->v[i] = cs->v[i - 1];
        i--;
    }
    cs->v[i] = *c;
    cs->n++;
}

static void collect(const prim_mesh *m, vec3 o, vec3 d, crossings *cs)
{
    ray_frame f = frame_of(o, d);
    uint32_t stack[STACK], top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const prim_mesh_node *n = &m->nodes[stack[--top]];
        if (!hits_box(&n->box, o, d))
            continue;
        if (n->count > 0) {
            for (uint32_t i = n->start; i < n->start + n->count; i++) {
                crossing c;
                if (cross_triangle(m, &f, i, &c))
                    keep(cs, &c);
            }
            continue;
        }
        if (top + 2 > STACK)
            continue; /* cannot happen: depth < 64 */
        stack[top++] = n->start;
        stack[top++] = (uint32_t)(n - m->nodes) + 1;
    }
}

/* ---- operations ---- */

uint32_t prim_mesh_max_spans(const prim *p)
{
    uint32_t half = p->u.mesh.mesh ? p->u.mesh.mesh->tri_count / 2 : 1;
    if (half < 1)
        half = 1;
    return half < PRIM_MESH_MAX_SPANS ? half : PRIM_MESH_MAX_SPANS;
}

static span_end end_at(const crossing *c, uint32_t leaf)
{
    span_end e = {c->t, leaf, (uint16_t)(c->tri & 0xffffu), 0};
    return e;
}

uint32_t prim_mesh_spans(const prim *p, uint32_t leaf, vec3 o, vec3 d, span *out,
                         uint32_t cap)
{
    const prim_mesh *m = p->u.mesh.mesh;
    if (!m || cap == 0)
        return 0;
    crossings cs;
    cs.n = 0;
    cs.overflow = 0;
    cs.any = 0;
    cs.count_only = 0;
    collect(m, o, d, &cs);
    uint32_t n = 0;
    int wind = 0, full = 0;
    span_end start = {0, leaf, 0, 0};
    for (uint32_t i = 0; i < cs.n && !full; i++) {
        int was_in = wind > 0;
        wind += cs.v[i].exit ? -1 : 1;
        int is_in = wind > 0;
        if (!was_in && is_in) {
            start = end_at(&cs.v[i], leaf);
        } else if (was_in && !is_in) {
            out[n].in = start;
            out[n].out = end_at(&cs.v[i], leaf);
            n++;
            full = n == cap;
        }
    }
    int open = wind > 0 && !full;
    if (cs.overflow || full || open) {
        /* Past the bounds (or a mesh that is not closed along this line):
         * fill to the last crossing of all. */
        span_end last = end_at(&cs.last, leaf);
        if (open) {
            out[n].in = start;
            out[n].out = last;
            n++;
        } else if (n > 0) {
            out[n - 1].out = last;
        }
    }
    return n;
}

vec3 prim_mesh_normal(const prim *p, vec3 q, uint16_t part)
{
    const prim_mesh *m = p->u.mesh.mesh;
    if (!m || part >= m->tri_count)
        return v3(0, 0, 1);
    uint32_t best = part;
    double best_dist = INFINITY;
    for (uint32_t i = part; i < m->tri_count; i += 65536u) {
        vec3 n = m->n[i];
        double dist = fabs(v3_dot(n, v3_sub(q, m->v[3 * i]))) / v3_length(n);
        if (dist < best_dist) {
            best_dist = dist;
            best = i;
        }
    }
    return m->n[best];
}

int prim_mesh_inside(const prim *p, vec3 q)
{
    const prim_mesh *m = p->u.mesh.mesh;
    if (!m || !(q.x >= m->bounds.lo.x && q.x <= m->bounds.hi.x && q.y >= m->bounds.lo.y &&
                q.y <= m->bounds.hi.y && q.z >= m->bounds.lo.z && q.z <= m->bounds.hi.z))
        return 0;
    crossings cs;
    cs.n = 0;
    cs.count_only = 1;
    cs.wind = 0;
    cs.on_surface = 0;
    vec3 d = v3(0.5, 0.70710678118654752, 0.86602540378443865);
    collect(m, q, d, &cs);
    return cs.on_surface || cs.wind > 0;
}
