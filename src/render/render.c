/* The render loop: camera rays, first-hit queries, shading, buffers.
 *
 * The image is cut into 16 x 16 tiles handed to OpenMP threads one at a
 * time (schedule dynamic), so a thread that drew cheap background tiles takes
 * more. Every pixel is computed from its own ray alone, so the buffers do not
 * depend on the thread count or the order of the tiles. Each thread owns a
 * scratch arena for the span lists of its queries, reset after every pixel
 * sample; the buffers are allocated before the loop, so the loop itself
 * never calls malloc once the arena holds its first block.
 *
 * Shading is Blinn-Phong under a fixed rig of two directional lights and
 * ambient light, all relative to the camera (a key light from the upper left
 * and towards the viewer, a weaker fill from the lower right), so every view
 * is lit; there are no shadows yet. Surfaces are two-sided: a hit whose
 * outward normal faces away from the viewer (the ray started inside the
 * solid) is shaded with the reversed normal. Colours are display values
 * (sRGB-encoded, as OpenSCAD's colours are): lighting multiplies them
 * directly, like fixed-function OpenGL, and they are written to 8-bit files
 * without a transfer curve. The colour buffer therefore holds display values,
 * not scene-linear light.
 */
#include "render/render.h"

#include <math.h>
#include <omp.h>
#include <stdlib.h>
#include <string.h>

#include "base/arena.h"
#include "base/error.h"
#include "render/camera.h"
#include "scene/scene.h"

/* The light rig, as directions towards the lights in camera coordinates
 * (right, up, towards the viewer) and intensities. */
static const double key_light[3] = {-0.5, 0.6, 0.8};
static const double fill_light[3] = {0.6, -0.3, 0.7};
static const double key_intensity = 0.65;
static const double fill_intensity = 0.25;
static const double ambient = 0.25;
static const double specular = 0.2; /* white highlight of the key light */
static const double shininess = 40.0;

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
}

typedef struct render_ctx {
    const csg_tree *tree;
    camera cam;
    vec3 key_dir, fill_dir; /* unit world directions towards the lights */
    sc_framebuffer *fb;
} render_ctx;

static vec3 camera_to_world(const camera *cam, const double c[3])
{
    vec3 w = v3_scale(cam->r, c[0]);
    w = v3_madd(w, cam->u, c[1]);
    w = v3_madd(w, cam->f, -c[2]);
    return v3_normalize(w);
}

static float clamp01(double v)
{
    return v <= 0 ? 0.0f : v >= 1 ? 1.0f : (float)v;
}

/* Blinn-Phong of base under the rig; n is the shading normal (facing the
 * viewer), view the unit direction towards the viewer. */
static void shade(const render_ctx *c, const float base[4], vec3 n, vec3 view,
                  float out[3])
{
    double diffuse = ambient + key_intensity * fmax(0.0, v3_dot(n, c->key_dir)) +
                     fill_intensity * fmax(0.0, v3_dot(n, c->fill_dir));
    double highlight = 0;
    if (v3_dot(n, c->key_dir) > 0) {
        vec3 h = v3_normalize(v3_add(c->key_dir, view));
        highlight = specular * pow(fmax(0.0, v3_dot(n, h)), shininess);
    }
    for (int k = 0; k < 3; k++)
        out[k] = clamp01(base[k] * diffuse + highlight);
}

static void render_pixel(const render_ctx *c, arena *scratch, int i, int j)
{
    sc_framebuffer *fb = c->fb;
    size_t p = (size_t)j * (size_t)fb->width + (size_t)i;
    csg_ray ray;
    cam_ray(&c->cam, i, j, 0.5, 0.5, &ray.o, &ray.d);
    ray.tmin = 0;
    ray.tmax = INFINITY;
    csg_hit hit;
    int found = csg_first_hit(c->tree, &ray, scratch, &hit);

    if (fb->mask)
        fb->mask[p] = found ? 255 : 0;
    if (fb->depth)
        fb->depth[p] = found ? (float)(hit.t * v3_length(ray.d)) : INFINITY;
    if (!found) {
        if (fb->color) {
            fb->color[3 * p + 0] = RENDER_BACKGROUND_R;
            fb->color[3 * p + 1] = RENDER_BACKGROUND_G;
            fb->color[3 * p + 2] = RENDER_BACKGROUND_B;
        }
        if (fb->normal)
            fb->normal[3 * p + 0] = fb->normal[3 * p + 1] = fb->normal[3 * p + 2] = 0;
        return;
    }
    if (!fb->color && !fb->normal)
        return;
    vec3 n = csg_hit_normal(c->tree, &ray, &hit);
    if (fb->normal) {
        fb->normal[3 * p + 0] = (float)n.x;
        fb->normal[3 * p + 1] = (float)n.y;
        fb->normal[3 * p + 2] = (float)n.z;
    }
    if (fb->color) {
        vec3 view = v3_normalize(v3_neg(ray.d));
        if (v3_dot(n, view) < 0) /* seen from inside the solid */
            n = v3_neg(n);
        shade(c, c->tree->leaves[hit.leaf].color, n, view, &fb->color[3 * p]);
    }
}

static void render_tile(const render_ctx *c, arena *scratch, int tile, int tiles_x)
{
    if (c->fb->cancel && *c->fb->cancel)
        return; /* cancelled: the remaining tiles are skipped */
    int x0 = (tile % tiles_x) * RENDER_TILE_SIZE;
    int y0 = (tile / tiles_x) * RENDER_TILE_SIZE;
    int x1 = x0 + RENDER_TILE_SIZE < c->fb->width ? x0 + RENDER_TILE_SIZE : c->fb->width;
    int y1 =
        y0 + RENDER_TILE_SIZE < c->fb->height ? y0 + RENDER_TILE_SIZE : c->fb->height;
    for (int j = y0; j < y1; j++) {
        for (int i = x0; i < x1; i++) {
            render_pixel(c, scratch, i, j);
            arena_reset(scratch);
        }
    }
}

void sc_framebuffer_release(sc_framebuffer *fb)
{
    if (!fb)
        return;
    free(fb->color);
    free(fb->depth);
    free(fb->mask);
    free(fb->normal);
    free(fb);
}

/* Allocates the buffers options ask for; NULL when out of memory. */
static sc_framebuffer *framebuffer_new(const sc_render_options *o)
{
    sc_framebuffer *fb = calloc(1, sizeof *fb);
    if (!fb)
        return NULL;
    fb->width = o->width;
    fb->height = o->height;
    fb->cancel = o->cancel;
    size_t pixels = (size_t)o->width * (size_t)o->height;
    int ok = 1;
    if (o->want_color)
        ok &= (fb->color = malloc(pixels * 3 * sizeof(float))) != NULL;
    if (o->want_depth)
        ok &= (fb->depth = malloc(pixels * sizeof(float))) != NULL;
    if (o->want_mask)
        ok &= (fb->mask = malloc(pixels)) != NULL;
    if (o->want_normal)
        ok &= (fb->normal = malloc(pixels * 3 * sizeof(float))) != NULL;
    if (!ok) {
        sc_framebuffer_release(fb);
        return NULL;
    }
    return fb;
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
    return SC_OK;
}

sc_status render_tree(const csg_tree *tree, const sc_render_options *options,
                      sc_framebuffer **framebuffer, sc_error *error)
{
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
    bbox bounds = tree->root == CSG_EMPTY ? bbox_empty() : tree->bounds;
    cam_view view;
    st = cam_view_from_options(options, &bounds, &view, error);
    if (st)
        return st;
    st = cam_init(&c.cam, &view, options->fov_deg, options->projection, options->width,
                  options->height, error);
    if (st)
        return st;
    c.key_dir = camera_to_world(&c.cam, key_light);
    c.fill_dir = camera_to_world(&c.cam, fill_light);

    c.fb = framebuffer_new(options);
    if (!c.fb)
        return err_set(error, SC_ERR_NOMEM, NULL, "out of memory for a %dx%d image",
                       options->width, options->height);

    int threads = options->threads > 0 ? options->threads : omp_get_max_threads();
    int tiles_x = (options->width + RENDER_TILE_SIZE - 1) / RENDER_TILE_SIZE;
    int tiles_y = (options->height + RENDER_TILE_SIZE - 1) / RENDER_TILE_SIZE;
    int tiles = tiles_x * tiles_y; /* at most 2048 * 2048 */

    int out_of_memory = 0; /* a thread could not get its scratch arena */
#pragma omp parallel num_threads(threads)
    {
        arena scratch;
        arena_init(&scratch, 0);
        /* Take the first block now rather than inside the loop. */
        int ready = arena_alloc(&scratch, 1) != NULL;
        arena_reset(&scratch);
        if (!ready) {
#pragma omp atomic write
            out_of_memory = 1;
        }
#pragma omp for schedule(dynamic, 1)
        for (int tile = 0; tile < tiles; tile++) {
            if (ready)
                render_tile(&c, &scratch, tile, tiles_x);
        }
        arena_free(&scratch);
    }
    if (out_of_memory) {
        sc_framebuffer_release(c.fb);
        return err_set(error, SC_ERR_NOMEM, NULL, "out of memory");
    }

    if (options->cancel && *options->cancel) {
        sc_framebuffer_release(c.fb);
        return err_set(error, SC_ERR_CANCELLED, NULL, "interrupted");
    }
    *framebuffer = c.fb;
    return SC_OK;
}

sc_status sc_render(const sc_scene *scene, const sc_render_options *options,
                    sc_framebuffer **framebuffer, sc_error *error)
{
    if (framebuffer)
        *framebuffer = NULL;
    if (!scene || !framebuffer)
        return err_set(error, SC_ERR_ARGUMENT, NULL,
                       "sc_render needs a scene and a framebuffer pointer");
    return render_tree(scene_tree(scene), options, framebuffer, error);
}
