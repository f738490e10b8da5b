/* text(): OpenSCAD 2021.01's text layout, as glyph outlines of lines and
 * quadratic and cubic Bezier curves, and linear_extrude of it.
 *
 *   text(text, size = 10, font, direction, language = "en", script,
 *        halign = "left", valign = "baseline", spacing = 1, $fn, $fa, $fs)
 *
 * Layout, step by step as OpenSCAD's FreetypeRenderer does it:
 *   - font: fontconfig matches the name ("Liberation Sans:style=Regular"
 *     when it is empty) as an outline, scalable font; the face's Unicode
 *     character map is selected. A name whose family fontconfig does not
 *     have matches some other family, silently in OpenSCAD; here with a
 *     warning that names both.
 *   - script and direction: when not given, the script of the text's
 *     characters (ignoring common and inherited ones; mixed scripts give
 *     "unknown") and that script's horizontal direction.
 *   - FreeType at char size 1e5 (26.6 points, 100 dpi), glyphs loaded with
 *     FreeType's default (hinted) outlines, shaped by HarfBuzz at that size.
 *   - an outline point v is FreeType's coordinate over scale = 1e5, while
 *     advances and offsets are HarfBuzz's over 1.024e5 (OpenSCAD keeps this
 *     2.4 % ratio for compatibility); a point of glyph g lands at
 *     size * ((v + offset_g) + advance_g), advance_g the sum of the earlier
 *     glyphs' advances times spacing;
 *   - horizontal text: width = sum of advances times spacing, ascent and
 *     descent the largest of the glyphs' grid-fitted boxes above and below
 *     the baseline; halign right/center shifts by -width or -width / 2,
 *     valign top/center/bottom by -ascent, (descent - ascent) / 2, descent.
 *     Vertical text: width the widest box, the advances summed as ascent.
 *     An unknown halign or valign is left or baseline, with a warning.
 *
 * Curves: FreeType's conic (quadratic) and cubic segments are kept as they
 * are for the exact outline prism. OpenSCAD flattens each into n points,
 * n = max(floor(fragments(size) / 8) + 1, 2) with its circle fragment rule
 * (faithful.h) at radius size: point k of n at a = k * (1 / n), as
 * pen (1-a)^2 + c1 * 2 (1-a) a + to a^2 (cubic likewise with pow), in the
 * glyph's own units before the offset and size; faithful mode does exactly
 * that. OpenSCAD then unions the glyph polygons with Clipper, by the
 * nonzero rule, on a grid of 2^-16 (coordinates truncated).
 *
 * Fill: the nonzero rule. TrueType fonts wind outlines clockwise,
 * PostScript ones counter-clockwise; each glyph is turned (all its contours
 * reversed) so that its outline runs counter-clockwise in the extrusion's
 * frame, so overlapping glyphs and mirrored copies unite.
 *
 * The layout itself (fontconfig, HarfBuzz, FreeType) is the plugin
 * spancast-text.so (text/text_freetype.c, text_layout.h), loaded by the
 * first text node, so that a model without text never loads those
 * libraries; without the plugin a text node is an error that names it.
 */
#include "build/build_text.h"

#include <ctype.h>
#include <math.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "base/grow.h"
#include "build/build_mesh.h"
#include "build/build_twod.h"
#include "build/text_layout.h"
#include "formats/plugin.h"
#include "model/faithful.h"
#include "twod/twod.h"

/* fontconfig 2.14.1 (Debian 12) loses 288 bytes while it parses its
 * configuration, once per process (seen with a five-line program that only
 * calls FcFontMatch). Sanitizer builds would report it as our leak; this
 * tells LeakSanitizer to ignore leaks allocated inside fontconfig. */
#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define TEXT_UNDER_ASAN 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__)
#define TEXT_UNDER_ASAN 1
#endif
#ifdef TEXT_UNDER_ASAN
const char *__lsan_default_suppressions(void);
const char *__lsan_default_suppressions(void)
{
    return "leak:libfontconfig.so\n";
}
#endif

/* ---- arguments ---- */

static void set_note(sc_error *note, const model_node *n, const char *file,
                     const char *message, const char *x, const char *y)
{
    if (!note || note->message[0])
        return; /* the first warning of a node is kept */
    sc_location loc = {file, n->loc.line, n->loc.column};
    err_set(note, SC_OK, &loc, message, x, y);
}

void text_shape_free(text_shape *s)
{
    free(s->segs);
    free(s->contour_start);
    free(s->glyph_start);
    free(s->offset);
    free(s->advance);
    memset(s, 0, sizeof *s);
}

static sc_status build_shape(const build_ctx *c, const model_node *n, text_shape *out,
                             sc_error *note)
{
    memset(out, 0, sizeof *out);
    if (n->pending)
        return build_pending(c, n);
    const model_text *a = n->u.text;
    if (!isfinite(a->size)) {
        /* OpenSCAD 2021.01 draws nothing for a size of inf or nan (a
         * .scad's 1/0, which its export writes as inf): no glyphs */
        out->curve_points = 2;
        return SC_OK;
    }
    long fragments = faithful_fragments(a->size, a->res.fn, a->res.fs, a->res.fa);
    out->curve_points = fragments < 0 ? 0 : (uint32_t)fmax(floor(fragments / 8.0) + 1, 2);
    out->size = a->size;
    if (a->length == 0)
        return SC_OK;
    char note_text[512] = "", why[512] = "";
    void *fn = NULL, *handle = NULL;
    static const char *const names[] = {"spancast_text_layout"};
    if (!plugin_load(TEXT_PLUGIN_FILE, "text", names, 1, &fn, &handle, why, sizeof why))
        return err_set(c->error, SC_ERR_IO, &n->loc, "text: %s", why);
    text_layout_fn *layout;
    /* A function pointer from dlsym: POSIX guarantees the conversion. */
    *(void **)&layout = fn;
    sc_status st = layout(a, out, note_text, sizeof note_text, why, sizeof why);
    plugin_unload(&handle);
    if (note_text[0])
        set_note(note, n, c->file, "%s%s", note_text, "");
    if (st == SC_ERR_NOMEM && !why[0])
        err_nomem(c->error, &n->loc);
    else if (st != SC_OK)
        err_set(c->error, st, &n->loc, "%s", why);
    if (st != SC_OK)
        text_shape_free(out);
    return st;
}

sc_status text_register_font(const char *path, sc_error *error)
{
    static pthread_mutex_t lock = PTHREAD_MUTEX_INITIALIZER;
    static void *pinned; /* the plugin's handle, never released */
    static const char *const names[] = {"spancast_text_register"};
    char why[512] = "";
    void *fn = NULL, *handle = NULL;
    if (!plugin_load(TEXT_PLUGIN_FILE, "text", names, 1, &fn, &handle, why, sizeof why))
        return err_set(error, SC_ERR_IO, NULL, "text: %s", why);
    text_register_fn *add;
    /* A function pointer from dlsym: POSIX guarantees the conversion. */
    *(void **)&add = fn;
    pthread_mutex_lock(&lock);
    sc_status st = add(path, why, sizeof why);
    if (!pinned) {
        pinned = handle;
        handle = NULL;
    }
    pthread_mutex_unlock(&lock);
    plugin_unload(&handle);
    if (st != SC_OK)
        return err_set(error, st, NULL, "%s", why);
    return SC_OK;
}

sc_status text_shape_build(const build_ctx *c, const model_node *n, text_shape *out,
                           sc_error *note)
{
    return build_shape(c, n, out, note);
}

/* ---- OpenSCAD's polygons ---- */

/* Adds (x, y) to the contour being built unless it repeats the previous
 * point; 0 when memory runs out or the region is full (TWOD_MAX_POINTS). */
static int poly_point(twod_region *r, double x, double y)
{
    uint32_t n = r->point_count;
    uint32_t s = r->start[r->contour_count - 1];
    if (n > s && r->xy[2 * n - 2] == x && r->xy[2 * n - 1] == y)
        return 1; /* a repeat of the previous point */
    return twod_add_point(r, x, y);
}

/* OpenSCAD's add_vertex and Clipper's snap: size * ((v + offset) +
 * advance), truncated to a multiple of 2^-16. */
static double place(double v, double offset, double advance, double size)
{
    double x = size * ((v + offset) + advance);
    return trunc(x * 65536.0) / 65536.0;
}

static sc_status flatten(const build_ctx *c, const model_node *n, const text_shape *s,
                         twod_region *out)
{
    uint32_t fn = s->curve_points;
    for (uint32_t g = 0; g < s->glyph_count; g++) {
        double ox = s->offset[2 * g], oy = s->offset[2 * g + 1];
        double ax = s->advance[2 * g], ay = s->advance[2 * g + 1];
        uint32_t first = out->contour_count;
        for (uint32_t k = s->glyph_start[g]; k < s->glyph_start[g + 1]; k++) {
            if (!twod_begin_contour(out))
                return err_nomem(c->error, &n->loc);
            const outline_seg *seg0 = &s->segs[s->contour_start[k]];
            if (!poly_point(out, place(seg0->x[0], ox, ax, s->size),
                            place(seg0->y[0], oy, ay, s->size)))
                return build_twod_add_error(c, n, out);
            for (uint32_t i = s->contour_start[k]; i < s->contour_start[k + 1]; i++) {
                const outline_seg *q = &s->segs[i];
                if (q->degree == 1) {
                    if (!poly_point(out, place(q->x[1], ox, ax, s->size),
                                    place(q->y[1], oy, ay, s->size)))
                        return build_twod_add_error(c, n, out);
                    continue;
                }
                for (uint32_t idx = 1; idx <= fn; idx++) {
                    const double a = idx * (1.0 / (double)fn);
                    double v[2];
                    for (int axis = 0; axis < 2; axis++) {
                        const double *p = axis ? q->y : q->x;
                        if (q->degree == 2)
                            v[axis] = p[0] * pow(1 - a, 2) +
                                      p[1] * 2 * pow(1 - a, 1) * a + p[2] * pow(a, 2);
                        else
                            v[axis] =
                                p[0] * pow(1 - a, 3) + p[1] * 3 * pow(1 - a, 2) * a +
                                p[2] * 3 * pow(1 - a, 1) * pow(a, 2) + p[3] * pow(a, 3);
                    }
                    if (!poly_point(out, place(v[0], ox, ax, s->size),
                                    place(v[1], oy, ay, s->size)))
                        return build_twod_add_error(c, n, out);
                }
            }
            twod_end_contour(out);
        }
        double area = 0;
        for (uint32_t k = first; k < out->contour_count; k++)
            area += twod_contour_area(out, k);
        if (area < 0)
            for (uint32_t k = first; k < out->contour_count; k++)
                twod_reverse_contour(out, k);
    }
    return SC_OK;
}

sc_status text_faithful_polygons(const build_ctx *c, const model_node *n,
                                 twod_region *out, sc_error *note)
{
    twod_clear(out);
    text_shape s;
    sc_status st = build_shape(c, n, &s, note);
    if (st != SC_OK)
        return st;
    if (s.curve_points == 0) {
        text_shape_free(&s);
        return err_set(c->error, SC_ERR_LIMIT, &n->loc,
                       "faithful mode: $fn, $fa and $fs of text size %g give too many "
                       "fragments (limit is %d)",
                       n->u.text->size, FAITHFUL_MAX_FRAGMENTS);
    }
    st = flatten(c, n, &s, out);
    text_shape_free(&s);
    if (st != SC_OK)
        twod_clear(out);
    return st;
}

/* ---- linear_extrude of text ---- */

/* group, union, render, color and multmatrix: the nodes text may be in. */
static int is_container(model_kind kind)
{
    return kind == MODEL_UNION || kind == MODEL_COLOR || kind == MODEL_XFORM;
}

/* Below n, under the containers: whether some 2D shape is text (all = 0;
 * '%' subtrees count) or every one is (all = 1; '%' subtrees do not). */
static int text_below(const model_node *n, int depth, int all)
{
    if (depth > TWOD_WALK_MAX_DEPTH)
        return 0;
    unsigned skipped = all ? MODEL_MOD_DISABLE | MODEL_MOD_BACKGROUND : MODEL_MOD_DISABLE;
    if (n->modifiers & skipped)
        return all;
    model_kind kind = n->kind;
    if (kind == MODEL_TEXT)
        return 1;
    if (!is_container(kind))
        return 0;
    for (const model_node *k = n->first_child; k; k = k->next)
        if (text_below(k, depth + 1, all) != all)
            return !all;
    return all;
}

int build_text_only(const model_node *n)
{
    if (!build_text_wanted(n))
        return 0;
    for (const model_node *k = n->first_child; k; k = k->next)
        if (!text_below(k, 1, 1))
            return 0;
    return 1;
}

int build_text_wanted(const model_node *n)
{
    for (const model_node *k = n->first_child; k; k = k->next)
        if (text_below(k, 1, 0))
            return 1;
    return 0;
}

/* The exact outlines gathered by the one 2D walk (build_twod.h). */
typedef struct gathered {
    twod_walker walk; /* first: the visitor is the walker */
    outline_seg *segs;
    uint32_t seg_count, seg_cap;
} gathered;

static sc_status gather_text(const build_ctx *c, const model_node *n, const affine2 *m,
                             gathered *g)
{
    sc_status st;
    text_shape s;
    if ((st = text_shape_build(c, n, &s, c->note)) != SC_OK)
        return st;
    if (s.size == 0)
        s.glyph_count = 0; /* every point at the origin: no area */
    for (uint32_t gi = 0; gi < s.glyph_count && st == SC_OK; gi++) {
        uint32_t first = g->seg_count;
        double area = 0;
        for (uint32_t i = s.contour_start[s.glyph_start[gi]];
             i < s.contour_start[s.glyph_start[gi + 1]]; i++) {
            outline_seg q = s.segs[i];
            for (uint32_t j = 0; j <= q.degree; j++) {
                q.x[j] = s.size * ((q.x[j] + s.offset[2 * gi]) + s.advance[2 * gi]);
                q.y[j] =
                    s.size * ((q.y[j] + s.offset[2 * gi + 1]) + s.advance[2 * gi + 1]);
                affine2_apply(m, q.x[j], q.y[j], &q.x[j], &q.y[j]);
            }
            if (!isfinite(q.x[0]) || !isfinite(q.y[0]))
                continue;
            /* the control polygon's area: its sign is the glyph's turn */
            for (uint32_t j = 0; j < q.degree; j++)
                area += q.x[j] * q.y[j + 1] - q.x[j + 1] * q.y[j];
            if (!grow_array32((void **)&g->segs, &g->seg_cap, g->seg_count + 1,
                              sizeof *g->segs)) {
                st = err_nomem(c->error, &n->loc);
                break;
            }
            g->segs[g->seg_count++] = q;
        }
        if (area < 0) {
            /* reverse each segment; contour order does not matter to the
             * crossings, only each segment's direction */
            for (uint32_t i = first; i < g->seg_count; i++) {
                outline_seg *q = &g->segs[i];
                for (uint32_t j = 0; j < (q->degree + 1) / 2; j++) {
                    uint32_t k = q->degree - j;
                    double tx = q->x[j], ty = q->y[j];
                    q->x[j] = q->x[k];
                    q->y[j] = q->y[k];
                    q->x[k] = tx;
                    q->y[k] = ty;
                }
            }
        }
    }
    text_shape_free(&s);
    return st;
}

/* The walk's visitor: the text below n, under the containers. */
static sc_status gather(twod_walker *walk, const model_node *n, const affine2 *m,
                        int depth, void *out)
{
    (void)out;
    const build_ctx *c = walk->c;
    const char *name = n->name;
    model_kind kind = n->kind;
    if (kind == MODEL_TEXT)
        return gather_text(c, n, m, (gathered *)walk);
    if (kind == MODEL_SQUARE || kind == MODEL_CIRCLE || kind == MODEL_POLYGON)
        return err_set(c->error, SC_ERR_UNSUPPORTED, &n->loc,
                       "'%s' beside text inside linear_extrude is not supported yet",
                       name);
    if (!is_container(kind))
        return err_set(c->error, SC_ERR_UNSUPPORTED, &n->loc,
                       "'%s' inside linear_extrude is not supported yet", name);
    affine2 inner = *m;
    if (kind == MODEL_XFORM) {
        sc_status st = twod_walk_fold(walk, n, m, &inner);
        if (st != SC_OK)
            return st;
    }
    return twod_walk_children(walk, n, &inner, depth);
}

sc_status build_text_extrude(const build_ctx *c, const model_node *n, double height,
                             int center, int emit, prim *out, const char **empty)
{
    gathered g;
    memset(&g, 0, sizeof g);
    g.walk = (twod_walker){c, "linear_extrude", "nodes", gather};
    affine2 id = affine2_identity();
    sc_status st = twod_walk_children(&g.walk, n, &id, 0);
    if (st == SC_OK && emit) {
        double z0 = center ? -height / 2 : 0, z1 = z0 + height;
        if (!(height > 0 && isfinite(height)) || g.seg_count == 0) {
            *empty = "linear_extrude without height or area is empty";
        } else {
            const prim_outline *o =
                prim_outline_create(c->csg, g.segs, g.seg_count, z0, z1);
            if (!o) {
                st = err_nomem(c->error, &n->loc);
            } else {
                memset(out, 0, sizeof *out);
                out->kind = PRIM_OUTLINE;
                out->u.outline.outline = o;
            }
        }
    }
    free(g.segs);
    return st;
}
