/* `spancast render` cut into tiles: for MPI ranks, and for images larger
 * than memory.
 *
 * A render of one process whose buffers fit in memory is a single
 * sc_render, as it always was. Otherwise the image (or its --region crop)
 * is cut into square tiles (tiles_side), each rendered as a crop of the
 * full image with sc_render, on any rank (dist.h). The renderer seeds every
 * sample by its pixel's place in the full image and reads nothing from
 * neighbouring pixels, so a tile's pixels are exactly those of the whole
 * render, and the image does not depend on the tiling or the number of
 * ranks. Rank 0 receives the tiles in order and either copies them into
 * one framebuffer, written afterwards by the usual writers (so every file
 * is byte for byte the single-process one), or, streamed, writes each
 * tile straight into a tiled EXR per output (image_stream.h).
 *
 * A piece of work is a run of tiles along a tile row, rendered by one
 * sc_render of the run's region: each sc_render starts and joins the
 * rank's threads once, and OpenMP's threads spin between two renders, so
 * a run costs far less CPU than its tiles one by one (on a loaded 2-core
 * machine, a 300x200 image in 70 separate tiles took ten times the CPU of
 * one render). Runs are at most TILES_UNIT_BYTES of buffers, shorter with
 * several ranks so that each rank gets many of them. Pieces are handed
 * out in order, none more than `window` beyond the oldest not yet
 * delivered, so rank 0 holds at most TILES_HELD_BYTES of them (or window
 * single tiles, when a tile is larger than that share) besides its image:
 * streamed, that and one tile's conversion per file is all it holds.
 */
#define _POSIX_C_SOURCE 200809L /* clock_gettime */

#include "cli/tiles.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "base/error.h"
#include "cli/dist.h"
#include "formats/image_stream.h"
#include "render/render.h"

/* Pieces of work a rank 0 holds ahead of the one it writes, per rank. */
#define TILES_WINDOW_PER_RANK 2
#define TILES_WINDOW_MIN 4
/* Largest buffers of one piece of work (a run of tiles), and of all the
 * pieces rank 0 holds at once, bytes (a piece is at least one tile). */
#define TILES_UNIT_BYTES ((size_t)32 << 20)
#define TILES_HELD_BYTES ((size_t)256 << 20)
/* With several ranks, at least this many pieces per rank, for balance. */
#define TILES_UNITS_PER_RANK 16

enum { OUT_COLOR, OUT_MASK, OUT_DEPTH, OUT_NORMAL, OUT_ID, OUT_COUNT };

typedef struct tiles_run {
    const sc_scene *scene;
    const sc_render_options *options;
    const tiles_outputs *out;
    int x0, y0, width, height; /* the area rendered, in the full image */
    int side, tiles_x, tiles_y;
    int per_unit, units_x; /* a piece of work: a run of per_unit tiles of a
                              tile row (fewer at its end); pieces a row */
    int streamed;
    sc_framebuffer *scratch;          /* streamed: one tile cut out of a run */
    sc_framebuffer *image;            /* rank 0: the assembled image, or (streamed)
                                         the size and counters alone */
    imgio_stream *streams[OUT_COUNT]; /* streamed: one per output, opened with
                                         the first tile */
    const char *paths[OUT_COUNT];
    int delivered;
} tiles_run;

int tiles_side(int width, int height)
{
    int side = 256;
    while (side > 32) {
        uint64_t across = ((uint64_t)width + (uint64_t)side - 1) / (uint64_t)side;
        uint64_t down = ((uint64_t)height + (uint64_t)side - 1) / (uint64_t)side;
        if (across * down >= 64)
            break;
        side /= 2;
    }
    return side;
}

/* The full image's size: options' size, or the grid of a contact sheet
 * (ceil(sqrt(n)) views a row, as render.c lays it out). */
static void full_size(const sc_render_options *o, int *width, int *height)
{
    int n = o->sheet_count > 0 ? o->sheet_count : 1;
    int cols = 1;
    while (cols * cols < n)
        cols++;
    *width = o->width * cols;
    *height = o->height * ((n + cols - 1) / cols);
}

static double seconds_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int has_region(const sc_render_options *o)
{
    return o->region[0] || o->region[1] || o->region[2] || o->region[3];
}

/* Piece k: its first tile (*tx, *ty) and its number of tiles. */
static int unit_tiles(const tiles_run *r, int k, int *tx, int *ty)
{
    *ty = k / r->units_x;
    *tx = (k % r->units_x) * r->per_unit;
    return *tx + r->per_unit < r->tiles_x ? r->per_unit : r->tiles_x - *tx;
}

/* Renders piece k: one sc_render of the run's region, so that the threads
 * of a rank meet once per run, not once per tile. */
static sc_status render_tile(void *user, int k, void **result, sc_error *error)
{
    const tiles_run *r = user;
    sc_render_options o = *r->options;
    int tx, ty;
    int n = unit_tiles(r, k, &tx, &ty);
    o.region[0] = r->x0 + tx * r->side;
    o.region[1] = r->y0 + ty * r->side;
    o.region[2] = o.region[0] + n * r->side < r->x0 + r->width ? o.region[0] + n * r->side
                                                               : r->x0 + r->width;
    o.region[3] = o.region[1] + r->side < r->y0 + r->height ? o.region[1] + r->side
                                                            : r->y0 + r->height;
    o.progress = NULL; /* progress is counted in runs delivered */
    sc_framebuffer *fb = NULL;
    sc_status st = sc_render(r->scene, &o, &fb, error);
    *result = fb;
    return st;
}

static void release_run(void *user, void *result)
{
    (void)user;
    sc_framebuffer_release(result);
}
/* ---- runs between ranks ---- */

/* The buffers a run's message carries (tile_header.buffers). */
enum { HAS_COLOR = 1, HAS_DEPTH = 2, HAS_MASK = 4, HAS_NORMAL = 8, HAS_ID = 16 };

#define STAT_COUNTS 9

/* A finished run as bytes, followed by its buffers in the order of the
 * HAS_ bits. */
typedef struct tile_header {
    int32_t width, height, buffers, threads;
    uint64_t counts[STAT_COUNTS]; /* sc_render_stats' counters, in its order */
    double setup_seconds, trace_seconds;
    char camera_info[256];
} tile_header;

static size_t pixel_bytes(int buffers)
{
    return (buffers & HAS_COLOR ? 3 * sizeof(float) : 0) +
           (buffers & HAS_DEPTH ? sizeof(float) : 0) + (buffers & HAS_MASK ? 1 : 0) +
           (buffers & HAS_NORMAL ? 3 * sizeof(float) : 0) +
           (buffers & HAS_ID ? sizeof(int32_t) : 0);
}

/* The buffers of fb, and their sizes a pixel, in wire order. */
static void buffer_list(const sc_framebuffer *fb, void *bufs[5], size_t sizes[5])
{
    bufs[0] = fb->color;
    sizes[0] = 3 * sizeof(float);
    bufs[1] = fb->depth;
    sizes[1] = sizeof(float);
    bufs[2] = fb->mask;
    sizes[2] = 1;
    bufs[3] = fb->normal;
    sizes[3] = 3 * sizeof(float);
    bufs[4] = fb->id;
    sizes[4] = sizeof(int32_t);
}

/* A run as bytes (malloc'd; NULL when out of memory). */
static void *pack_run(void *user, const void *result, size_t *size)
{
    (void)user;
    const sc_framebuffer *fb = result;
    tile_header h;
    memset(&h, 0, sizeof h);
    h.width = fb->width;
    h.height = fb->height;
    void *bufs[5];
    size_t sizes[5];
    buffer_list(fb, bufs, sizes);
    for (int b = 0; b < 5; b++)
        if (bufs[b])
            h.buffers |= 1 << b;
    const sc_render_stats *s = &fb->stats;
    const uint64_t counts[STAT_COUNTS] = {
        s->camera_rays,     s->shadow_rays,     s->reflection_rays,
        s->refraction_rays, s->primitive_tests, s->span_operations,
        s->node_visits,     s->bvh_node_visits, s->scratch_mallocs};
    memcpy(h.counts, counts, sizeof counts);
    h.threads = s->threads;
    h.setup_seconds = s->setup_seconds;
    h.trace_seconds = s->trace_seconds;
    memcpy(h.camera_info, fb->camera_info, sizeof h.camera_info);
    size_t pixels = (size_t)fb->width * (size_t)fb->height;
    *size = sizeof h + pixels * pixel_bytes(h.buffers);
    char *msg = malloc(*size);
    if (!msg)
        return NULL;
    memcpy(msg, &h, sizeof h);
    char *at = msg + sizeof h;
    for (int b = 0; b < 5; b++) {
        if (!bufs[b])
            continue;
        memcpy(at, bufs[b], pixels * sizes[b]);
        at += pixels * sizes[b];
    }
    return msg;
}

/* The run in size bytes; NULL when they are malformed or out of memory. */
static void *unpack_run(void *user, const void *bytes, size_t size)
{
    (void)user;
    const char *msg = bytes;
    tile_header h;
    if (size < sizeof h)
        return NULL;
    memcpy(&h, msg, sizeof h);
    if (h.width <= 0 || h.height <= 0 || h.width > RENDER_MAX_SIDE || h.height > 256 ||
        h.buffers < 0 || h.buffers > 31)
        return NULL;
    size_t pixels = (size_t)h.width * (size_t)h.height;
    if (size != sizeof h + pixels * pixel_bytes(h.buffers))
        return NULL;
    sc_framebuffer *fb = calloc(1, sizeof *fb);
    if (!fb)
        return NULL;
    fb->width = h.width;
    fb->height = h.height;
    void **targets[5] = {(void **)&fb->color, (void **)&fb->depth, (void **)&fb->mask,
                         (void **)&fb->normal, (void **)&fb->id};
    void *unused[5];
    size_t sizes[5];
    buffer_list(fb, unused, sizes);
    const char *at = msg + sizeof h;
    for (int b = 0; b < 5; b++) {
        if (!(h.buffers & 1 << b))
            continue;
        *targets[b] = malloc(pixels * sizes[b]);
        if (!*targets[b]) {
            sc_framebuffer_release(fb);
            return NULL;
        }
        memcpy(*targets[b], at, pixels * sizes[b]);
        at += pixels * sizes[b];
    }
    sc_render_stats *s = &fb->stats;
    s->camera_rays = h.counts[0];
    s->shadow_rays = h.counts[1];
    s->reflection_rays = h.counts[2];
    s->refraction_rays = h.counts[3];
    s->primitive_tests = h.counts[4];
    s->span_operations = h.counts[5];
    s->node_visits = h.counts[6];
    s->bvh_node_visits = h.counts[7];
    s->scratch_mallocs = h.counts[8];
    s->threads = h.threads;
    s->setup_seconds = h.setup_seconds;
    s->trace_seconds = h.trace_seconds;
    memcpy(fb->camera_info, h.camera_info, sizeof fb->camera_info);
    fb->camera_info[sizeof fb->camera_info - 1] = '\0';
    return fb;
}

static void add_stats(sc_render_stats *sum, const sc_render_stats *s)
{
    sum->camera_rays += s->camera_rays;
    sum->shadow_rays += s->shadow_rays;
    sum->reflection_rays += s->reflection_rays;
    sum->refraction_rays += s->refraction_rays;
    sum->primitive_tests += s->primitive_tests;
    sum->span_operations += s->span_operations;
    sum->node_visits += s->node_visits;
    sum->bvh_node_visits += s->bvh_node_visits;
    sum->scratch_mallocs += s->scratch_mallocs;
    sum->setup_seconds += s->setup_seconds;
    if (s->threads > sum->threads)
        sum->threads = s->threads;
}

/* Copies the rows of buffer src (a tile, tile_w values of size bytes a
 * row) into dst (the image, image_w a row) at (x, y). */
static void copy_rows(void *dst, const void *src, size_t size, int image_w, int x, int y,
                      int tile_w, int tile_h)
{
    if (!dst || !src)
        return;
    for (int j = 0; j < tile_h; j++)
        memcpy((char *)dst + (((size_t)(y + j) * (size_t)image_w + (size_t)x) * size),
               (const char *)src + (size_t)j * (size_t)tile_w * size,
               (size_t)tile_w * size);
}

/* Copies the tile of run fb that starts at column x of it into
 * r->scratch (allocated on first use). */
static sc_status cut_tile(tiles_run *r, const sc_framebuffer *fb, int x, int w,
                          sc_error *error)
{
    sc_framebuffer *t = r->scratch;
    if (!t) {
        size_t pixels = (size_t)r->side * (size_t)r->side;
        t = r->scratch = calloc(1, sizeof *t);
        int ok = t != NULL;
        if (ok && fb->color)
            ok = (t->color = malloc(pixels * 3 * sizeof(float))) != NULL;
        if (ok && fb->depth)
            ok = (t->depth = malloc(pixels * sizeof(float))) != NULL;
        if (ok && fb->mask)
            ok = (t->mask = malloc(pixels)) != NULL;
        if (ok && fb->normal)
            ok = (t->normal = malloc(pixels * 3 * sizeof(float))) != NULL;
        if (ok && fb->id)
            ok = (t->id = malloc(pixels * sizeof(int32_t))) != NULL;
        if (!ok)
            return err_nomem(error, NULL);
    }
    t->width = w;
    t->height = fb->height;
    /* Rows of w values from column x of fb into rows of w values. */
    for (int j = 0; j < fb->height; j++) {
        size_t from = (size_t)j * (size_t)fb->width + (size_t)x,
               to = (size_t)j * (size_t)w;
        if (fb->color)
            memcpy(t->color + 3 * to, fb->color + 3 * from,
                   (size_t)w * 3 * sizeof(float));
        if (fb->depth)
            memcpy(t->depth + to, fb->depth + from, (size_t)w * sizeof(float));
        if (fb->mask)
            memcpy(t->mask + to, fb->mask + from, (size_t)w);
        if (fb->normal)
            memcpy(t->normal + 3 * to, fb->normal + 3 * from,
                   (size_t)w * 3 * sizeof(float));
        if (fb->id)
            memcpy(t->id + to, fb->id + from, (size_t)w * sizeof(int32_t));
    }
    return SC_OK;
}

static sc_status deliver_tile(void *user, int k, const void *result, sc_error *error)
{
    tiles_run *r = user;
    const sc_framebuffer *fb = result;
    sc_framebuffer *image = r->image;
    int tx, ty;
    int n = unit_tiles(r, k, &tx, &ty);
    if (k == 0)
        memcpy(image->camera_info, fb->camera_info, sizeof image->camera_info);
    add_stats(&image->stats, &fb->stats);
    if (r->streamed) {
        static const imgio_kind kinds[OUT_COUNT] = {IMGIO_COLOR, IMGIO_MASK, IMGIO_DEPTH,
                                                    IMGIO_NORMAL, IMGIO_ID};
        for (int t = 0; t < n; t++) {
            const sc_framebuffer *tile = fb;
            if (n > 1) {
                int x = t * r->side;
                int w = fb->width - x < r->side ? fb->width - x : r->side;
                sc_status st = cut_tile(r, fb, x, w, error);
                if (st)
                    return st;
                tile = r->scratch;
            }
            for (int o = 0; o < OUT_COUNT; o++) {
                if (!r->paths[o])
                    continue;
                sc_status st = SC_OK;
                if (!r->streams[o])
                    st = imgio_stream_open(r->paths[o], kinds[o], r->width, r->height,
                                           r->side, fb->camera_info, &r->streams[o],
                                           error);
                if (st == SC_OK)
                    st = imgio_stream_write(r->streams[o], tx + t, ty, tile, error);
                if (st)
                    return st;
            }
        }
    } else {
        int x = tx * r->side, y = ty * r->side, w = fb->width, h = fb->height;
        copy_rows(image->color, fb->color, 3 * sizeof(float), r->width, x, y, w, h);
        copy_rows(image->depth, fb->depth, sizeof(float), r->width, x, y, w, h);
        copy_rows(image->mask, fb->mask, 1, r->width, x, y, w, h);
        copy_rows(image->normal, fb->normal, 3 * sizeof(float), r->width, x, y, w, h);
        copy_rows(image->id, fb->id, sizeof(int32_t), r->width, x, y, w, h);
    }
    r->delivered++;
    if (r->options->progress)
        r->options->progress(r->options->progress_user,
                             (double)r->delivered / (r->units_x * r->tiles_y));
    return SC_OK;
}

sc_status dist_run_here(const dist_work *job, sc_error *error)
{
    for (int k = 0; k < job->count; k++) {
        if (job->cancel && *job->cancel)
            return err_set(error, SC_ERR_CANCELLED, NULL, "interrupted");
        void *result = NULL;
        sc_status st = job->run(job->user, k, &result, error);
        if (st == SC_OK)
            st = job->deliver(job->user, k, result, error);
        if (result)
            job->release(job->user, result);
        if (st)
            return st;
    }
    return SC_OK;
}

/* Rank 0's image: every buffer options ask for, width x height, or
 * (streamed) none. NULL when out of memory. */
static sc_framebuffer *new_image(const sc_render_options *o, int width, int height,
                                 int streamed)
{
    sc_framebuffer *fb = NULL;
    if (!streamed) {
        fb = render_framebuffer_new(o, width, height);
    } else if ((fb = calloc(1, sizeof *fb))) {
        fb->width = width;
        fb->height = height;
        fb->cancel = o->cancel;
    }
    if (!fb)
        return NULL;
    fb->x0 = has_region(o) ? o->region[0] : 0;
    fb->y0 = has_region(o) ? o->region[1] : 0;
    return fb;
}

/* Streamed outputs must be tiled formats. */
static sc_status check_streamable(const tiles_run *r, const char *why, sc_error *error)
{
    for (int o = 0; o < OUT_COUNT; o++)
        if (r->paths[o] && !imgio_stream_supported(r->paths[o]))
            return err_set(error, SC_ERR_ARGUMENT, NULL,
                           "cannot write '%s': %s; only .exr and .tif outputs are "
                           "written tile by tile",
                           r->paths[o], why);
    return SC_OK;
}

sc_status tiles_render(const sc_scene *scene, const sc_render_options *options,
                       const tiles_outputs *out, sc_framebuffer **fb, int *written,
                       sc_error *error)
{
    *fb = NULL;
    *written = 0;
    tiles_run r;
    memset(&r, 0, sizeof r);
    r.scene = scene;
    r.options = options;
    r.out = out;
    r.paths[OUT_COLOR] = out->color;
    r.paths[OUT_MASK] = out->mask;
    r.paths[OUT_DEPTH] = out->depth;
    r.paths[OUT_NORMAL] = out->normal;
    r.paths[OUT_ID] = out->id;
    int full_w, full_h;
    full_size(options, &full_w, &full_h);
    if (has_region(options)) {
        r.x0 = options->region[0];
        r.y0 = options->region[1];
        r.width = options->region[2] - r.x0;
        r.height = options->region[3] - r.y0;
    } else {
        r.width = full_w;
        r.height = full_h;
    }
    /* Whether rank 0 could hold the image: the budget of sc_render. */
    sc_render_options whole = *options;
    whole.width = r.width;
    whole.height = r.height;
    sc_error budget;
    int fits = options->width <= RENDER_MAX_SIDE && options->height <= RENDER_MAX_SIDE &&
               render_check_memory(&whole, &budget) == SC_OK;
    if (dist_size() == 1 && fits && !out->tiled)
        return sc_render(scene, options, fb, error);
    r.streamed = out->tiled || !fits;
    if (r.streamed) { /* on every rank alike: the same command line */
        sc_status st = check_streamable(
            &r, out->tiled ? "--tiled writes each tile as it is done" : budget.message,
            error);
        if (st)
            return st;
    }
    r.side = tiles_side(r.width, r.height);
    r.tiles_x = (r.width + r.side - 1) / r.side;
    r.tiles_y = (r.height + r.side - 1) / r.side;
    /* Runs of tiles as long as TILES_UNIT_BYTES allows, shorter with
     * several ranks so that each gets TILES_UNITS_PER_RANK of them. */
    const sc_render_options *o = options;
    size_t pixel_bytes = (o->want_color ? 12 : 0) + (o->want_depth ? 4 : 0) +
                         (o->want_mask ? 1 : 0) + (o->want_normal ? 12 : 0) +
                         (o->want_id ? 4 : 0);
    size_t tile_bytes = (size_t)r.side * (size_t)r.side * (pixel_bytes ? pixel_bytes : 1);
    int window = TILES_WINDOW_PER_RANK * dist_size();
    if (window < TILES_WINDOW_MIN)
        window = TILES_WINDOW_MIN;
    size_t unit_bytes = TILES_HELD_BYTES / (size_t)window;
    if (unit_bytes > TILES_UNIT_BYTES)
        unit_bytes = TILES_UNIT_BYTES;
    r.per_unit = (int)(unit_bytes / tile_bytes);
    if (r.per_unit > r.tiles_x)
        r.per_unit = r.tiles_x;
    int ranks = dist_size();
    while (r.per_unit > 1 && ranks > 1 &&
           (int64_t)((r.tiles_x + r.per_unit - 1) / r.per_unit) * r.tiles_y <
               (int64_t)TILES_UNITS_PER_RANK * ranks)
        r.per_unit /= 2;
    if (r.per_unit < 1)
        r.per_unit = 1;
    r.units_x = (r.tiles_x + r.per_unit - 1) / r.per_unit;
    int out_of_memory = 0;
    if (dist_rank() == 0) {
        r.image = new_image(options, r.width, r.height, r.streamed);
        out_of_memory = r.image == NULL;
    }
    dist_work job;
    memset(&job, 0, sizeof job);
    /* Without its image rank 0 hands out no tile: the other ranks are told
     * to stop at once. */
    job.count = out_of_memory ? 0 : r.units_x * r.tiles_y;
    job.run = render_tile;
    job.pack = pack_run;
    job.unpack = unpack_run;
    job.deliver = deliver_tile;
    job.release = release_run;
    job.user = &r;
    job.window = window;
    job.cancel = options->cancel;
    double start = seconds_now();
    sc_status st = dist_run(&job, error);
    if (st == SC_OK && out_of_memory)
        st = err_set(error, SC_ERR_NOMEM, NULL, "out of memory for a %dx%d image",
                     r.width, r.height);
    if (r.image)
        r.image->stats.trace_seconds = seconds_now() - start;
    for (int o = 0; o < OUT_COUNT; o++) {
        if (!r.streams[o])
            continue;
        if (st == SC_OK)
            st = imgio_stream_finish(r.streams[o], options->cancel, error);
        else
            imgio_stream_abandon(r.streams[o]);
        r.streams[o] = NULL;
    }
    if (st == SC_OK && options->cancel && *options->cancel)
        st = err_set(error, SC_ERR_CANCELLED, NULL, "interrupted");
    sc_framebuffer_release(r.scratch);
    if (st) {
        sc_framebuffer_release(r.image);
        return st;
    }
    *fb = r.image;
    *written = r.streamed;
    return SC_OK;
}
