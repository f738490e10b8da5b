/* Queries on a loaded scene: the spans along a line, the camera ray of a
 * pixel, and point membership (the sc_scene_spans, sc_scene_pixel_ray and
 * sc_scene_inside calls of spancast.h).
 *
 * They are thin: each runs the tree's ALL_SPANS query (csg_spans) with a
 * scratch arena of its own, so a scene can be queried from several threads
 * at once, and turns its span ends into what a user can read: the leaf's
 * source-order id, kind and position, the outward normal of the resulting
 * solid (csg_hit_normal, which applies the flip of subtracted surfaces) and
 * the point. The pixel ray is the renderer's own (render/camera.h), built
 * by the same two calls sc_render makes, so `spans --pixel` and the depth
 * AOV can never drift apart.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "api/options.h"
#include "base/arena.h"
#include "base/cancel.h"
#include "base/error.h"
#include "base/sized.h"
#include "build/scene.h"
#include "csg/csg.h"
#include "render/camera.h"
#include "render/render.h"

struct sc_span_list {
    size_t count;
    sc_span spans[]; /* count of them */
};

void sc_ray_query_init_size(sc_ray_query *query, size_t size)
{
    if (query && size >= sizeof query->size)
        sized_clear(query, size);
}

static int finite3(const double v[3])
{
    return isfinite(v[0]) && isfinite(v[1]) && isfinite(v[2]);
}

/* Fills *out from a span end of ray r. */
static void describe_end(const csg_tree *t, const csg_ray *r, const span_end *e,
                         sc_span_end *out)
{
    memset(out, 0, sizeof *out);
    out->t = e->t;
    out->leaf = -1;
    if (isfinite(e->t)) {
        vec3 p = v3_madd(r->o, r->d, e->t);
        out->point[0] = p.x;
        out->point[1] = p.y;
        out->point[2] = p.z;
    }
    if (e->leaf == SPAN_NO_LEAF || e->leaf >= t->leaf_count || !isfinite(e->t))
        return;
    const csg_leaf *l = &t->leaves[e->leaf];
    out->leaf = (int)l->object_id;
    out->leaf_kind = sc_leaf_kind_name((int)l->prim.kind);
    out->location = l->loc;
    out->subtracted = e->flip != 0;
    csg_hit hit = {e->t, e->leaf, e->part, e->flip, 0};
    vec3 n = csg_hit_normal(t, r, &hit);
    /* + 0.0 turns a negated zero into +0, so that (1, -0, -0) reads (1, 0, 0). */
    out->normal[0] = n.x + 0.0;
    out->normal[1] = n.y + 0.0;
    out->normal[2] = n.z + 0.0;
}

/* The tree's spans along r, from a fresh scratch arena: the caller frees
 * it on success, this frees it on failure. The query runs in a cancel token of its own,
 * without a flag or a budget, only to learn whether an implicit leaf gave up on the line
 * at the root finder's bound (SOLVE_MAX_EVALS): its spans would then be cut short, so
 * that is SC_ERR_LIMIT at the leaf rather than a silently truncated answer. Also
 * SC_ERR_NOMEM. */
static sc_status line_spans(const csg_tree *t, const csg_ray *r, arena *scratch,
                            span_list *out, sc_error *error)
{
    arena_init(scratch, 16 * 1024);
    cancel_token token;
    cancel_init(&token, NULL, 0);
    cancel_scope scope;
    cancel_enter(&scope, &token);
    int ok = csg_spans(t, r, scratch, out);
    cancel_leave(&scope);
    cancel_reason reason = cancel_check(&token);
    sc_status st = SC_OK;
    if (reason != CANCEL_NONE)
        st = render_limit_error(t, (int)reason, atomic_load(&token.leaf),
                                atomic_load(&token.prim), error);
    else if (!ok)
        st = err_nomem(error, NULL);
    if (st != SC_OK)
        arena_free(scratch);
    return st;
}

sc_status sc_scene_spans(const sc_scene *scene, const sc_ray_query *query,
                         sc_span_list **out, sc_error *error)
{
    err_clear(error);
    if (!out)
        return err_set(error, SC_ERR_ARGUMENT, NULL, "no result pointer");
    *out = NULL;
    if (!scene || !query)
        return err_set(error, SC_ERR_ARGUMENT, NULL, "no scene or no query");
    sc_ray_query own;
    sc_status st0 = options_ray_query(query, &own, error);
    if (st0 != SC_OK)
        return st0;
    query = &own;
    if (!finite3(query->origin) || !finite3(query->direction))
        return err_set(error, SC_ERR_ARGUMENT, NULL, "ray values must be finite");
    const csg_tree *t = scene_tree(scene);
    csg_ray r;
    r.o = v3(query->origin[0], query->origin[1], query->origin[2]);
    r.d = v3(query->direction[0], query->direction[1], query->direction[2]);
    double len = v3_length(r.d);
    if (!(len > 0) || !isfinite(len))
        return err_set(error, SC_ERR_ARGUMENT, NULL, "ray direction must not be zero");
    r.tmin = query->both_ways ? -INFINITY : 0;
    r.tmax = INFINITY;
    arena scratch;
    span_list spans;
    sc_status st = line_spans(t, &r, &scratch, &spans, error);
    if (st != SC_OK)
        return st;
    sc_span_list *list = malloc(sizeof *list + (size_t)spans.n * sizeof list->spans[0]);
    if (!list) {
        arena_free(&scratch);
        return err_nomem(error, NULL);
    }
    list->count = spans.n;
    for (uint32_t k = 0; k < spans.n; k++) {
        sc_span *s = &list->spans[k];
        describe_end(t, &r, &spans.v[k].in, &s->in);
        describe_end(t, &r, &spans.v[k].out, &s->out);
        s->distance = (s->out.t - s->in.t) * len;
    }
    arena_free(&scratch);
    *out = list;
    return SC_OK;
}

size_t sc_span_list_count(const sc_span_list *list)
{
    return list ? list->count : 0;
}

const sc_span *sc_span_list_get(const sc_span_list *list, size_t index)
{
    return list && index < list->count ? &list->spans[index] : NULL;
}

void sc_span_list_release(sc_span_list *list)
{
    free(list);
}

sc_status sc_scene_pixel_ray(const sc_scene *scene, const sc_render_options *options,
                             int i, int j, double origin[3], double direction[3],
                             sc_error *error)
{
    err_clear(error);
    if (!scene || !options || !origin || !direction)
        return err_set(error, SC_ERR_ARGUMENT, NULL, "no scene, options or result");
    sc_render_options own;
    render_options_defaults(&own);
    sc_status st0 =
        sized_read(&own, sizeof own, options, SIZED_MIN(sc_render_options, sheet),
                   "sc_render_options", error);
    if (st0 != SC_OK)
        return st0;
    options = &own;
    const csg_tree *t = scene_tree(scene);
    /* The bounds and the two calls of sc_render (render.c) */
    bbox bounds;
    sc_status st = render_frame_bounds(t, scene_shading(scene), options, &bounds, error);
    if (st)
        return st;
    cam_view view;
    st = cam_view_from_options(options, &bounds, &view, error);
    if (st)
        return st;
    camera cam;
    st = cam_init(&cam, &view, options->fov_deg, options->projection, options->width,
                  options->height, error);
    if (st)
        return st;
    if (i < 0 || j < 0 || i >= options->width || j >= options->height)
        return err_set(error, SC_ERR_ARGUMENT, NULL,
                       "pixel %d,%d is outside the %dx%d image", i, j, options->width,
                       options->height);
    vec3 o, d;
    cam_ray(&cam, i, j, 0.5, 0.5, &o, &d);
    origin[0] = o.x;
    origin[1] = o.y;
    origin[2] = o.z;
    direction[0] = d.x;
    direction[1] = d.y;
    direction[2] = d.z;
    return SC_OK;
}

int sc_scene_frame_bounds(const sc_scene *scene, const sc_render_options *options,
                          double lo[3], double hi[3])
{
    for (int k = 0; k < 3; k++)
        lo[k] = hi[k] = 0;
    sc_render_options own;
    render_options_defaults(&own);
    sc_error error;
    bbox box;
    if (!scene ||
        (options &&
         sized_read(&own, sizeof own, options, SIZED_MIN(sc_render_options, sheet),
                    "sc_render_options", &error) != SC_OK) ||
        render_frame_bounds(scene_tree(scene), scene_shading(scene), &own, &box,
                            &error) != SC_OK ||
        bbox_is_empty(&box))
        return 0;
    lo[0] = box.lo.x, lo[1] = box.lo.y, lo[2] = box.lo.z;
    hi[0] = box.hi.x, hi[1] = box.hi.y, hi[2] = box.hi.z;
    return 1;
}

sc_status sc_scene_inside(const sc_scene *scene, const double p[3], int *where,
                          sc_error *error)
{
    err_clear(error);
    *where = SC_OUTSIDE;
    if (!scene || !p)
        return err_set(error, SC_ERR_ARGUMENT, NULL, "no scene or no point");
    if (!finite3(p))
        return err_set(error, SC_ERR_ARGUMENT, NULL, "point coordinates must be finite");
    const csg_tree *t = scene_tree(scene);
    /* The three axes vote, and any of them finds p on the surface when a
     * span ends there. A point on an edge or a corner of a mesh (or of a
     * polygon's extrusion) has each axis line in a face's plane or along
     * an edge, where the mesh breaks the tie as a miss: then four oblique
     * lines, whose directions and their opposites cover the eight
     * octants, so that one of them crosses into every right-angled edge
     * and corner through p, say whether a span ends at p. */
    static const double oblique[4][3] = {{0.61923, 0.43762, 0.65189},
                                         {0.61923, -0.43762, 0.65189},
                                         {0.61923, 0.43762, -0.65189},
                                         {-0.61923, 0.43762, 0.65189}};
    int votes = 0;
    for (int line = 0; line < 7; line++) {
        csg_ray r;
        r.o = v3(p[0], p[1], p[2]);
        r.d = line < 3
                  ? v3(line == 0, line == 1, line == 2)
                  : v3(oblique[line - 3][0], oblique[line - 3][1], oblique[line - 3][2]);
        r.tmin = -INFINITY; /* the whole line: no clipped ends near p */
        r.tmax = INFINITY;
        double eps = csg_eps(t, r.o, r.d);
        arena scratch;
        span_list spans;
        sc_status st = line_spans(t, &r, &scratch, &spans, error);
        if (st != SC_OK)
            return st;
        int on = 0, in = 0;
        for (uint32_t k = 0; k < spans.n; k++) {
            const span *s = &spans.v[k];
            if ((s->in.leaf != SPAN_NO_LEAF && fabs(s->in.t) <= eps) ||
                (s->out.leaf != SPAN_NO_LEAF && fabs(s->out.t) <= eps))
                on = 1;
            if (s->in.t < 0 && s->out.t > 0)
                in = 1;
        }
        arena_free(&scratch);
        if (on) {
            *where = SC_ON;
            return SC_OK;
        }
        votes += line < 3 && in;
    }
    *where = votes >= 2 ? SC_INSIDE : SC_OUTSIDE;
    return SC_OK;
}
