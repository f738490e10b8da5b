/* Interference between the top-level objects of a model (sc_objects_*):
 * which pairs share interior, how much, and where.
 *
 * The objects are found in the typed model (model.h), lowered once: the
 * nodes at the top of the file, or, when there is only one, the children
 * of the grouping node it is (a module call exports as one group(), a
 * translated assembly as one multmatrix), descending while such a node has
 * a single child. Each object becomes a scene of its own, built from the
 * whole model with every other object disabled (MODEL_MOD_DISABLE), as the
 * '*' modifier would: the transforms, colours and $fn above it stay what
 * they are in the model.
 *
 * The overlap of a pair is the volume of A intersect B, integrated like
 * the measures (quad.h) over the box the two objects' boxes share: along
 * each line both span lists are intersected by the boolean sweep with its
 * regularisation (span.h), so solids that only touch within the scene
 * tolerance leave nothing, and the overlap is exact per line.
 */
#define _POSIX_C_SOURCE 200809L /* strdup */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "api/lines.h"
#include "api/mesh_model.h"
#include "api/quad.h"
#include "base/arena.h"
#include "api/options.h"
#include "base/error.h"
#include "build/build.h"
#include "build/scene.h"
#include "csg/csg.h"
#include "csg/span.h"
#include "render/render.h"
#include "formats/file.h"
#include "model/model.h"
#include "syntax/parse.h"

struct sc_objects {
    char *path;         /* the file name every location points to */
    parse_tree *syntax; /* owns the names the model's nodes point to */
    model *typed;       /* lowered once; each object's build disables the others */
    int root_marked;    /* the lowering marked a '!' node in the model */
    size_t count;
    model_node **nodes;
    sc_scene **scenes;
};

/* A node that unions its children and may stand for a group of objects
 * (group, union, render, color, multmatrix). */
static int is_grouping(const model_node *n)
{
    return n->kind == MODEL_UNION || n->kind == MODEL_COLOR || n->kind == MODEL_XFORM;
}

/* A node that is part of the solid (not disabled, not background). */
static int counts(const model_node *n)
{
    return !(n->modifiers & (MODEL_MOD_DISABLE | MODEL_MOD_BACKGROUND));
}

static size_t counted(const model_node *first)
{
    size_t n = 0;
    for (const model_node *c = first; c; c = c->next)
        n += counts(c);
    return n;
}

static model_node *only_counted(model_node *first)
{
    for (model_node *c = first; c; c = c->next)
        if (counts(c))
            return c;
    return NULL;
}

void sc_objects_release(sc_objects *objects)
{
    if (!objects)
        return;
    for (size_t k = 0; k < objects->count; k++)
        sc_scene_release(objects->scenes ? objects->scenes[k] : NULL);
    free(objects->scenes);
    free(objects->nodes);
    model_free(objects->typed);
    parse_tree_free(objects->syntax);
    free(objects->path);
    free(objects);
}

/* Clears the '!' marks from first and its siblings and their subtrees
 * (*marked says whether there was one), and returns the node the lowering
 * would choose as the design's root now (lower.c's find_root): the first
 * with '!' in file order outside the disabled subtrees, entering the nodes
 * whose children the builder walks. The recursion is as deep as the
 * model, which the parser bounds (PARSE_MAX_DEPTH). */
static model_node *clear_roots(model_node *first, int enabled, int *marked)
{
    model_node *found = NULL;
    for (model_node *n = first; n; n = n->next) {
        int on = enabled && !(n->modifiers & MODEL_MOD_DISABLE);
        *marked |= n->is_root;
        n->is_root = 0;
        if (on && !found && (n->modifiers & MODEL_MOD_ROOT))
            found = n;
        if (!model_is_leaf(n->kind)) {
            model_node *inner = clear_roots(n->first_child, on, marked);
            if (!found)
                found = inner;
        }
    }
    return found;
}

/* Marks the design's root for the objects enabled now: a '!' inside a
 * disabled object is not the design's, as when the lowering skips a '*'
 * subtree. A '!' the lowering found but did not mark (below a node whose
 * children are not lowered) stays the design's root as lowered. */
static void choose_root(sc_objects *o)
{
    if (!o->root_marked)
        return;
    int marked = 0;
    model_node *root = clear_roots(o->typed->first, 1, &marked);
    if (root)
        root->is_root = 1;
    o->typed->has_root = root != NULL;
}

/* Builds object k alone: every other object disabled for the build, as
 * the '*' modifier would disable it. */
static sc_status build_object(sc_objects *o, size_t k, int flags, size_t max_triangles,
                              sc_error *error)
{
    unsigned *saved = malloc(o->count * sizeof *saved);
    if (!saved)
        return err_nomem(error, NULL);
    for (size_t j = 0; j < o->count; j++) {
        saved[j] = o->nodes[j]->modifiers;
        if (j != k)
            o->nodes[j]->modifiers |= MODEL_MOD_DISABLE;
    }
    choose_root(o);
    sc_scene *s = calloc(1, sizeof *s);
    sc_status st = SC_OK;
    if (!s || !(s->path = strdup(o->path)))
        st = err_nomem(error, NULL);
    else
        st = build_scene(o->typed, flags, max_triangles, &s->tree, &s->look, &s->warnings,
                         &s->warning_count, error);
    for (size_t j = 0; j < o->count; j++)
        o->nodes[j]->modifiers = saved[j];
    free(saved);
    if (st) {
        sc_scene_release(s);
        return st;
    }
    o->scenes[k] = s;
    return SC_OK;
}

/* The objects of length bytes of text named path; mesh: the text is the
 * one-line import of the mesh file path (its errors are put back on the
 * mesh file). */
static sc_status load_text(const char *path, const char *text, size_t length, int mesh,
                           const sc_load_options *options, sc_objects **out,
                           sc_error *error)
{
    sc_load_options lo;
    sc_status st = options_load(options, &lo, error);
    if (st != SC_OK)
        return st;
    sc_objects *o = calloc(1, sizeof *o);
    if (!o || !(o->path = strdup(path))) {
        free(o);
        return err_nomem(error, NULL);
    }
    st = parse_text(o->path, text, length, &o->syntax, error);
    if (st == SC_OK)
        st = model_lower(o->syntax, &o->typed, error);
    if (st) {
        if (mesh)
            mesh_model_unplace(error, path);
        sc_objects_release(o);
        return st;
    }
    if (o->typed->has_root) {
        model_node *root = clear_roots(o->typed->first, 1, &o->root_marked);
        if (root && o->root_marked)
            root->is_root = 1; /* the lowering's choice, found again */
    }
    model_node *first = o->typed->first;
    while (counted(first) == 1) {
        model_node *n = only_counted(first);
        if (!is_grouping(n) || !n->first_child)
            break;
        first = n->first_child;
    }
    size_t count = counted(first);
    o->nodes = calloc(count ? count : 1, sizeof *o->nodes);
    o->scenes = calloc(count ? count : 1, sizeof *o->scenes);
    if (!o->nodes || !o->scenes) {
        sc_objects_release(o);
        return err_nomem(error, NULL);
    }
    for (model_node *c = first; c; c = c->next)
        if (counts(c))
            o->nodes[o->count++] = c;
    int threads = options_threads_begin(lo.threads);
    for (size_t k = 0; k < o->count && st == SC_OK; k++)
        st = build_object(o, k, options_build_flags(&lo) | (mesh ? BUILD_MESH_MODEL : 0),
                          lo.max_triangles, error);
    options_threads_end(threads);
    if (st) {
        if (mesh)
            mesh_model_unplace(error, path);
        sc_objects_release(o);
        return st;
    }
    *out = o;
    return SC_OK;
}

/* The checks both loads start with. */
static sc_status check_load(const char *name, sc_objects **out, sc_error *error)
{
    err_clear(error);
    if (!out)
        return err_set(error, SC_ERR_ARGUMENT, NULL, "no result pointer");
    *out = NULL;
    if (!name)
        return err_set(error, SC_ERR_ARGUMENT, NULL, "no file name");
    return SC_OK;
}

sc_status sc_objects_load(const char *path, const sc_load_options *options,
                          sc_objects **out, sc_error *error)
{
    sc_status st = check_load(path, out, error);
    if (st != SC_OK)
        return st;
    const char *why = NULL;
    size_t length = 0;
    char *text = NULL;
    int mesh = mesh_model_is_mesh(path);
    if (mesh) { /* one object: the model that imports it */
        if ((st = mesh_model_text(path, &text, &length, error)) != SC_OK)
            return st;
    } else if (!(text = file_read(path, (size_t)1 << 31, &length, &why))) {
        return err_set(error, SC_ERR_IO, NULL, "cannot read '%s': %s", path, why);
    }
    st = load_text(path, text, length, mesh, options, out, error);
    free(text);
    return st;
}

sc_status sc_objects_load_string(const char *name, const char *text, size_t length,
                                 const sc_load_options *options, sc_objects **out,
                                 sc_error *error)
{
    sc_status st = check_load(name, out, error);
    if (st != SC_OK)
        return st;
    if (!text && length)
        return err_set(error, SC_ERR_ARGUMENT, NULL, "no text");
    return load_text(name, text ? text : "", length, 0, options, out, error);
}

size_t sc_objects_count(const sc_objects *objects)
{
    return objects ? objects->count : 0;
}

const sc_scene *sc_objects_scene(const sc_objects *objects, size_t index)
{
    return objects && index < objects->count ? objects->scenes[index] : NULL;
}

sc_location sc_objects_location(const sc_objects *objects, size_t index)
{
    sc_location none = {NULL, 0, 0};
    return objects && index < objects->count ? objects->nodes[index]->loc : none;
}

const char *sc_objects_name(const sc_objects *objects, size_t index)
{
    return objects && index < objects->count ? objects->nodes[index]->name : NULL;
}

/* ---- the overlap of a pair ---- */

typedef struct pair_shared {
    const csg_tree *a, *b;
    lines_scratch work; /* per thread: spans, and the box of the common ones */
} pair_shared;

static int sample_pair(void *context, int thread, double u, double v, double *values,
                       uint64_t *signature)
{
    const lines_axis *m = context;
    const pair_shared *s = m->shared;
    int a = m->axis;
    arena *scratch = &s->work.arenas[thread];
    csg_ray r;
    span_list sa, sb;
    double eps;
    if (!lines_pair_spans(a, u, v, s->a, s->b, scratch, &r, &sa, &sb, &eps))
        return 0;
    int oom = 0;
    span_list both = span_combine(SPAN_INTERSECTION, sa, sb, eps, scratch, &oom);
    if (oom)
        return 0;
    *signature = lines_signature(0, both);
    double length = 0;
    double *box = s->work.box[thread];
    for (uint32_t k = 0; k < both.n; k++) {
        double t0 = both.v[k].in.t, t1 = both.v[k].out.t;
        if (!isfinite(t0) || !isfinite(t1))
            return 0;
        length += t1 - t0;
        for (int e = 0; e < 2; e++) {
            double p[3] = {r.o.x, r.o.y, r.o.z};
            p[a] = e ? t1 : t0;
            for (int i = 0; i < 3; i++) {
                box[i] = fmin(box[i], p[i]);
                box[3 + i] = fmax(box[3 + i], p[i]);
            }
        }
    }
    values[0] = length;
    return 1;
}

/* The overlap of trees a and b within the box lo..hi into *out; *found is
 * 0 when they share no volume. SC_ERR_LIMIT comes with error filled at
 * the leaf that passed the limit. */
static sc_status overlap_pair(const csg_tree *ta, const csg_tree *tb, const double lo[3],
                              const double hi[3], const sc_measure_options *options,
                              int threads, sc_overlap *out, int *found, sc_error *error)
{
    pair_shared shared = {ta, tb, {0}};
    if (!lines_scratch_init(&shared.work, threads, 1))
        return SC_ERR_NOMEM;
    lines_axis axes[3];
    void *contexts[3];
    lines_axes(axes, &shared, contexts);
    int rule[1] = {QUAD_EACH};
    double floor[1] = {1e-6 * (hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2])};
    quad_grid grids[3];
    int converged;
    sc_measure_options o = *options;
    o.threads = threads;
    o.progress = NULL;
    sc_status st = quad_integrate3(lo, hi, 1, 1, rule, floor, sample_pair, contexts, &o,
                                   grids, &converged);
    *found = 0;
    if (st == SC_OK) {
        out->volume = quad_combine(grids, 0);
        double seen[6];
        if (!lines_scratch_box(&shared.work, &o, seen))
            st = SC_ERR_NOMEM; /* the exchange with the other processes failed */
        *found = out->volume.value > 0 && seen[0] <= seen[3];
        out->converged = converged;
        for (int i = 0; i < 3; i++) {
            out->box_lo[i] = *found ? seen[i] : 0;
            out->box_hi[i] = *found ? seen[3 + i] : 0;
        }
    }
    if (st == SC_ERR_ARGUMENT && (grids[0].failed || grids[1].failed || grids[2].failed))
        st = SC_ERR_NOMEM; /* bounded trees: the sampler fails only for memory */
    if (st == SC_ERR_LIMIT)
        quad_limit_error(grids, ta, tb, error);
    for (int a = 0; a < 3; a++)
        quad_free(&grids[a]);
    lines_scratch_free(&shared.work);
    return st;
}

/* sc_objects_overlaps with the library's own options: the pairs into
 * *pairs (malloc'd; NULL when none) and *count. */
static sc_status find_overlaps(const sc_objects *objects,
                               const sc_measure_options *options, sc_overlap **pairs,
                               size_t *count, sc_error *error)
{
    err_clear(error);
    *pairs = NULL;
    *count = 0;
    if (!objects || !options)
        return err_set(error, SC_ERR_ARGUMENT, NULL, "no objects or no options");
    if (!(options->tolerance > 0 && options->tolerance < 1))
        return err_set(error, SC_ERR_ARGUMENT, NULL,
                       "tolerance must lie between 0 and 1 (got %g)", options->tolerance);
    int threads = options_thread_count(options->threads);
    size_t n = objects->count, cap = 0, total = n * (n - (n > 0)) / 2, done = 0;
    sc_overlap *list = NULL;
    for (size_t i = 0; i < n; i++)
        for (size_t j = i + 1; j < n; j++, done++) {
            if (options->progress && total)
                options->progress(options->progress_user, (double)done / (double)total);
            const csg_tree *ta = scene_tree(objects->scenes[i]);
            const csg_tree *tb = scene_tree(objects->scenes[j]);
            if (ta->root == CSG_EMPTY || tb->root == CSG_EMPTY)
                continue;
            double lo[3] = {fmax(ta->bounds.lo.x, tb->bounds.lo.x),
                            fmax(ta->bounds.lo.y, tb->bounds.lo.y),
                            fmax(ta->bounds.lo.z, tb->bounds.lo.z)};
            double hi[3] = {fmin(ta->bounds.hi.x, tb->bounds.hi.x),
                            fmin(ta->bounds.hi.y, tb->bounds.hi.y),
                            fmin(ta->bounds.hi.z, tb->bounds.hi.z)};
            /* Boxes that do not share a volume larger than the tolerance of
             * the scenes cannot hold an overlap. */
            double eps = 1e-9 * fmax(ta->scale, tb->scale);
            int thin = 0;
            for (int k = 0; k < 3; k++) {
                if (!isfinite(lo[k]) || !isfinite(hi[k])) {
                    free(list);
                    *count = 0;
                    return err_set(error, SC_ERR_ARGUMENT, NULL,
                                   "object %zu or %zu is unbounded", i + 1, j + 1);
                }
                thin |= !(hi[k] - lo[k] > eps);
            }
            if (thin)
                continue;
            sc_overlap pair;
            memset(&pair, 0, sizeof pair);
            int found = 0;
            sc_status st =
                overlap_pair(ta, tb, lo, hi, options, threads, &pair, &found, error);
            if (st) {
                free(list);
                *count = 0;
                if (st == SC_ERR_CANCELLED)
                    return err_set(error, st, NULL, "overlap search cancelled");
                if (st == SC_ERR_LIMIT)
                    return st;
                return err_nomem(error, NULL);
            }
            if (!found)
                continue;
            pair.a = i;
            pair.b = j;
            if (*count == cap) {
                cap = cap ? cap * 2 : 8;
                sc_overlap *p = realloc(list, cap * sizeof *p);
                if (!p) {
                    free(list);
                    *count = 0;
                    return err_nomem(error, NULL);
                }
                list = p;
            }
            list[(*count)++] = pair;
        }
    if (options->progress)
        options->progress(options->progress_user, 1);
    *pairs = list;
    return SC_OK;
}

struct sc_overlap_list {
    sc_overlap *pairs;
    size_t count;
};

sc_status sc_objects_overlaps(const sc_objects *objects,
                              const sc_measure_options *options, sc_overlap_list **out,
                              sc_error *error)
{
    err_clear(error);
    if (!out)
        return err_set(error, SC_ERR_ARGUMENT, NULL, "no result pointer");
    *out = NULL;
    if (!objects || !options)
        return err_set(error, SC_ERR_ARGUMENT, NULL, "no objects or no options");
    sc_measure_options o;
    sc_status st = options_measure(options, &o, error);
    if (st != SC_OK)
        return st;
    sc_overlap_list *list = calloc(1, sizeof *list);
    if (!list)
        return err_nomem(error, NULL);
    st = find_overlaps(objects, &o, &list->pairs, &list->count, error);
    if (st != SC_OK) {
        sc_overlap_list_release(list);
        return st;
    }
    *out = list;
    return SC_OK;
}

size_t sc_overlap_list_count(const sc_overlap_list *list)
{
    return list ? list->count : 0;
}

const sc_overlap *sc_overlap_list_get(const sc_overlap_list *list, size_t index)
{
    return list && index < list->count ? &list->pairs[index] : NULL;
}

void sc_overlap_list_release(sc_overlap_list *list)
{
    if (!list)
        return;
    free(list->pairs);
    free(list);
}
