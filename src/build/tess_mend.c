/* OpenSCAD's mending of libtess2's triangles (tess_mend.h).
 *
 * The hash tables are followed as libstdc++ keeps them: a singly linked
 * list of nodes, and by bucket the node before the bucket's first, so
 * that a bucket's keys lie together in the list. A key whose bucket holds
 * keys goes just before them; one whose bucket is empty goes to the front
 * of the list. A table without keys has no buckets; its first key makes
 * 13, and a key past as many keys as buckets makes the next count of the
 * prime policy, the keys relinked one by one in their order. Erasing a
 * key takes it out of the list and leaves the others' order. */
#include "build/tess_mend.h"

#include <stdlib.h>
#include <string.h>

#include "base/grow.h"
#include "base/sort.h"

#define NIL UINT32_MAX

/* libstdc++'s bucket counts for a table grown one key at a time (max
 * load factor 1): 13 for the first key, then the next on the key past
 * the count. */
static const uint32_t bucket_counts[] = {13,   29,   59,    127,   257,   541,   1109,
                                         2357, 5087, 10273, 20753, 42043, 85229, 172933};
#define BUCKET_GRADES (sizeof bucket_counts / sizeof bucket_counts[0])

typedef struct node {
    uint64_t key, hash;
    uint32_t next; /* the next in the list, NIL at the end */
    uint32_t val;  /* a count, or the first cell of a list (NIL: empty) */
    uint32_t last; /* the last cell of its list, NIL: empty */
} node;

typedef struct cell {
    uint32_t value, next;
} cell;

typedef struct table {
    node *node; /* node 0 is the head, before the first */
    uint32_t nodes, node_cap;
    uint32_t *before; /* by bucket: the node before its first, NIL: empty */
    uint32_t buckets; /* 0 before the first key */
    uint32_t grade;   /* of the next bucket count */
    uint32_t size;
    uint32_t empty; /* a new node's val: 0 (a count) or NIL (an empty list) */
} table;

typedef struct mend {
    table edges, out_of, into; /* EdgeDict's edges, v2e, v2e_reverse */
    cell *cell;                /* the lists' cells */
    uint32_t cells, cell_cap;
    int nomem, broken;
} mend;

static int table_init(table *t, uint32_t empty)
{
    memset(t, 0, sizeof *t);
    t->empty = empty;
    if (!grow_array32((void **)&t->node, &t->node_cap, 1, sizeof *t->node))
        return 0;
    t->node[0].next = NIL;
    t->nodes = 1;
    return 1;
}

static void table_free(table *t)
{
    free(t->node);
    free(t->before);
}

static uint32_t bucket(const table *t, uint32_t node)
{
    return (uint32_t)(t->node[node].hash % t->buckets);
}

/* Links node x into the list at its bucket (libstdc++'s
 * _M_insert_bucket_begin, and its rehash, which links in the same way). */
static void table_link(table *t, uint32_t x)
{
    uint32_t b = bucket(t, x);
    if (t->before[b] != NIL) {
        t->node[x].next = t->node[t->before[b]].next;
        t->node[t->before[b]].next = x;
        return;
    }
    t->node[x].next = t->node[0].next;
    t->node[0].next = x;
    if (t->node[x].next != NIL)
        t->before[bucket(t, t->node[x].next)] = x;
    t->before[b] = 0;
}

static uint32_t table_find(const table *t, uint64_t key, uint64_t hash)
{
    if (!t->buckets)
        return NIL;
    uint32_t b = (uint32_t)(hash % t->buckets);
    if (t->before[b] == NIL)
        return NIL;
    for (uint32_t q = t->node[t->before[b]].next; q != NIL && bucket(t, q) == b;
         q = t->node[q].next)
        if (t->node[q].key == key)
            return q;
    return NIL;
}

/* The table's node for key, made (count 0, empty list) when it has none,
 * as operator[] makes it: NIL when memory runs out or the table outgrows
 * the bucket counts above. */
static uint32_t table_get(mend *m, table *t, uint64_t key, uint64_t hash)
{
    uint32_t x = table_find(t, key, hash);
    if (x != NIL)
        return x;
    if (!grow_array32((void **)&t->node, &t->node_cap, t->nodes + 1, sizeof *t->node)) {
        m->nomem = 1;
        return NIL;
    }
    if (t->size + 1 > t->buckets) {
        if (t->grade == BUCKET_GRADES) {
            m->broken = 1;
            return NIL;
        }
        uint32_t count = bucket_counts[t->grade++];
        uint32_t *before = malloc(count * sizeof *before);
        if (!before) {
            m->nomem = 1;
            return NIL;
        }
        free(t->before);
        t->before = before;
        t->buckets = count;
        for (uint32_t b = 0; b < count; b++)
            before[b] = NIL;
        uint32_t p = t->node[0].next;
        t->node[0].next = NIL;
        while (p != NIL) {
            uint32_t after = t->node[p].next;
            table_link(t, p);
            p = after;
        }
    }
    x = t->nodes++;
    t->node[x].key = key;
    t->node[x].hash = hash;
    t->node[x].val = t->empty;
    t->node[x].last = NIL;
    table_link(t, x);
    t->size++;
    return x;
}

/* Takes node x out (libstdc++'s _M_erase). */
static void table_erase(table *t, uint32_t x)
{
    uint32_t b = bucket(t, x), p = t->before[b];
    while (t->node[p].next != x)
        p = t->node[p].next;
    uint32_t after = t->node[x].next;
    if (p == t->before[b]) {
        if (after == NIL || bucket(t, after) != b) { /* the bucket empties */
            if (after != NIL)
                t->before[bucket(t, after)] = t->before[b];
            t->before[b] = NIL;
        }
    } else if (after != NIL && bucket(t, after) != b) {
        t->before[bucket(t, after)] = p;
    }
    t->node[p].next = after;
    t->size--;
}

/* boost::hash_combine of Boost 1.74 on 64 bits. */
static uint64_t boost_hash_combine(uint64_t seed, uint64_t k)
{
    const uint64_t m = 0xc6a4a7935bd1e995u;
    k *= m;
    k ^= k >> 47;
    k *= m;
    seed ^= k;
    seed *= m;
    return seed + 0xe6546b64u;
}

/* ---- EdgeDict's edges: a count by directed edge ---- */

static uint64_t edge_key(uint32_t a, uint32_t b)
{
    return (uint64_t)a << 32 | b;
}

static uint64_t edge_hash(uint32_t a, uint32_t b)
{
    return boost_hash_combine(boost_hash_combine(0, a), b);
}

static uint32_t edge_count(const mend *m, uint32_t a, uint32_t b)
{
    uint32_t x = table_find(&m->edges, edge_key(a, b), edge_hash(a, b));
    return x == NIL ? 0 : m->edges.node[x].val;
}

static void edge_add(mend *m, uint32_t a, uint32_t b)
{
    uint32_t x = table_get(m, &m->edges, edge_key(a, b), edge_hash(a, b));
    if (x != NIL)
        m->edges.node[x].val++;
}

static void edge_remove(mend *m, uint32_t a, uint32_t b)
{
    uint32_t x = table_get(m, &m->edges, edge_key(a, b), edge_hash(a, b));
    if (x != NIL && --m->edges.node[x].val == 0)
        table_erase(&m->edges, x);
}

/* EdgeDict::remove of triangle (a, b, c): each edge there is taken out,
 * and the reverse of each edge that is not put in. */
static void edge_remove_triangle(mend *m, const uint32_t v[3])
{
    for (int i = 0; i < 3; i++) {
        uint32_t a = v[i], b = v[(i + 1) % 3];
        if (edge_count(m, a, b) > 0)
            edge_remove(m, a, b);
        else
            edge_add(m, b, a);
    }
}

/* ---- v2e and v2e_reverse: a list of points by point ---- */

static void list_push(mend *m, table *t, uint32_t at, uint32_t value)
{
    uint32_t x = table_get(m, t, at, at);
    if (x == NIL)
        return;
    if (!grow_array32((void **)&m->cell, &m->cell_cap, m->cells + 1, sizeof *m->cell)) {
        m->nomem = 1;
        return;
    }
    uint32_t c = m->cells++;
    m->cell[c].value = value;
    m->cell[c].next = NIL;
    if (t->node[x].last == NIL)
        t->node[x].val = c;
    else
        m->cell[t->node[x].last].next = c;
    t->node[x].last = c;
}

static int list_has(const mend *m, const table *t, uint32_t x, uint32_t value)
{
    for (uint32_t c = t->node[x].val; c != NIL; c = m->cell[c].next)
        if (m->cell[c].value == value)
            return 1;
    return 0;
}

/* EdgeDict::remove_from_v2e's half for one table: value out of the list
 * at `at` (its first), and the key out when its list empties. */
static void list_remove(mend *m, table *t, uint32_t at, uint32_t value)
{
    uint32_t x = table_get(m, t, at, at);
    if (x == NIL)
        return;
    uint32_t prev = NIL;
    for (uint32_t c = t->node[x].val; c != NIL; prev = c, c = m->cell[c].next) {
        if (m->cell[c].value != value)
            continue;
        if (prev == NIL)
            t->node[x].val = m->cell[c].next;
        else
            m->cell[prev].next = m->cell[c].next;
        if (t->node[x].last == c)
            t->node[x].last = prev;
        break;
    }
    if (t->node[x].last == NIL)
        table_erase(t, x);
}

/* EdgeDict::extractTriangle: the ear (prev, v, next) into tri. */
static void extract(mend *m, uint32_t v, uint32_t next, uint32_t tri[3])
{
    uint32_t r = table_get(m, &m->into, v, v);
    if (r == NIL || m->into.node[r].last == NIL) {
        m->broken = 1; /* OpenSCAD asserts here */
        return;
    }
    uint32_t prev = m->cell[m->into.node[r].val].value;
    tri[0] = prev;
    tri[1] = v;
    tri[2] = next;
    uint32_t x = table_get(m, &m->out_of, next, next);
    if (x == NIL)
        return;
    if (!list_has(m, &m->out_of, x, prev)) {
        list_push(m, &m->out_of, prev, next);
        list_push(m, &m->into, next, prev);
    }
    list_remove(m, &m->out_of, v, next);
    list_remove(m, &m->into, v, prev);
    list_remove(m, &m->out_of, prev, v);
    list_remove(m, &m->into, prev, next);
    list_remove(m, &m->out_of, next, prev);
    list_remove(m, &m->into, next, v);
}

/* The first position in the face of number (present: it comes from the
 * face), from the face's points sorted as number << 32 | position. */
static uint32_t position_of(const uint64_t *sorted, uint32_t n, uint32_t number)
{
    uint32_t lo = 0, hi = n;
    while (lo < hi) {
        uint32_t mid = lo + (hi - lo) / 2;
        if (sorted[mid] >> 32 < number)
            lo = mid + 1;
        else
            hi = mid;
    }
    return (uint32_t)sorted[lo];
}

long tess_mend(const uint32_t *face, uint32_t n, const uint32_t *tris, uint32_t count,
               uint32_t *out, uint32_t out_cap)
{
    mend m = {0};
    uint64_t *sorted = malloc((n ? n : 1) * sizeof *sorted);
    long made = 0;
    if (!sorted || !table_init(&m.edges, 0) || !table_init(&m.out_of, NIL) ||
        !table_init(&m.into, NIL)) {
        m.nomem = 1;
        goto done;
    }
    for (uint32_t i = 0; i < n; i++) { /* EdgeDict::add(face) */
        uint32_t a = face[i], b = face[(i + 1) % n];
        if (edge_count(&m, b, a) > 0)
            edge_remove(&m, b, a);
        else
            edge_add(&m, a, b);
    }
    for (uint32_t k = 0; k < count && !m.nomem && !m.broken; k++) {
        uint32_t v[3];
        for (int i = 0; i < 3; i++)
            v[i] = face[tris[3 * k + i]];
        /* turned round where an edge runs against the face's, unless one
         * before it runs with it */
        int reverse = 0;
        for (int i = 0; i < 3; i++) {
            uint32_t a = v[i], b = v[(i + 1) % 3];
            if (edge_count(&m, a, b) > 0) {
                reverse = 0;
                break;
            }
            if (edge_count(&m, b, a) > 0)
                reverse = 1;
        }
        if (reverse) {
            uint32_t x = v[0];
            v[0] = v[2];
            v[2] = x;
        }
        edge_remove_triangle(&m, v);
        if ((uint32_t)made == out_cap) {
            m.broken = 1;
            break;
        }
        memcpy(&out[3 * made++], v, sizeof v);
    }
    /* EdgeDict::triangulateLoops */
    for (uint32_t e = m.edges.node[0].next; e != NIL && !m.nomem && !m.broken;
         e = m.edges.node[e].next)
        for (uint32_t c = 0; c < m.edges.node[e].val; c++) {
            uint32_t a = (uint32_t)(m.edges.node[e].key >> 32),
                     b = (uint32_t)m.edges.node[e].key;
            list_push(&m, &m.out_of, a, b);
            list_push(&m, &m.into, b, a);
        }
    uint32_t steps = m.cells; /* each ear takes at least one edge */
    while (m.out_of.size && !m.nomem && !m.broken) {
        uint32_t x = m.out_of.node[0].next;
        for (uint32_t q = x; q != NIL; q = m.out_of.node[q].next)
            if (m.out_of.node[q].last != NIL &&
                m.out_of.node[q].last == m.out_of.node[q].val) {
                x = q;
                break;
            }
        if (steps-- == 0 || (uint32_t)made == out_cap || m.out_of.node[x].last == NIL) {
            m.broken = 1;
            break;
        }
        uint32_t *tri = &out[3 * made];
        extract(&m, (uint32_t)m.out_of.node[x].key, m.cell[m.out_of.node[x].val].value,
                tri);
        if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2])
            m.broken = 1;
        made++;
    }
    if (m.nomem || m.broken)
        goto done;
    for (uint32_t i = 0; i < n; i++)
        sorted[i] = (uint64_t)face[i] << 32 | i;
    if (!sort_u64(sorted, n)) {
        m.nomem = 1;
        goto done;
    }
    for (long k = 0; k < 3 * made; k++)
        out[k] = position_of(sorted, n, out[k]);
done:
    table_free(&m.edges);
    table_free(&m.out_of);
    table_free(&m.into);
    free(m.cell);
    free(sorted);
    return m.nomem ? -1 : m.broken ? -2 : made;
}
