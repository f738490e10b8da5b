/* A DXF reader that gives the contours OpenSCAD 2021.01's DxfData gives,
 * for import("file.dxf") inside linear_extrude and rotate_extrude.
 *
 * The file is a list of (group code, value) line pairs. Code 0 ends the
 * entity being read and names the next; 2 names a section or block, 8 the
 * layer, 10/20 and 11/21 add x and y values (minus the origin, times the
 * scale, outside BLOCKS), 40 is a radius (times the scale) or an ellipse's
 * axis ratio, 41/42 an ellipse's angles or an insert's x/y scale, 50/51 an
 * arc's angles or an insert's rotation, 70 a polyline's flags. Entities
 * become line segments:
 *   LINE         (x0, y0) to (x1, y1)
 *   LWPOLYLINE   its vertices in order, closed when flag 1 is set
 *   CIRCLE       f segments, f from the radius by OpenSCAD's $fn/$fa/$fs
 *                rule (faithful_fragments), point k at 360 k / f degrees
 *   ARC          ceil(f * sweep / 360) segments from the start angle; the
 *                end angle is raised by 360 until it is not below the start
 *   ELLIPSE      ceil(f * sweep / 2 pi) segments, f from the major radius,
 *                turned by the angle of the major axis (code 11/21)
 *   INSERT       the named block's segments, scaled by 41/42, turned by 50,
 *                times the scale, moved to the insert point
 * In ENTITIES only the chosen layer's entities count (all when no layer is
 * given); in BLOCKS every entity counts, for the block being defined.
 * Other entities (SPLINE, POLYLINE, TEXT, ...) are ignored, as OpenSCAD
 * ignores them with a warning.
 *
 * Every end point is snapped to a grid of 2^-10 units: to its own cell when
 * that cell has points, else to the nearest neighbouring cell with points,
 * else to a new cell (OpenSCAD's Grid2d, including its way of searching the
 * neighbours). Segments are then joined into paths: first, repeatedly, a
 * path from the lowest segment with an end no other remaining segment
 * shares, followed from segment to segment through shared cells; then
 * closed paths from the lowest remaining segment. Each path becomes one
 * contour (an open one closed by its last edge), in reverse order, less
 * its first point, after OpenSCAD's fixup_path_direction has turned the
 * closed ones where there is no open path (fixup_direction); the caller
 * sanitizes them with the even-odd rule. Grid cells also list block
 * segments under the index the next drawing segment will get, as
 * OpenSCAD's do; that index can make an end look shared.
 *
 * The text is read as OpenSCAD reads it: line pairs split at '\n' only,
 * each line trimmed; codes and values parsed as boost::lexical_cast parses
 * them (values: decimal numbers, nan, inf and infinity in any case;
 * numbers that overflow are not numbers). Where OpenSCAD warns and reads
 * on, so does this reader, with OpenSCAD's warning at the DXF file's line
 * (dxf_options.warn; --strict makes it an error):
 *   a code that is not an integer ends the reading ("Illegal ID"), with no
 *   warning when the text has ended (a last line without its value, or
 *   without a newline); so a blank line ends it, text after 0 EOF is
 *   read, and a file with CR line ends is one line, read as nothing;
 *   a value that is not a number ("Illegal value") skips its pair;
 *   an entity short of points ("Not enough input values") is left out
 *   where OpenSCAD's .at() throws (a LWPOLYLINE after the edges it has),
 *   and as the exception skips the rest of OpenSCAD's case 0, the entity
 *   being read stays the one left out, with its values and settings: the
 *   next entity's values add to them, its name is lost.
 * Values that are not numbers (nan) and infinities flow on as numbers,
 * and a segment count that is one of those or past the int range draws
 * nothing, as OpenSCAD's conversion to int gives INT_MIN. Sizes are
 * limited (dxf.h).
 */
#include "formats/dxf.h"

#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "base/grow.h"
#include "formats/file.h"
#include "model/faithful.h"

#define DXF_GRID (1.0 / 1024.0) /* OpenSCAD's GRID_COARSE */
#define DXF_PI 3.14159265358979323846
/* Most turns an arc's or ellipse's end angle is raised by: OpenSCAD adds
 * a turn at a time (a start of 1e6 degrees and an end of 0 is 2778 turns;
 * 10^7 take a few milliseconds), and never ends where a turn no longer
 * changes the angle. */
enum { DXF_MAX_TURNS = 10000000 };

typedef struct text_ref {
    const char *s;
    size_t n;
} text_ref;

typedef struct cell {
    uint32_t *k; /* segment indices, in the order they were listed */
    uint32_t n, cap;
} cell;

typedef struct seg {
    uint32_t p[2]; /* point indices */
    int disabled;
} seg;

typedef struct block {
    text_ref name;
    uint32_t *p; /* 2 point indices per segment */
    uint32_t n, cap;
} block;

typedef struct reader {
    const char *path;
    sc_error *error;
    const dxf_options *o;
    int line;        /* the DXF line an error is set at */
    int entity_line; /* the line naming the entity being read */
    /* the grid: an open-addressing table from cell keys to cells */
    int64_t *keys;  /* 2 per slot */
    uint32_t *slot; /* cell index + 1, 0 when empty */
    size_t slot_cap;
    cell *cells;
    uint32_t cell_count, cell_cap;
    /* points (x, y and grid cell) and segments */
    double *xy;
    uint32_t *point_cell;
    uint32_t point_count;
    size_t xy_cap, point_cell_cap;
    seg *segs;
    uint32_t seg_count, seg_cap;
    uint32_t added;       /* segments added anywhere, for the limit */
    uint32_t block_lines; /* segments added in BLOCKS */
    block *blocks;
    uint32_t block_count, block_cap;
    /* the entity being read */
    text_ref mode, layer, iddata, current_block;
    int in_entities, in_blocks, flags;
    double *xs, *ys;
    uint32_t nx, ny, xs_cap, ys_cap;
    double radius, arc_start, arc_stop, ell_start, ell_stop;
    int short_of; /* the entity lacked a value OpenSCAD reads with .at() */
    uint32_t warnings;
    char *unsupported;
} reader;

static sc_status fail(reader *r, const char *format, const char *what)
{
    sc_location loc = {r->path, r->line, 1};
    return err_set(r->error, SC_ERR_SEMANTIC, &loc, format, what);
}

static sc_status nomem(reader *r)
{
    sc_location loc = {r->path, r->line, 1};
    return err_nomem(r->error, &loc);
}

/* A warning at the DXF line; see dxf_options.warn. Past DXF_MAX_WARNINGS
 * they are counted only: under --strict the first that changes the
 * drawing has stopped the reader long before. */
static sc_status warn(reader *r, int line, int changes, const char *format, ...)
    SC_PRINTF(4, 5);
static sc_status warn(reader *r, int line, int changes, const char *format, ...)
{
    if (!r->o->warn || ++r->warnings > DXF_MAX_WARNINGS)
        return SC_OK;
    char message[400];
    va_list args;
    va_start(args, format);
    vsnprintf(message, sizeof message, format, args);
    va_end(args);
    sc_location loc = {r->path, line, 1};
    return r->o->warn(r->o->warn_ctx, &loc, changes, message);
}

static int is(text_ref t, const char *s)
{
    size_t n = strlen(s);
    return t.n == n && memcmp(t.s, s, n) == 0;
}

static int same(text_ref a, text_ref b)
{
    return a.n == b.n && (a.n == 0 || memcmp(a.s, b.s, a.n) == 0);
}

/* ---- the grid ---- */

static uint64_t hash_key(int64_t x, int64_t y)
{
    uint64_t h = (uint64_t)x * 0x9E3779B97F4A7C15u ^ (uint64_t)y * 0xC2B2AE3D27D4EB4Fu;
    return h ^ (h >> 29);
}

/* The cell at (x, y), or UINT32_MAX. */
static uint32_t grid_find(const reader *r, int64_t x, int64_t y)
{
    if (!r->slot_cap)
        return UINT32_MAX;
    size_t mask = r->slot_cap - 1;
    for (size_t i = hash_key(x, y) & mask;; i = (i + 1) & mask) {
        if (!r->slot[i])
            return UINT32_MAX;
        if (r->keys[2 * i] == x && r->keys[2 * i + 1] == y)
            return r->slot[i] - 1;
    }
}

static void grid_put(reader *r, int64_t x, int64_t y, uint32_t c)
{
    size_t mask = r->slot_cap - 1;
    size_t i = hash_key(x, y) & mask;
    while (r->slot[i])
        i = (i + 1) & mask;
    r->slot[i] = c + 1;
    r->keys[2 * i] = x;
    r->keys[2 * i + 1] = y;
}

/* The cell at (x, y), made when it is missing; UINT32_MAX when memory runs
 * out. */
static uint32_t grid_cell(reader *r, int64_t x, int64_t y)
{
    uint32_t c = grid_find(r, x, y);
    if (c != UINT32_MAX)
        return c;
    if (2 * ((size_t)r->cell_count + 1) > r->slot_cap) {
        size_t cap = r->slot_cap ? 2 * r->slot_cap : 1024;
        int64_t *keys = malloc(cap * 2 * sizeof *keys);
        uint32_t *slot = calloc(cap, sizeof *slot);
        if (!keys || !slot) {
            free(keys);
            free(slot);
            return UINT32_MAX;
        }
        int64_t *old_keys = r->keys;
        uint32_t *old_slot = r->slot;
        size_t old_cap = r->slot_cap;
        r->keys = keys;
        r->slot = slot;
        r->slot_cap = cap;
        for (size_t i = 0; i < old_cap; i++)
            if (old_slot[i])
                grid_put(r, old_keys[2 * i], old_keys[2 * i + 1], old_slot[i] - 1);
        free(old_keys);
        free(old_slot);
    }
    if (!grow_array32((void **)&r->cells, &r->cell_cap, r->cell_count + 1,
                      sizeof *r->cells))
        return UINT32_MAX;
    c = r->cell_count++;
    memset(&r->cells[c], 0, sizeof r->cells[c]);
    grid_put(r, x, y, c);
    return c;
}

/* OpenSCAD's grid index of v: round(v / GRID_COARSE) converted to a
 * 64-bit integer as C++ converts on x86-64 (cvttsd2si: a value past the
 * range, or not a number, gives INT64_MIN), for coordinates past 2^53. */
static int64_t grid_index(double v)
{
    double d = round(v / DXF_GRID);
    if (!(d >= -9223372036854775808.0 && d < 9223372036854775808.0))
        return INT64_MIN;
    return (int64_t)d;
}

/* OpenSCAD's Grid2d::align: snaps (*x, *y) and returns its cell. */
static uint32_t grid_align(reader *r, double *x, double *y)
{
    int64_t ix = grid_index(*x);
    int64_t iy = grid_index(*y);
    /* At INT64_MIN OpenSCAD's loops start at the index minus 1, which
     * wraps round on x86-64 to past their end: they find nothing. */
    if (ix != INT64_MIN && iy != INT64_MIN && grid_find(r, ix, iy) == UINT32_MAX) {
        /* OpenSCAD moves ix and iy inside its search loops, which changes
         * their bounds and later distances; this does the same. */
        int dist = 10;
        for (int64_t jx = ix - 1; jx <= ix + 1; ++jx) {
            for (int64_t jy = iy - 1; jy <= iy + 1; ++jy) {
                if (grid_find(r, jx, jy) == UINT32_MAX)
                    continue;
                int d = abs((int)(ix - jx)) + abs((int)(iy - jy));
                if (d < dist) {
                    dist = d;
                    ix = jx;
                    iy = jy;
                }
            }
        }
    }
    *x = (double)ix * DXF_GRID;
    *y = (double)iy * DXF_GRID;
    return grid_cell(r, ix, iy);
}

static int cell_push(reader *r, uint32_t c, uint32_t k)
{
    cell *e = &r->cells[c];
    if (!grow_array32((void **)&e->k, &e->cap, e->n + 1, sizeof *e->k))
        return 0;
    e->k[e->n++] = k;
    return 1;
}

/* ---- points, segments and blocks ---- */

static uint32_t add_point(reader *r, double x, double y, uint32_t c)
{
    size_t n = r->point_count;
    if (!grow_array((void **)&r->xy, &r->xy_cap, 2 * n + 2, sizeof *r->xy) ||
        !grow_array((void **)&r->point_cell, &r->point_cell_cap, n + 1,
                    sizeof *r->point_cell))
        return UINT32_MAX;
    r->xy[2 * n] = x;
    r->xy[2 * n + 1] = y;
    r->point_cell[n] = c;
    return r->point_count++;
}

static block *find_block(reader *r, text_ref name)
{
    for (uint32_t i = 0; i < r->block_count; i++)
        if (same(r->blocks[i].name, name))
            return &r->blocks[i];
    return NULL;
}

static int layer_ok(const reader *r)
{
    const char *want = r->o->layer;
    return !want || !want[0] || is(r->layer, want);
}

/* OpenSCAD's ADD_LINE. */
static sc_status add_line(reader *r, double x1, double y1, double x2, double y2)
{
    if (!r->in_entities && !r->in_blocks)
        return SC_OK;
    if (r->in_entities && !layer_ok(r))
        return SC_OK;
    if (r->added >= DXF_MAX_SEGMENTS) {
        sc_location loc = {r->path, r->line, 1};
        return err_set(r->error, SC_ERR_LIMIT, &loc,
                       "too many line segments in a DXF drawing (limit is %u)",
                       DXF_MAX_SEGMENTS);
    }
    r->added++;
    r->block_lines += r->in_blocks;
    uint32_t c1 = grid_align(r, &x1, &y1);
    if (c1 == UINT32_MAX)
        return nomem(r);
    uint32_t c2 = grid_align(r, &x2, &y2);
    if (c2 == UINT32_MAX || !cell_push(r, c1, r->seg_count) ||
        !cell_push(r, c2, r->seg_count))
        return nomem(r);
    block *b = NULL;
    if (r->in_blocks && r->current_block.n && !(b = find_block(r, r->current_block))) {
        if (r->block_count >= DXF_MAX_BLOCKS) {
            sc_location loc = {r->path, r->line, 1};
            return err_set(r->error, SC_ERR_LIMIT, &loc,
                           "too many blocks in a DXF drawing (limit is %u)",
                           DXF_MAX_BLOCKS);
        }
        if (!grow_array32((void **)&r->blocks, &r->block_cap, r->block_count + 1,
                          sizeof *r->blocks))
            return nomem(r);
        b = &r->blocks[r->block_count++];
        memset(b, 0, sizeof *b);
        b->name = r->current_block;
    }
    if (!r->in_entities && !b)
        return SC_OK;
    uint32_t p1 = add_point(r, x1, y1, c1), p2 = add_point(r, x2, y2, c2);
    if (p1 == UINT32_MAX || p2 == UINT32_MAX)
        return nomem(r);
    if (r->in_entities) {
        if (!grow_array32((void **)&r->segs, &r->seg_cap, r->seg_count + 1,
                          sizeof *r->segs))
            return nomem(r);
        r->segs[r->seg_count++] = (seg){{p1, p2}, 0};
    } else {
        if (!grow_array32((void **)&b->p, &b->cap, 2 * b->n + 2, sizeof *b->p))
            return nomem(r);
        b->p[2 * b->n] = p1;
        b->p[2 * b->n + 1] = p2;
        b->n++;
    }
    return SC_OK;
}

/* ---- entities ---- */

static sc_status fragments(reader *r, double radius, long *n)
{
    *n = faithful_fragments(radius, r->o->fn, r->o->fs, r->o->fa);
    if (*n < 0) {
        sc_location loc = {r->path, r->line, 1};
        return err_set(r->error, SC_ERR_LIMIT, &loc,
                       "DXF circle or arc has too many fragments (limit is %d)",
                       FAITHFUL_MAX_FRAGMENTS);
    }
    return SC_OK;
}

static sc_status too_many(reader *r, double n)
{
    if (n <= DXF_MAX_SEGMENTS)
        return SC_OK;
    sc_location loc = {r->path, r->line, 1};
    return err_set(r->error, SC_ERR_LIMIT, &loc,
                   "too many line segments in a DXF drawing (limit is %u)",
                   DXF_MAX_SEGMENTS);
}

/* Whether the entity has count points: OpenSCAD reads them with .at(),
 * whose exception leaves the entity out (read_pairs, case 0). */
static int have(reader *r, uint32_t count)
{
    if (r->nx >= count && r->ny >= count)
        return 1;
    r->short_of = 1;
    return 0;
}

/* OpenSCAD's static_cast<int> of a segment count on x86-64: a count past
 * the int range, or not a number, is INT_MIN, which draws nothing. */
static double segment_count(double count)
{
    return count >= -2147483648.0 && count < 2147483648.0 ? count : 0;
}

static sc_status end_arc(reader *r)
{
    sc_status st;
    long f;
    if (!have(r, 1))
        return SC_OK;
    if ((st = fragments(r, r->radius, &f)) != SC_OK)
        return st;
    int turns = 0;
    while (r->arc_start > r->arc_stop) {
        if (++turns > DXF_MAX_TURNS)
            return fail(r, "DXF %s angles are too far apart", "ARC");
        r->arc_stop += 360.0;
    }
    double sweep = r->arc_stop - r->arc_start, cx = r->xs[0], cy = r->ys[0];
    double count = segment_count(ceil((double)f * sweep / 360));
    if ((st = too_many(r, count)) != SC_OK)
        return st;
    int n = (int)count;
    for (int i = 0; i < n; ++i) {
        double a1 = r->arc_start + sweep * i / n;
        double a2 = r->arc_start + sweep * (i + 1) / n;
        st = add_line(r, faithful_cos_deg(a1) * r->radius + cx,
                      faithful_sin_deg(a1) * r->radius + cy,
                      faithful_cos_deg(a2) * r->radius + cx,
                      faithful_sin_deg(a2) * r->radius + cy);
        if (st != SC_OK)
            return st;
    }
    return SC_OK;
}

static sc_status end_ellipse(reader *r)
{
    sc_status st;
    /* OpenSCAD raises the end angle before it reads the points */
    int turns = 0;
    while (r->ell_start > r->ell_stop && turns <= DXF_MAX_TURNS) {
        turns++;
        r->ell_stop += 2 * DXF_PI;
    }
    if (!have(r, 2))
        return SC_OK;
    if (turns > DXF_MAX_TURNS)
        return fail(r, "DXF %s angles are too far apart", "ELLIPSE");
    double cx = r->xs[0], cy = r->ys[0], ex = r->xs[1], ey = r->ys[1];
    double r_major = sqrt(ex * ex + ey * ey);
    double cosval = ex / r_major;
    if (cosval > 1.0)
        cosval = 1.0;
    if (cosval < -1.0)
        cosval = -1.0;
    double rot = acos(cosval);
    if (ey < 0.0)
        rot = 2 * DXF_PI - rot;
    double r_minor = r_major * r->radius, sweep = r->ell_stop - r->ell_start;
    long f;
    if ((st = fragments(r, r_major, &f)) != SC_OK)
        return st;
    double count = segment_count(ceil((double)f * sweep / (2 * DXF_PI)));
    if ((st = too_many(r, count)) != SC_OK)
        return st;
    int n = (int)count;
    double px = 0, py = 0;
    for (int i = 0; i <= n; ++i) {
        double a = r->ell_start + sweep * i / n;
        double x = cos(a) * r_major, y = sin(a) * r_minor;
        double qx = cos(rot) * x - sin(rot) * y + cx,
               qy = sin(rot) * x + cos(rot) * y + cy;
        if (i > 0 && (st = add_line(r, px, py, qx, qy)) != SC_OK)
            return st;
        px = qx;
        py = qy;
    }
    return SC_OK;
}

static sc_status end_insert(reader *r)
{
    sc_status st;
    block *b = find_block(r, r->iddata);
    /* OpenSCAD reads the insert point for each block segment */
    if (!b || !b->n || !have(r, 1))
        return SC_OK;
    uint32_t n = b->n;
    size_t index = (size_t)(b - r->blocks);
    double a = r->arc_start, s = r->o->scale;
    double c = faithful_cos_deg(a), sn = faithful_sin_deg(a);
    for (uint32_t i = 0; i < n; i++) {
        b = &r->blocks[index]; /* add_line may move the blocks */
        const double *p = r->xy + 2 * (size_t)b->p[2 * i];
        const double *q = r->xy + 2 * (size_t)b->p[2 * i + 1];
        double lx1 = p[0] * r->ell_start, ly1 = p[1] * r->ell_stop;
        double lx2 = q[0] * r->ell_start, ly2 = q[1] * r->ell_stop;
        st = add_line(
            r, (c * lx1 - sn * ly1) * s + r->xs[0], (sn * lx1 + c * ly1) * s + r->ys[0],
            (c * lx2 - sn * ly2) * s + r->xs[0], (sn * lx2 + c * ly2) * s + r->ys[0]);
        if (st != SC_OK)
            return st;
    }
    return SC_OK;
}

/* Code 0: the entity in r->mode is complete. */
static sc_status end_entity(reader *r)
{
    sc_status st = SC_OK;
    if (is(r->mode, "SECTION")) {
        r->in_entities = is(r->iddata, "ENTITIES");
        r->in_blocks = is(r->iddata, "BLOCKS");
    } else if (is(r->mode, "LINE")) {
        if (have(r, 2))
            st = add_line(r, r->xs[0], r->ys[0], r->xs[1], r->ys[1]);
    } else if (is(r->mode, "LWPOLYLINE")) {
        /* OpenSCAD goes round max(x count, y count) vertices, adding edges
         * until a vertex lacks a value */
        uint32_t n = r->nx > r->ny ? r->nx : r->ny;
        uint32_t m = r->nx < r->ny ? r->nx : r->ny;
        for (uint32_t i = 1; st == SC_OK && i < n; ++i) {
            if (i >= m) {
                r->short_of = 1;
                return SC_OK;
            }
            st = add_line(r, r->xs[i - 1], r->ys[i - 1], r->xs[i % n], r->ys[i % n]);
        }
        if (st == SC_OK && (r->flags & 1)) {
            if (n == 0 || n != m) {
                r->short_of = 1;
                return SC_OK;
            }
            st = add_line(r, r->xs[n - 1], r->ys[n - 1], r->xs[0], r->ys[0]);
        }
    } else if (is(r->mode, "CIRCLE")) {
        long n;
        if (!have(r, 1))
            return SC_OK;
        if ((st = fragments(r, r->radius, &n)) != SC_OK)
            return st;
        double cx = r->xs[0], cy = r->ys[0], rad = r->radius;
        for (long i = 0; st == SC_OK && i < n; ++i) {
            double a1 = (360.0 * (double)i) / (double)n;
            double a2 = (360.0 * (double)(i + 1)) / (double)n;
            st = add_line(
                r, faithful_cos_deg(a1) * rad + cx, faithful_sin_deg(a1) * rad + cy,
                faithful_cos_deg(a2) * rad + cx, faithful_sin_deg(a2) * rad + cy);
        }
    } else if (is(r->mode, "ARC")) {
        st = end_arc(r);
    } else if (is(r->mode, "ELLIPSE")) {
        st = end_ellipse(r);
    } else if (is(r->mode, "INSERT")) {
        st = end_insert(r);
    } else if (is(r->mode, "DIMENSION") && layer_ok(r)) {
        /* dimensions are annotations: no geometry */
    } else if (is(r->mode, "BLOCK")) {
        r->current_block = r->iddata;
    } else if (is(r->mode, "ENDBLK")) {
        r->current_block.n = 0;
    } else if (is(r->mode, "ENDSEC")) {
    } else if (r->in_blocks || (r->in_entities && layer_ok(r))) {
        if (r->unsupported && !r->unsupported[0]) {
            size_t n = r->mode.n < 31 ? r->mode.n : 31;
            memcpy(r->unsupported, r->mode.s, n);
            r->unsupported[n] = 0;
        }
    }
    return st;
}

/* ---- the text ---- */

/* std::getline then boost::trim: the next line of text from *pos, without
 * surrounding white space. A line that reaches the end of the text without
 * a newline sets *eof; once it is set no line is read (0, an empty line). */
static int next_line(const char *text, size_t size, size_t *pos, int *eof, text_ref *out)
{
    out->s = text + *pos;
    out->n = 0;
    if (*eof)
        return 0;
    size_t a = *pos, b = a;
    while (b < size && text[b] != '\n')
        b++;
    if (b < size) {
        *pos = b + 1;
    } else {
        *pos = size;
        *eof = 1;
    }
    size_t e = b;
    while (a < e && (text[a] == ' ' || (text[a] >= '\t' && text[a] <= '\r')))
        a++;
    while (e > a && (text[e - 1] == ' ' || (text[e - 1] >= '\t' && text[e - 1] <= '\r')))
        e--;
    out->s = text + a;
    out->n = e - a;
    return 1;
}

static int same_letters(const char *s, const char *lower, size_t n)
{
    for (size_t i = 0; i < n; i++)
        if (s[i] != lower[i] && s[i] != lower[i] - 'a' + 'A')
            return 0;
    return 1;
}

/* boost::lexical_cast<double>: [+-] then nan, nan(...), inf or infinity in
 * any case; else what libstdc++'s stream reads, all of the text: [+-],
 * digits with at most one point (one digit at least), an exponent [eE][+-]
 * digits; a value that overflows to infinity fails, one that underflows is
 * read. No hex, no 'd' exponent, no spaces inside. */
static int parse_double(text_ref t, double *out)
{
    const char *s = t.s;
    size_t n = t.n, i = 0;
    if (n == 0)
        return 0;
    int minus = s[0] == '-';
    if (minus || s[0] == '+')
        i = 1;
    if (n - i >= 3 && same_letters(s + i, "nan", 3)) {
        size_t rest = n - i - 3;
        if (rest && (rest < 2 || s[i + 3] != '(' || s[n - 1] != ')'))
            return 0;
        *out = copysign(NAN, minus ? -1.0 : 1.0);
        return 1;
    }
    if ((n - i == 3 && same_letters(s + i, "inf", 3)) ||
        (n - i == 8 && same_letters(s + i, "infinity", 8))) {
        *out = minus ? -INFINITY : INFINITY;
        return 1;
    }
    size_t digits = 0, point = 0;
    for (; i < n && ((s[i] >= '0' && s[i] <= '9') || (s[i] == '.' && !point)); i++) {
        point += s[i] == '.';
        digits += s[i] != '.';
    }
    if (!digits)
        return 0;
    if (i < n && (s[i] == 'e' || s[i] == 'E')) {
        i++;
        if (i < n && (s[i] == '+' || s[i] == '-'))
            i++;
        size_t exponent = 0;
        for (; i < n && s[i] >= '0' && s[i] <= '9'; i++)
            exponent++;
        if (!exponent)
            return 0;
    }
    if (i != n)
        return 0;
    char small[128];
    char *buf = n < sizeof small ? small : malloc(n + 1);
    if (!buf)
        return 0;
    memcpy(buf, s, n);
    buf[n] = 0;
    double v = strtod(buf, NULL);
    if (buf != small)
        free(buf);
    if (isinf(v))
        return 0;
    *out = v;
    return 1;
}

/* boost::lexical_cast<int>: [+-] then digits, all of the text, in range. */
static int parse_int(text_ref t, long *out)
{
    size_t i = 0;
    if (t.n == 0)
        return 0;
    int minus = t.s[0] == '-';
    if (minus || t.s[0] == '+')
        i = 1;
    if (i == t.n)
        return 0;
    long long v = 0;
    for (; i < t.n; i++) {
        char ch = t.s[i];
        if (ch < '0' || ch > '9')
            return 0;
        v = 10 * v + (ch - '0');
        if (v > 2147483648LL)
            return 0;
    }
    if (minus)
        v = -v;
    if (v > 2147483647LL)
        return 0;
    *out = (long)v;
    return 1;
}

static sc_status push_value(reader *r, double **a, uint32_t *n, uint32_t *cap, double v)
{
    if (*n > DXF_MAX_SEGMENTS)
        return too_many(r, (double)*n);
    if (!grow_array32((void **)a, cap, *n + 1, sizeof **a))
        return nomem(r);
    (*a)[(*n)++] = v;
    return SC_OK;
}

/* Shorter text for messages. */
#define SHOWN(t) (int)((t).n < 40 ? (t).n : 40), (t).s

/* OpenSCAD's loop over (group code, value) line pairs: a code that is not
 * an integer ends it, with a warning unless the text has ended; a value
 * that is not a number skips the rest of its pair, with a warning; an
 * entity short of points is left out at the next code 0, with a warning,
 * and as OpenSCAD's exception skips the rest of that case, the entity
 * being read stays what it was, with its values: those that follow add to
 * them. */
static sc_status read_pairs(reader *r, const char *text, size_t size)
{
    size_t pos = 0;
    int line = 0, eof = 0;
    text_ref code, data;
    while (!eof) {
        size_t code_at = pos;
        int code_line = line + 1;
        line += next_line(text, size, &pos, &eof, &code);
        line += next_line(text, size, &pos, &eof, &data);
        long id;
        if (!parse_int(code, &id)) {
            if (eof)
                break;
            /* only blank lines left: nothing more would have been drawn */
            int blank = 1;
            for (size_t i = code_at; i < size && blank; i++)
                blank = text[i] == ' ' || (text[i] >= '\t' && text[i] <= '\r');
            return warn(r, code_line, !blank,
                        "Illegal ID '%.*s': OpenSCAD reads no further in the DXF file",
                        SHOWN(code));
        }
        r->line = code_line;
        double v = 0;
        long iv = 0;
        int numeric = (id >= 10 && id <= 16) || (id >= 20 && id <= 26) || id == 40 ||
                      id == 41 || id == 42 || id == 50 || id == 51;
        if ((numeric && !parse_double(data, &v)) || (id == 70 && !parse_int(data, &iv))) {
            sc_status st =
                warn(r, code_line + 1, 1,
                     "Illegal value '%.*s' (group code %ld): OpenSCAD skips it",
                     SHOWN(data), id);
            if (st != SC_OK)
                return st;
            continue;
        }
        int raw = r->in_blocks;
        sc_status st = SC_OK;
        switch (id) {
        case 0:
            r->line = r->entity_line;
            r->short_of = 0;
            if ((st = end_entity(r)) != SC_OK)
                return st;
            if (r->short_of) {
                st = warn(r, r->entity_line, 1,
                          "Not enough input values for %.*s: OpenSCAD leaves out the "
                          "%.*s that lacks them, and reads the values after it as more "
                          "of it",
                          SHOWN(data), SHOWN(r->mode));
                break;
            }
            r->entity_line = code_line + 1; /* the line naming the entity */
            r->mode = data;
            r->layer.n = r->iddata.n = 0;
            r->flags = 0;
            r->nx = r->ny = 0;
            r->radius = r->arc_start = r->arc_stop = 0;
            r->ell_start = r->ell_stop = 0;
            if (is(r->mode, "INSERT"))
                r->ell_start = r->ell_stop = 1.0;
            break;
        case 2:
            r->iddata = data;
            break;
        case 8:
            r->layer = data;
            break;
        case 10:
        case 11:
            st = push_value(r, &r->xs, &r->nx, &r->xs_cap,
                            raw ? v : (v - r->o->origin_x) * r->o->scale);
            break;
        case 20:
        case 21:
            st = push_value(r, &r->ys, &r->ny, &r->ys_cap,
                            raw ? v : (v - r->o->origin_y) * r->o->scale);
            break;
        case 40:
            r->radius = raw ? v : v * r->o->scale;
            break;
        case 41:
            r->ell_start = v;
            break;
        case 42:
            r->ell_stop = v;
            break;
        case 50:
            r->arc_start = v;
            break;
        case 51:
            r->arc_stop = v;
            break;
        case 70:
            r->flags = (int)iv;
            break;
        default:
            break;
        }
        if (st != SC_OK)
            return st;
    }
    return SC_OK;
}

/* ---- joining segments into paths ---- */

static int shared_end(const reader *r, uint32_t idx, int j)
{
    const cell *e = &r->cells[r->point_cell[r->segs[idx].p[j]]];
    for (uint32_t i = 0; i < e->n; i++) {
        uint32_t k = e->k[i];
        if (k != idx && k < r->seg_count && !r->segs[k].disabled)
            return 1;
    }
    return 0;
}

/* Follows a path from segment cur's end cp, disabling the segments, and
 * adds it to out as a contour (reversed; open paths keep their first
 * point). */
/* OpenSCAD's fixup_path_direction on a closed path of n points (its last
 * the point it closes at): from the first point of the lowest x, b, with
 * a the point before it (n - 2 before the first) and c the one after (1
 * after the last), the path is reversed where atan2(a - b) < atan2(c - b)
 * with x and y swapped, as OpenSCAD calls it. Which point the contour then
 * drops (the path's first) changes the outline where the path passes a
 * point twice. */
static void fixup_direction(const reader *r, uint32_t *path, uint32_t n)
{
    if (n < 2)
        return;
    uint32_t b = 0;
    for (uint32_t j = 1; j < n; j++)
        if (r->xy[2 * (size_t)path[j]] < r->xy[2 * (size_t)path[b]])
            b = j;
    uint32_t a = b == 0 ? n - 2 : b - 1, c = b == n - 1 ? 1 : b + 1;
    const double *pa = r->xy + 2 * (size_t)path[a], *pb = r->xy + 2 * (size_t)path[b],
                 *pc = r->xy + 2 * (size_t)path[c];
    if (atan2(pa[0] - pb[0], pa[1] - pb[1]) < atan2(pc[0] - pb[0], pc[1] - pb[1]))
        for (uint32_t i = 0, j = n - 1; i < j; i++, j--) {
            uint32_t t = path[i];
            path[i] = path[j];
            path[j] = t;
        }
}

/* turn: a closed path OpenSCAD's fixup_path_direction reaches (it stops at
 * the first open path, and open paths come first). */
static sc_status follow(reader *r, uint32_t cur, int cp, int closed, int turn,
                        uint32_t *path, uint32_t *count, twod_region *out)
{
    uint32_t n = 0;
    path[n++] = r->segs[cur].p[cp];
    for (;;) {
        uint32_t ref = r->segs[cur].p[!cp];
        path[n++] = ref;
        r->segs[cur].disabled = 1;
        const cell *e = &r->cells[r->point_cell[ref]];
        int found = 0;
        for (uint32_t i = 0; i < e->n && !found; i++) {
            uint32_t k = e->k[i];
            if (k >= r->seg_count || r->segs[k].disabled)
                continue;
            for (int j = 0; j < 2 && !found; j++) {
                if (r->point_cell[r->segs[k].p[j]] == r->point_cell[ref]) {
                    cur = k;
                    cp = j;
                    found = 1;
                }
            }
        }
        if (!found)
            break;
    }
    *count = n;
    if (closed && turn)
        fixup_direction(r, path, n);
    if (!twod_begin_contour(out))
        return nomem(r);
    for (uint32_t j = 1; j < (closed ? n : n + 1); j++) {
        const double *p = r->xy + 2 * (size_t)path[n - j];
        if (!twod_add_point(out, p[0], p[1]))
            return nomem(r);
    }
    return SC_OK;
}

static sc_status join_paths(reader *r, twod_region *out)
{
    if (!r->seg_count)
        return SC_OK;
    uint32_t *path = malloc(((size_t)r->seg_count + 2) * sizeof *path);
    if (!path)
        return nomem(r);
    sc_status st = SC_OK;
    uint32_t n;
    int opened = 0; /* an open path was made */
    /* open paths: from the lowest segment with an unshared end. Segments
     * below the last start had no unshared end, and only those listed in
     * the cells of the path just taken can have one now, so the next
     * search starts at the lowest of those; block segments listed under
     * drawing indices break that reasoning, and with them every search
     * starts at 0. */
    for (uint32_t start = 0, again = 1; again && st == SC_OK;) {
        again = 0;
        for (uint32_t idx = start; idx < r->seg_count && !again; idx++) {
            if (r->segs[idx].disabled)
                continue;
            for (int j = 0; j < 2 && !again; j++) {
                if (!shared_end(r, idx, j)) {
                    st = follow(r, idx, j, 0, 0, path, &n, out);
                    opened = 1;
                    again = 1;
                    start = r->block_lines ? 0 : idx;
                    for (uint32_t i = 0; i < n && start; i++) {
                        const cell *e = &r->cells[r->point_cell[path[i]]];
                        for (uint32_t q = 0; q < e->n; q++)
                            if (e->k[q] < start && !r->segs[e->k[q]].disabled)
                                start = e->k[q];
                    }
                }
            }
        }
    }
    /* closed paths: from the lowest remaining segment */
    for (uint32_t idx = 0; idx < r->seg_count && st == SC_OK; idx++)
        if (!r->segs[idx].disabled)
            st = follow(r, idx, 0, 1, !opened, path, &n, out);
    free(path);
    return st;
}

static void reader_free(reader *r)
{
    for (uint32_t i = 0; i < r->cell_count; i++)
        free(r->cells[i].k);
    for (uint32_t i = 0; i < r->block_count; i++)
        free(r->blocks[i].p);
    free(r->cells);
    free(r->keys);
    free(r->slot);
    free(r->xy);
    free(r->point_cell);
    free(r->segs);
    free(r->blocks);
    free(r->xs);
    free(r->ys);
}

sc_status dxf_read(const char *text, size_t size, const char *path, const dxf_options *o,
                   twod_region *out, char *unsupported, sc_error *error)
{
    reader r;
    memset(&r, 0, sizeof r);
    r.path = path;
    r.error = error;
    r.o = o;
    r.unsupported = unsupported;
    if (unsupported)
        unsupported[0] = 0;
    twod_clear(out);
    sc_status st = read_pairs(&r, text, size);
    if (st == SC_OK && r.warnings > DXF_MAX_WARNINGS) {
        char message[120];
        snprintf(message, sizeof message,
                 "%u more warnings of the DXF file are not shown",
                 r.warnings - DXF_MAX_WARNINGS);
        sc_location loc = {path, 0, 0};
        st = o->warn(o->warn_ctx, &loc, 0, message);
    }
    if (st == SC_OK)
        st = join_paths(&r, out);
    reader_free(&r);
    out->sanitized = 0;
    return st;
}

sc_status dxf_read_file(const char *path, const sc_location *at, const dxf_options *o,
                        twod_region *out, char *unsupported, sc_error *error)
{
    size_t len = 0;
    const char *why = NULL;
    char *buf = file_read(path, DXF_MAX_FILE, &len, &why);
    sc_status st;
    if (!buf)
        st = err_set(error, why == file_no_memory ? SC_ERR_NOMEM : SC_ERR_IO, at,
                     "import: cannot read '%s': %s", path, why);
    else
        st = dxf_read(buf, len, path, o, out, unsupported, error);
    free(buf);
    return st;
}
