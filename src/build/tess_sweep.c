/* libtess2's sweep of a simple polygon, as OpenSCAD 2021.01's copy of
 * libtess2 makes it (see tess_sweep.h). The names follow libtess2's:
 * half-edge e and its other half e ^ 1 (Sym), Onext (the next edge
 * counter-clockwise round the origin), Lnext (the next edge round the
 * left face), the active regions of the sweep line, each above its upper
 * edge eUp (directed right to left), kept bottom to top in a list (the
 * edge dictionary). Ids are never reused; a sweep that would need more
 * than its fixed room gives up like a degenerate one.
 */
#include "build/tess_sweep.h"

#include <stdlib.h>
#include <string.h>

typedef struct region {
    int up; /* eUp */
    int winding, inside, sentinel, dirty, fix;
    int prev, next; /* below, above; 0 is the list's head */
} region;

typedef struct sweep {
    /* half-edges */
    int *onext, *lnext, *org, *lface, *winding, *active;
    unsigned char *dead;
    int edges, edge_cap;
    /* vertices: coordinates, an edge out of each, contour position */
    float *vs, *vt;
    int *an, *idx;
    int verts, vert_cap;
    /* faces: the list (0 heads it), anEdge, inside */
    int *fprev, *fnext, *fan;
    unsigned char *finside;
    int faces, face_cap;
    region *reg;
    int regions, region_cap;
    int event;
    /* the event queue, as libtess2's: the contour's points sorted by
     * pqInit (order[0 .. sorted), the next at the end; queued: by vertex,
     * not yet taken or deleted), and a heap of the points the sweep
     * makes where edges cross (heap[1 .. heap_size]; heap_at: by vertex,
     * its node, 0 when none) */
    int *order, sorted;
    unsigned char *queued;
    int *heap, *heap_at, heap_size;
    unsigned char *killed; /* by vertex: merged into another */
    int depth;             /* of sweep_event's recursion */
    int fail;              /* not in general position, or out of room: give up */
} sweep;

#define DST(w, e) ((w)->org[(e) ^ 1])
#define OPREV(w, e) ((w)->lnext[(e) ^ 1])
#define LPREV(w, e) ((w)->onext[e] ^ 1)
#define RPREV(w, e) ((w)->onext[(e) ^ 1])
#define DNEXT(w, e) (RPREV(w, e) ^ 1)

/* ---- geometry, in float as libtess2 computes ---- */

/* Points of the plane, which need not be vertices (an intersection). */
typedef struct point {
    float s, t;
} point;

static point at(const sweep *w, int v)
{
    return (point){w->vs[v], w->vt[v]};
}

static int point_leq(point u, point v)
{
    return u.s < v.s || (u.s == v.s && u.t <= v.t);
}

static int point_eq(point u, point v)
{
    return u.s == v.s && u.t == v.t;
}

/* TransLeq: the order by t first */
static int trans_leq(point u, point v)
{
    return u.t < v.t || (u.t == v.t && u.s <= v.s);
}

/* tesedgeEval: how far v lies above the edge u-x, in t */
static float point_eval(point u, point v, point x)
{
    float gap_l = v.s - u.s, gap_r = x.s - v.s;
    if (gap_l + gap_r > 0) {
        if (gap_l < gap_r)
            return (v.t - u.t) + (u.t - x.t) * (gap_l / (gap_l + gap_r));
        return (v.t - x.t) + (x.t - u.t) * (gap_r / (gap_l + gap_r));
    }
    return 0;
}

/* tesedgeSign: the sign of point_eval, computed more cheaply */
static float point_sign(point u, point v, point x)
{
    float gap_l = v.s - u.s, gap_r = x.s - v.s;
    if (gap_l + gap_r > 0)
        return (v.t - x.t) * gap_l + (v.t - u.t) * gap_r;
    return 0;
}

static int vert_leq(const sweep *w, int u, int v)
{
    return point_leq(at(w, u), at(w, v));
}

static int vert_eq(const sweep *w, int u, int v)
{
    return point_eq(at(w, u), at(w, v));
}

static float edge_eval(const sweep *w, int u, int v, int x)
{
    return point_eval(at(w, u), at(w, v), at(w, x));
}

static float edge_sign(const sweep *w, int u, int v, int x)
{
    return point_sign(at(w, u), at(w, v), at(w, x));
}

/* testransEval and testransSign: the same with s and t exchanged */
static point swap_st(point p)
{
    return (point){p.t, p.s};
}

/* Interpolate: x and y weighted by b and a, each at least 0 */
static float interpolate(float a, float x, float b, float y)
{
    a = a < 0 ? 0 : a;
    b = b < 0 ? 0 : b;
    if (a <= b)
        return b == 0 ? (x + y) / 2 : x + (y - x) * (a / (a + b));
    return y + (x - y) * (b / (a + b));
}

/* One coordinate of tesedgeIntersect, in the order leq (by s: the s;
 * by t, with the points' s and t exchanged: the t). */
static float intersect_along(point *o1, point *d1, point *o2, point *d2,
                             int (*leq)(point, point), int by_t)
{
    point x;
    if (!leq(*o1, *d1)) {
        x = *o1;
        *o1 = *d1;
        *d1 = x;
    }
    if (!leq(*o2, *d2)) {
        x = *o2;
        *o2 = *d2;
        *d2 = x;
    }
    if (!leq(*o1, *o2)) {
        x = *o1;
        *o1 = *o2;
        *o2 = x;
        x = *d1;
        *d1 = *d2;
        *d2 = x;
    }
    point a = by_t ? swap_st(*o1) : *o1, b = by_t ? swap_st(*d1) : *d1;
    point c = by_t ? swap_st(*o2) : *o2, d = by_t ? swap_st(*d2) : *d2;
    if (!leq(*o2, *d1))
        return (c.s + b.s) / 2; /* no intersection: the best guess */
    float z1, z2;
    if (leq(*d1, *d2)) {
        z1 = point_eval(a, c, b);
        z2 = point_eval(c, b, d);
        if (z1 + z2 < 0) {
            z1 = -z1;
            z2 = -z2;
        }
        return interpolate(z1, c.s, z2, b.s);
    }
    z1 = point_sign(a, c, b);
    z2 = -point_sign(a, d, b);
    if (z1 + z2 < 0) {
        z1 = -z1;
        z2 = -z2;
    }
    return interpolate(z1, c.s, z2, d.s);
}

/* tesedgeIntersect: where the edges o1-d1 and o2-d2 cross, within both
 * bounding boxes. */
static point edge_intersect(point o1, point d1, point o2, point d2)
{
    point v;
    v.s = intersect_along(&o1, &d1, &o2, &d2, point_leq, 0);
    v.t = intersect_along(&o1, &d1, &o2, &d2, trans_leq, 1);
    return v;
}

/* ---- the mesh ---- */

static int make_edge(sweep *w)
{
    if (w->edges + 2 > w->edge_cap) {
        w->fail = 1;
        return -1;
    }
    int e = w->edges;
    w->edges += 2;
    for (int h = e; h < e + 2; h++) {
        w->onext[h] = h;
        w->lnext[h] = h ^ 1;
        w->org[h] = -1;
        w->lface[h] = -1;
        w->winding[h] = 0;
        w->active[h] = 0;
        w->dead[h] = 0;
    }
    return e;
}

/* libtess2's Splice: exchanges a->Onext and b->Onext */
static void splice(sweep *w, int a, int b)
{
    int a_next = w->onext[a], b_next = w->onext[b];
    w->lnext[a_next ^ 1] = b;
    w->lnext[b_next ^ 1] = a;
    w->onext[a] = b_next;
    w->onext[b] = a_next;
}

/* MakeVertex: a new vertex for the ring of e (coordinates from like) */
static int make_vertex(sweep *w, int e, int like)
{
    if (w->verts >= w->vert_cap) {
        w->fail = 1;
        return -1;
    }
    int v = w->verts++;
    w->an[v] = e;
    w->vs[v] = like >= 0 ? w->vs[like] : 0;
    w->vt[v] = like >= 0 ? w->vt[like] : 0;
    w->idx[v] = -1;
    int x = e, steps = 0;
    do {
        w->org[x] = v;
        x = w->onext[x];
    } while (x != e && ++steps < w->edge_cap);
    if (x != e)
        w->fail = 1;
    return v;
}

/* MakeFace: a new face for the loop of e, just before next in the list */
static int make_face(sweep *w, int e, int next)
{
    if (w->faces >= w->face_cap) {
        w->fail = 1;
        return -1;
    }
    int f = w->faces++;
    int prev = w->fprev[next];
    w->fprev[f] = prev;
    w->fnext[prev] = f;
    w->fnext[f] = next;
    w->fprev[next] = f;
    w->fan[f] = e;
    w->finside[f] = w->finside[next];
    int x = e, steps = 0;
    do {
        w->lface[x] = f;
        x = w->lnext[x];
    } while (x != e && ++steps < w->edge_cap);
    if (x != e)
        w->fail = 1;
    return f;
}

static void kill_vertex(sweep *w, int v, int to)
{
    if (v >= 0)
        w->killed[v] = 1;
    int e = w->an[v], x = e, steps = 0;
    do {
        w->org[x] = to;
        x = w->onext[x];
    } while (x != e && ++steps < w->edge_cap);
    if (x != e)
        w->fail = 1;
}

static void kill_face(sweep *w, int f, int to)
{
    int e = w->fan[f], x = e, steps = 0;
    do {
        w->lface[x] = to;
        x = w->lnext[x];
    } while (x != e && ++steps < w->edge_cap);
    if (x != e)
        w->fail = 1;
    w->fnext[w->fprev[f]] = w->fnext[f];
    w->fprev[w->fnext[f]] = w->fprev[f];
}

static int mesh_make_edge(sweep *w)
{
    int e = make_edge(w);
    if (e < 0 || make_vertex(w, e, -1) < 0 || make_vertex(w, e ^ 1, -1) < 0 ||
        make_face(w, e, 0) < 0)
        return -1;
    return e;
}

static void mesh_splice(sweep *w, int e_org, int e_dst)
{
    if (e_org == e_dst || w->fail)
        return;
    int joining_vertices = w->org[e_dst] != w->org[e_org];
    int joining_loops = w->lface[e_dst] != w->lface[e_org];
    if (joining_vertices)
        kill_vertex(w, w->org[e_dst], w->org[e_org]);
    if (joining_loops)
        kill_face(w, w->lface[e_dst], w->lface[e_org]);
    splice(w, e_dst, e_org);
    if (!joining_vertices) {
        int old = w->org[e_org];
        make_vertex(w, e_dst, old);
        w->an[old] = e_org;
    }
    if (!joining_loops) {
        make_face(w, e_dst, w->lface[e_org]);
        w->fan[w->lface[e_org]] = e_org;
    }
}

static void mesh_delete(sweep *w, int e)
{
    int sym = e ^ 1;
    int joining_loops = w->lface[e] != w->lface[sym];
    if (joining_loops)
        kill_face(w, w->lface[e], w->lface[sym]);
    if (w->onext[e] == e) {
        kill_vertex(w, w->org[e], -1);
    } else {
        w->fan[w->lface[sym]] = OPREV(w, e);
        w->an[w->org[e]] = w->onext[e];
        splice(w, e, OPREV(w, e));
        if (!joining_loops)
            make_face(w, e, w->lface[e]);
    }
    if (w->onext[sym] == sym) {
        kill_vertex(w, w->org[sym], -1);
        kill_face(w, w->lface[sym], -1);
    } else {
        w->fan[w->lface[e]] = OPREV(w, sym);
        w->an[w->org[sym]] = w->onext[sym];
        splice(w, sym, OPREV(w, sym));
    }
    w->dead[e] = w->dead[sym] = 1;
}

static int mesh_split_edge(sweep *w, int e_org)
{
    int made = make_edge(w);
    if (made < 0)
        return -1;
    splice(w, made, w->lnext[e_org]);
    w->org[made] = DST(w, e_org);
    if (make_vertex(w, made ^ 1, -1) < 0)
        return -1;
    w->lface[made] = w->lface[made ^ 1] = w->lface[e_org];
    int e_new = made ^ 1;
    splice(w, e_org ^ 1, OPREV(w, e_org ^ 1));
    splice(w, e_org ^ 1, e_new);
    w->org[e_org ^ 1] = w->org[e_new];
    w->an[DST(w, e_new)] = e_new ^ 1;
    w->lface[e_new ^ 1] = w->lface[e_org ^ 1];
    w->winding[e_new] = w->winding[e_org];
    w->winding[e_new ^ 1] = w->winding[e_org ^ 1];
    return e_new;
}

static int mesh_connect(sweep *w, int e_org, int e_dst)
{
    int e = make_edge(w);
    if (e < 0)
        return -1;
    int sym = e ^ 1;
    int joining_loops = w->lface[e_dst] != w->lface[e_org];
    if (joining_loops)
        kill_face(w, w->lface[e_dst], w->lface[e_org]);
    splice(w, e, w->lnext[e_org]);
    splice(w, sym, e_dst);
    w->org[e] = DST(w, e_org);
    w->org[sym] = w->org[e_dst];
    w->lface[e] = w->lface[sym] = w->lface[e_org];
    w->fan[w->lface[e_org]] = sym;
    if (!joining_loops)
        make_face(w, e, w->lface[e_org]);
    return e;
}

/* ---- the active regions ---- */

static int below(const sweep *w, int r)
{
    return w->reg[r].prev;
}

static int above(const sweep *w, int r)
{
    return w->reg[r].next;
}

/* EdgeLeq: edge e1 is below or at e2 where the sweep line is */
static int edge_leq(const sweep *w, int e1, int e2)
{
    int ev = w->event;
    if (DST(w, e1) == ev) {
        if (DST(w, e2) == ev) {
            if (vert_leq(w, w->org[e1], w->org[e2]))
                return edge_sign(w, DST(w, e2), w->org[e1], w->org[e2]) <= 0;
            return edge_sign(w, DST(w, e1), w->org[e2], w->org[e1]) >= 0;
        }
        return edge_sign(w, DST(w, e2), ev, w->org[e2]) <= 0;
    }
    if (DST(w, e2) == ev)
        return edge_sign(w, DST(w, e1), ev, w->org[e1]) >= 0;
    float t1 = edge_eval(w, DST(w, e1), ev, w->org[e1]);
    float t2 = edge_eval(w, DST(w, e2), ev, w->org[e2]);
    return t1 >= t2;
}

static int new_region(sweep *w, int up)
{
    if (w->regions >= w->region_cap) {
        w->fail = 1;
        return 0;
    }
    int r = w->regions++;
    memset(&w->reg[r], 0, sizeof w->reg[r]);
    w->reg[r].up = up;
    w->active[up] = r;
    return r;
}

/* dictInsertBefore: r goes below node, as low as the order lets it */
static void insert_before(sweep *w, int node, int r)
{
    do
        node = w->reg[node].prev;
    while (node != 0 && !edge_leq(w, w->reg[node].up, w->reg[r].up));
    int next = w->reg[node].next;
    w->reg[r].next = next;
    w->reg[next].prev = r;
    w->reg[r].prev = node;
    w->reg[node].next = r;
}

static void delete_region(sweep *w, int r)
{
    w->active[w->reg[r].up] = 0;
    w->reg[w->reg[r].prev].next = w->reg[r].next;
    w->reg[w->reg[r].next].prev = w->reg[r].prev;
}

static int add_region_below(sweep *w, int r_above, int up)
{
    int r = new_region(w, up);
    if (r)
        insert_before(w, r_above, r);
    return r;
}

static void compute_winding(sweep *w, int r)
{
    w->reg[r].winding = w->reg[above(w, r)].winding + w->winding[w->reg[r].up];
    w->reg[r].inside = w->reg[r].winding & 1;
}

static void finish_region(sweep *w, int r)
{
    int e = w->reg[r].up, f = w->lface[e];
    w->finside[f] = (unsigned char)w->reg[r].inside;
    w->fan[f] = e;
    delete_region(w, r);
}

static void fix_upper_edge(sweep *w, int r, int e)
{
    mesh_delete(w, w->reg[r].up);
    w->reg[r].fix = 0;
    w->reg[r].up = e;
    w->active[e] = r;
}

/* ---- the event queue (priorityq.c) ---- */

static void heap_place(sweep *w, int node, int v)
{
    w->heap[node] = v;
    w->heap_at[v] = node;
}

static void float_down(sweep *w, int node)
{
    int v = w->heap[node];
    for (;;) {
        int child = node << 1;
        if (child < w->heap_size && vert_leq(w, w->heap[child + 1], w->heap[child]))
            ++child;
        if (child > w->heap_size || vert_leq(w, v, w->heap[child])) {
            heap_place(w, node, v);
            return;
        }
        heap_place(w, node, w->heap[child]);
        node = child;
    }
}

static void float_up(sweep *w, int node)
{
    int v = w->heap[node];
    for (;;) {
        int parent = node >> 1;
        if (parent == 0 || vert_leq(w, w->heap[parent], v)) {
            heap_place(w, node, v);
            return;
        }
        heap_place(w, node, w->heap[parent]);
        node = parent;
    }
}

static void heap_insert(sweep *w, int v)
{
    int node = ++w->heap_size;
    heap_place(w, node, v);
    float_up(w, node);
}

static int heap_extract(sweep *w)
{
    int v = w->heap[1];
    heap_place(w, 1, w->heap[w->heap_size]);
    w->heap_at[v] = 0;
    if (--w->heap_size > 0)
        float_down(w, 1);
    return v;
}

/* pqDelete: v out of the queue, wherever it is */
static void queue_delete(sweep *w, int v)
{
    int node = w->heap_at[v];
    if (node) {
        heap_place(w, node, w->heap[w->heap_size]);
        w->heap_at[v] = 0;
        if (node <= --w->heap_size) {
            if (node <= 1 || vert_leq(w, w->heap[node >> 1], w->heap[node]))
                float_down(w, node);
            else
                float_up(w, node);
        }
        return;
    }
    w->queued[v] = 0;
    while (w->sorted > 0 && !w->queued[w->order[w->sorted - 1]])
        w->sorted--;
}

/* pqMinimum and pqExtractMin: the least point, the heap's on a tie; -1
 * when the queue is empty */
static int queue_minimum(const sweep *w)
{
    if (w->sorted == 0)
        return w->heap_size ? w->heap[1] : -1;
    int v = w->order[w->sorted - 1];
    if (w->heap_size && vert_leq(w, w->heap[1], v))
        return w->heap[1];
    return v;
}

static int queue_extract(sweep *w)
{
    if (w->sorted == 0)
        return w->heap_size ? heap_extract(w) : -1;
    int v = w->order[w->sorted - 1];
    if (w->heap_size && vert_leq(w, w->heap[1], v))
        return heap_extract(w);
    w->queued[v] = 0;
    while (w->sorted > 0 && !w->queued[w->order[w->sorted - 1]])
        w->sorted--;
    return v;
}

/* ---- the checks: splices where a point lies on another edge, cuts
 * where two edges cross ---- */

/* CheckForRightSplice: the right ends of the edges of r_up and the region
 * below it out of order: the one spliced into the other edge (or the two
 * merged where they are one point, the upper taken out of the queue). */
static int check_right_splice(sweep *w, int r_up)
{
    int r_lo = below(w, r_up);
    int e_up = w->reg[r_up].up, e_lo = w->reg[r_lo].up;
    int o_up = w->org[e_up], o_lo = w->org[e_lo];
    if (vert_leq(w, o_up, o_lo)) {
        if (edge_sign(w, DST(w, e_lo), o_up, o_lo) > 0)
            return 0;
        if (!vert_eq(w, o_up, o_lo)) { /* o_up into e_lo */
            if (mesh_split_edge(w, e_lo ^ 1) < 0)
                return 1;
            mesh_splice(w, e_up, OPREV(w, e_lo));
            w->reg[r_up].dirty = w->reg[r_lo].dirty = 1;
        } else if (o_up != o_lo) {
            queue_delete(w, o_up);
            mesh_splice(w, OPREV(w, e_lo), e_up);
        }
    } else {
        if (edge_sign(w, DST(w, e_up), o_lo, o_up) < 0)
            return 0;
        w->reg[above(w, r_up)].dirty = w->reg[r_up].dirty = 1; /* o_lo into e_up */
        if (mesh_split_edge(w, e_up ^ 1) < 0)
            return 1;
        mesh_splice(w, OPREV(w, e_lo), e_up);
    }
    return 1;
}

/* CheckForLeftSplice: the same for the left ends, the one not the other
 * spliced into the other's edge. */
static int check_left_splice(sweep *w, int r_up)
{
    int r_lo = below(w, r_up);
    int e_up = w->reg[r_up].up, e_lo = w->reg[r_lo].up;
    int e;
    if (vert_leq(w, DST(w, e_up), DST(w, e_lo))) {
        if (edge_sign(w, DST(w, e_up), DST(w, e_lo), w->org[e_up]) < 0)
            return 0;
        w->reg[above(w, r_up)].dirty = w->reg[r_up].dirty = 1;
        if ((e = mesh_split_edge(w, e_up)) < 0)
            return 1;
        mesh_splice(w, e_lo ^ 1, e);
        w->finside[w->lface[e]] = (unsigned char)w->reg[r_up].inside;
    } else {
        if (edge_sign(w, DST(w, e_lo), DST(w, e_up), w->org[e_lo]) > 0)
            return 0;
        w->reg[r_up].dirty = w->reg[r_lo].dirty = 1;
        if ((e = mesh_split_edge(w, e_lo)) < 0)
            return 1;
        mesh_splice(w, w->lnext[e_up], e_lo ^ 1);
        w->finside[w->lface[e ^ 1]] = (unsigned char)w->reg[r_up].inside;
    }
    return 1;
}

static int check_intersect(sweep *w, int r_up)
{
    int e_up = w->reg[r_up].up, e_lo = w->reg[below(w, r_up)].up;
    int o_up = w->org[e_up], o_lo = w->org[e_lo];
    int d_up = DST(w, e_up), d_lo = DST(w, e_lo);
    if (o_up == o_lo)
        return 0;
    float t_min_up = w->vt[o_up] <= w->vt[d_up] ? w->vt[o_up] : w->vt[d_up];
    float t_max_lo = w->vt[o_lo] >= w->vt[d_lo] ? w->vt[o_lo] : w->vt[d_lo];
    if (t_min_up > t_max_lo)
        return 0;
    if (vert_leq(w, o_up, o_lo)) {
        if (edge_sign(w, d_lo, o_up, o_lo) > 0)
            return 0;
    } else if (edge_sign(w, d_up, o_lo, o_up) < 0) {
        return 0;
    }
    /* they meet: where, kept right of the event and left of both right
     * ends */
    point isect = edge_intersect(at(w, d_up), at(w, o_up), at(w, d_lo), at(w, o_lo));
    if (point_leq(isect, at(w, w->event)))
        isect = at(w, w->event);
    int o_min = vert_leq(w, o_up, o_lo) ? o_up : o_lo;
    if (point_leq(at(w, o_min), isect))
        isect = at(w, o_min);
    if (point_eq(isect, at(w, o_up)) || point_eq(isect, at(w, o_lo))) {
        check_right_splice(w, r_up); /* at a right end */
        return 0;
    }
    point ev = at(w, w->event);
    if ((!vert_eq(w, d_up, w->event) && point_sign(at(w, d_up), ev, isect) >= 0) ||
        (!vert_eq(w, d_lo, w->event) && point_sign(at(w, d_lo), ev, isect) <= 0)) {
        w->fail = 1; /* the new edges would pass the event on the wrong side */
        return 1;
    }
    /* they cross: both cut at a new point, which joins the queue */
    int r_lo = below(w, r_up);
    if (mesh_split_edge(w, e_up ^ 1) < 0 || mesh_split_edge(w, e_lo ^ 1) < 0)
        return 1;
    mesh_splice(w, OPREV(w, e_lo), e_up);
    int x = w->org[e_up];
    w->vs[x] = isect.s;
    w->vt[x] = isect.t;
    heap_insert(w, x);
    w->reg[above(w, r_up)].dirty = w->reg[r_up].dirty = w->reg[r_lo].dirty = 1;
    return 0;
}

static void walk_dirty_regions(sweep *w, int r_up)
{
    int r_lo = below(w, r_up);
    for (int steps = 0; !w->fail; steps++) {
        if (steps > w->edge_cap) {
            w->fail = 1;
            return;
        }
        while (r_lo && w->reg[r_lo].dirty) {
            r_up = r_lo;
            r_lo = below(w, r_lo);
        }
        if (!w->reg[r_up].dirty) {
            r_lo = r_up;
            r_up = above(w, r_up);
            if (r_up == 0 || !w->reg[r_up].dirty)
                return;
        }
        w->reg[r_up].dirty = 0;
        int e_up = w->reg[r_up].up, e_lo = w->reg[r_lo].up;
        if (DST(w, e_up) != DST(w, e_lo) && check_left_splice(w, r_up)) {
            if (w->fail)
                return;
            /* a fixable edge is needed no more */
            if (w->reg[r_lo].fix) {
                delete_region(w, r_lo);
                mesh_delete(w, e_lo);
                r_lo = below(w, r_up);
                e_lo = w->reg[r_lo].up;
            } else if (w->reg[r_up].fix) {
                delete_region(w, r_up);
                mesh_delete(w, e_up);
                r_up = above(w, r_lo);
                e_up = w->reg[r_up].up;
            }
        }
        if (w->org[e_up] != w->org[e_lo]) {
            if (DST(w, e_up) != DST(w, e_lo) && !w->reg[r_up].fix && !w->reg[r_lo].fix &&
                (DST(w, e_up) == w->event || DST(w, e_lo) == w->event)) {
                if (check_intersect(w, r_up))
                    return;
            } else {
                check_right_splice(w, r_up);
                if (w->fail)
                    return;
            }
        }
        if (w->org[e_up] == w->org[e_lo] && DST(w, e_up) == DST(w, e_lo)) {
            w->winding[e_lo] += w->winding[e_up];
            w->winding[e_lo ^ 1] += w->winding[e_up ^ 1];
            delete_region(w, r_up);
            mesh_delete(w, e_up);
            r_up = above(w, r_lo);
        }
    }
}

static void add_right_edges(sweep *w, int r_up, int e_first, int e_last, int e_top_left,
                            int clean_up)
{
    int e = e_first, steps = 0;
    do {
        if (!add_region_below(w, r_up, e ^ 1))
            return;
        e = w->onext[e];
    } while (e != e_last && ++steps < w->edge_cap);
    if (e != e_last) {
        w->fail = 1;
        return;
    }
    if (e_top_left < 0)
        e_top_left = RPREV(w, w->reg[below(w, r_up)].up);
    int r_prev = r_up, e_prev = e_top_left, first = 1, r;
    for (;;) {
        r = below(w, r_prev);
        if (!r) {
            w->fail = 1;
            return;
        }
        e = w->reg[r].up ^ 1;
        if (w->org[e] != w->org[e_prev])
            break;
        if (w->onext[e] != e_prev) {
            mesh_splice(w, OPREV(w, e), e);
            mesh_splice(w, OPREV(w, e_prev), e);
        }
        w->reg[r].winding = w->reg[r_prev].winding - w->winding[e];
        w->reg[r].inside = w->reg[r].winding & 1;
        w->reg[r_prev].dirty = 1;
        if (!first && check_right_splice(w, r_prev)) {
            if (w->fail)
                return;
            w->winding[e] += w->winding[e_prev];
            w->winding[e ^ 1] += w->winding[e_prev ^ 1];
            delete_region(w, r_prev);
            mesh_delete(w, e_prev);
        }
        first = 0;
        r_prev = r;
        e_prev = e;
    }
    w->reg[r_prev].dirty = 1;
    if (clean_up)
        walk_dirty_regions(w, r_prev);
}

static int top_left_region(sweep *w, int r)
{
    int o = w->org[w->reg[r].up];
    do
        r = above(w, r);
    while (r && w->org[w->reg[r].up] == o);
    if (!r) {
        w->fail = 1;
        return 0;
    }
    if (w->reg[r].fix) {
        int e = mesh_connect(w, w->reg[below(w, r)].up ^ 1, w->lnext[w->reg[r].up]);
        if (e < 0)
            return 0;
        fix_upper_edge(w, r, e);
        r = above(w, r);
    }
    return r;
}

static int finish_left_regions(sweep *w, int r_first)
{
    int r_prev = r_first, e_prev = w->reg[r_first].up;
    while (!w->fail) {
        w->reg[r_prev].fix = 0;
        int r = below(w, r_prev);
        if (!r) {
            w->fail = 1;
            break;
        }
        int e = w->reg[r].up;
        if (w->org[e] != w->org[e_prev]) {
            if (!w->reg[r].fix) {
                finish_region(w, r_prev);
                break;
            }
            e = mesh_connect(w, LPREV(w, e_prev), e ^ 1);
            if (e < 0)
                break;
            fix_upper_edge(w, r, e);
        }
        if (w->onext[e_prev] != e) {
            mesh_splice(w, OPREV(w, e), e);
            mesh_splice(w, e_prev, e);
        }
        finish_region(w, r_prev);
        e_prev = w->reg[r].up;
        r_prev = r;
    }
    return e_prev;
}

static void connect_right_vertex(sweep *w, int r_up, int e_bottom_left)
{
    int r_lo = below(w, r_up);
    int e_up = w->reg[r_up].up, e_lo = w->reg[r_lo].up;
    if (DST(w, e_up) != DST(w, e_lo))
        check_intersect(w, r_up);
    if (w->fail)
        return;
    if (vert_eq(w, w->org[e_up], w->event) || vert_eq(w, w->org[e_lo], w->event)) {
        w->fail = 1; /* the degenerate cases, after a cut at the event */
        return;
    }
    int e_new = vert_leq(w, w->org[e_lo], w->org[e_up]) ? OPREV(w, e_lo) : e_up;
    e_new = mesh_connect(w, LPREV(w, e_bottom_left), e_new);
    if (e_new < 0)
        return;
    add_right_edges(w, r_up, e_new, w->onext[e_new], w->onext[e_new], 0);
    if (w->fail)
        return;
    w->reg[w->active[e_new ^ 1]].fix = 1;
    walk_dirty_regions(w, r_up);
}

static void sweep_event(sweep *w, int v);

static void connect_left_vertex(sweep *w, int v)
{
    int key = w->an[v] ^ 1, r_up = w->reg[0].next;
    while (r_up != 0 && !edge_leq(w, key, w->reg[r_up].up))
        r_up = w->reg[r_up].next;
    int r_lo = r_up ? below(w, r_up) : 0;
    if (!r_lo) {
        w->fail = 1;
        return;
    }
    int e_up = w->reg[r_up].up, e_lo = w->reg[r_lo].up;
    if (edge_sign(w, DST(w, e_up), v, w->org[e_up]) == 0) {
        /* ConnectLeftDegenerate: v on the edge above, spliced into it
         * (its ends are not v's point: such points are merged) */
        if (vert_eq(w, w->org[e_up], v) || vert_eq(w, DST(w, e_up), v)) {
            w->fail = 1;
            return;
        }
        if (mesh_split_edge(w, e_up ^ 1) < 0)
            return;
        if (w->reg[r_up].fix) { /* the rest of a fixable edge goes */
            mesh_delete(w, w->onext[e_up]);
            w->reg[r_up].fix = 0;
        }
        mesh_splice(w, w->an[v], e_up);
        sweep_event(w, v);
        return;
    }
    int r = vert_leq(w, DST(w, e_lo), DST(w, e_up)) ? r_up : r_lo;
    if (w->reg[r_up].inside || w->reg[r].fix) {
        int e_new;
        if (r == r_up) {
            e_new = mesh_connect(w, w->an[v] ^ 1, w->lnext[e_up]);
        } else {
            e_new = mesh_connect(w, DNEXT(w, e_lo), w->an[v]);
            e_new = e_new < 0 ? -1 : e_new ^ 1;
        }
        if (e_new < 0)
            return;
        if (w->reg[r].fix) {
            fix_upper_edge(w, r, e_new);
        } else {
            int made = add_region_below(w, r_up, e_new);
            if (!made)
                return;
            compute_winding(w, made);
        }
        sweep_event(w, v); /* it has a left edge now */
    } else {
        add_right_edges(w, r_up, w->an[v], w->an[v], -1, 1);
    }
}

static void sweep_event_at(sweep *w, int v);

/* SweepEvent, which recurses for a point it joined to an edge; a deeper
 * recursion than a few steps is not libtess2's, and ends the sweep. */
static void sweep_event(sweep *w, int v)
{
    if (w->fail)
        return;
    if (++w->depth > 8) {
        w->fail = 1;
        return;
    }
    sweep_event_at(w, v);
    w->depth--;
}

static void sweep_event_at(sweep *w, int v)
{
    w->event = v;
    int e = w->an[v], steps = 0;
    while (w->active[e] == 0) {
        e = w->onext[e];
        if (e == w->an[v]) {
            connect_left_vertex(w, v);
            return;
        }
        if (++steps > w->edge_cap) {
            w->fail = 1;
            return;
        }
    }
    int r_up = top_left_region(w, w->active[e]);
    if (!r_up || w->fail)
        return;
    int r = below(w, r_up);
    int e_top_left = w->reg[r].up;
    int e_bottom_left = finish_left_regions(w, r);
    if (w->fail)
        return;
    if (w->onext[e_bottom_left] == e_top_left)
        connect_right_vertex(w, r_up, e_bottom_left);
    else
        add_right_edges(w, r_up, w->onext[e_bottom_left], e_top_left, e_top_left, 1);
}

static void add_sentinel(sweep *w, float s_min, float s_max, float t)
{
    int e = mesh_make_edge(w);
    if (e < 0)
        return;
    w->vs[w->org[e]] = s_max;
    w->vt[w->org[e]] = t;
    w->vs[DST(w, e)] = s_min;
    w->vt[DST(w, e)] = t;
    w->event = DST(w, e);
    w->idx[w->org[e]] = w->idx[DST(w, e)] = -2; /* not a point of the polygon */
    int r = new_region(w, e);
    if (!r)
        return;
    w->reg[r].sentinel = 1;
    insert_before(w, 0, r);
}

/* ---- the whole ---- */

static int sweep_alloc(sweep *w, uint32_t n)
{
    size_t room = 16 * (size_t)n + 64;
    w->edge_cap = (int)(4 * room);
    w->vert_cap = w->face_cap = w->region_cap = (int)room;
    size_t e = (size_t)w->edge_cap, v = (size_t)w->vert_cap, f = (size_t)w->face_cap;
    w->onext = malloc(6 * e * sizeof(int));
    w->dead = malloc(e + f + 2 * v);
    w->vs = malloc(2 * v * sizeof(float));
    w->an = malloc((2 * v + 3 * f) * sizeof(int));
    w->reg = malloc((size_t)w->region_cap * sizeof *w->reg);
    if (!w->onext || !w->dead || !w->vs || !w->an || !w->reg)
        return 0;
    w->lnext = w->onext + e;
    w->org = w->lnext + e;
    w->lface = w->org + e;
    w->winding = w->lface + e;
    w->active = w->winding + e;
    w->finside = w->dead + e;
    w->queued = w->finside + f;
    w->killed = w->queued + v;
    memset(w->queued, 0, 2 * v);
    w->heap = malloc(2 * (v + 1) * sizeof(int));
    if (!w->heap)
        return 0;
    w->heap_at = w->heap + v + 1;
    memset(w->heap_at, 0, v * sizeof(int));
    w->vt = w->vs + v;
    w->idx = w->an + v;
    w->fprev = w->idx + v;
    w->fnext = w->fprev + f;
    w->fan = w->fnext + f;
    /* the face list's head, and the dictionary's */
    w->faces = 1;
    w->fprev[0] = w->fnext[0] = 0;
    w->fan[0] = -1;
    w->finside[0] = 0;
    w->regions = 1;
    memset(&w->reg[0], 0, sizeof w->reg[0]);
    w->reg[0].up = -1;
    return 1;
}

static void sweep_free(sweep *w)
{
    free(w->heap);
    free(w->onext);
    free(w->dead);
    free(w->vs);
    free(w->an);
    free(w->reg);
}

/* RemoveDegenerateEdges: each edge of the contour between two points
 * that are one (two neighbours on one point) goes, in libtess2's order of
 * its edge list (the contour's last edge first), the origin of its first
 * half merged into that of the next edge round its loop (which vertex
 * stays decides where the triangles meet); gone marks the vertices merged
 * away. A loop left with one or two edges gives up. */
static void remove_degenerate_edges(sweep *w, uint32_t n, unsigned char *gone)
{
    for (int k = (int)n - 1; k >= 0 && !w->fail; k--) {
        int e = 2 * k;
        if (w->dead[e])
            continue;
        int e_lnext = w->lnext[e];
        if (vert_eq(w, w->org[e], DST(w, e)) && w->lnext[e_lnext] != e) {
            gone[w->org[e]] = 1;
            mesh_splice(w, e_lnext, e);
            mesh_delete(w, e);
            e = e_lnext;
            e_lnext = w->lnext[e];
        }
        if (w->lnext[e_lnext] == e)
            w->fail = 1;
    }
}

/* libtess2's pqInit: the vertices a[0 .. n) (in the order it inserts
 * them) sorted in descending (s, t) order by its randomized quicksort,
 * then insertion sort, which decide the order of equal vertices; the
 * sweep takes them from the end. */
static void event_order(const sweep *w, int *a, int n)
{
    struct {
        int p, r;
    } stack[50], *top = stack;
    unsigned int seed = 2016473283u;
    top->p = 0;
    top->r = n - 1;
    ++top;
    while (--top >= stack) {
        int p = top->p, r = top->r;
        while (r > p + 10) {
            seed = seed * 1539415821u + 1;
            int i = p + (int)(seed % (unsigned int)(r - p + 1)), j = r + 1;
            int piv = a[i];
            a[i] = a[p];
            a[p] = piv;
            i = p - 1;
            do {
                do
                    ++i;
                while (!vert_leq(w, a[i], piv));
                do
                    --j;
                while (!vert_leq(w, piv, a[j]));
                int x = a[i];
                a[i] = a[j];
                a[j] = x;
            } while (i < j);
            int x = a[i]; /* undo the last swap */
            a[i] = a[j];
            a[j] = x;
            if (i - p < r - j) {
                top->p = j + 1;
                top->r = r;
                ++top;
                r = i - 1;
            } else {
                top->p = p;
                top->r = i - 1;
                ++top;
                p = j + 1;
            }
        }
        for (int i = p + 1; i <= r; ++i) {
            int piv = a[i], j;
            for (j = i; j > p && !vert_leq(w, piv, a[j - 1]); --j)
                a[j] = a[j - 1];
            a[j] = piv;
        }
    }
}

/* The mesh, compact and in libtess2's order of faces, into out. */
static int export_mesh(const sweep *w, uint32_t n, tess_swept *out)
{
    int *edge_id = malloc((size_t)w->edges * sizeof *edge_id);
    int *face_id = malloc((size_t)w->faces * sizeof *face_id);
    int *made = malloc((size_t)(w->verts ? w->verts : 1) * sizeof *made);
    /* the points made where edges cross, by vertex: their numbers past n */
    uint32_t extra = 0;
    for (int v = 0; made && v < w->verts; v++)
        made[v] = w->idx[v] == -1 && !w->killed[v] ? (int)(n + 1 + extra++) : -1;
    out->extra = extra;
    out->extra_s = malloc(2 * (size_t)(extra ? extra : 1) * sizeof(float));
    if (out->extra_s) {
        out->extra_t = out->extra_s + extra;
        for (int v = 0; made && v < w->verts; v++)
            if (made[v] >= 0) {
                out->extra_s[made[v] - (int)n - 1] = w->vs[v];
                out->extra_t[made[v] - (int)n - 1] = w->vt[v];
            }
    }
    uint32_t edges = 0, faces = 1;
    for (int e = 0; edge_id && e < w->edges; e += 2)
        if (!w->dead[e]) {
            edge_id[e] = (int)edges;
            edge_id[e + 1] = (int)edges + 1;
            edges += 2;
        }
    if (face_id)
        for (int f = w->fnext[0]; f != 0; f = w->fnext[f])
            face_id[f] = (int)faces++;
    out->org = malloc(3 * (size_t)edges * sizeof(uint32_t));
    out->face_next = malloc(3 * (size_t)faces * sizeof(uint32_t));
    out->inside = malloc(faces);
    if (!edge_id || !face_id || !made || !out->extra_s || !out->org || !out->face_next ||
        !out->inside) {
        free(edge_id);
        free(face_id);
        free(made);
        tess_swept_free(out);
        return -1;
    }
    out->lnext = out->org + edges;
    out->lface = out->lnext + edges;
    out->face_prev = out->face_next + faces;
    out->face_edge = out->face_prev + faces;
    out->edges = edges;
    out->faces = faces;
    for (int e = 0; e < w->edges; e++) {
        if (w->dead[e])
            continue;
        uint32_t k = (uint32_t)edge_id[e];
        int v = w->org[e];
        out->org[k] = v < 0            ? n
                      : w->idx[v] >= 0 ? (uint32_t)w->idx[v]
                      : made[v] >= 0   ? (uint32_t)made[v]
                                       : n;
        out->lnext[k] = (uint32_t)edge_id[w->lnext[e]];
        out->lface[k] = w->lface[e] > 0 ? (uint32_t)face_id[w->lface[e]] : 0;
    }
    uint32_t prev = 0;
    out->inside[0] = 0;
    out->face_edge[0] = 0;
    for (int f = w->fnext[0]; f != 0; f = w->fnext[f]) {
        uint32_t k = (uint32_t)face_id[f];
        out->face_prev[k] = prev;
        out->face_next[prev] = k;
        out->face_edge[k] = (uint32_t)edge_id[w->fan[f]];
        out->inside[k] = w->finside[f];
        prev = k;
    }
    out->face_next[prev] = 0;
    out->face_prev[0] = prev;
    free(edge_id);
    free(face_id);
    free(made);
    return 1;
}

int tess_sweep_faithful(const float *s, const float *t, uint32_t n, tess_swept *out)
{
    memset(out, 0, sizeof *out);
    if (n < 3)
        return 0;
    sweep w;
    memset(&w, 0, sizeof w);
    int *order = malloc(n * sizeof *order);
    if (!order || !sweep_alloc(&w, n)) {
        free(order);
        sweep_free(&w);
        return -1;
    }
    /* the contour as tessAddContour makes it */
    int e = -1;
    for (uint32_t i = 0; i < n && !w.fail; i++) {
        if (e < 0) {
            e = mesh_make_edge(&w);
            if (e >= 0)
                mesh_splice(&w, e, e ^ 1);
        } else if (mesh_split_edge(&w, e) >= 0) {
            e = w.lnext[e];
        }
        if (w.fail)
            break;
        int v = w.org[e];
        w.vs[v] = s[i];
        w.vt[v] = t[i];
        w.idx[v] = (int)i;
        order[i] = v;
        w.winding[e] = 1;
        w.winding[e ^ 1] = -1;
    }
    unsigned char *gone = w.fail ? NULL : calloc((size_t)w.vert_cap, 1);
    if (!w.fail && !gone) {
        free(order);
        sweep_free(&w);
        return -1;
    }
    if (!w.fail)
        remove_degenerate_edges(&w, n, gone);
    /* the vertices in libtess2's list: from the contour's second point
     * round to its first */
    uint32_t live = 0;
    int first = order[0];
    for (uint32_t k = 1; k < n && !w.fail; k++)
        if (!gone[order[k]])
            order[live++] = order[k];
    if (!w.fail && !gone[first])
        order[live++] = first;
    free(gone);
    int ok = !w.fail && live >= 3;
    if (ok)
        event_order(&w, order, (int)live);
    if (ok) {
        /* the sentinels, about the bounds enlarged as libtess2 does */
        float s_lo = s[0], s_hi = s[0], t_lo = t[0], t_hi = t[0];
        for (uint32_t i = 1; i < n; i++) {
            s_lo = s[i] < s_lo ? s[i] : s_lo;
            s_hi = s[i] > s_hi ? s[i] : s_hi;
            t_lo = t[i] < t_lo ? t[i] : t_lo;
            t_hi = t[i] > t_hi ? t[i] : t_hi;
        }
        float wide = s_hi - s_lo, high = t_hi - t_lo;
        float ds = wide > 0.01f ? wide : 0.01f, dt = high > 0.01f ? high : 0.01f;
        add_sentinel(&w, s_lo - ds, s_hi + ds, t_lo - dt);
        add_sentinel(&w, s_lo - ds, s_hi + ds, t_hi + dt);
        /* each vertex from the end, with those on its point merged into
         * it first (SpliceMergeVertices) */
        /* tessComputeInterior: each point, least first, with those on
         * its point merged into it first (SpliceMergeVertices) */
        for (uint32_t i = 0; i < live; i++)
            w.queued[order[i]] = 1;
        w.order = order;
        w.sorted = (int)live;
        for (int v; !w.fail && (v = queue_extract(&w)) >= 0;) {
            for (int next; (next = queue_minimum(&w)) >= 0 && vert_eq(&w, next, v);)
                mesh_splice(&w, w.an[v], w.an[queue_extract(&w)]);
            if (w.killed[v]) { /* a point the sweep merged away, still queued */
                w.fail = 1;
                break;
            }
            sweep_event(&w, v);
        }
        /* RemoveDegenerateFaces */
        for (int f = w.fnext[0], next; !w.fail && f != 0; f = next) {
            next = w.fnext[f];
            int a = w.fan[f];
            if (w.lnext[w.lnext[a]] == a) {
                w.winding[w.onext[a]] += w.winding[a];
                w.winding[w.onext[a] ^ 1] += w.winding[a ^ 1];
                mesh_delete(&w, a);
            }
        }
        ok = !w.fail;
    }
    int result = ok ? export_mesh(&w, n, out) : 0;
    free(order);
    sweep_free(&w);
    return result;
}

void tess_swept_free(tess_swept *out)
{
    free(out->extra_s);
    free(out->org);
    free(out->face_next);
    free(out->inside);
    memset(out, 0, sizeof *out);
}
