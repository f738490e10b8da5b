/* The render loop: camera rays, shading, buffers.
 *
 * The image (or the --region crop of it) is cut into 16 x 16 tiles handed
 * to OpenMP threads one at a time (schedule dynamic), so a thread that drew
 * cheap background tiles takes more; no more threads start than there are
 * tiles, and they are released when the trace ends rather than left
 * spinning beside the caller's next steps. Every pixel sample is computed from
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
 *
 * Preview drawing is decided per sample too. Edge lines: the sample casts
 * eight more rays, half the line's width away along the axes and the
 * diagonals, and is on a line when what one of them sees differs from what
 * its own ray sees (edge_between); nothing is read from a neighbouring
 * pixel or tile, so a crop or another tiling gives the same pixels, and
 * the samples antialias the lines. Overlay lines (overlay.h) are tested at
 * the sample's point against the depth its ray sees. A contact sheet is
 * one image whose pixels belong to tiles, each a view with its own camera,
 * shading and overlay; a pixel finds its view by its position in the full
 * image, so --region crops a sheet like any image.
 *
 * Modifiers and alpha, with --preview only (OpenSCAD's render, F6, shows
 * neither, so without it nothing here runs). OpenSCAD's preview (F5) draws
 * the solid, then the '%' (background) and '#' (highlight) parts with
 * OpenGL blending, depth-tested against the solid (OpenCSGRenderer: the
 * parts are CSG products of their own drawn after the root's). Here the
 * parts are trees of their own (shading.overlay), whose surfaces a
 * sample's ray meets no farther than the solid's first hit (within the
 * query tolerance, so a '#' part that is also a face of the solid shows
 * on it); those surfaces (chosen as below), lit by OpenSCAD's preview light,
 * are blended over the sample's colour from the back to the front: c =
 * a part + (1 - a) c. A '#' part is drawn in OpenSCAD's highlight colour
 * (255, 81, 81, alpha 128), a '%' part in its background colour (180, 180,
 * 180, alpha 128) unless the file coloured it (Renderer::getColor,
 * setColor). A solid whose leaves have colour alpha below 1 is drawn as
 * layers, front to back, each with its leaf's alpha, the background
 * behind the last. Which surfaces are layers follows OpenSCAD's draw of
 * its products (the children of the top-level unions, shade.h's
 * leaf_product): a lone leaf, or a render() by itself (one mesh), is
 * drawn rear faces first, then front faces, with the depth test and
 * depth writes on, so every rear surface of it is a layer, and the front
 * surfaces before its nearest rear one; of a product of several leaves,
 * OpenCSG's depth pass keeps the nearest, so the first surface where the
 * ray enters it is. Parts take the same rule. OpenSCAD blends in the
 * order it draws, which depends on the file; this front-to-back rule is
 * the one a depth-sorted draw would give, and does not depend on the
 * file's order. Tracing one tree, the rule misses the surfaces of one
 * translucent leaf inside another, which OpenGL draws.
 * Blending, as OpenGL does it, is on display (sRGB) values. The AOVs are
 * the solid's first hit, untouched by either.
 *
 * Stopping: the render's cancel token (base/cancel.h) carries the
 * caller's flag and the budget of implicit-surface work (budget.c); each
 * thread works inside a scope on it, so the root finders and mesh walks
 * poll it, and the tile loop checks it before every pixel and sample. A
 * stopped render frees its buffers and returns SC_ERR_CANCELLED or the
 * budget's SC_ERR_LIMIT.
 */
#define _DEFAULT_SOURCE /* madvise, MADV_HUGEPAGE, posix_memalign */
#include "render/render.h"

#include <math.h>
#include <omp.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#if defined(__linux__)
#include <sys/mman.h>
#endif

#include "base/arena.h"
#include "base/cancel.h"
#include "base/error.h"
#include "base/sized.h"
#include "build/scene.h"
#include "formats/color.h"
#include "render/camera.h"
#include "render/overlay.h"
#include "render/sample.h"
#include "render/shade.h"

void sc_render_options_init_size(sc_render_options *options, size_t size)
{
    /* The library's own defaults in full, then as much of them as the
     * caller's struct holds (base/sized.h). */
    if (!options || size < sizeof options->size)
        return;
    sc_render_options o;
    render_options_defaults(&o);
    memcpy(options, &o, size < sizeof o ? size : sizeof o);
    options->size = size;
}

void render_options_defaults(sc_render_options *options)
{
    sized_clear(options, sizeof *options);
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
    sc_color_scheme_default(&options->scheme);
    /* Cornfield's cgal-face-2d and cgal-edge-2d (ColorMap.cc) */
    options->face_2d[0] = 0x00 / 255.0f;
    options->face_2d[1] = 0xbf / 255.0f;
    options->face_2d[2] = 0x99 / 255.0f;
    options->edge_2d[0] = 1;
    options->edge_angle_deg = RENDER_DEFAULT_EDGE_ANGLE;
    options->edge_width = 1;
    options->ao_radius = RENDER_DEFAULT_AO_RADIUS;
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
    options->aperture = c->aperture;
    options->focus = c->focus;
    return 1;
}

/* OpenSCAD's preview colours for '#' and '%' parts (Renderer::getColor:
 * COLORMODE_HIGHLIGHT and COLORMODE_BACKGROUND), display values. */
static const float highlight_rgba[4] = {255 / 255.0f, 81 / 255.0f, 81 / 255.0f,
                                        128 / 255.0f};
static const float background_rgba[4] = {180 / 255.0f, 180 / 255.0f, 180 / 255.0f,
                                         128 / 255.0f};

/* Most surfaces of a translucent solid a sample blends; the background
 * stands for whatever lies behind them. */
#define RENDER_MAX_LAYERS 64

/* One view of the render: the whole image, or a tile of a contact sheet. */
typedef struct render_view {
    camera cam;
    shade_scene shade;
    overlay over;
    int prepared; /* shade and over hold memory */
    /* the preview's modifier parts (shading.overlay): part_count of them */
    shade_scene part[SHADING_OVERLAYS];
    int part_kind[SHADING_OVERLAYS]; /* SHADING_OVERLAY_* of each */
    int part_count;
} render_view;

typedef struct render_ctx {
    const csg_tree *tree;
    render_view *views;
    int view_count;
    int tile_w, tile_h, cols; /* a view's size; views per row */
    int spp, grid_width;
    /* The samples this call renders, of spp, and the caller's running sums
     * (sc_render_options.sample_sum) or NULL. */
    int sample_start, sample_end;
    double *sample_sum;
    int x0, y0;           /* the crop's corner in the full image */
    int edges;            /* draw edge lines */
    double edge_half;     /* neighbour offset in pixels: half the line width */
    double edge_cos;      /* cosine of the crease angle */
    double edge_color[3]; /* linear */
    int overlays;         /* some view has overlay lines or a label */
    double shutter[2];    /* sample times lie in [open, close] */
    sc_framebuffer *fb;
    cancel_token *cancel;  /* the caller's flag and the work budget */
    uint64_t pixel_credit; /* evaluations allowed for each pixel done */
} render_ctx;

/* Per-thread state and counters. */
typedef struct render_thread {
    arena scratch;
    shade_counters count;
    csg_counters csg;
    uint64_t camera_rays;
} render_thread;

/* A camera ray and what it sees. */
typedef struct view_ray {
    csg_ray ray;
    int found;
    shade_hit hit;
} view_ray;

static void trace_view_ray(const render_view *v, shade_thread *st, int i, int j,
                           double sx, double sy, view_ray *out)
{
    cam_ray(&v->cam, i, j, sx, sy, &out->ray.o, &out->ray.d);
    cam_lens_ray(&v->cam, st->lens[0], st->lens[1], &out->ray.o, &out->ray.d);
    out->ray.tmin = 0;
    out->ray.tmax = INFINITY;
    out->found = shade_first_hit(&v->shade, st, &out->ray, &out->hit);
}

/* Pixel size at forward depth z, in world units. */
static double pixel_size(const camera *cam, double z)
{
    double half = cam->projection == SC_PROJECTION_ORTHOGRAPHIC ? cam->distance : z;
    return 2 * cam->a * half / cam->height;
}

/* Normals closer than this (1 - cosine) are one plane's, up to rounding. */
#define EDGE_COPLANAR 1e-9

/* Whether an edge lies between what two neighbouring rays see: one hits
 * and the other misses; a cap meets a surface; the leaf changes (a seam
 * where boolean operands meet); the normals turn by more than the crease
 * angle; the surface of the leaf changes to one in another plane; or b's
 * hit is off a's tangent plane by more than two pixels' size at a's depth
 * (a step in depth: a silhouette over something behind). */
static int edge_between(const render_ctx *c, const render_view *v, const view_ray *a,
                        const view_ray *b)
{
    if (a->found != b->found)
        return 1;
    if (!a->found)
        return 0;
    if (a->hit.cap != b->hit.cap)
        return 1;
    vec3 na = shade_hit_normal(&v->shade, &a->ray, &a->hit);
    vec3 nb = shade_hit_normal(&v->shade, &b->ray, &b->hit);
    double turn = v3_dot(na, nb);
    if (turn < c->edge_cos)
        return 1;
    /* Another leaf (a seam where boolean operands meet) or another surface
     * of the leaf (a mesh's facet, a polyhedron's face): an edge unless the
     * two lie in one plane, so that coplanar faces of a union and the
     * diagonals splitting a planar face draw no line, but OpenSCAD's
     * facets do. (Parallel planes apart are a step in depth, below.) */
    int other = a->hit.hit.leaf != b->hit.hit.leaf || a->hit.hit.part != b->hit.hit.part;
    if (!a->hit.cap && other && turn < 1 - EDGE_COPLANAR)
        return 1;
    vec3 pa = v3_madd(a->ray.o, a->ray.d, a->hit.hit.t);
    double denom = v3_dot(na, b->ray.d), blen = v3_length(b->ray.d);
    if (!(fabs(denom) > 1e-9 * blen))
        return 1;
    double predicted = v3_dot(na, v3_sub(pa, b->ray.o)) / denom;
    double step = fabs(b->hit.hit.t - predicted) * blen;
    return step > 2 * pixel_size(&v->cam, overlay_depth(&v->cam, pa));
}

/* Whether the sample's point lies on an edge line: an edge between its own
 * ray and one of the eight rays half the line's width away (along the
 * axes and the diagonals, so that a line at any angle is crossed by an
 * offset within 22.5 degrees of its normal: the line is drawn at least
 * cos(22.5) = 0.92 of its width wide, never dropped). */
static int on_edge(const render_ctx *c, const render_view *v, shade_thread *st, int i,
                   int j, double sx, double sy, const view_ray *centre)
{
    const double h = 0.7071067811865476;
    const double dirs[8][2] = {{1, 0}, {-1, 0},  {0, 1},  {0, -1},
                               {h, h}, {-h, -h}, {h, -h}, {-h, h}};
    for (int k = 0; k < 8; k++) {
        view_ray nb;
        st->count.edge_rays++;
        trace_view_ray(v, st, i, j, sx + c->edge_half * dirs[k][0],
                       sy + c->edge_half * dirs[k][1], &nb);
        if (edge_between(c, v, centre, &nb))
            return 1;
    }
    return 0;
}

/* The query tolerance along r at its hit t, in units of t. */
static double hit_tolerance(const shade_scene *s, const csg_ray *r, double t)
{
    return SHADE_OFFSET * csg_eps(s->tree, v3_madd(r->o, r->d, t), r->d);
}

/* The opacity of a hit's surface in s. */
static double hit_alpha(const shade_scene *s, const shade_hit *h)
{
    return s->leaf_alpha[h->hit.leaf];
}

/* A surface that a translucent walk draws: where, how opaque, and its
 * lit colour on display values. */
typedef struct layer {
    double t, alpha, display[3];
} layer;

/* Most surfaces of one modifier part a sample blends. */
#define RENDER_PART_LAYERS 16

/* Whether product is one of the count in list. */
static int seen(const uint32_t *list, int count, uint32_t product)
{
    for (int q = 0; q < count; q++)
        if (list[q] == product)
            return 1;
    return 0;
}

/* Walks the surfaces of s along ray from its first hit (hit; none when
 * !found) up to the ray's tmax, front to back, and keeps in out (at most
 * max) those OpenSCAD's preview draws (see the file's comment): of a
 * lone leaf or render(), which OpenSCAD draws rear faces first, then
 * front faces with the depth test, every rear surface and the front
 * surfaces before the first rear one; of a product of several leaves, the first surface
 * where the ray enters it, which OpenCSG's depth pass keeps. Stops once what it kept is
 * opaque. Returns the count kept. */
static int walk_layers(const render_ctx *c, const shade_scene *s, shade_thread *st,
                       csg_ray ray, shade_hit hit, int found, layer *out, int max)
{
    uint32_t drawn[RENDER_MAX_LAYERS]; /* the products drawn */
    uint32_t rear[RENDER_MAX_LAYERS];  /* the whole products met leaving */
    int drawn_count = 0, rear_count = 0, n = 0;
    double cover = 0;
    for (int k = 0; k < RENDER_MAX_LAYERS && found && cover < 1 && n < max; k++) {
        uint32_t product = s->leaf_product ? s->leaf_product[hit.hit.leaf] : CSG_EMPTY;
        int draw;
        if (product == CSG_EMPTY)
            draw = !hit.hit.exiting;
        else if (s->leaf_whole[hit.hit.leaf]) {
            /* a lone leaf or render(): its rear faces, and its front faces
             * before the depth its nearest rear face leaves */
            int behind = seen(rear, rear_count, product);
            draw = hit.hit.exiting || !behind;
            if (hit.hit.exiting && !behind)
                rear[rear_count++] = product;
        } else {
            draw = !hit.hit.exiting && !seen(drawn, drawn_count, product);
            if (draw)
                drawn[drawn_count++] = product;
        }
        if (draw) {
            double lit[3];
            shade_ray(s, st, &ray, &hit, 0, 1.0 / c->spp, lit);
            out[n].t = hit.hit.t;
            out[n].alpha = hit_alpha(s, &hit);
            for (int q = 0; q < 3; q++)
                out[n].display[q] = color_linear_to_srgb(lit[q]);
            cover += (1 - cover) * out[n].alpha;
            n++;
        }
        double t = hit.hit.t;
        ray.tmin = t + hit_tolerance(s, &ray, t);
        found = shade_first_hit(s, st, &ray, &hit);
    }
    return n;
}

/* The linear colour of a translucent solid along r (found): the surfaces
 * walk_layers keeps blended front to back on display values, the
 * background behind (see the file's comment). */
static void translucent_color(const render_ctx *c, const render_view *v, shade_thread *st,
                              const view_ray *r, double rgb[3])
{
    layer layers[RENDER_MAX_LAYERS];
    int n = walk_layers(c, &v->shade, st, r->ray, r->hit, 1, layers, RENDER_MAX_LAYERS);
    double sum[3] = {0, 0, 0}, cover = 0; /* premultiplied display values */
    for (int k = 0; k < n; k++) {
        for (int q = 0; q < 3; q++)
            sum[q] += (1 - cover) * layers[k].alpha * layers[k].display[q];
        cover += (1 - cover) * layers[k].alpha;
    }
    for (int q = 0; q < 3; q++) {
        if (cover < 1)
            sum[q] += (1 - cover) * color_linear_to_srgb(v->shade.background[q]);
        rgb[q] = color_srgb_to_linear(sum[q]);
    }
}

/* Blends the surfaces of the view's modifier parts that r meets in front
 * of the solid (walk_layers) over rgb (linear), as OpenSCAD draws them:
 * the '%' parts, then the '#' parts, each from the back to the front,
 * with the depth test and depth writes on, so that a '#' surface behind
 * the nearest '%' surface drawn is hidden. */
static void blend_parts(const render_ctx *c, const render_view *v, shade_thread *st,
                        const view_ray *r, double rgb[3])
{
    double tmax = INFINITY;
    if (r->found)
        tmax = r->hit.hit.t + hit_tolerance(&v->shade, &r->ray, r->hit.hit.t);
    double out[3];
    for (int q = 0; q < 3; q++)
        out[q] = color_linear_to_srgb(rgb[q]);
    static const int order[SHADING_OVERLAYS] = {SHADING_OVERLAY_BACKGROUND,
                                                SHADING_OVERLAY_HIGHLIGHT};
    int blended = 0;
    for (int pass = 0; pass < SHADING_OVERLAYS; pass++)
        for (int k = 0; k < v->part_count; k++) {
            if (v->part_kind[k] != order[pass])
                continue;
            const shade_scene *part = &v->part[k];
            csg_ray ray = r->ray;
            ray.tmax = tmax;
            shade_hit hit;
            int found = shade_first_hit(part, st, &ray, &hit);
            layer layers[RENDER_PART_LAYERS];
            int n = walk_layers(c, part, st, ray, hit, found, layers, RENDER_PART_LAYERS);
            for (int q = n; q-- > 0;) /* from the back */
                for (int ch = 0; ch < 3; ch++)
                    out[ch] = layers[q].alpha * layers[q].display[ch] +
                              (1 - layers[q].alpha) * out[ch];
            /* the nearest surface drawn is in the depth buffer */
            if (n)
                tmax = layers[0].t + hit_tolerance(part, &ray, layers[0].t);
            blended |= n > 0;
        }
    if (blended)
        for (int q = 0; q < 3; q++)
            rgb[q] = color_srgb_to_linear(out[q]);
}

/* The linear colour of one sample of pixel (i, j) of view v: what r sees,
 * then edge lines, then the preview's modifier parts, then overlay
 * lines. */
static void sample_color(const render_ctx *c, const render_view *v, shade_thread *st,
                         int i, int j, double sx, double sy, const view_ray *r,
                         double rgb[3])
{
    if (r->found && v->shade.translucent && hit_alpha(&v->shade, &r->hit) < 1)
        translucent_color(c, v, st, r, rgb);
    else if (r->found)
        shade_ray(&v->shade, st, &r->ray, &r->hit, 0, 1.0 / c->spp, rgb);
    else
        memcpy(rgb, v->shade.background, 3 * sizeof *rgb);
    if (c->edges && on_edge(c, v, st, i, j, sx, sy, r))
        memcpy(rgb, c->edge_color, 3 * sizeof *rgb);
    if (v->part_count)
        blend_parts(c, v, st, r, rgb);
    if (c->overlays) {
        double depth = INFINITY;
        if (r->found)
            depth = overlay_depth(&v->cam, v3_madd(r->ray.o, r->ray.d, r->hit.hit.t));
        /* OpenSCAD draws the axes first and a 2D model's polygons after,
         * with GL_LESS: an axis in their plane stays over them */
        if (r->found && v->shade.flat)
            depth *= 1 + 1e-7;
        overlay_sample(&v->over, i + sx, j + sy, depth, rgb);
    }
}

static void render_pixel(const render_ctx *c, render_thread *th, int i, int j)
{
    sc_framebuffer *fb = c->fb;
    size_t p = (size_t)j * (size_t)fb->width + (size_t)i;
    int x = c->x0 + i, y = c->y0 + j; /* in the full image */
    int aovs = fb->mask || fb->depth || fb->normal || fb->id;
    int vi = (y / c->tile_h) * c->cols + x / c->tile_w;
    int vx = x % c->tile_w, vy = y % c->tile_h; /* in the view's image */
    const render_view *v = vi < c->view_count ? &c->views[vi] : NULL;
    shade_thread st;
    st.scratch = &th->scratch;
    st.csg = &th->csg;
    memset(&st.count, 0, sizeof st.count);
    sample_pixel px = {(uint32_t)x, (uint32_t)y, 0, c->spp, c->grid_width, 0};
    st.px = px;
    st.lens[0] = st.lens[1] = 0; /* the centre ray passes the lens's centre */
    st.time = 0.5 * (c->shutter[0] + c->shutter[1]); /* the centre of the shutter */

    /* The centre ray: the AOVs, and the colour at one sample per pixel. */
    view_ray centre;
    centre.found = 0;
    if (v && (aovs || c->spp == 1)) {
        st.rng = sample_rng_for((uint32_t)x, (uint32_t)y, 0);
        trace_view_ray(v, &st, vx, vy, 0.5, 0.5, &centre);
        th->camera_rays++;
    }
    int found = centre.found;
    const csg_hit *hit = &centre.hit.hit;
    if (fb->mask)
        fb->mask[p] = found ? 255 : 0;
    if (fb->depth)
        fb->depth[p] = found ? (float)(hit->t * v3_length(centre.ray.d)) : INFINITY;
    if (fb->id)
        fb->id[p] = found ? (int32_t)c->tree->leaves[hit->leaf].object_id : -1;
    if (fb->normal) {
        vec3 n =
            found ? shade_hit_normal(&v->shade, &centre.ray, &centre.hit) : v3(0, 0, 0);
        fb->normal[3 * p + 0] = (float)n.x;
        fb->normal[3 * p + 1] = (float)n.y;
        fb->normal[3 * p + 2] = (float)n.z;
    }
    if (!fb->color) {
        arena_reset(&th->scratch);
        return;
    }
    if (!v) { /* a sheet's grid cell without a view */
        for (int k = 0; k < 3; k++)
            fb->color[3 * p + k] = (float)c->views[0].shade.background[k];
        arena_reset(&th->scratch);
        return;
    }
    /* Summed in sample order from the caller's running sum, so that passes
     * ending at spp add exactly what one render of spp samples adds. */
    double sum[3] = {0, 0, 0};
    if (c->sample_sum)
        memcpy(sum, c->sample_sum + 3 * p, sizeof sum);
    for (int s = c->sample_start; s < c->sample_end; s++) {
        if (s > c->sample_start && cancel_check(c->cancel))
            break; /* the image is abandoned */
        st.rng = sample_rng_for((uint32_t)x, (uint32_t)y, (uint32_t)s);
        st.px.s = s;
        st.px.dim = 0;
        memset(&st.count, 0, sizeof st.count);
        double rgb[3];
        if (c->spp == 1) {
            sample_color(c, v, &st, vx, vy, 0.5, 0.5, &centre, rgb);
        } else {
            double sx, sy;
            sample_offset(s, c->spp, c->grid_width, &st.rng, &sx, &sy);
            if (v->cam.lens_radius > 0) {
                double lu, lv;
                sample_2d(&st.px, &st.rng, &lu, &lv);
                sample_disc(lu, lv, &st.lens[0], &st.lens[1]);
            }
            if (c->tree->has_motion && c->shutter[1] > c->shutter[0]) {
                double u, unused;
                sample_2d(&st.px, &st.rng, &u, &unused);
                st.time = c->shutter[0] + u * (c->shutter[1] - c->shutter[0]);
            }
            view_ray r;
            trace_view_ray(v, &st, vx, vy, sx, sy, &r);
            th->camera_rays++;
            sample_color(c, v, &st, vx, vy, sx, sy, &r, rgb);
        }
        for (int k = 0; k < 3; k++)
            sum[k] += rgb[k];
        th->count.shadow_rays += st.count.shadow_rays;
        th->count.reflection_rays += st.count.reflection_rays;
        th->count.refraction_rays += st.count.refraction_rays;
        th->camera_rays += st.count.edge_rays;
        arena_reset(&th->scratch);
    }
    if (c->sample_sum)
        memcpy(c->sample_sum + 3 * p, sum, sizeof sum);
    int summed = c->sample_sum ? c->sample_end : c->sample_end - c->sample_start;
    for (int k = 0; k < 3; k++)
        fb->color[3 * p + k] = (float)(sum[k] / summed);
}

static void render_tile(const render_ctx *c, render_thread *th, int tile, int tiles_x)
{
    int x0 = (tile % tiles_x) * RENDER_TILE_SIZE;
    int y0 = (tile / tiles_x) * RENDER_TILE_SIZE;
    int x1 = x0 + RENDER_TILE_SIZE < c->fb->width ? x0 + RENDER_TILE_SIZE : c->fb->width;
    int y1 =
        y0 + RENDER_TILE_SIZE < c->fb->height ? y0 + RENDER_TILE_SIZE : c->fb->height;
    /* The work budget is credited a row of the tile at a time: one atomic
     * addition on the token, which every thread shares, per row instead
     * of per pixel. */
    for (int j = y0; j < y1; j++) {
        for (int i = x0; i < x1; i++) {
            if (cancel_check(c->cancel))
                return; /* stopped: the rest is skipped */
            render_pixel(c, th, i, j);
        }
        cancel_credit(c->cancel, (uint64_t)(x1 - x0) * c->pixel_credit);
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
    free(fb->id);
    free(fb);
}

/* A buffer of the framebuffer, freed by free(). The trace writes each of
 * its pages once, and the first write of each 4 KiB page is a page fault
 * (on a virtual machine, several microseconds): a buffer of a few
 * megabytes is aligned to 2 MiB and offered to the kernel's transparent
 * huge pages, one fault for 512 pages where the kernel grants them. */
static void *buffer_alloc(size_t size)
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    const size_t huge = (size_t)2 << 20;
    if (size >= 2 * huge) {
        void *p = NULL;
        if (posix_memalign(&p, huge, size) != 0)
            return NULL;
        (void)madvise(p, size & ~(huge - 1), MADV_HUGEPAGE); /* only advice */
        return p;
    }
#endif
    return malloc(size);
}

sc_framebuffer *render_framebuffer_new(const sc_render_options *o, int width, int height)
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
        ok &= (fb->color = buffer_alloc(pixels * 3 * sizeof(float))) != NULL;
    if (o->want_depth)
        ok &= (fb->depth = buffer_alloc(pixels * sizeof(float))) != NULL;
    if (o->want_mask)
        ok &= (fb->mask = malloc(pixels)) != NULL;
    if (o->want_normal)
        ok &= (fb->normal = buffer_alloc(pixels * 3 * sizeof(float))) != NULL;
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

/* The full image's size: the options' size, or a sheet of tiles that
 * size. */
static void image_size(const sc_render_options *o, int *cols, int *width, int *height)
{
    int n = o->sheet_count > 0 ? o->sheet_count : 1;
    int c = 1;
    while (c * c < n)
        c++;
    int rows = (n + c - 1) / c;
    *cols = c;
    *width = o->width * c;
    *height = o->height * rows;
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
    if (o->sample_start < 0 || o->sample_start >= o->spp || o->sample_count < 0 ||
        o->sample_count > o->spp - o->sample_start)
        return err_set(error, SC_ERR_ARGUMENT, NULL,
                       "sample start %d and count %d do not fit %d samples per pixel",
                       o->sample_start, o->sample_count, o->spp);
    if (o->max_depth < 0 || o->max_depth > SHADE_MAX_DEPTH)
        return err_set(error, SC_ERR_ARGUMENT, NULL,
                       "maximum depth must be 0 to %d (got %d)", SHADE_MAX_DEPTH,
                       o->max_depth);
    if (o->sheet_count < 0 || o->sheet_count > SC_MAX_SHEET)
        return err_set(error, SC_ERR_ARGUMENT, NULL, "a sheet has 1 to %d views (got %d)",
                       SC_MAX_SHEET, o->sheet_count);
    for (int k = 0; k < o->sheet_count; k++)
        if (!sc_view_preset_name(o->sheet[k]))
            return err_set(error, SC_ERR_ARGUMENT, NULL, "sheet view %d is not a view",
                           k + 1);
    if (o->section_count < 0 || o->section_count > SC_MAX_SECTIONS)
        return err_set(error, SC_ERR_ARGUMENT, NULL, "at most %d section cuts (got %d)",
                       SC_MAX_SECTIONS, o->section_count);
    if (o->view & SC_VIEW_EDGES &&
        !(o->edge_width > 0 && o->edge_width <= RENDER_MAX_EDGE_WIDTH))
        return err_set(error, SC_ERR_ARGUMENT, NULL,
                       "edge width must be above 0 and at most %d pixels (got %g)",
                       RENDER_MAX_EDGE_WIDTH, o->edge_width);
    if (o->view & SC_VIEW_EDGES && !(o->edge_angle_deg > 0 && o->edge_angle_deg < 180))
        return err_set(error, SC_ERR_ARGUMENT, NULL,
                       "edge angle must be between 0 and 180 degrees (got %g)",
                       o->edge_angle_deg);
    if (!(o->shutter[0] >= 0 && o->shutter[0] <= o->shutter[1] && o->shutter[1] <= 1))
        return err_set(error, SC_ERR_ARGUMENT, NULL,
                       "shutter %g,%g is not an interval of [0, 1]", o->shutter[0],
                       o->shutter[1]);
    if (o->ao_samples < 0 || o->ao_samples > RENDER_MAX_AO)
        return err_set(error, SC_ERR_ARGUMENT, NULL,
                       "ambient occlusion takes 0 to %d rays (got %d)", RENDER_MAX_AO,
                       o->ao_samples);
    if (o->ao_samples > 0 && !(o->ao_radius > 0 && isfinite(o->ao_radius)))
        return err_set(error, SC_ERR_ARGUMENT, NULL,
                       "ambient occlusion radius must be above 0 (got %g)", o->ao_radius);
    int cols, width, height;
    image_size(o, &cols, &width, &height);
    if (width > RENDER_MAX_SIDE || height > RENDER_MAX_SIDE)
        return err_set(error, SC_ERR_ARGUMENT, NULL,
                       "a sheet of %dx%d pixels is too large (at most %d a side)", width,
                       height, RENDER_MAX_SIDE);
    const int *r = o->region;
    if (has_region(o) && !(r[0] >= 0 && r[1] >= 0 && r[0] < r[2] && r[1] < r[3] &&
                           r[2] <= width && r[3] <= height))
        return err_set(error, SC_ERR_ARGUMENT, NULL,
                       "region %d,%d,%d,%d is not a non-empty crop of the %dx%d image",
                       r[0], r[1], r[2], r[3], width, height);
    return SC_OK;
}

/* Sets up the shading of view v's modifier parts (see the file's
 * comment): OpenSCAD's preview light, no occlusion, no bounces, the
 * highlight and background colours. */
static sc_status prepare_parts(render_view *v, const shading *look,
                               const sc_render_options *options, sc_error *error)
{
    sc_render_options part_options = *options;
    part_options.lighting = SC_LIGHTING_OPENSCAD;
    part_options.ao_samples = 0;
    part_options.max_depth = 0;
    for (int k = 0; k < SHADING_OVERLAYS; k++) {
        const csg_tree *tree = look->overlay[k];
        if (!tree || tree->root == CSG_EMPTY)
            continue;
        shade_scene *s = &v->part[v->part_count];
        sc_status st = shade_prepare(s, tree, NULL, &v->cam, &part_options, error);
        if (st == SC_OK && (st = shade_mark_renders(s, &look->overlay_renders[k], error)))
            shade_release(s);
        if (st)
            return st;
        v->part_kind[v->part_count++] = k;
        int highlight = k == SHADING_OVERLAY_HIGHLIGHT;
        shade_paint_part(s, highlight ? highlight_rgba : background_rgba, !highlight);
    }
    return SC_OK;
}

/* Upper-case names of the sheet's labels. */
static const char *const preset_labels[] = {NULL,    "TOP",   "BOTTOM", "LEFT",
                                            "RIGHT", "FRONT", "BACK",   "DIAGONAL"};

/* Sets up view k of ctx for options: its camera (a sheet tile's preset
 * framed like viewall with autocenter), shading and overlay. */
static sc_status prepare_view(render_ctx *c, int k, const shading *look,
                              const sc_render_options *options, const bbox *bounds,
                              sc_error *error)
{
    render_view *v = &c->views[k];
    sc_render_options view_options = *options;
    const char *label = NULL;
    if (options->sheet_count > 0) {
        sc_view_preset preset = options->sheet[k];
        view_options.camera_mode = SC_CAMERA_GIMBAL;
        memset(view_options.camera, 0, sizeof view_options.camera);
        sc_view_preset_rotation(preset, view_options.camera + 3);
        view_options.camera[6] = CAM_DEFAULT_DISTANCE;
        view_options.viewall = 1;
        view_options.autocenter = 1;
        label = preset_labels[preset];
    }
    cam_view view;
    sc_status st = cam_view_from_options(&view_options, bounds, &view, error);
    if (st == SC_OK)
        st = cam_init(&v->cam, &view, options->fov_deg, options->projection,
                      options->width, options->height, error);
    if (st == SC_OK)
        st = cam_set_lens(&v->cam, options->aperture, options->focus, error);
    if (st)
        return st;
    st = shade_prepare(&v->shade, c->tree, look, &v->cam, options, error);
    if (st)
        return st;
    /* a 2D model's outlines, which OpenSCAD's render draws over it */
    overlay_outlines outlines = {NULL, NULL, 0, options->edge_2d};
    if (v->shade.flat && look) {
        outlines.points = look->flat_points;
        outlines.start = look->flat_start;
        outlines.count = look->flat_outlines;
    }
    st = overlay_prepare(&v->over, &v->cam, options->view, &options->scheme,
                         outlines.count ? &outlines : NULL, label,
                         options->sheet_count > 0, error);
    if (st) {
        shade_release(&v->shade);
        return st;
    }
    v->prepared = 1;
    if (options->preview && look)
        st = prepare_parts(v, look, options, error);
    if (st)
        return st;
    if (v->over.count || label)
        c->overlays = 1;
    return SC_OK;
}

static void release_views(render_ctx *c)
{
    for (int k = 0; c->views && k < c->view_count; k++) {
        if (!c->views[k].prepared)
            continue;
        shade_release(&c->views[k].shade);
        overlay_release(&c->views[k].over);
        for (int p = 0; p < c->views[k].part_count; p++)
            shade_release(&c->views[k].part[p]);
    }
    free(c->views);
    c->views = NULL;
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

/* The box OpenSCAD's preview frames for tree (OpenCSGRenderer::
 * getBoundingBox): each product's is the union of the boxes of the
 * objects it intersects, not their overlap (CSGProduct::getBoundingBox),
 * so an intersection spans all its operands' boxes; a difference its
 * first operand's. A slab (slabs: those of t, or NULL) is framed by its
 * polygons' box. Without intersections or slabs, the tree's bounds. */
static sc_status preview_bounds(const csg_tree *t, const shading_slabs *slabs, bbox *out,
                                sc_error *error)
{
    *out = t->root == CSG_EMPTY ? bbox_empty() : t->bounds;
    int intersects = slabs && slabs->count;
    for (uint32_t i = 0; t->root != CSG_EMPTY && i < t->node_count; i++)
        intersects |= t->nodes[i].op == CSG_INTERSECTION;
    if (!intersects || t->root == CSG_EMPTY)
        return SC_OK;
    bbox *box = malloc((size_t)t->node_count * sizeof *box);
    if (!box)
        return err_nomem(error, NULL);
    for (uint32_t i = 0; i < t->node_count; i++) { /* children first */
        const csg_node *n = &t->nodes[i];
        if (n->op == CSG_LEAF) {
            box[i] = n->bounds;
            uint32_t id = t->leaves[n->leaf].object_id;
            size_t lo =
                slabs ? shading_find_id(slabs->items, slabs->count, sizeof *slabs->items,
                                        offsetof(shading_slab, object), id)
                      : 0;
            if (slabs && lo < slabs->count && slabs->items[lo].object == id)
                box[i] = slabs->items[lo].flat;
            continue;
        }
        const uint32_t *child = t->child_ids + n->first_child; /* a leaf has none */
        if (n->op == CSG_DIFFERENCE) {
            box[i] = n->child_count ? box[child[0]] : bbox_empty();
        } else {
            box[i] = bbox_empty();
            for (uint32_t k = 0; k < n->child_count; k++)
                box[i] = bbox_union(box[i], box[child[k]]);
        }
    }
    *out = box[t->root];
    free(box);
    return SC_OK;
}

sc_status render_frame_bounds(const csg_tree *tree, const shading *look,
                              const sc_render_options *options, bbox *out,
                              sc_error *error)
{
    if (!options->preview) {
        if (look && look->flat_2d && look->flat_outlines)
            *out = look->flat_box;
        else if (tree->root == CSG_EMPTY)
            *out = bbox_empty();
        else
            *out = look && look->has_solid_box ? look->solid_box : tree->bounds;
        return SC_OK;
    }
    /* The preview frames its modifier parts too, as OpenSCAD's does, and
     * the boxes OpenSCAD's products have. */
    const shading_slabs *slabs = NULL;
    if (look && look->preview_solid) {
        tree = look->preview_solid; /* without the '#' operands OpenSCAD leaves out */
        slabs = &look->preview_slabs;
    }
    sc_status st = preview_bounds(tree, slabs, out, error);
    for (int k = 0; st == SC_OK && look && k < SHADING_OVERLAYS; k++) {
        const csg_tree *part = look->overlay[k];
        bbox box;
        if (part &&
            (st = preview_bounds(part, &look->overlay_slabs[k], &box, error)) == SC_OK &&
            part->root != CSG_EMPTY)
            *out = bbox_union(*out, box);
    }
    return st;
}

sc_status render_scene(const csg_tree *tree, const shading *look,
                       const sc_render_options *options, sc_framebuffer **framebuffer,
                       sc_error *error)
{
    double start = seconds_now();
    *framebuffer = NULL;
    sc_render_options own; /* the caller's options, completed with defaults */
    render_options_defaults(&own);
    if (options) {
        sc_status st =
            sized_read(&own, sizeof own, options, SIZED_MIN(sc_render_options, sheet),
                       "sc_render_options", error);
        if (st)
            return st;
    }
    options = &own;
    sc_status st = check_options(options, error);
    if (st)
        return st;
    const csg_tree *solid = tree;
    if (options->preview && look && look->preview_solid)
        tree = look->preview_solid; /* without the '#' operands OpenSCAD leaves out */

    render_ctx c;
    memset(&c, 0, sizeof c);
    c.tree = tree;
    c.spp = options->spp;
    c.grid_width = sample_grid_width(options->spp);
    c.sample_start = options->sample_start;
    c.sample_end = options->sample_count > 0
                       ? options->sample_start + options->sample_count
                       : options->spp;
    c.sample_sum = options->sample_sum;
    c.shutter[0] = options->shutter[0];
    c.shutter[1] = options->shutter[1];
    c.tile_w = options->width;
    c.tile_h = options->height;
    c.view_count = options->sheet_count > 0 ? options->sheet_count : 1;
    int width, height;
    image_size(options, &c.cols, &width, &height);
    /* The buffers' budget: the crop, else the whole sheet. */
    sc_render_options whole = *options;
    whole.width = has_region(options) ? options->region[2] - options->region[0] : width;
    whole.height = has_region(options) ? options->region[3] - options->region[1] : height;
    st = render_check_memory(&whole, error);
    if (st)
        return st;
    c.edges = (options->view & SC_VIEW_EDGES) != 0;
    c.edge_half = options->edge_width / 2;
    c.edge_cos = cos(options->edge_angle_deg * 3.14159265358979323846 / 180);
    for (int k = 0; k < 3; k++)
        c.edge_color[k] = color_srgb_to_linear(options->scheme.edge[k]);
    bbox bounds;
    if ((st = render_frame_bounds(solid, look, options, &bounds, error)) != SC_OK)
        return st;
    c.views = calloc((size_t)c.view_count, sizeof *c.views);
    if (!c.views)
        return err_nomem(error, NULL);
    for (int k = 0; k < c.view_count; k++) {
        st = prepare_view(&c, k, look, options, &bounds, error);
        if (st) {
            release_views(&c);
            return st;
        }
    }
    if (has_region(options)) {
        c.x0 = options->region[0];
        c.y0 = options->region[1];
        width = options->region[2] - c.x0;
        height = options->region[3] - c.y0;
    }
    c.fb = render_framebuffer_new(options, width, height);
    if (!c.fb) {
        release_views(&c);
        return err_set(error, SC_ERR_NOMEM, NULL, "out of memory for a %dx%d image",
                       width, height);
    }
    c.fb->x0 = c.x0;
    c.fb->y0 = c.y0;
    describe_camera(&c.views[0].cam, options->fov_deg, c.fb->camera_info,
                    sizeof c.fb->camera_info);

    int threads = options->threads > 0 ? options->threads : omp_get_max_threads();
    int tiles_x = (width + RENDER_TILE_SIZE - 1) / RENDER_TILE_SIZE;
    int tiles_y = (height + RENDER_TILE_SIZE - 1) / RENDER_TILE_SIZE;
    int tiles = tiles_x * tiles_y; /* at most 2048 * 2048 */
    /* A thread without a tile would only start, wait and spin. */
    if (threads > tiles)
        threads = tiles > 0 ? tiles : 1;
    int done = 0;
    sc_render_stats *stats = &c.fb->stats;
    stats->threads = threads;
    double traced = seconds_now();
    stats->setup_seconds = traced - start;

    cancel_token cancel;
    cancel_init(&cancel, options->cancel, RENDER_MIN_IMPLICIT_EVALS);
    c.pixel_credit = render_work_credit(options);
    c.cancel = &cancel;
    int out_of_memory = 0; /* a thread could not get its scratch arena */
#pragma omp parallel num_threads(threads)
    {
        cancel_scope scope;
        cancel_enter(&scope, &cancel);
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
        cancel_leave(&scope);
    }
    /* libgomp's idle workers spin (GOMP_SPINCOUNT, 300,000 turns by
     * default) waiting for another parallel region, on the cores the
     * caller's next steps need: writing the image and exiting, for the
     * command line. Released here, they end now; a later render starts
     * its threads again (tens of microseconds). Inside an enclosing
     * parallel region this does nothing. */
    if (threads > 1)
        omp_pause_resource_all(omp_pause_soft);
    if (options->progress)
        options->progress(options->progress_user, 1.0);
    release_views(&c);
    stats->trace_seconds = seconds_now() - traced;
    if (out_of_memory) {
        sc_framebuffer_release(c.fb);
        return err_nomem(error, NULL);
    }
    if (cancel_check(&cancel) != CANCEL_NONE) {
        sc_framebuffer_release(c.fb);
        return render_stop_error(tree, &cancel, error);
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
