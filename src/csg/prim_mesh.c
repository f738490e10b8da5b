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
 * (+1 at an entry, -1 at an exit); the line is inside where it is not
 * zero. For a closed, consistently oriented mesh without self-overlap
 * this is the parity rule; faces split into fans of triangles (a
 * non-convex face) cancel where the fan overlaps itself. Where a fold
 * turns part of the mesh inside out (a twisted extrusion in too few
 * slices) the winding is negative there, and that part is solid too, as
 * OpenSCAD draws the triangles: a span end on a triangle that faces into
 * the span gets the flip bit (as under parity, below).
 * At most PRIM_MESH_MAX_CROSSINGS crossings are kept, the smallest t
 * first, and the largest t of all is remembered; at most prim_max_spans
 * spans are written. Past either bound the last span written is stretched
 * to the largest crossing: the spans before it and every first hit stay
 * exact, the far side of a very intricate mesh is filled (documented in
 * docs/meshes.md).
 *
 * Parity meshes (prim_mesh.parity: a mesh that is open, non-manifold or
 * inconsistently wound, built anyway in exact mode): a winding number
 * means nothing when the faces do not agree on a side, so the line is
 * inside after an odd count of crossings, whichever way each triangle
 * faces, and a span end on a triangle that faces into the span gets the
 * flip bit, so its normal still points out of the span. On a closed mesh
 * the two rules agree; on an open one each line is paired up on its own
 * (see docs/meshes.md). A triangle listed twice would cancel itself under
 * parity; it is kept once, as OpenSCAD draws it once.
 *
 * Membership: the winding number of q, from the crossings of the ray
 * q + t (1, sqrt 2, sqrt 3) / 2 with t > 0 (exits minus entries), not
 * zero; a
 * crossing at t = 0 puts q on the surface, which is inside (closed); for
 * a parity mesh, an odd count of those crossings.
 *
 * Hierarchy: a binary tree over the triangles, built by binned surface
 * area heuristic (16 bins along the widest axis of the centres of the
 * triangles' boxes, the plane that minimises area(left) count(left) +
 * area(right) count(right)) down to 4 triangles a leaf; where no plane
 * separates the centres, or past depth 48, the median splits instead, so
 * the depth stays below 48 + log2(n). A mesh of 65,536 triangles or
 * more is built on OpenMP's threads (outside a parallel region): every
 * right subtree of 32,768 triangles or more is a task with nodes of its
 * own, appended once its left sibling is done, so the nodes come out as
 * one thread makes them.
 * Each node holds both children's boxes (one cache line), as floats
 * relative to the centre of the mesh. A box test that rounds the wrong way
 * must not drop a triangle the ray touches, so every box is rounded outward
 * to float and padded by 1e-9 of the mesh's extent, and the ray parameters
 * of the slab test are widened by 2^-40 of their size: together far more
 * than the rounding of the coordinates and of the slab test, and far less
 * than anything visible. Which triangles are tested never changes a
 * crossing: each one is exact on its own.
 *
 * Walk: near child first, over the part of the line a query needs. The
 * computed t of a crossing is an average of the corners' z, so it lies in
 * the box's slab along the ray's axis kz; a node whose kz slab lies outside
 * the range holds no crossing the range wants. With the mesh entirely
 * after the range start, the line before it holds no crossing and the walk
 * starts there; otherwise it starts at the line's beginning, since the
 * winding at the range start needs every crossing before it. A closed
 * mesh's entries and exits along any line cancel, so the winding at a
 * first-crossing query's start is also minus the sum of the crossings after
 * it; when the part of the mesh's box after the start is at most
 * CLOSED_AFTER times the part before it, only that part is walked (a shadow
 * ray from a surface towards the outside). A query that
 * wants only the first crossing after lo also stops at the first crossing
 * found past lo plus a few eps, which it must see to tell a span from a
 * sliver (regularisation), and falls back to the whole range when that is
 * not enough to decide; one that wants every span up to hi goes on past hi
 * the same way until the span that reaches over hi has closed.
 *
 * Normals: a span end's part is the triangle's index modulo 65536 (parts
 * are 16 bits); a mesh with more triangles is asked which of the triangles
 * with that residue has its plane closest to the point.
 */
#include "csg/prim_mesh.h"

#include <math.h>
#include <omp.h>
#include <stdlib.h>
#include <string.h>

#include "base/cancel.h"
#include "csg/csg.h"

enum { LEAF_SIZE = 4, BINS = 16, SAH_DEPTH = 48, STACK = 128 };

/* How much longer than the part of the box before a first-crossing query's
 * start the part after it may be for a closed mesh's walk to take that part
 * (closed_after): the walk before the start also goes on past it to the
 * first crossing, and starts over when that cannot decide. On the renders
 * of a twisted gear and a 10^6-triangle torus (bench/README.md), whose
 * shadow rays leave mesh surfaces, 1 (the nearer part) traces 6-8 % slower
 * than 3, 4, 8 or always, which are within the noise of one another. */
#define CLOSED_AFTER 4

/* Relative widening of the slab test's ray parameters (see the header). */
#define SLAB_WIDEN 0x1p-40

static inline double min2(double a, double b)
{
    return a < b ? a : b;
}

static inline double max2(double a, double b)
{
    return a > b ? a : b;
}

/* ---- building ---- */

/* A triangle's box, relative to the mesh's origin, padded and rounded
 * outward to float, as its nodes will hold it; the items are sorted in
 * place into leaf order. Rounding is monotone, so the union of the items'
 * boxes is the box of the union, rounded and padded once: every node box
 * is exact in float arithmetic from here on. */
typedef struct item {
    float lo[3], hi[3];
    uint32_t tri; /* the triangle's index in the caller's array */
} item;

/* A box and the box of its items' centres. */
typedef struct bounds2 {
    float lo[3], hi[3];
    float clo[3], chi[3];
} bounds2;

typedef struct builder_state {
    item *items;
    prim_mesh_node *nodes;
    uint32_t node_count;
} builder_state;

/* A built subtree as its parent sees it. */
typedef struct child_ref {
    uint32_t index, count; /* count > 0: a leaf of triangles index .. */
    float lo[3], hi[3];
} child_ref;

/* The float next to f (not NaN) toward -infinity (down) or +infinity, as
 * nextafterf gives it, by a step of its bits: zero's neighbours are the
 * smallest subnormals, and a step away from zero makes a number's bits
 * (sign aside) one larger. Inline: the library call took a third of the
 * time of rounding a mesh's boxes. */
static float float_step(float f, int down)
{
    uint32_t u;
    memcpy(&u, &f, sizeof u);
    if ((u & 0x7fffffffu) == 0)
        u = down ? 0x80000001u : 1u;
    else if ((u >> 31) == (uint32_t)down) /* away from zero */
        u++;
    else
        u--;
    memcpy(&f, &u, sizeof f);
    return f;
}

static float round_down(double x)
{
    float f = (float)x;
    if ((double)f > x)
        f = float_step(f, 1);
    return f;
}

static float round_up(double x)
{
    float f = (float)x;
    if ((double)f < x)
        f = float_step(f, 0);
    return f;
}

static inline float minf2(float a, float b)
{
    return a < b ? a : b;
}

static inline float maxf2(float a, float b)
{
    return a > b ? a : b;
}

static float centre(const item *it, int axis)
{
    return 0.5f * (it->lo[axis] + it->hi[axis]);
}

static void bounds_empty(bounds2 *b)
{
    for (int a = 0; a < 3; a++) {
        b->lo[a] = b->clo[a] = INFINITY;
        b->hi[a] = b->chi[a] = -INFINITY;
    }
}

static void bounds_add_item(bounds2 *b, const item *it)
{
    for (int a = 0; a < 3; a++) {
        b->lo[a] = minf2(b->lo[a], it->lo[a]);
        b->hi[a] = maxf2(b->hi[a], it->hi[a]);
        float c = centre(it, a);
        b->clo[a] = minf2(b->clo[a], c);
        b->chi[a] = maxf2(b->chi[a], c);
    }
}

static void bounds_add(bounds2 *b, const bounds2 *o)
{
    for (int a = 0; a < 3; a++) {
        b->lo[a] = minf2(b->lo[a], o->lo[a]);
        b->hi[a] = maxf2(b->hi[a], o->hi[a]);
        b->clo[a] = minf2(b->clo[a], o->clo[a]);
        b->chi[a] = maxf2(b->chi[a], o->chi[a]);
    }
}

static void bounds_of(const builder_state *s, uint32_t lo, uint32_t hi, bounds2 *b)
{
    bounds_empty(b);
    for (uint32_t i = lo; i < hi; i++)
        bounds_add_item(b, &s->items[i]);
}

static double half_area(const bounds2 *b)
{
    double x = (double)b->hi[0] - b->lo[0], y = (double)b->hi[1] - b->lo[1],
           z = (double)b->hi[2] - b->lo[2];
    return x * y + y * z + z * x;
}

static void set_child(prim_mesh_node *n, int k, const child_ref *r)
{
    n->child[k] = r->index;
    n->count[k] = r->count;
    for (int a = 0; a < 3; a++) {
        n->box[0][a][k] = r->lo[a];
        n->box[1][a][k] = r->hi[a];
    }
}

static void set_empty(prim_mesh_node *n, int k)
{
    n->child[k] = 0;
    n->count[k] = 0;
    for (int a = 0; a < 3; a++) {
        n->box[0][a][k] = INFINITY;
        n->box[1][a][k] = -INFINITY;
    }
}

/* In double: a width of a few subnormal floats would make a float scale
 * infinite, and 0 times it NaN. The product is tested before the cast, so
 * that an infinite or NaN one goes to an end bin rather than through an
 * undefined cast. */
static int bin_of(float c, float lo, double scale)
{
    double t = ((double)c - lo) * scale;
    return t >= BINS ? BINS - 1 : t > 0 ? (int)t : 0;
}

static void swap_items(item *a, item *b)
{
    item t = *a;
    *a = *b;
    *b = t;
}

/* Moves the k-th smallest centre (along axis) of items[lo .. hi) to
 * position k, smaller ones before it (Hoare's selection, iterative). */
static void select_kth(builder_state *s, uint32_t lo, uint32_t hi, uint32_t k, int axis)
{
    item *items = s->items;
    while (hi - lo > 1) {
        float pivot = centre(&items[lo + (hi - lo) / 2], axis);
        uint32_t i = lo, j = hi - 1;
        while (i <= j) {
            while (centre(&items[i], axis) < pivot)
                i++;
            while (centre(&items[j], axis) > pivot)
                j--;
            if (i <= j) {
                swap_items(&items[i], &items[j]);
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

/* The split position of items[lo .. hi) (more than LEAF_SIZE triangles,
 * centres spread over [clo, clo + width) along axis) by binned SAH, after
 * which the items are partitioned and left and right hold the two sides'
 * bounds; 0 when no plane separates them. */
static uint32_t sah_split(builder_state *s, uint32_t lo, uint32_t hi, int axis, float clo,
                          float width, bounds2 *left, bounds2 *right)
{
    uint32_t count[BINS] = {0};
    bounds2 bin[BINS];
    for (int b = 0; b < BINS; b++)
        bounds_empty(&bin[b]);
    double scale = BINS / (double)width;
    for (uint32_t i = lo; i < hi; i++) {
        const item *it = &s->items[i];
        int b = bin_of(centre(it, axis), clo, scale);
        count[b]++;
        bounds_add_item(&bin[b], it);
    }
    double right_area[BINS];
    uint32_t right_count[BINS];
    bounds2 acc;
    bounds_empty(&acc);
    uint32_t n = 0;
    for (int b = BINS - 1; b > 0; b--) {
        bounds_add(&acc, &bin[b]);
        n += count[b];
        right_area[b] = n ? half_area(&acc) : 0;
        right_count[b] = n;
    }
    double best = INFINITY;
    int best_bin = 0;
    bounds_empty(&acc);
    n = 0;
    for (int b = 1; b < BINS; b++) {
        bounds_add(&acc, &bin[b - 1]);
        n += count[b - 1];
        if (n == 0 || right_count[b] == 0)
            continue;
        double cost = half_area(&acc) * n + right_area[b] * right_count[b];
        if (cost < best) {
            best = cost;
            best_bin = b;
        }
    }
    if (best_bin == 0)
        return 0;
    bounds_empty(left);
    bounds_empty(right);
    for (int b = 0; b < BINS; b++)
        bounds_add(b < best_bin ? left : right, &bin[b]);
    uint32_t i = lo, j = hi;
    while (i < j) {
        if (bin_of(centre(&s->items[i], axis), clo, scale) < best_bin) {
            i++;
        } else {
            j--;
            swap_items(&s->items[i], &s->items[j]);
        }
    }
    return i > lo && i < hi ? i : 0;
}

/* Splits items[lo .. hi), whose bounds are b, for a node: returns the
 * split position, after which left and right hold the two sides' bounds,
 * or 0 for a leaf (at most LEAF_SIZE triangles). */
static uint32_t split_items(builder_state *s, uint32_t lo, uint32_t hi, int depth,
                            const bounds2 *b, bounds2 *left, bounds2 *right)
{
    if (hi - lo <= LEAF_SIZE)
        return 0;
    float ex = b->chi[0] - b->clo[0], ey = b->chi[1] - b->clo[1],
          ez = b->chi[2] - b->clo[2];
    int axis = ex >= ey && ex >= ez ? 0 : ey >= ez ? 1 : 2;
    float width = axis == 0 ? ex : axis == 1 ? ey : ez;
    uint32_t mid = 0;
    if (depth < SAH_DEPTH && width > 0)
        mid = sah_split(s, lo, hi, axis, b->clo[axis], width, left, right);
    if (mid == 0) {
        mid = lo + (hi - lo) / 2;
        select_kth(s, lo, hi, mid, axis);
        bounds_of(s, lo, mid, left);
        bounds_of(s, mid, hi, right);
    }
    return mid;
}

/* A subtree with bounds b as its parent sees it: a leaf of count
 * triangles from index, or (count 0) inner node index. */
static child_ref ref_of(uint32_t index, uint32_t count, const bounds2 *b)
{
    child_ref r;
    for (int a = 0; a < 3; a++) {
        r.lo[a] = b->lo[a];
        r.hi[a] = b->hi[a];
    }
    r.index = index;
    r.count = count;
    return r;
}

/* The inner node index over children l and g, as its parent sees it. */
static child_ref inner_ref(builder_state *s, uint32_t index, const child_ref *l,
                           const child_ref *g, const bounds2 *b)
{
    set_child(&s->nodes[index], 0, l);
    set_child(&s->nodes[index], 1, g);
    return ref_of(index, 0, b);
}

/* A right subtree of at least this many triangles is built as a task of
 * its own (a million triangles: about 30 tasks). */
enum { TASK_MIN = 1u << 15 };

/* Builds the subtree over items[lo .. hi), whose bounds are b, and returns
 * it; inner nodes are appended to s->nodes (at most one per split, so
 * fewer than the triangles), each before its left subtree's, which come
 * before its right subtree's. With tasks (inside a parallel region), a
 * right subtree of TASK_MIN triangles or more is an OpenMP task with nodes
 * of its own, appended (their inner references moved) once the left one
 * is done: the same nodes in the same order as without. */
static child_ref build_subtree(builder_state *s, uint32_t lo, uint32_t hi, int depth,
                               const bounds2 *b, int tasks)
{
    bounds2 left, right;
    uint32_t mid = split_items(s, lo, hi, depth, b, &left, &right);
    if (mid == 0)
        return ref_of(lo, hi - lo, b);
    uint32_t index = s->node_count++;
    builder_state own = {s->items, NULL, 0};
    if (tasks && hi - mid >= TASK_MIN)
        own.nodes = malloc((size_t)(hi - mid) * sizeof *own.nodes);
    child_ref l, g;
    if (!own.nodes) {
        l = build_subtree(s, lo, mid, depth + 1, &left, tasks);
        g = build_subtree(s, mid, hi, depth + 1, &right, tasks);
        return inner_ref(s, index, &l, &g, b);
    }
#pragma omp task shared(own, g, right)
    g = build_subtree(&own, mid, hi, depth + 1, &right, tasks);
    l = build_subtree(s, lo, mid, depth + 1, &left, tasks);
#pragma omp taskwait
    uint32_t at = s->node_count;
    for (uint32_t i = 0; i < own.node_count; i++) {
        prim_mesh_node n = own.nodes[i];
        for (int k = 0; k < 2; k++)
            if (n.count[k] == 0)
                n.child[k] += at;
        s->nodes[at + i] = n;
    }
    s->node_count += own.node_count;
    if (g.count == 0)
        g.index += at;
    free(own.nodes);
    return inner_ref(s, index, &l, &g, b);
}

const prim_mesh *prim_mesh_create(struct csg_builder *b, const vec3 *points,
                                  const uint32_t *tris, uint32_t tri_count)
{
    return prim_mesh_create_rule(b, points, tris, tri_count, 0);
}

/* Whether triangle i of tris has area: one without is crossed by no ray. */
static int has_area(const vec3 *points, const uint32_t *tris, uint32_t i)
{
    vec3 a = points[tris[3 * i]], bb = points[tris[3 * i + 1]],
         c = points[tris[3 * i + 2]];
    vec3 n = v3_cross(v3_sub(bb, a), v3_sub(c, a));
    return v3_dot(n, n) > 0;
}

/* A triangle by its three point indices in ascending order, and where it
 * was listed. */
typedef struct tri_key {
    uint32_t v[3], index;
} tri_key;

static int tri_key_order(const void *pa, const void *pb)
{
    const tri_key *a = pa, *b = pb;
    for (int k = 0; k < 3; k++)
        if (a->v[k] != b->v[k])
            return a->v[k] < b->v[k] ? -1 : 1;
    return a->index < b->index ? -1 : a->index > b->index;
}

/* Which of tri_count triangles repeat one listed before them (the same
 * three points, wound either way): a flag per triangle, or NULL when out of
 * memory. Under parity two copies of a face cancel each other, so a face
 * listed twice would vanish, where OpenSCAD draws it. */
static uint8_t *repeated_triangles(const uint32_t *tris, uint32_t tri_count)
{
    uint8_t *repeated = calloc(tri_count ? tri_count : 1, 1);
    tri_key *keys = malloc((size_t)(tri_count ? tri_count : 1) * sizeof *keys);
    if (!repeated || !keys) {
        free(repeated);
        free(keys);
        return NULL;
    }
    for (uint32_t i = 0; i < tri_count; i++) {
        uint32_t a = tris[3 * i], b = tris[3 * i + 1], c = tris[3 * i + 2], t;
        if (a > b)
            t = a, a = b, b = t;
        if (b > c)
            t = b, b = c, c = t;
        if (a > b)
            t = a, a = b, b = t;
        keys[i] = (tri_key){{a, b, c}, i};
    }
    qsort(keys, tri_count, sizeof *keys, tri_key_order);
    for (uint32_t i = 1; i < tri_count; i++)
        if (!memcmp(keys[i].v, keys[i - 1].v, sizeof keys[i].v))
            repeated[keys[i].index] = 1;
    free(keys);
    return repeated;
}

const prim_mesh *prim_mesh_create_rule(struct csg_builder *b, const vec3 *points,
                                       const uint32_t *tris, uint32_t tri_count,
                                       int parity)
{
    builder_state s;
    memset(&s, 0, sizeof s);
    const prim_mesh *result = NULL;
    bbox bounds = bbox_empty();
    uint32_t kept = 0;
    uint8_t *skip = parity ? repeated_triangles(tris, tri_count)
                           : calloc(tri_count ? tri_count : 1, 1);
    if (!skip)
        return NULL;
    for (uint32_t i = 0; i < tri_count; i++)
        skip[i] |= !has_area(points, tris, i);
    for (uint32_t i = 0; i < tri_count; i++) {
        if (skip[i])
            continue;
        kept++;
        for (int k = 0; k < 3; k++)
            bounds = bbox_add_point(bounds, points[tris[3 * i + k]]);
    }
    if (kept == 0) {
        free(skip);
        return NULL;
    }
    vec3 ext = v3_sub(bounds.hi, bounds.lo);
    double pad =
        1e-9 * fmax(fmax(ext.x, ext.y), fmax(ext.z, v3_max_abs(bounds.lo))) + 1e-300;
    pad = fmax(pad, 1e-9 * v3_max_abs(bounds.hi));
    vec3 origin = bbox_center(&bounds);
    const double *o = &origin.x;
    /* A split makes one inner node and never an empty side, so a tree over
     * kept triangles has fewer than kept inner nodes; a single leaf still
     * needs node 0. */
    s.items = malloc((size_t)kept * sizeof *s.items);
    s.nodes = malloc((size_t)kept * sizeof *s.nodes);
    if (!s.items || !s.nodes)
        goto done;
    bounds2 all;
    bounds_empty(&all);
    for (uint32_t i = 0, k = 0; i < tri_count; i++) {
        if (skip[i])
            continue;
        item *it = &s.items[k++];
        it->tri = i;
        for (int a = 0; a < 3; a++) {
            double p = (&points[tris[3 * i]].x)[a], q = (&points[tris[3 * i + 1]].x)[a],
                   r = (&points[tris[3 * i + 2]].x)[a];
            it->lo[a] = round_down(min2(min2(p, q), r) - o[a] - pad);
            it->hi[a] = round_up(max2(max2(p, q), r) - o[a] + pad);
        }
        bounds_add_item(&all, it);
    }
    child_ref root;
    if (kept < 2 * TASK_MIN || omp_in_parallel() || omp_get_max_threads() < 2) {
        root = build_subtree(&s, 0, kept, 0, &all, 0);
    } else {
#pragma omp parallel
#pragma omp single
        root = build_subtree(&s, 0, kept, 0, &all, 1);
    }
    if (root.count > 0) {
        s.node_count = 1;
        set_child(&s.nodes[0], 0, &root);
        set_empty(&s.nodes[0], 1);
    }
    prim_mesh *m = csg_builder_alloc(b, sizeof *m);
    vec3 *v = csg_builder_alloc(b, (size_t)3 * kept * sizeof *v);
    vec3 *nrm = csg_builder_alloc(b, (size_t)kept * sizeof *nrm);
    /* one cache line a node: align the array to 64 bytes */
    unsigned char *raw =
        csg_builder_alloc(b, (size_t)s.node_count * sizeof(prim_mesh_node) + 63);
    if (!m || !v || !nrm || !raw)
        goto done;
    prim_mesh_node *nodes = (prim_mesh_node *)(raw + ((64 - (uintptr_t)raw % 64) % 64));
    for (uint32_t i = 0; i < kept; i++) {
        const uint32_t *t = &tris[3 * s.items[i].tri];
        for (int k = 0; k < 3; k++)
            v[3 * i + k] = points[t[k]];
        nrm[i] = v3_cross(v3_sub(v[3 * i + 1], v[3 * i]), v3_sub(v[3 * i + 2], v[3 * i]));
    }
    memcpy(nodes, s.nodes, (size_t)s.node_count * sizeof *nodes);
    m->v = v;
    m->n = nrm;
    m->nodes = nodes;
    m->tri_count = kept;
    m->parity = parity;
    m->node_count = s.node_count;
    m->bounds = bounds;
    m->origin = origin;
    result = m;
done:
    free(skip);
    free(s.items);
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

/* The sign of an edge function e = e(p, q) (computed exactly signed by
 * diff_of_products) with its zero resolved: > 0 or < 0 as the origin,
 * moved by eps (1, eta), lies left or right of p -> q. Returns +1, -1, or
 * 0 for a degenerate edge (p = q). */
static inline int edge_sign(double e, double px, double py, double qx, double qy)
{
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

/* The sign of a b - c d where the rounded products decide it, else 0: the
 * error of the rounded difference is below 2^-50 of |a b| + |c d| (plus
 * the underflow of the products), so a value beyond that has the exact
 * sign. It lets most missed triangles go without the exact evaluation. */
static inline int quick_sign(double a, double b, double c, double d)
{
    double ab = a * b, cd = c * d, e = ab - cd;
    double bound = 0x1p-50 * (fabs(ab) + fabs(cd)) + 0x1p-1000;
    return e > bound ? 1 : e < -bound ? -1 : 0;
}

/* Crosses triangle i; returns 1 and fills *c when the line meets it. */
static int cross_triangle(const prim_mesh *m, const ray_frame *f, uint32_t i, crossing *c)
{
    double x[3], y[3], z[3];
    for (int k = 0; k < 3; k++) {
        const vec3 *q = &m->v[3 * i + k];
        double p[3] = {q->x - f->o.x, q->y - f->o.y, q->z - f->o.z};
        double pz = p[f->kz];
        x[k] = p[f->kx] - f->sx * pz;
        y[k] = p[f->ky] - f->sy * pz;
        z[k] = f->sz * pz;
    }
    int qu = quick_sign(x[1], y[2], y[1], x[2]);
    int qv = quick_sign(x[2], y[0], y[2], x[0]);
    int qw = quick_sign(x[0], y[1], y[0], x[1]);
    if ((qu > 0 || qv > 0 || qw > 0) && (qu < 0 || qv < 0 || qw < 0))
        return 0; /* two edges certainly disagree */
    double u = diff_of_products(x[1], y[2], y[1], x[2]);
    double v = diff_of_products(x[2], y[0], y[2], x[0]);
    double w = diff_of_products(x[0], y[1], y[0], x[1]);
    int su = edge_sign(u, x[1], y[1], x[2], y[2]); /* BC */
    int sv = edge_sign(v, x[2], y[2], x[0], y[0]); /* CA */
    int sw = edge_sign(w, x[0], y[0], x[1], y[1]); /* AB */
    if (su == 0 || sv == 0 || sw == 0 || su != sv || sv != sw)
        return 0;
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

typedef struct crossings {
    crossing v[PRIM_MESH_MAX_CROSSINGS];
    uint32_t n;
    int overflow;
    crossing last; /* the largest t of all */
    int any;
    int count_only; /* membership: only the winding of t > 0 is wanted */
    int parity;     /* the mesh's inside rule is parity (prim_mesh.parity) */
    int wind;       /* count_only: exits minus entries (parity: crossings) */
    int on_surface; /* count_only: a crossing at t = 0 */
    int wind0;      /* the winding before the first crossing kept */
    double t0;      /* where a span open there begins, before every crossing */
} crossings;

static void crossings_init(crossings *cs, const prim_mesh *m, int count_only)
{
    cs->parity = m->parity;
    cs->n = 0;
    cs->overflow = 0;
    cs->any = 0;
    cs->count_only = count_only;
    cs->wind = 0;
    cs->on_surface = 0;
    cs->wind0 = 0;
    cs->t0 = 0;
}

/* 1 when a sorts before b: by t, at equal t exits first (so touching
 * pieces fuse and grazes leave no gap), then by triangle, so the order
 * never depends on the order of the walk. */
static int before(const crossing *a, const crossing *b)
{
    if (a->t != b->t)
        return a->t < b->t;
    if (a->exit != b->exit)
        return a->exit > b->exit;
    return a->tri < b->tri;
}

static void keep(crossings *cs, const crossing *c)
{
    if (cs->count_only) {
        if (c->t == 0)
            cs->on_surface = 1;
        else if (c->t > 0)
            cs->wind += cs->parity || c->exit ? 1 : -1;
        return;
    }
    if (!cs->any || before(&cs->last, c))
        cs->last = *c;
    cs->any = 1;
    if (cs->n == PRIM_MESH_MAX_CROSSINGS) {
        cs->overflow = 1;
        if (!before(c, &cs->v[cs->n - 1]))
            return;
        cs->n--; /* the largest kept one makes way */
    }
    uint32_t i = cs->n;
    while (i > 0 && before(c, &cs->v[i - 1])) {
        cs->v[i] = cs->v[i - 1];
        i--;
    }
    cs->v[i] = *c;
    cs->n++;
}

/* The ray as the slab tests see it: its origin relative to the mesh's
 * origin, the reciprocals of its direction (a zero component gets a large
 * finite one, so a plane through the origin gives 0, never NaN), and which
 * corner of a box is met first on each axis. */
typedef struct slab_ray {
    double o[3], inv[3];
    int near[3]; /* 1 when the hi plane comes first (direction < 0) */
    int kz;
} slab_ray;

static slab_ray slab_ray_of(const prim_mesh *m, vec3 o, vec3 d, int kz)
{
    slab_ray r;
    const double *oo = &o.x, *dd = &d.x, *c = &m->origin.x;
    for (int a = 0; a < 3; a++) {
        r.o[a] = oo[a] - c[a];
        double inv = 1.0 / dd[a];
        r.inv[a] = isfinite(inv) ? inv : copysign(1e300, dd[a]);
        r.near[a] = r.inv[a] < 0;
    }
    r.kz = kz;
    return r;
}

/* Widens a slab parameter interval by SLAB_WIDEN of its ends' size. */
static inline double widen_down(double t)
{
    return t - fabs(t) * SLAB_WIDEN;
}

static inline double widen_up(double t)
{
    return t + fabs(t) * SLAB_WIDEN;
}

/* Tests both children of node n: hit[k] is 1 when the line meets child
 * k's box and the box's kz slab meets [lo, hi]; key[k] is where the line
 * enters the box (the order of the walk), kz_near[k] where the kz slab
 * begins (what a later, narrower range is checked against). The two
 * children go side by side through the same operations, which compilers
 * turn into two-lane vector code. */
static inline void children_hit(const prim_mesh_node *n, const slab_ray *r, double lo,
                                double hi, int hit[2], double key[2], double kz_near[2])
{
    double t0[2] = {-INFINITY, -INFINITY}, t1[2] = {INFINITY, INFINITY};
    for (int a = 0; a < 3; a++) {
        const float *near = n->box[r->near[a]][a], *far = n->box[1 - r->near[a]][a];
        for (int k = 0; k < 2; k++) {
            double tn = ((double)near[k] - r->o[a]) * r->inv[a];
            double tf = ((double)far[k] - r->o[a]) * r->inv[a];
            t0[k] = max2(t0[k], tn);
            t1[k] = min2(t1[k], tf);
        }
    }
    int kz = r->kz;
    const float *near = n->box[r->near[kz]][kz], *far = n->box[1 - r->near[kz]][kz];
    for (int k = 0; k < 2; k++) {
        double z0 = widen_down(((double)near[k] - r->o[kz]) * r->inv[kz]);
        double z1 = widen_up(((double)far[k] - r->o[kz]) * r->inv[kz]);
        double w0 = widen_down(t0[k]), w1 = widen_up(t1[k]);
        key[k] = w0;
        kz_near[k] = z0;
        hit[k] = w0 <= w1 && z0 <= hi && z1 >= lo;
    }
}

/* The same test for one child, for the mesh's whole box. */
static int child_hit(const prim_mesh_node *n, int k, const slab_ray *r, double lo,
                     double hi, double *key, double *kz_near)
{
    int hit[2];
    double keys[2], near[2];
    children_hit(n, r, lo, hi, hit, keys, near);
    *key = keys[k];
    *kz_near = near[k];
    return hit[k];
}

/* A walk over the crossings in a range of the line. */
typedef struct walk {
    double lo, hi; /* the range; hi narrows when stop is set */
    int lo_open;   /* crossings at t == lo are not wanted */
    int stop;      /* narrow hi to the first crossing at or past pivot, plus reach */
    double pivot, reach;
} walk;

static void take(walk *w, crossings *cs, const crossing *c)
{
    if (c->t < w->lo || (w->lo_open && c->t == w->lo) || c->t > w->hi)
        return;
    keep(cs, c);
    if (w->stop && c->t >= w->pivot && c->t + w->reach < w->hi)
        w->hi = c->t + w->reach;
}

typedef struct pending {
    uint32_t index;
    double kz_near;
} pending;

/* Nodes a walk visits between polls of the cancel token. */
#define MESH_POLL_NODES 4096

/* Adds to cs every crossing of the line with t in the walk's range (and,
 * when it narrows, every crossing up to its final hi); near boxes first.
 * The stack holds at most one node a level, and the depth is below
 * SAH_DEPTH + 32. Every MESH_POLL_NODES nodes it polls the calling
 * thread's cancel token (base/cancel.h) and, once that has stopped, ends
 * with what it has: the caller abandons the query's result then. */
static void gather(const prim_mesh *m, const ray_frame *f, const slab_ray *r, walk *w,
                   crossings *cs)
{
    pending stack[STACK];
    uint32_t top = 0, visits = 0;
    const prim_mesh_node *n = &m->nodes[0];
    for (;;) {
        if (++visits % MESH_POLL_NODES == 0 && cancel_poll())
            return;
        double key[2], kz_near[2];
        int hit[2];
        children_hit(n, r, w->lo, w->hi, hit, key, kz_near);
        int near = hit[0] && hit[1] ? key[1] < key[0] : hit[1];
        pending inner[2];
        int inner_count = 0;
        for (int j = 0; j < 2; j++) {
            int k = j == 0 ? near : 1 - near;
            if (!hit[k])
                continue;
            if (n->count[k] == 0) {
                inner[inner_count].index = n->child[k];
                inner[inner_count].kz_near = kz_near[k];
                inner_count++;
                continue;
            }
            if (kz_near[k] > w->hi)
                continue; /* the walk narrowed past it */
            for (uint32_t i = n->child[k]; i < n->child[k] + n->count[k]; i++) {
                crossing c;
                if (cross_triangle(m, f, i, &c))
                    take(w, cs, &c);
            }
        }
        for (int j = inner_count; j-- > 0 && top < STACK;)
            stack[top++] = inner[j];
        for (;;) {
            if (top == 0) {
                /* Crossings kept before hi narrowed past them lie beyond
                 * what the walk has seen in full: a later walk from hi
                 * takes them again. */
                while (w->stop && cs->n > 0 && cs->v[cs->n - 1].t > w->hi)
                    cs->n--;
                return;
            }
            top--;
            if (stack[top].kz_near <= w->hi)
                break;
        }
        n = &m->nodes[stack[top].index];
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

/* The end of a span at crossing c; entering says which end. Under the
 * parity rule a triangle may face either way, so its normal is flipped
 * where it faces into the span. */
static span_end end_at(const crossing *c, uint32_t leaf, int entering)
{
    span_end e = {c->t, leaf, (uint16_t)(c->tri & 0xffffu), 0};
    if (c->exit == entering)
        e.flip = 1;
    return e;
}

/* The crossings of the line within [lo, hi] (all of them for an infinite
 * range) into cs. */
static void gather_range(const prim_mesh *m, vec3 o, vec3 d, double lo, double hi,
                         crossings *cs)
{
    ray_frame f = frame_of(o, d);
    slab_ray r = slab_ray_of(m, o, d, f.kz);
    walk w = {lo, hi, 0, 0, 0, 0};
    gather(m, &f, &r, &w, cs);
}

/* One crossing of a walk along the line by winding number (or, for a
 * parity mesh, by the count of crossings mod 2): updates the winding *wind
 * and, where the line enters the solid, the *start of the span. Returns 1
 * where the line leaves the solid, with the span that ends there in
 * *closed, else 0 (and *closed is not touched). */
static int wind_step(const crossing *c, uint32_t leaf, int parity, int *wind,
                     span_end *start, span *closed)
{
    int was_in = *wind != 0;
    if (parity)
        *wind ^= 1;
    else
        *wind += c->exit ? -1 : 1;
    int is_in = *wind != 0;
    if (!was_in && is_in) {
        *start = end_at(c, leaf, 1);
    } else if (was_in && !is_in) {
        closed->in = *start;
        closed->out = end_at(c, leaf, 0);
        return 1;
    }
    return 0;
}

/* The spans of the whole line from all its crossings, by the rules of the
 * header (the bounds on crossings and spans, the fill past them). A line
 * that stays inside after its last crossing (a parity mesh crossed an odd
 * number of times) is filled to far, where it leaves the mesh's box, so
 * that its last crossing is still a surface: OpenSCAD draws every face of
 * a mesh it draws as it is. */
static uint32_t spans_of(const crossings *cs, uint32_t leaf, double far, span *out,
                         uint32_t cap)
{
    uint32_t n = 0;
    int wind = cs->wind0, full = 0;
    span_end start = {cs->t0, leaf, 0, 0};
    for (uint32_t i = 0; i < cs->n && !full; i++) {
        if (wind_step(&cs->v[i], leaf, cs->parity, &wind, &start, &out[n])) {
            n++;
            full = n == cap;
        }
    }
    int open = wind != 0 && !full;
    if (cs->overflow || full || open) {
        /* Past the bounds (or a mesh that is not closed along this line):
         * fill to the last crossing of all. */
        span_end last = end_at(&cs->last, leaf, 0);
        if (open) {
            out[n].in = start;
            out[n].out = last;
            if (!cs->overflow && far > last.t)
                out[n].out.t = far;
            n++;
        } else if (n > 0) {
            out[n - 1].out = last;
        }
    }
    return n;
}

/* Where the line of f and r meets the whole mesh's box: *z0, and *z1
 * where it reaches the far side of the box's kz slab, which holds every
 * crossing's t, both widened outwards as the hierarchy's tests are.
 * Returns 0 when the line misses the box. */
static int line_box(const prim_mesh *m, const ray_frame *f, const slab_ray *r, double *z0,
                    double *z1)
{
    prim_mesh_node root = m->nodes[0];
    for (int a = 0; a < 3; a++) {
        root.box[0][a][0] = fminf(root.box[0][a][0], root.box[0][a][1]);
        root.box[1][a][0] = fmaxf(root.box[1][a][0], root.box[1][a][1]);
    }
    double key;
    if (!child_hit(&root, 0, r, -INFINITY, INFINITY, &key, z0))
        return 0;
    *z1 = widen_up(((double)root.box[1 - r->near[f->kz]][f->kz][0] - r->o[f->kz]) *
                   r->inv[f->kz]);
    return 1;
}

uint32_t prim_mesh_spans(const prim *p, uint32_t leaf, vec3 o, vec3 d, span *out,
                         uint32_t cap)
{
    const prim_mesh *m = p->u.mesh.mesh;
    if (!m || cap == 0)
        return 0;
    ray_frame f = frame_of(o, d);
    slab_ray r = slab_ray_of(m, o, d, f.kz);
    double z0, z1;
    if (!line_box(m, &f, &r, &z0, &z1))
        z1 = -INFINITY; /* no crossing either */
    crossings cs;
    crossings_init(&cs, m, 0);
    gather_range(m, o, d, -INFINITY, INFINITY, &cs);
    return spans_of(&cs, leaf, z1, out, cap);
}

/* The spans of the crossings a partial walk found, complete up to t_end,
 * regularised with eps into tmp; a span still open at t_end ends there with
 * leaf SPAN_NO_LEAF (regularisation carries the mark along). Returns the
 * count, or UINT32_MAX when there are more than cap spans or the open span
 * was too short to survive (the caller then walks the whole line). */
static uint32_t partial_spans(const crossings *cs, double t_end, double eps,
                              uint32_t leaf, span *tmp, uint32_t cap)
{
    uint32_t n = 0;
    int wind = cs->wind0;
    span_end start = {cs->t0, leaf, 0, 0};
    for (uint32_t i = 0; i < cs->n; i++) {
        span closed;
        if (wind_step(&cs->v[i], leaf, cs->parity, &wind, &start, &closed)) {
            if (n == cap)
                return UINT32_MAX;
            tmp[n++] = closed;
        }
    }
    int open = wind != 0;
    if (open) {
        if (n == cap)
            return UINT32_MAX;
        span_end mark = {t_end, SPAN_NO_LEAF, 0, 0};
        tmp[n].in = start;
        tmp[n].out = mark;
        n++;
    }
    n = span_regularize(tmp, n, eps);
    if (open && (n == 0 || tmp[n - 1].out.leaf != SPAN_NO_LEAF))
        return UINT32_MAX;
    return n;
}

/* The FIRST answer from a walk complete up to t_end (see prim_spans_range):
 * the count written to out, or UINT32_MAX when these crossings cannot
 * decide it. */
static uint32_t first_answer(const crossings *cs, double t_end, double lo, double eps,
                             double far_end, uint32_t leaf, span *out, uint32_t cap,
                             int complete)
{
    span tmp[PRIM_MESH_MAX_CROSSINGS / 2 + 1];
    uint32_t n = partial_spans(cs, t_end, eps, leaf, tmp, cap);
    if (n == UINT32_MAX)
        return n;
    uint32_t s = 0;
    while (s < n && !(tmp[s].out.t > lo))
        s++;
    if (s == n) {
        if (!complete)
            return UINT32_MAX;
        memcpy(out, tmp, (size_t)n * sizeof *tmp);
        return n;
    }
    const span *S = &tmp[s];
    int open = S->out.leaf == SPAN_NO_LEAF;
    int final_out = !open && (s + 1 < n || S->out.t < t_end - 2 * eps);
    int resolved = S->in.t >= lo ? final_out || S->out.t - S->in.t > eps : final_out;
    if (!resolved)
        return UINT32_MAX;
    memcpy(out, tmp, (size_t)(s + 1) * sizeof *tmp);
    if (open) {
        /* Only the in end matters; the out end lies somewhere before the
         * mesh's far side, which callers may use as a size hint. */
        span_end end = {max2(far_end, S->in.t), leaf, 0, 0};
        out[s].out = end;
    }
    return s + 1;
}

/* The crossings at or after a of a line that starts inside the box of a
 * closed, consistently oriented mesh (z0 < a, where its kz slab begins),
 * with the winding before a: along any line such a mesh's entries and
 * exits cancel (its faces bound the solid, and the perturbed line of the
 * header crosses them in general position), so the winding at a is minus
 * the sum of what comes after it. Returns 0 (cs to be reset) when the
 * crossings overflow or the sum is not a winding. */
static int closed_after(const prim_mesh *m, const ray_frame *f, const slab_ray *r,
                        double a, double z0, crossings *cs)
{
    walk w = {a, INFINITY, 0, 0, 0, 0};
    gather(m, f, r, &w, cs);
    if (cs->overflow)
        return 0;
    int sum = 0;
    for (uint32_t i = 0; i < cs->n; i++)
        sum += cs->v[i].exit ? -1 : 1;
    cs->wind0 = -sum;
    cs->t0 = z0;
    return sum <= 0;
}

uint32_t prim_mesh_spans_range(const prim *p, uint32_t leaf, vec3 o, vec3 d, double lo,
                               double hi, double eps, int first, span *out, uint32_t cap)
{
    const prim_mesh *m = p->u.mesh.mesh;
    if (!m || cap == 0)
        return 0;
    if (!(lo <= hi) || !(eps >= 0) || !isfinite(eps))
        return prim_mesh_spans(p, leaf, o, d, out, cap);
    ray_frame f = frame_of(o, d);
    slab_ray r = slab_ray_of(m, o, d, f.kz);
    /* The whole mesh: where the line meets its box, and the kz slab that
     * holds every crossing's t. */
    double z0, z1;
    if (!line_box(m, &f, &r, &z0, &z1))
        return 0;
    double a = lo - 2 * eps, b = hi + 2 * eps;
    if (z1 < a || z0 > b)
        return 0; /* every crossing lies outside the range: so does the solid */
    /* Nothing before a when the mesh begins after it; else the winding at
     * a needs every crossing before it. */
    double from = z0 > a ? a : -INFINITY;
    crossings cs;
    crossings_init(&cs, m, 0);
    if (first && from == -INFINITY && !m->parity && z1 - a <= CLOSED_AFTER * (a - z0) &&
        closed_after(m, &f, &r, a, z0, &cs)) {
        uint32_t n = first_answer(&cs, INFINITY, lo, eps, z1, leaf, out, cap, 1);
        if (n != UINT32_MAX)
            return n;
        crossings_init(&cs, m, 0);
    }
    if (first) {
        walk w = {from, b, 0, 1, lo, 4 * eps};
        gather(m, &f, &r, &w, &cs);
        if (!cs.overflow) {
            uint32_t n = first_answer(&cs, w.hi, lo, eps, z1, leaf, out, cap, w.hi >= b);
            if (n != UINT32_MAX)
                return n;
        }
        crossings_init(&cs, m, 0);
    }
    walk w = {from, b, 0, 0, 0, 0};
    gather(m, &f, &r, &w, &cs);
    /* Every span that reaches over b must be whole: walk on past b until
     * the last one has closed, a little at a time. */
    for (int round = 0; !cs.overflow && w.hi < INFINITY; round++) {
        span tmp[PRIM_MESH_MAX_CROSSINGS / 2 + 1];
        uint32_t n = partial_spans(&cs, w.hi, eps, leaf, tmp, cap);
        if (n == UINT32_MAX)
            break;
        if (n == 0 ||
            (tmp[n - 1].out.leaf != SPAN_NO_LEAF && tmp[n - 1].out.t < w.hi - 2 * eps)) {
            memcpy(out, tmp, (size_t)n * sizeof *tmp);
            return n;
        }
        walk next = {w.hi, INFINITY, 1, round < 4, w.hi, 4 * eps};
        gather(m, &f, &r, &next, &cs);
        w.hi = next.hi;
    }
    if (cs.overflow || w.hi < INFINITY) {
        crossings_init(&cs, m, 0);
        gather_range(m, o, d, -INFINITY, INFINITY, &cs);
    }
    return spans_of(&cs, leaf, z1, out, cap);
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
    crossings_init(&cs, m, 1);
    vec3 d = v3(0.5, 0.70710678118654752, 0.86602540378443865);
    gather_range(m, q, d, 0, INFINITY, &cs);
    return cs.on_surface || (m->parity ? (cs.wind & 1) : cs.wind != 0);
}
