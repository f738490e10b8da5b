/* The solid's own box: see bounds.h. */
#include "csg/bounds.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

enum {
    GRID = 32,        /* lines per side of each axis's grid */
    SEEDS = 3,        /* points each side's search starts from */
    MAX_ROUNDS = 400, /* rounds of one search */
    /* lines in all: past them a node still to sample keeps its tree box
     * (a model of thousands of drilled parts on one plane) */
    BUDGET = 60000
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
    double lo[3], hi[3], centre[3];
    seed best[6][SEEDS]; /* side 2a + 1: high along axis a; 2a: low; best first */
    long lines_left;
    int out_of_memory;
} finder;

/* Adds a point of the surface to the box and to each side's seeds. */
static void see(finder *f, const double p[3])
{
    for (int i = 0; i < 3; i++) {
        f->lo[i] = fmin(f->lo[i], p[i]);
        f->hi[i] = fmax(f->hi[i], p[i]);
    }
    for (int side = 0; side < 6; side++) {
        int a = side / 2;
        seed s = {side & 1 ? p[a] : -p[a], p[(a + 1) % 3], p[(a + 2) % 3]};
        seed *best = f->best[side];
        if (!(s.value > best[SEEDS - 1].value))
            continue;
        int k = SEEDS - 1;
        for (; k > 0 && s.value > best[k - 1].value; k--)
            best[k] = best[k - 1];
        best[k] = s;
    }
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
            see(f, p);
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
    o[a] = sign * here->value - sign * len * 1e-6;
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

/* The box of node id's solid, sampled: each side's value (side & 1: hi,
 * else -lo) into value; -INFINITY for every side when no line met it. */
static void sample(finder *f, uint32_t id, double value[6])
{
    const csg_tree *t = f->t;
    const bbox *b = &t->nodes[id].bounds;
    double tlo[3] = {b->lo.x, b->lo.y, b->lo.z}, thi[3] = {b->hi.x, b->hi.y, b->hi.z};
    double extent = 0;
    f->node = id;
    for (int i = 0; i < 3; i++) {
        f->lo[i] = INFINITY;
        f->hi[i] = -INFINITY;
        f->centre[i] = (tlo[i] + thi[i]) / 2;
        extent = fmax(extent, thi[i] - tlo[i]);
    }
    for (int side = 0; side < 6; side++)
        for (int k = 0; k < SEEDS; k++)
            f->best[side][k].value = -INFINITY;
    double cell[3];
    for (int i = 0; i < 3; i++)
        cell[i] = (thi[i] - tlo[i]) / GRID;
    for (int a = 0; a < 3 && !f->out_of_memory; a++) {
        int ia = (a + 1) % 3, ib = (a + 2) % 3;
        for (int i = 0; i < GRID; i++)
            for (int j = 0; j < GRID && !f->out_of_memory; j++)
                line(f, a, tlo[ia] + (i + 0.5) * cell[ia], tlo[ib] + (j + 0.5) * cell[ib],
                     1);
    }
    /* The seeds change as the searches see more; each side starts from the
     * ones it had when its turn came. */
    double tol = ldexp(extent, -30);
    for (int side = 0; side < 6 && !f->out_of_memory; side++) {
        int a = side / 2, ia = (a + 1) % 3, ib = (a + 2) % 3;
        seed from[SEEDS];
        memcpy(from, f->best[side], sizeof from);
        double limit = side & 1 ? thi[a] : -tlo[a];
        if (from[0].value >= limit - tol)
            continue; /* on the node's box already: nothing lies farther */
        for (int k = 0; k < SEEDS && !f->out_of_memory; k++)
            if (isfinite(from[k].value))
                climb(f, side, from[k], cell[ia], cell[ib], tol);
    }
    for (int side = 0; side < 6; side++) {
        int a = side / 2;
        double limit = side & 1 ? thi[a] : -tlo[a];
        double got = side & 1 ? f->hi[a] : -f->lo[a];
        if (f->lines_left <= 0) {
            value[side] = limit; /* out of lines: the box no search found */
            continue;
        }
        /* A span end rounded past the node's box stays inside it. */
        value[side] = f->lo[0] <= f->hi[0] ? fmin(got, limit) : -INFINITY;
    }
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

static double tree_side(const csg_node *n, int side)
{
    double lo[3] = {n->bounds.lo.x, n->bounds.lo.y, n->bounds.lo.z};
    double hi[3] = {n->bounds.hi.x, n->bounds.hi.y, n->bounds.hi.z};
    return side & 1 ? hi[side / 2] : -lo[side / 2];
}

/* How far node id's solid reaches on side (hi, or -lo), -INFINITY where
 * it is empty. A union's is its farthest operand's, trying the operands
 * whose boxes reach farthest first and stopping at one whose box cannot
 * beat what was found; a difference's is its first operand's where no
 * subtrahend's box reaches as far; the rest is sampled. */
static double side_of(bounder *b, uint32_t id, int side)
{
    if (b->known[id] & (1u << side))
        return b->value[id][side];
    const csg_tree *t = b->f.t;
    const csg_node *n = &t->nodes[id];
    const uint32_t *kids = t->child_ids + n->first_child;
    double got = -INFINITY;
    int sampled = 0;
    if (n->op == CSG_LEAF) {
        if (exact_leaf(&t->leaves[n->leaf]))
            got = tree_side(n, side);
        else
            sampled = 1;
    } else if (n->op == CSG_UNION) {
        /* operands in order of how far their boxes reach (a few passes of
         * picking the farthest left: most unions stop after one or two) */
        uint8_t *done = calloc(n->child_count, 1);
        if (!done) {
            b->f.out_of_memory = 1;
            return tree_side(n, side);
        }
        for (;;) {
            uint32_t pick = UINT32_MAX;
            double reach = -INFINITY;
            for (uint32_t k = 0; k < n->child_count; k++) {
                double r = tree_side(&t->nodes[kids[k]], side);
                if (!done[k] && (pick == UINT32_MAX || r > reach))
                    pick = k, reach = r;
            }
            if (pick == UINT32_MAX || !(reach > got) || b->f.out_of_memory)
                break;
            done[pick] = 1;
            got = fmax(got, side_of(b, kids[pick], side));
        }
        free(done);
    } else if (n->op == CSG_DIFFERENCE || n->child_count == 1) {
        got = side_of(b, kids[0], side);
        for (uint32_t k = 1; k < n->child_count && !sampled; k++)
            if (tree_side(&t->nodes[kids[k]], side) >= got)
                sampled = 1;
    } else {
        sampled = 1;
    }
    if (sampled && b->no_sampling) {
        got = tree_side(n, side);
    } else if (sampled) {
        double value[6];
        sample(&b->f, id, value);
        memcpy(b->value[id], value, sizeof value);
        b->known[id] = 0x3f;
        return value[side];
    }
    b->value[id][side] = got;
    b->known[id] |= (uint8_t)(1u << side);
    return got;
}

int csg_solid_bounds(const csg_tree *t, bbox *out)
{
    *out = t->bounds;
    if (t->root == CSG_EMPTY || t->has_motion || bbox_is_empty(&t->bounds))
        return 1;
    for (int side = 0; side < 6; side++)
        if (!isfinite(tree_side(&t->nodes[t->root], side)))
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
    for (int side = 0; side < 6; side++)
        if (!isfinite(got[side]))
            return 1; /* no line met the solid */
    out->lo = v3(-got[0], -got[2], -got[4]);
    out->hi = v3(got[1], got[3], got[5]);
    return 1;
}
