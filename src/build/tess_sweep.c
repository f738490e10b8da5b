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
    int again; /* sweep_event runs a second time for a left vertex it joined */
    int fail;  /* not in general position, or out of room: give up */
} sweep;

#define DST(w, e) ((w)->org[(e) ^ 1])
#define OPREV(w, e) ((w)->lnext[(e) ^ 1])
#define LPREV(w, e) ((w)->onext[e] ^ 1)
#define RPREV(w, e) ((w)->onext[(e) ^ 1])
#define DNEXT(w, e) (RPREV(w, e) ^ 1)

/* ---- geometry, in float as libtess2 computes ---- */

static int vert_leq(const sweep *w, int u, int v)
{
    return w->vs[u] < w->vs[v] || (w->vs[u] == w->vs[v] && w->vt[u] <= w->vt[v]);
}

static int vert_eq(const sweep *w, int u, int v)
{
    return w->vs[u] == w->vs[v] && w->vt[u] == w->vt[v];
}

/* tesedgeEval: how far v lies above the edge u-x, in t */
static float edge_eval(const sweep *w, int u, int v, int x)
{
    float gap_l = w->vs[v] - w->vs[u], gap_r = w->vs[x] - w->vs[v];
    if (gap_l + gap_r > 0) {
        if (gap_l < gap_r)
            return (w->vt[v] - w->vt[u]) +
                   (w->vt[u] - w->vt[x]) * (gap_l / (gap_l + gap_r));
        return (w->vt[v] - w->vt[x]) + (w->vt[x] - w->vt[u]) * (gap_r / (gap_l + gap_r));
    }
    return 0;
}

/* tesedgeSign: the sign of edge_eval, computed more cheaply */
static float edge_sign(const sweep *w, int u, int v, int x)
{
    float gap_l = w->vs[v] - w->vs[u], gap_r = w->vs[x] - w->vs[v];
    if (gap_l + gap_r > 0)
        return (w->vt[v] - w->vt[x]) * gap_l + (w->vt[v] - w->vt[u]) * gap_r;
    return 0;
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

/* ---- the checks, which here only look: a splice or a crossing they
 * would make ends the sweep (w->fail) ---- */

static int check_right_splice(sweep *w, int r_up)
{
    int e_up = w->reg[r_up].up, e_lo = w->reg[below(w, r_up)].up;
    int o_up = w->org[e_up], o_lo = w->org[e_lo];
    if (vert_leq(w, o_up, o_lo)) {
        if (edge_sign(w, DST(w, e_lo), o_up, o_lo) > 0)
            return 0;
        if (o_up != o_lo) /* a splice */
            w->fail = 1;
    } else {
        if (edge_sign(w, DST(w, e_up), o_lo, o_up) < 0)
            return 0;
        w->fail = 1;
    }
    return 1;
}

static int check_left_splice(sweep *w, int r_up)
{
    int e_up = w->reg[r_up].up, e_lo = w->reg[below(w, r_up)].up;
    if (vert_leq(w, DST(w, e_up), DST(w, e_lo))) {
        if (edge_sign(w, DST(w, e_up), DST(w, e_lo), w->org[e_up]) < 0)
            return 0;
    } else if (edge_sign(w, DST(w, e_lo), DST(w, e_up), w->org[e_lo]) > 0) {
        return 0;
    }
    w->fail = 1;
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
    w->fail = 1; /* they meet */
    return 1;
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
        if (DST(w, e_up) != DST(w, e_lo) && check_left_splice(w, r_up))
            return;
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
    if (DST(w, e_up) != DST(w, e_lo) && check_intersect(w, r_up))
        return;
    if (vert_eq(w, w->org[e_up], w->event) || vert_eq(w, w->org[e_lo], w->event)) {
        w->fail = 1; /* the degenerate cases */
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
        w->fail = 1; /* ConnectLeftDegenerate */
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
        if (w->again) { /* it has a left edge now: never twice */
            w->fail = 1;
            return;
        }
        w->again = 1;
        sweep_event(w, v);
        w->again = 0;
    } else {
        add_right_edges(w, r_up, w->an[v], w->an[v], -1, 1);
    }
}

static void sweep_event(sweep *w, int v)
{
    if (w->fail)
        return;
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
    w->dead = malloc(e + f);
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

/* The vertices of the contour in (s, t) order (insertion sort: faces are
 * small); 0 when two are equal. */
static int event_order(const sweep *w, int *order, uint32_t n)
{
    for (uint32_t i = 1; i < n; i++)
        for (uint32_t j = i; j > 0 && !vert_leq(w, order[j - 1], order[j]); j--) {
            int x = order[j];
            order[j] = order[j - 1];
            order[j - 1] = x;
        }
    for (uint32_t i = 1; i < n; i++)
        if (vert_eq(w, order[i - 1], order[i]))
            return 0;
    return 1;
}

/* The mesh, compact and in libtess2's order of faces, into out. */
static int export_mesh(const sweep *w, uint32_t n, tess_swept *out)
{
    int *edge_id = malloc((size_t)w->edges * sizeof *edge_id);
    int *face_id = malloc((size_t)w->faces * sizeof *face_id);
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
    if (!edge_id || !face_id || !out->org || !out->face_next || !out->inside) {
        free(edge_id);
        free(face_id);
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
        out->org[k] = v >= 0 && w->idx[v] >= 0 ? (uint32_t)w->idx[v] : n;
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
    uint32_t live = 0;
    for (uint32_t i = 0; i < n && !w.fail; i++)
        if (!gone[order[i]])
            order[live++] = order[i];
    free(gone);
    int ok = !w.fail && live >= 3 && event_order(&w, order, live);
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
        for (uint32_t i = 0; i < live && !w.fail; i++)
            sweep_event(&w, order[i]);
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
    free(out->org);
    free(out->face_next);
    free(out->inside);
    memset(out, 0, sizeof *out);
}
