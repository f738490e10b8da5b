/* The render loop: camera rays, shading, buffers.
 *
 * The image (or the --region crop of it) is cut into 16 x 16 tiles handed
 * to OpenMP threads one at a time (schedule dynamic), so a thread that drew
 * cheap background tiles takes more. Every pixel sample is computed from
 * its own rays and its own random numbers, seeded by the pixel's position
 * in the full image and the sample's index (sample.h), so the buffers do
 * not depend on the thread count, the order of the tiles or the crop. Each
 * thread owns a scratch arena for the span lists of its queries, reset after
 * every pixel sample; the buffers are allocated before the loop, so the
 * loop itself never calls malloc once the arena holds its first blocks.
 *
 * Colour is the mean of the pixel's samples, each traced by shade_ray
 * (shade.h) in linear light (color.h). The AOVs (mask, depth, normal, id)
 * come from the ray through the pixel's centre alone, so they are exact
 * and the same at any sample count. Progress is reported from the thread
 * that started the render, after each tile it finishes.
 */
#include "render/render.h"

#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/arena.h"
#include "base/error.h"
#include "build/scene.h"
#include "render/camera.h"
#include "render/sample.h"
#include "render/shade.h"

void sc_render_options_init(sc_render_options *options)
{
    memset(options, 0, sizeof *options);
    options->width = 800;
    options->height = 600;
    options->camera_mode = SC_CAMERA_AUTO;
    options->fov_deg = CAM_DEFAULT_FOV;
    options->projection = SC_PROJECTION_PERSPECTIVE;
    options->threads = 0;
    options->want_color = 1;
    options->up[2] = 1;
    options->spp = 1;
    options->max_depth = 5;
}

int sc_render_options_from_scene(sc_render_options *options, const sc_scene *scene)
{
    const shading *look = scene ? scene_shading(scene) : NULL;
    if (!look || !look->has_camera)
        return 0;
    const shading_camera *c = &look->camera;
    options->camera_mode = SC_CAMERA_VECTOR;
    memcpy(options->camera, c->eye, sizeof c->eye);
    memcpy(options->camera + 3, c->center, sizeof c->center);
    memcpy(options->up, c->up, sizeof c->up);
    options->fov_deg = c->fov_deg;
    options->projection = c->projection;
    return 1;
}

typedef struct render_ctx {
    const csg_tree *tree;
    camera cam;
    shade_scene shade;
    int spp, grid_width;
    int x0, y0; /* the crop's corner in the full image */
    sc_framebuffer *fb;
} render_ctx;

/* Per-thread state and counters. */
typedef struct render_thread {
    arena scratch;
    shade_counters count;
    csg_counters csg;
    uint64_t camera_rays;
} render_thread;

static void render_pixel(const render_ctx *c, render_thread *th, int i, int j)
{
    sc_framebuffer *fb = c->fb;
    size_t p = (size_t)j * (size_t)fb->width + (size_t)i;
    int x = c->x0 + i, y = c->y0 + j; /* in the full image */
    int aovs = fb->mask || fb->depth || fb->normal || fb->id;

    /* The centre ray: the AOVs, and the colour at one sample per pixel. */
    csg_ray centre;
    csg_hit hit;
    int found = 0;
    if (aovs || c->spp == 1) {
        cam_ray(&c->cam, x, y, 0.5, 0.5, &centre.o, &centre.d);
        centre.tmin = 0;
        centre.tmax = INFINITY;
        th->camera_rays++;
        found = csg_first_hit_counted(c->tree, &centre, &th->scratch, &th->csg, &hit);
        if (fb->mask)
            fb->mask[p] = found ? 255 : 0;
        if (fb->depth)
            fb->depth[p] = found ? (float)(hit.t * v3_length(centre.d)) : INFINITY;
        if (fb->id)
            fb->id[p] = found ? (int32_t)c->tree->leaves[hit.leaf].object_id : -1;
        if (fb->normal) {
            vec3 n = found ? csg_hit_normal(c->tree, &centre, &hit) : v3(0, 0, 0);
            fb->normal[3 * p + 0] = (float)n.x;
            fb->normal[3 * p + 1] = (float)n.y;
            fb->normal[3 * p + 2] = (float)n.z;
        }
    }
    if (!fb->color) {
        arena_reset(&th->scratch);
        return;
    }
    double sum[3] = {0, 0, 0};
    for (int s = 0; s < c->spp; s++) {
        shade_thread st;
        st.scratch = &th->scratch;
        st.csg = &th->csg;
        st.rng = sample_rng_for((uint32_t)x, (uint32_t)y, (uint32_t)s);
        memset(&st.count, 0, sizeof st.count);
        double rgb[3];
        if (c->spp == 1) {
            if (found)
                shade_ray(&c->shade, &st, &centre, &hit, 0, 1.0, rgb);
            else
                memcpy(rgb, c->shade.background, sizeof rgb);
        } else {
            double sx, sy;
            sample_offset(s, c->spp, c->grid_width, &st.rng, &sx, &sy);
            csg_ray ray;
            cam_ray(&c->cam, x, y, sx, sy, &ray.o, &ray.d);
            ray.tmin = 0;
            ray.tmax = INFINITY;
            th->camera_rays++;
            shade_ray(&c->shade, &st, &ray, NULL, 0, 1.0 / c->spp, rgb);
        }
        for (int k = 0; k < 3; k++)
            sum[k] += rgb[k];
        th->count.shadow_rays += st.count.shadow_rays;
        th->count.reflection_rays += st.count.reflection_rays;
        th->count.refraction_rays += st.count.refraction_rays;
        arena_reset(&th->scratch);
    }
    for (int k = 0; k < 3; k++)
        fb->color[3 * p + k] = (float)(sum[k] / c->spp);
}

static void render_tile(const render_ctx *c, render_thread *th, int tile, int tiles_x)
{
    if (c->fb->cancel && *c->fb->cancel)
        return; /* cancelled: the remaining tiles are skipped */
    int x0 = (tile % tiles_x) * RENDER_TILE_SIZE;
    int y0 = (tile / tiles_x) * RENDER_TILE_SIZE;
    int x1 = x0 + RENDER_TILE_SIZE < c->fb->width ? x0 + RENDER_TILE_SIZE : c->fb->width;
    int y1 =
        y0 + RENDER_TILE_SIZE < c->fb->height ? y0 + RENDER_TILE_SIZE : c->fb->height;
    for (int j = y0; j < y1; j++)
        for (int i = x0; i < x1; i++)
            render_pixel(c, th, i, j);
}

void sc_framebuffer_release(sc_framebuffer *fb)
{
    if (!fb)
        return;
    free(fb->color);
    free(fb->depth);
    free(fb->mask);
    free(fb->normal);
    free(fb->id);
    free(fb);
}

/* Allocates the buffers options ask for, width x height; NULL when out of
 * memory. */
static sc_framebuffer *framebuffer_new(const sc_render_options *o, int width, int height)
{
    sc_framebuffer *fb = calloc(1, sizeof *fb);
    if (!fb)
        return NULL;
    fb->width = width;
    fb->height = height;
    fb->cancel = o->cancel;
    size_t pixels = (size_t)width * (size_t)height;
    int ok = 1;
    if (o->want_color)
        ok &= (fb->color = malloc(pixels * 3 * sizeof(float))) != NULL;
    if (o->want_depth)
        ok &= (fb->depth = malloc(pixels * sizeof(float))) != NULL;
    if (o->want_mask)
        ok &= (fb->mask = malloc(pixels)) != NULL;
    if (o->want_normal)
        ok &= (fb->normal = malloc(pixels * 3 * sizeof(float))) != NULL;
    if (o->want_id)
        ok &= (fb->id = malloc(pixels * sizeof(int32_t))) != NULL;
    if (!ok) {
        sc_framebuffer_release(fb);
        return NULL;
    }
    return fb;
}

static int has_region(const sc_render_options *o)
{
    return o->region[0] || o->region[1] || o->region[2] || o->region[3];
}

static sc_status check_options(const sc_render_options *o, sc_error *error)
{
    if (o->width <= 0 || o->height <= 0 || o->width > RENDER_MAX_SIDE ||
        o->height > RENDER_MAX_SIDE)
        return err_set(error, SC_ERR_ARGUMENT, NULL,
                       "image size %dx%d is out of range (1 to %d pixels a side)",
                       o->width, o->height, RENDER_MAX_SIDE);
    if (o->threads < 0)
        return err_set(error, SC_ERR_ARGUMENT, NULL,
                       "thread count must not be negative (got %d)", o->threads);
    if (o->spp < 1 || o->spp > RENDER_MAX_SPP)
        return err_set(error, SC_ERR_ARGUMENT, NULL,
                       "samples per pixel must be 1 to %d (got %d)", RENDER_MAX_SPP,
                       o->spp);
    if (o->max_depth < 0 || o->max_depth > SHADE_MAX_DEPTH)
        return err_set(error, SC_ERR_ARGUMENT, NULL,
                       "maximum depth must be 0 to %d (got %d)", SHADE_MAX_DEPTH,
                       o->max_depth);
    const int *r = o->region;
    if (has_region(o) && !(r[0] >= 0 && r[1] >= 0 && r[0] < r[2] && r[1] < r[3] &&
                           r[2] <= o->width && r[3] <= o->height))
        return err_set(error, SC_ERR_ARGUMENT, NULL,
                       "region %d,%d,%d,%d is not a non-empty crop of the %dx%d image",
                       r[0], r[1], r[2], r[3], o->width, o->height);
    return SC_OK;
}

static double seconds_now(void)
{
    return omp_get_wtime();
}

static void describe_camera(const camera *cam, double fov_deg, char *out, size_t size)
{
    snprintf(out, size,
             "eye %.9g,%.9g,%.9g center %.9g,%.9g,%.9g up %.9g,%.9g,%.9g fov %.9g "
             "projection %s",
             cam->eye.x, cam->eye.y, cam->eye.z, cam->center.x, cam->center.y,
             cam->center.z, cam->u.x, cam->u.y, cam->u.z, fov_deg,
             cam->projection == SC_PROJECTION_ORTHOGRAPHIC ? "orthographic"
                                                           : "perspective");
}

sc_status render_scene(const csg_tree *tree, const shading *look,
                       const sc_render_options *options, sc_framebuffer **framebuffer,
                       sc_error *error)
{
    double start = seconds_now();
    *framebuffer = NULL;
    sc_render_options defaults;
    if (!options) {
        sc_render_options_init(&defaults);
        options = &defaults;
    }
    sc_status st = check_options(options, error);
    if (st == SC_OK)
        st = render_check_memory(options, error);
    if (st)
        return st;

    render_ctx c;
    memset(&c, 0, sizeof c);
    c.tree = tree;
    c.spp = options->spp;
    c.grid_width = sample_grid_width(options->spp);
    bbox bounds = tree->root == CSG_EMPTY ? bbox_empty() : tree->bounds;
    cam_view view;
    st = cam_view_from_options(options, &bounds, &view, error);
    if (st)
        return st;
    st = cam_init(&c.cam, &view, options->fov_deg, options->projection, options->width,
                  options->height, error);
    if (st)
        return st;
    int width = options->width, height = options->height;
    if (has_region(options)) {
        c.x0 = options->region[0];
        c.y0 = options->region[1];
        width = options->region[2] - c.x0;
        height = options->region[3] - c.y0;
    }
    c.fb = framebuffer_new(options, width, height);
    if (!c.fb)
        return err_set(error, SC_ERR_NOMEM, NULL, "out of memory for a %dx%d image",
                       width, height);
    c.fb->x0 = c.x0;
    c.fb->y0 = c.y0;
    describe_camera(&c.cam, options->fov_deg, c.fb->camera_info,
                    sizeof c.fb->camera_info);
    st = shade_prepare(&c.shade, tree, look, &c.cam, options->max_depth, error);
    if (st) {
        sc_framebuffer_release(c.fb);
        return st;
    }

    int threads = options->threads > 0 ? options->threads : omp_get_max_threads();
    int tiles_x = (width + RENDER_TILE_SIZE - 1) / RENDER_TILE_SIZE;
    int tiles_y = (height + RENDER_TILE_SIZE - 1) / RENDER_TILE_SIZE;
    int tiles = tiles_x * tiles_y; /* at most 2048 * 2048 */
    int done = 0;
    sc_render_stats *stats = &c.fb->stats;
    stats->threads = threads;
    double traced = seconds_now();
    stats->setup_seconds = traced - start;

    int out_of_memory = 0; /* a thread could not get its scratch arena */
#pragma omp parallel num_threads(threads)
    {
        render_thread th;
        memset(&th, 0, sizeof th);
        arena_init(&th.scratch, 0);
        /* Take the first block now rather than inside the loop. */
        int ready = arena_alloc(&th.scratch, 1) != NULL;
        arena_reset(&th.scratch);
        if (!ready) {
#pragma omp atomic write
            out_of_memory = 1;
        }
        int reporter = omp_get_thread_num() == 0 && options->progress;
#pragma omp for schedule(dynamic, 1)
        for (int tile = 0; tile < tiles; tile++) {
            if (ready)
                render_tile(&c, &th, tile, tiles_x);
            int now;
#pragma omp atomic capture
            now = ++done;
            if (reporter)
                options->progress(options->progress_user, (double)now / tiles);
        }
#pragma omp critical(render_stats)
        {
            stats->camera_rays += th.camera_rays;
            stats->shadow_rays += th.count.shadow_rays;
            stats->reflection_rays += th.count.reflection_rays;
            stats->refraction_rays += th.count.refraction_rays;
            stats->primitive_tests += th.csg.prim_tests;
            stats->span_operations += th.csg.span_ops;
            stats->node_visits += th.csg.nodes;
            stats->bvh_node_visits += th.csg.bvh_nodes;
            stats->scratch_mallocs += th.scratch.block_allocs;
        }
        arena_free(&th.scratch);
    }
    if (options->progress)
        options->progress(options->progress_user, 1.0);
    shade_release(&c.shade);
    stats->trace_seconds = seconds_now() - traced;
    if (out_of_memory) {
        sc_framebuffer_release(c.fb);
        return err_nomem(error, NULL);
    }
    if (options->cancel && *options->cancel) {
        sc_framebuffer_release(c.fb);
        return err_set(error, SC_ERR_CANCELLED, NULL, "interrupted");
    }
    *framebuffer = c.fb;
    return SC_OK;
}

sc_status render_tree(const csg_tree *tree, const sc_render_options *options,
                      sc_framebuffer **framebuffer, sc_error *error)
{
    return render_scene(tree, NULL, options, framebuffer, error);
}

sc_status sc_render(const sc_scene *scene, const sc_render_options *options,
                    sc_framebuffer **framebuffer, sc_error *error)
{
    if (framebuffer)
        *framebuffer = NULL;
    if (!scene || !framebuffer)
        return err_set(error, SC_ERR_ARGUMENT, NULL,
                       "sc_render needs a scene and a framebuffer pointer");
    return render_scene(scene_tree(scene), scene_shading(scene), options, framebuffer,
                        error);
}
