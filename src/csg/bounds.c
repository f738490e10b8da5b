/* The solid's own box: see bounds.h. */
#include "csg/bounds.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

enum {
    GRID = 32,        /* lines per side of each axis's grid */
    SEEDS = 3,        /* points each side's search starts from */
    MAX_ROUNDS = 200, /* rounds of one search */
    /* lines in all: past them a node still to sample keeps its tree box
     * (a model of thousands of drilled parts on one plane) */
    BUDGET = 400000
};

/* A point seen, as one side sees it: how far out it lies along the side's
 * axis (negated for a low side) and where the side's lines through it
 * cross the other two axes. */
typedef struct seed {
    double value, u, v;
} seed;

/* One line of a side's search: how far out it reaches (-INFINITY where it
 * misses the solid), and the slope of that reach in u and v on the surface
 * it ends on (from the surface's normal; 0 where the normal lies in the
 * side's plane) with the surface's leaf and part. */
typedef struct reach {
    double value, du, dv;
    uint32_t leaf, part;
} reach;

/* The sampling of one node's subtree. */
typedef struct finder {
    const csg_tree *t;
    uint32_t node;
    arena *scratch;
    double centre[3];
    seed best[SEEDS]; /* the farthest points of the side searched, farthest first */
    long lines_left;
    int out_of_memory;
} finder;

/* Adds a point of the surface, found by a line of side's axis, to the
 * side's seeds (the first is the farthest). */
static void see(finder *f, int side, const double p[3])
{
    int a = side / 2;
    seed s = {side & 1 ? p[a] : -p[a], p[(a + 1) % 3], p[(a + 2) % 3]};
    seed *best = f->best;
    if (!(s.value > best[SEEDS - 1].value))
        return;
    int k = SEEDS - 1;
    for (; k > 0 && s.value > best[k - 1].value; k--)
        best[k] = best[k - 1];
    best[k] = s;
}

/* The line along axis a through (u, v): sees each span end, and returns
 * how far out the node's solid reaches along it for side. */
static reach line(finder *f, int a, double u, double v, int side)
{
    reach out = {-INFINITY, 0, 0, 0, 0};
    if (f->lines_left <= 0)
        return out;
    f->lines_left--;
    csg_ray r = csg_axis_line(a, f->centre[a], u, v);
    const double o[3] = {r.o.x, r.o.y, r.o.z};
    arena_reset(f->scratch);
    span_list s;
    if (!csg_spans_node(f->t, f->node, &r, f->scratch, &s)) {
        f->out_of_memory = 1;
        return out;
    }
    for (uint32_t k = 0; k < s.n; k++) {
        const span_end *ends[2] = {&s.v[k].in, &s.v[k].out};
        for (int e = 0; e < 2; e++) {
            if (!isfinite(ends[e]->t))
                continue;
            double p[3] = {o[0], o[1], o[2]};
            p[a] += ends[e]->t;
            see(f, side, p);
        }
    }
    if (s.n == 0)
        return out;
    const span_end *end = side & 1 ? &s.v[s.n - 1].out : &s.v[0].in;
    out.value = side & 1 ? o[a] + end->t : -(o[a] + end->t);
    if (end->leaf == SPAN_NO_LEAF)
        return out;
    csg_hit hit = {end->t, end->leaf, end->part, end->flip, (uint8_t)(side & 1)};
    vec3 nv = csg_hit_normal(f->t, &r, &hit);
    double n[3] = {nv.x, nv.y, nv.z};
    /* On the surface n . dp = 0: along the axis the reach moves by
     * -(n_u du + n_v dv) / n_a, negated for a low side. */
    double na = side & 1 ? n[a] : -n[a];
    if (na > 1e-12) {
        out.du = -n[(a + 1) % 3] / na;
        out.dv = -n[(a + 2) % 3] / na;
    }
    out.leaf = end->leaf;
    out.part = end->part;
    return out;
}

/* Where the solid's surface ends toward (wu, wv) from the line through
 * (u, v) whose reach is value: the direction in (u, v) along the wall
 * there (the surface crossed going from just inside the reach's point
 * toward the neighbour), uphill on the slopes (du, dv) of the line's own
 * surface, into *tu, *tv. Returns 0 where there is none (the neighbour
 * lies past no wall within len, or the wall runs square to the slope). A
 * hole's rim is such a wall: the reach rises along it to a corner that
 * neither the eight neighbours nor the ridges find. */
static int wall_tangent(finder *f, int side, double u, double v, const reach *here,
                        double wu, double wv, double len, double *tu, double *tv)
{
    int a = side / 2, ia = (a + 1) % 3, ib = (a + 2) % 3;
    double sign = side & 1 ? 1 : -1;
    double o[3], d[3] = {0, 0, 0};
    /* just inside: back along the axis by a millionth of the step */
    o[a] = sign * here->value - sign * 1e-6 * hypot(wu, wv);
    o[ia] = u;
    o[ib] = v;
    d[ia] = wu;
    d[ib] = wv;
    csg_ray r;
    r.o = v3(o[0], o[1], o[2]);
    r.d = v3(d[0], d[1], d[2]);
    r.tmin = 0;
    r.tmax = len;
    arena_reset(f->scratch);
    span_list s;
    if (!csg_spans_node(f->t, f->node, &r, f->scratch, &s)) {
        f->out_of_memory = 1;
        return 0;
    }
    if (s.n == 0 || s.v[0].in.t > 0 || s.v[0].out.leaf == SPAN_NO_LEAF)
        return 0; /* not inside at the start, or no wall within len */
    const span_end *e = &s.v[0].out;
    csg_hit hit = {e->t, e->leaf, e->part, e->flip, 1};
    vec3 nv = csg_hit_normal(f->t, &r, &hit);
    double n[3] = {nv.x, nv.y, nv.z};
    double nu = n[ia], nw = n[ib], m = hypot(nu, nw);
    if (!(m > 1e-12))
        return 0;
    *tu = -nw / m;
    *tv = nu / m;
    double up = *tu * here->du + *tv * here->dv;
    if (fabs(up) < 1e-12)
        return 0;
    if (up < 0)
        *tu = -*tu, *tv = -*tv;
    return 1;
}

/* The pattern search of one side from one seed, with the grid's steps. A
 * round tries the eight neighbours at the step, and along each ridge the
 * current line's surface makes with a neighbour's (the direction square
 * to the difference of their slopes, uphill): on a polyhedron's peak the
 * reach rises along the edges, which a fixed set of directions can miss. */
static void climb(finder *f, int side, seed from, double hu, double hv, double tol)
{
    int a = side / 2;
    double u = from.u, v = from.v;
    reach here = line(f, a, u, v, side);
    for (int round = 0; round < MAX_ROUNDS && !f->out_of_memory; round++) {
        if (hu <= tol && hv <= tol)
            break;
        double best = here.value, bu = u, bv = v;
        reach around[8];
        int offsets[8][2];
        int count = 0;
        for (int du = -1; du <= 1; du++)
            for (int dv = -1; dv <= 1; dv++) {
                if ((du == 0 && dv == 0) || (du && !(hu > 0)) || (dv && !(hv > 0)))
                    continue;
                double nu = u + du * hu, nv = v + dv * hv;
                reach got = line(f, a, nu, nv, side);
                offsets[count][0] = du;
                offsets[count][1] = dv;
                around[count++] = got;
                if (got.value > best)
                    best = got.value, bu = nu, bv = nv;
            }
        /* Ridges, in steps scaled to the grid's (u and v may differ). */
        double step = fmax(hu, hv);
        for (int k = 0; k < count && isfinite(here.value) && !f->out_of_memory; k++) {
            const reach *o = &around[k];
            if (o->leaf == here.leaf && o->part == here.part && isfinite(o->value))
                continue;
            double ru, rv;
            if (isfinite(o->value) && o->value > here.value - step) {
                double gu = here.du - o->du, gv = here.dv - o->dv;
                double len = hypot(gu, gv);
                if (!(len > 0))
                    continue;
                ru = -gv / len, rv = gu / len;
                if (ru * here.du + rv * here.dv < 0)
                    ru = -ru, rv = -rv;
            } else if (!wall_tangent(f, side, u, v, &here, offsets[k][0] * hu,
                                     offsets[k][1] * hv, 1, &ru, &rv)) {
                continue;
            }
            double nu = u + ru * step * (hu > 0), nv = v + rv * step * (hv > 0);
            reach got = line(f, a, nu, nv, side);
            if (got.value > best)
                best = got.value, bu = nu, bv = nv;
        }
        if (best > here.value) {
            u = bu;
            v = bv;
            here = line(f, a, u, v, side);
        } else {
            hu /= 2;
            hv /= 2;
        }
    }
}

static double box_side(const bbox *box, int side)
{
    double lo[3] = {box->lo.x, box->lo.y, box->lo.z};
    double hi[3] = {box->hi.x, box->hi.y, box->hi.z};
    return side & 1 ? hi[side / 2] : -lo[side / 2];
}

/* How far node id's solid reaches on side (hi, or -lo), searched along
 * lines of the side's axis over region (a box inside the node's, about the
 * part searched): -INFINITY when no line met the solid; the region's side
 * when the lines ran out. */
static double search(finder *f, uint32_t id, bbox region, int side)
{
    const bbox *b = &f->t->nodes[id].bounds;
    region = bbox_intersect(region, *b);
    double rlo[3] = {region.lo.x, region.lo.y, region.lo.z};
    double rhi[3] = {region.hi.x, region.hi.y, region.hi.z};
    double extent = 0;
    f->node = id;
    for (int i = 0; i < 3; i++) {
        f->centre[i] = (rlo[i] + rhi[i]) / 2;
        extent = fmax(extent, rhi[i] - rlo[i]);
    }
    for (int k = 0; k < SEEDS; k++)
        f->best[k].value = -INFINITY;
    int a = side / 2, ia = (a + 1) % 3, ib = (a + 2) % 3;
    double limit = box_side(&region, side);
    if (bbox_is_empty(&region))
        return -INFINITY;
    double cu = (rhi[ia] - rlo[ia]) / GRID, cv = (rhi[ib] - rlo[ib]) / GRID;
    for (int i = 0; i < GRID; i++)
        for (int j = 0; j < GRID && !f->out_of_memory; j++)
            line(f, a, rlo[ia] + (i + 0.5) * cu, rlo[ib] + (j + 0.5) * cv, side);
    double tol = ldexp(extent, -26);
    seed from[SEEDS];
    memcpy(from, f->best, sizeof from);
    /* on the region's box already: nothing lies farther */
    for (int k = 0; k < SEEDS && from[0].value < limit - tol && !f->out_of_memory; k++)
        if (isfinite(from[k].value))
            climb(f, side, from[k], cu, cv, tol);
    if (f->lines_left <= 0)
        return limit; /* out of lines: the box no search found */
    /* the farthest point seen (-INFINITY: none); a span end rounded past
     * the node's box stays inside it */
    return fmin(f->best[0].value, box_side(b, side));
}

/* What the search knows of each node: the sides found (known[id] & 1 <<
 * side) and their values. */
typedef struct bounder {
    finder f;
    double (*value)[6];
    uint8_t *known;
    int no_sampling; /* the tree's boxes only (implicit leaves) */
} bounder;

/* A leaf whose tree box is its solid's: a box under any transform (its
 * corners are its vertices), and the primitives whose local box is theirs
 * under a transform that keeps the axes (each row of the matrix one
 * non-zero). */
static int exact_leaf(const csg_leaf *l)
{
    if (l->prim.kind == PRIM_BOX)
        return 1;
    switch (l->prim.kind) {
    case PRIM_SPHERE:
    case PRIM_CYLINDER:
    case PRIM_CONVEX:
    case PRIM_MESH:
    case PRIM_TORUS:
        break;
    default:
        return 0;
    }
    for (int i = 0; i < 3; i++) {
        int nonzero = 0;
        for (int j = 0; j < 3; j++)
            nonzero += l->to_local.m[i][j] != 0;
        if (nonzero != 1)
            return 0;
    }
    return 1;
}

typedef struct reach_of {
    double reach;
    uint32_t id;
} reach_of;

static int farther_first(const void *pa, const void *pb)
{
    const reach_of *a = pa, *b = pb;
    if (a->reach != b->reach)
        return a->reach > b->reach ? -1 : 1;
    return a->id < b->id ? -1 : a->id > b->id;
}

/* The operands of a union, farthest reaching on side first (by their
 * boxes); NULL when out of memory. */
static uint32_t *by_reach(const csg_tree *t, const csg_node *n, int side)
{
    size_t count = n->child_count ? n->child_count : 1;
    reach_of *r = malloc(count * sizeof *r);
    uint32_t *order = malloc(count * sizeof *order);
    if (!r || !order) {
        free(r);
        free(order);
        return NULL;
    }
    const uint32_t *kids = t->child_ids + n->first_child;
    for (uint32_t k = 0; k < n->child_count; k++) {
        double reach = box_side(&t->nodes[kids[k]].bounds, side);
        r[k] = (reach_of){isnan(reach) ? -INFINITY : reach, kids[k]};
    }
    qsort(r, n->child_count, sizeof *r, farther_first);
    for (uint32_t k = 0; k < n->child_count; k++)
        order[k] = r[k].id;
    free(r);
    return order;
}

static double side_of(bounder *b, uint32_t id, int side);

/* A difference or an intersection: the parts of its first operand (found
 * down the first operands of cuts inside it: the operands of a union, else
 * the operand itself), farthest first, each its own side where it is the
 * first operand of this difference and no subtrahend's box reaches as far
 * as the part does, else searched over the part's box, until no part left
 * can reach farther than what was found. Searching part by part keeps a
 * thin part and every part's extreme in the search's grid. */
static double cut_side(bounder *b, uint32_t id, int side)
{
    const csg_tree *t = b->f.t;
    const csg_node *n = &t->nodes[id];
    const uint32_t *kids = t->child_ids + n->first_child;
    /* down the first operands of nested cuts: ((a | b) - c) & d is
     * (a - c) & d | (b - c) & d, searched over a's box and b's */
    uint32_t one = kids[0];
    int direct = 1;
    while (t->nodes[one].op != CSG_LEAF && t->nodes[one].op != CSG_UNION)
        one = t->child_ids[t->nodes[one].first_child], direct = 0;
    const csg_node *first = &t->nodes[one];
    uint32_t count = 1, *order = &one, *owned = NULL;
    if (first->op == CSG_UNION) {
        owned = order = by_reach(t, first, side);
        count = first->child_count;
        if (!order) {
            b->f.out_of_memory = 1;
            return box_side(&n->bounds, side);
        }
    }
    double got = -INFINITY, bound = box_side(&n->bounds, side);
    for (uint32_t k = 0; k < count && !b->f.out_of_memory; k++) {
        const csg_node *part = &t->nodes[order[k]];
        if (!(fmin(box_side(&part->bounds, side), bound) > got))
            break;
        double v = -INFINITY;
        int cut = n->op != CSG_DIFFERENCE || !direct;
        if (!cut) {
            v = side_of(b, order[k], side);
            for (uint32_t j = 1; j < n->child_count && !cut; j++)
                cut = box_side(&t->nodes[kids[j]].bounds, side) >= v;
        }
        if (cut)
            v = b->no_sampling ? fmin(box_side(&part->bounds, side), bound)
                               : search(&b->f, id, part->bounds, side);
        got = fmax(got, v);
    }
    free(owned);
    return got;
}

/* How far node id's solid reaches on side (hi, or -lo), -INFINITY where
 * it is empty. A union's is its farthest operand's, trying the operands
 * whose boxes reach farthest first and stopping at one whose box cannot
 * beat what was found; an exact leaf's its box's; a difference's or an
 * intersection's cut_side's; the rest is searched. */
static double side_of(bounder *b, uint32_t id, int side)
{
    if (b->known[id] & (1u << side))
        return b->value[id][side];
    const csg_tree *t = b->f.t;
    const csg_node *n = &t->nodes[id];
    double got = -INFINITY;
    if (n->op == CSG_LEAF) {
        if (exact_leaf(&t->leaves[n->leaf]) || b->no_sampling)
            got = box_side(&n->bounds, side);
        else
            got = search(&b->f, id, n->bounds, side);
    } else if (n->op == CSG_UNION) {
        uint32_t *order = by_reach(t, n, side);
        if (!order) {
            b->f.out_of_memory = 1;
            return box_side(&n->bounds, side);
        }
        for (uint32_t k = 0; k < n->child_count && !b->f.out_of_memory; k++) {
            if (!(box_side(&t->nodes[order[k]].bounds, side) > got))
                break;
            got = fmax(got, side_of(b, order[k], side));
        }
        free(order);
    } else if (n->child_count == 1) {
        /* (a leaf has no children: a tree of leaves alone has no child_ids) */
        got = side_of(b, t->child_ids[n->first_child], side);
    } else {
        got = cut_side(b, id, side);
    }
    b->value[id][side] = got;
    b->known[id] |= (uint8_t)(1u << side);
    return got;
}

int csg_solid_bounds(const csg_tree *t, bbox *out, int *met)
{
    *out = t->bounds;
    *met = 1;
    if (t->root == CSG_EMPTY || t->has_motion || bbox_is_empty(&t->bounds))
        return 1;
    for (int side = 0; side < 6; side++)
        if (!isfinite(box_side(&t->bounds, side)))
            return 1;
    bounder b;
    memset(&b, 0, sizeof b);
    arena scratch;
    arena_init(&scratch, 16 * 1024);
    b.f.t = t;
    b.f.scratch = &scratch;
    b.f.lines_left = BUDGET;
    /* An implicit leaf's lines are root searches, a thousand times a
     * polyhedron's: its tree keeps the boxes of its parts. */
    for (uint32_t k = 0; k < t->leaf_count; k++)
        b.no_sampling |= t->leaves[k].prim.kind == PRIM_IMPLICIT;
    b.value = malloc((size_t)t->node_count * sizeof *b.value);
    b.known = calloc(t->node_count, 1);
    double got[6];
    for (int side = 0; side < 6 && b.value && b.known && !b.f.out_of_memory; side++)
        got[side] = side_of(&b, t->root, side);
    int ok = b.value && b.known && !b.f.out_of_memory;
    free(b.value);
    free(b.known);
    arena_free(&scratch);
    if (!ok)
        return 0;
    /* a side no line met keeps the tree's (a slab thinner than the grid
     * across it is met only by the lines along its thickness) */
    int found = 0;
    for (int side = 0; side < 6; side++) {
        found += isfinite(got[side]) != 0;
        if (!isfinite(got[side]))
            got[side] = box_side(&t->bounds, side);
    }
    *met = found > 0;
    out->lo = v3(-got[0], -got[2], -got[4]);
    out->hi = v3(got[1], got[3], got[5]);
    return 1;
}
