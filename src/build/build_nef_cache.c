/* The CGAL solids of one build, by subtree (build_nef_cache.h).
 *
 * OpenSCAD 2021.01 keys its geometry caches (GeometryCache, CGALCache) by
 * a subtree's text as its .csg export writes it, without whitespace
 * (Tree::getIdString), and applies a multmatrix to the Nef polyhedron of
 * its child after the child is evaluated, so that one subtree under
 * several transforms is evaluated once. The key here is the subtree's
 * structure: each node's kind, name, modifiers, arguments (numbers by
 * their bits, so that -0 and 0 differ, as they may in a mirror), matrix
 * and children, recursively. A 64-bit hash finds the candidates; a
 * candidate stands for the subtree only when a full structural comparison
 * finds them equal, so two subtrees that merely hash alike are each
 * evaluated. Only nodes whose every argument is compared take part
 * (build_nef_cache_key); a subtree with another kind (an import, whose
 * file is read with its own rules, a material, a resize) or with an
 * argument error or a warning of its own model (a bad point index, a
 * matrix that is not finite) is not cached.
 *
 * Timing: OpenSCAD puts a child's geometry in its cache when the parent
 * collects its children (GeometryEvaluator::collectChildren3D), so two
 * equal siblings are both evaluated, each with its warnings, and a later
 * equal subtree elsewhere is not. Solids recorded here are found only
 * once their parent publishes them (build_nef_cache_publish).
 *
 * Entries live in an array in the order recorded; an open-addressing
 * table of indices, by hash, finds them.
 */
#include "build/build_nef_cache.h"

#include <stdlib.h>
#include <string.h>

typedef struct entry {
    uint64_t hash;
    const model_node *node; /* the subtree evaluated (the model outlives the build) */
    nef_solid *solid;       /* in the subtree's frame; NULL: empty */
    int published;
} entry;

struct build_nef_cache {
    entry *entries;
    size_t count, cap;
    uint32_t *table;   /* index + 1 into entries; 0: free */
    size_t table_cap;  /* 0 or a power of two */
    nef_plugin plugin; /* opened with the first solid, closed with the cache */
    size_t evaluated, reused;
};

build_nef_cache *build_nef_cache_new(void)
{
    return calloc(1, sizeof(build_nef_cache));
}

void build_nef_cache_free(build_nef_cache *cache)
{
    if (!cache)
        return;
    for (size_t i = 0; i < cache->count; i++) {
        if (cache->entries[i].solid)
            cache->plugin.release(cache->entries[i].solid);
    }
    free(cache->entries);
    free(cache->table);
    nef_plugin_close(&cache->plugin);
    free(cache);
}

/* ---- the key ---- */

/* The subtree walks stop here; deeper subtrees are not cached. */
enum { KEY_MAX_DEPTH = 1000 };

static uint64_t mix(uint64_t h, uint64_t v)
{
    h ^= v + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
    h ^= h >> 31;
    h *= 0xbf58476d1ce4e5b9ull;
    h ^= h >> 29;
    return h;
}

static uint64_t mix_bytes(uint64_t h, const void *p, size_t n)
{
    const unsigned char *b = p;
    uint64_t word = 0;
    size_t k = 0;
    for (size_t i = 0; i < n; i++) {
        word |= (uint64_t)b[i] << (8 * k);
        if (++k == 8) {
            h = mix(h, word);
            word = 0;
            k = 0;
        }
    }
    return mix(mix(h, word), n);
}

static uint64_t mix_string(uint64_t h, const char *s)
{
    return s ? mix_bytes(h, s, strlen(s)) : mix(h, 0x5a5a);
}

static int same_string(const char *a, const char *b)
{
    return a == b || (a && b && strcmp(a, b) == 0);
}

/* n bytes at a and b equal (either may be NULL when n is 0). */
static int same_bytes(const void *a, const void *b, size_t n)
{
    return n == 0 || memcmp(a, b, n) == 0;
}

/* The bits of n numbers equal. */
static int same_bits(const double *a, const double *b, size_t n)
{
    return same_bytes(a, b, n * sizeof *a);
}

/* The point indices of a polyhedron's faces (face_start may be NULL
 * without faces). */
static size_t face_indices(const model_node *p)
{
    uint32_t faces = p->u.polyhedron.face_count;
    return faces && p->u.polyhedron.face_start ? p->u.polyhedron.face_start[faces] : 0;
}

static int same_res(const model_resolution *a, const model_resolution *b)
{
    return same_bits(&a->fn, &b->fn, 1) && same_bits(&a->fa, &b->fa, 1) &&
           same_bits(&a->fs, &b->fs, 1);
}

static uint64_t mix_res(uint64_t h, const model_resolution *r)
{
    double v[3] = {r->fn, r->fa, r->fs};
    return mix_bytes(h, v, sizeof v);
}

/* Whether n's own arguments can be compared; mixes them into *h. */
static int key_args(const model_node *n, uint64_t *h)
{
    uint64_t k = *h;
    if (n->pending || n->not_finite || n->unsized)
        return 0;
    switch (n->kind) {
    case MODEL_UNION:
    case MODEL_DIFFERENCE:
    case MODEL_INTERSECTION:
    case MODEL_HULL:
    case MODEL_MINKOWSKI:
        break;
    case MODEL_XFORM:
        k = mix_bytes(k, n->u.xform->m, sizeof n->u.xform->m);
        break;
    case MODEL_COLOR: {
        const model_color *c = n->u.color;
        k = mix(k, (uint64_t)c->set * 2 + (uint64_t)c->has_alpha);
        k = mix_bytes(k, c->c, sizeof c->c);
        k = mix_bytes(k, &c->alpha, sizeof c->alpha);
        break;
    }
    case MODEL_CUBE:
        k = mix_bytes(k, n->u.cube.size, sizeof n->u.cube.size);
        k = mix(k, (uint64_t)n->u.cube.center);
        break;
    case MODEL_SPHERE:
        k = mix_res(mix_bytes(k, &n->u.sphere.r, sizeof(double)), &n->u.sphere.res);
        break;
    case MODEL_CYLINDER: {
        double v[3] = {n->u.cylinder.h, n->u.cylinder.r1, n->u.cylinder.r2};
        k = mix_res(mix(mix_bytes(k, v, sizeof v), (uint64_t)n->u.cylinder.center),
                    &n->u.cylinder.res);
        break;
    }
    case MODEL_POLYHEDRON: {
        const model_node *p = n;
        if (p->u.polyhedron.bad_count || p->u.polyhedron.bad_point)
            return 0;
        uint32_t faces = p->u.polyhedron.face_count;
        k = mix_bytes(k, p->u.polyhedron.points,
                      (size_t)p->u.polyhedron.point_count * sizeof(vec3));
        if (faces)
            k = mix_bytes(k, p->u.polyhedron.face_start,
                          ((size_t)faces + 1) * sizeof(uint32_t));
        k = mix_bytes(k, p->u.polyhedron.indices, face_indices(p) * sizeof(uint32_t));
        break;
    }
    case MODEL_LINEAR_EXTRUDE: {
        const model_linear_extrude *e = n->u.linear_extrude;
        if (e->exact_error)
            return 0;
        double v[5] = {e->height, e->twist, e->slices, e->sx, e->sy};
        k = mix_res(
            mix(mix_bytes(k, v, sizeof v), (uint64_t)e->center * 2 + (uint64_t)e->plain),
            &e->res);
        break;
    }
    case MODEL_ROTATE_EXTRUDE:
        k = mix_res(mix_bytes(k, &n->u.rotate_extrude->angle, sizeof(double)),
                    &n->u.rotate_extrude->res);
        break;
    case MODEL_SQUARE: {
        double v[2] = {n->u.square->sx, n->u.square->sy};
        k = mix(mix_bytes(k, v, sizeof v), (uint64_t)n->u.square->center);
        break;
    }
    case MODEL_CIRCLE: {
        double v[2] = {n->u.circle->r, n->u.circle->d};
        k = mix_res(mix(mix_bytes(k, v, sizeof v), (uint64_t)n->u.circle->has_d),
                    &n->u.circle->res);
        break;
    }
    case MODEL_POLYGON: {
        const model_polygon *p = n->u.polygon;
        if (p->bad_count || p->bad_point)
            return 0;
        k = mix(k, (uint64_t)p->has_points * 2 + (uint64_t)p->has_paths);
        k = mix_bytes(k, p->xy, (size_t)p->point_count * 2 * sizeof(double));
        if (p->path_start) {
            k = mix_bytes(k, p->path_start,
                          ((size_t)p->path_count + 1) * sizeof(uint32_t));
            k = mix_bytes(k, p->index,
                          (size_t)p->path_start[p->path_count] * sizeof(uint32_t));
        } else {
            k = mix(k, p->path_count);
        }
        break;
    }
    case MODEL_OFFSET: {
        const model_offset *o = n->u.offset;
        k = mix_bytes(k, &o->delta, sizeof o->delta);
        k = mix(k, (uint64_t)o->has_r * 4 + (uint64_t)o->has_delta * 2 +
                       (uint64_t)o->chamfer);
        k = mix_res(k, &o->res);
        break;
    }
    case MODEL_TEXT: {
        const model_text *t = n->u.text;
        double v[2] = {t->size, t->spacing};
        k = mix_bytes(k, t->text, t->length);
        k = mix_res(mix_bytes(k, v, sizeof v), &t->res);
        const char *s[6] = {t->font,   t->direction, t->language,
                            t->script, t->halign,    t->valign};
        for (int i = 0; i < 6; i++)
            k = mix_string(k, s[i]);
        break;
    }
    case MODEL_PROJECTION:
        k = mix(k, (uint64_t)n->u.projection.cut);
        break;
    default:
        return 0;
    }
    *h = k;
    return 1;
}

static int key_node(const model_node *n, uint64_t *h, int depth)
{
    if (depth > KEY_MAX_DEPTH)
        return 0;
    uint64_t k = mix(*h, (uint64_t)n->kind);
    k = mix(k, (uint64_t)n->modifiers * 2 + (uint64_t)(n->is_root != 0));
    k = mix(mix_string(k, n->name), n->child_count);
    if (!key_args(n, &k))
        return 0;
    for (const model_node *c = n->first_child; c; c = c->next) {
        if (!key_node(c, &k, depth + 1))
            return 0;
    }
    *h = mix(k, 0xc4);
    return 1;
}

int build_nef_cache_key(const model_node *n, uint64_t *hash)
{
    uint64_t h = 0x853c49e6748fea9bull;
    if (!key_node(n, &h, 0))
        return 0;
    *hash = h;
    return 1;
}

/* Whether a and b, of one kind, have the same arguments (key_args took
 * both). */
static int same_args(const model_node *a, const model_node *b)
{
    switch (a->kind) {
    case MODEL_XFORM:
        return memcmp(a->u.xform->m, b->u.xform->m, sizeof a->u.xform->m) == 0;
    case MODEL_COLOR: {
        const model_color *x = a->u.color, *y = b->u.color;
        return x->set == y->set && x->has_alpha == y->has_alpha &&
               same_bits(x->c, y->c, 4) && same_bits(&x->alpha, &y->alpha, 1);
    }
    case MODEL_CUBE:
        return same_bits(a->u.cube.size, b->u.cube.size, 3) &&
               a->u.cube.center == b->u.cube.center;
    case MODEL_SPHERE:
        return same_bits(&a->u.sphere.r, &b->u.sphere.r, 1) &&
               same_res(&a->u.sphere.res, &b->u.sphere.res);
    case MODEL_CYLINDER:
        return same_bits(&a->u.cylinder.h, &b->u.cylinder.h, 1) &&
               same_bits(&a->u.cylinder.r1, &b->u.cylinder.r1, 1) &&
               same_bits(&a->u.cylinder.r2, &b->u.cylinder.r2, 1) &&
               a->u.cylinder.center == b->u.cylinder.center &&
               same_res(&a->u.cylinder.res, &b->u.cylinder.res);
    case MODEL_POLYHEDRON: {
        uint32_t faces = a->u.polyhedron.face_count;
        return a->u.polyhedron.point_count == b->u.polyhedron.point_count &&
               faces == b->u.polyhedron.face_count &&
               same_bytes(a->u.polyhedron.points, b->u.polyhedron.points,
                          (size_t)a->u.polyhedron.point_count * sizeof(vec3)) &&
               (!faces ||
                same_bytes(a->u.polyhedron.face_start, b->u.polyhedron.face_start,
                           ((size_t)faces + 1) * sizeof(uint32_t))) &&
               same_bytes(a->u.polyhedron.indices, b->u.polyhedron.indices,
                          face_indices(a) * sizeof(uint32_t));
    }
    case MODEL_LINEAR_EXTRUDE: {
        const model_linear_extrude *x = a->u.linear_extrude, *y = b->u.linear_extrude;
        return same_bits(&x->height, &y->height, 1) && x->center == y->center &&
               same_bits(&x->twist, &y->twist, 1) &&
               same_bits(&x->slices, &y->slices, 1) && same_bits(&x->sx, &y->sx, 1) &&
               same_bits(&x->sy, &y->sy, 1) && x->plain == y->plain &&
               same_res(&x->res, &y->res);
    }
    case MODEL_ROTATE_EXTRUDE:
        return same_bits(&a->u.rotate_extrude->angle, &b->u.rotate_extrude->angle, 1) &&
               same_res(&a->u.rotate_extrude->res, &b->u.rotate_extrude->res);
    case MODEL_SQUARE:
        return same_bits(&a->u.square->sx, &b->u.square->sx, 1) &&
               same_bits(&a->u.square->sy, &b->u.square->sy, 1) &&
               a->u.square->center == b->u.square->center;
    case MODEL_CIRCLE:
        return same_bits(&a->u.circle->r, &b->u.circle->r, 1) &&
               same_bits(&a->u.circle->d, &b->u.circle->d, 1) &&
               a->u.circle->has_d == b->u.circle->has_d &&
               same_res(&a->u.circle->res, &b->u.circle->res);
    case MODEL_POLYGON: {
        const model_polygon *x = a->u.polygon, *y = b->u.polygon;
        if (x->has_points != y->has_points || x->has_paths != y->has_paths ||
            x->point_count != y->point_count || x->path_count != y->path_count ||
            !x->path_start != !y->path_start ||
            !same_bits(x->xy, y->xy, (size_t)x->point_count * 2))
            return 0;
        return !x->path_start ||
               (same_bytes(x->path_start, y->path_start,
                           ((size_t)x->path_count + 1) * sizeof(uint32_t)) &&
                same_bytes(x->index, y->index,
                           (size_t)x->path_start[x->path_count] * sizeof(uint32_t)));
    }
    case MODEL_OFFSET: {
        const model_offset *x = a->u.offset, *y = b->u.offset;
        return same_bits(&x->delta, &y->delta, 1) && x->has_r == y->has_r &&
               x->has_delta == y->has_delta && x->chamfer == y->chamfer &&
               same_res(&x->res, &y->res);
    }
    case MODEL_TEXT: {
        const model_text *x = a->u.text, *y = b->u.text;
        return x->length == y->length && same_bytes(x->text, y->text, x->length) &&
               same_bits(&x->size, &y->size, 1) &&
               same_bits(&x->spacing, &y->spacing, 1) && same_res(&x->res, &y->res) &&
               same_string(x->font, y->font) && same_string(x->direction, y->direction) &&
               same_string(x->language, y->language) &&
               same_string(x->script, y->script) && same_string(x->halign, y->halign) &&
               same_string(x->valign, y->valign);
    }
    case MODEL_PROJECTION:
        return a->u.projection.cut == b->u.projection.cut;
    default: /* no arguments */
        return 1;
    }
}

/* Whether subtrees a and b are equal (both passed key_node). */
static int same_node(const model_node *a, const model_node *b, int depth)
{
    if (a == b)
        return 1;
    if (depth > KEY_MAX_DEPTH || a->kind != b->kind || a->modifiers != b->modifiers ||
        (a->is_root != 0) != (b->is_root != 0) || a->child_count != b->child_count ||
        !same_string(a->name, b->name) || !same_args(a, b))
        return 0;
    const model_node *x = a->first_child, *y = b->first_child;
    for (; x && y; x = x->next, y = y->next) {
        if (!same_node(x, y, depth + 1))
            return 0;
    }
    return !x && !y;
}

/* ---- the table ---- */

/* The slot of the first entry equal to n, or of the free slot that ends
 * the probe. */
static size_t slot_of(const build_nef_cache *cache, const model_node *n, uint64_t hash)
{
    size_t mask = cache->table_cap - 1, i = (size_t)(hash ^ (hash >> 32)) & mask;
    for (;; i = (i + 1) & mask) {
        uint32_t at = cache->table[i];
        if (!at)
            return i;
        const entry *e = &cache->entries[at - 1];
        if (e->hash == hash && same_node(e->node, n, 0))
            return i;
    }
}

int build_nef_cache_find(build_nef_cache *cache, const model_node *n, uint64_t hash,
                         const nef_solid **solid)
{
    *solid = NULL;
    if (!cache->table_cap)
        return 0;
    uint32_t at = cache->table[slot_of(cache, n, hash)];
    if (!at || !cache->entries[at - 1].published)
        return 0;
    *solid = cache->entries[at - 1].solid;
    cache->reused++;
    return 1;
}

/* Room for one more entry and its slot. Returns 0 when memory runs out. */
static int grow(build_nef_cache *cache)
{
    if (cache->count == cache->cap) {
        size_t cap = cache->cap ? 2 * cache->cap : 16;
        if (cap > UINT32_MAX / 2)
            return 0;
        entry *e = realloc(cache->entries, cap * sizeof *e);
        if (!e)
            return 0;
        cache->entries = e;
        cache->cap = cap;
    }
    if (2 * (cache->count + 1) <= cache->table_cap)
        return 1;
    size_t cap = cache->table_cap ? 2 * cache->table_cap : 32;
    uint32_t *table = calloc(cap, sizeof *table);
    if (!table)
        return 0;
    for (size_t k = 0; k < cache->count; k++) {
        size_t i =
            (size_t)(cache->entries[k].hash ^ (cache->entries[k].hash >> 32)) & (cap - 1);
        while (table[i])
            i = (i + 1) & (cap - 1);
        table[i] = (uint32_t)k + 1;
    }
    free(cache->table);
    cache->table = table;
    cache->table_cap = cap;
    return 1;
}

int build_nef_cache_put(build_nef_cache *cache, const model_node *n, uint64_t hash,
                        nef_solid *solid, int keep, const nef_plugin *plugin)
{
    cache->evaluated++;
    if (!keep) {
        if (solid)
            plugin->release(solid);
        return 1;
    }
    if (!cache->plugin.handle) {
        char why[600];
        if (!nef_plugin_open(&cache->plugin, why, sizeof why)) {
            if (solid)
                plugin->release(solid);
            return 0;
        }
    }
    if (!grow(cache)) {
        if (solid)
            plugin->release(solid);
        return 0;
    }
    size_t i = slot_of(cache, n, hash);
    if (cache->table[i]) { /* an equal sibling's, not yet published */
        if (solid)
            plugin->release(solid);
        return 1;
    }
    cache->entries[cache->count] = (entry){hash, n, solid, 0};
    cache->table[i] = (uint32_t)++cache->count;
    return 1;
}

size_t build_nef_cache_mark(const build_nef_cache *cache)
{
    return cache->count;
}

void build_nef_cache_publish(build_nef_cache *cache, size_t mark)
{
    for (size_t k = mark; k < cache->count; k++)
        cache->entries[k].published = 1;
}

void build_nef_cache_counts(const build_nef_cache *cache, size_t *evaluated,
                            size_t *reused)
{
    *evaluated = cache->evaluated;
    *reused = cache->reused;
}
