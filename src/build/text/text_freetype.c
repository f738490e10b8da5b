/* The text plugin (spancast-text.so, text_layout.h): text() laid out as
 * OpenSCAD 2021.01's FreetypeRenderer does it, through fontconfig, HarfBuzz
 * and FreeType, the only code that links them. build_text.c describes the
 * layout, step by step; this file is those steps. It fills the text_shape
 * with malloc'd arrays and reports failures and warnings as text, never
 * printing; build_text.c adds the node's position.
 *
 * fontconfig's configuration is its own (the process's default, built on
 * first use), with the font files spancast_text_register adds to it and
 * the folders of OPENSCAD_FONT_PATH, as OpenSCAD's FontCache adds them; the
 * FreeType library and face live for one node's layout.
 */
#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include <fontconfig/fontconfig.h>
#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_GLYPH_H
#include FT_OUTLINE_H
#include FT_TRUETYPE_IDS_H
#include <hb-ft.h>
#include <hb.h>

#include "base/grow.h"
#include "build/text_layout.h"

static const double ft_scale = 1e5;
static const double hb_unscale = 1.0 / 1.024e5;
static const char default_font[] = "Liberation Sans:style=Regular";

/* Where one layout's messages go (text_layout_fn). */
typedef struct layout_ctx {
    char *note, *err;
    size_t note_size, err_size;
} layout_ctx;

/* A failure: its message into c->err; returns status. */
static sc_status fail(layout_ctx *c, sc_status status, const char *format, ...)
    __attribute__((format(printf, 3, 4)));
static sc_status fail(layout_ctx *c, sc_status status, const char *format, ...)
{
    va_list ap;
    va_start(ap, format);
    vsnprintf(c->err, c->err_size, format, ap);
    va_end(ap);
    return status;
}

/* Out of memory: no message, the caller has the one of err_nomem. */
static sc_status nomem(layout_ctx *c)
{
    if (c->err_size)
        c->err[0] = 0;
    return SC_ERR_NOMEM;
}

/* A warning, when none has been given yet (the first of a node is kept). */
static void put_note(layout_ctx *c, const char *format, const char *x, const char *y)
    __attribute__((format(printf, 2, 0)));
static void put_note(layout_ctx *c, const char *format, const char *x, const char *y)
{
    if (!c->note_size || c->note[0])
        return;
    snprintf(c->note, c->note_size, format, x, y);
}

/* ---- font lookup ---- */

/* Whether the face's charmap is a Windows symbol font's, with its
 * characters at 0xf000 and above, the Private Use Area of Unicode
 * (OpenSCAD's FontCache::is_windows_symbol_font). */
static int is_windows_symbol_font(FT_Face face)
{
    if (!face->charmap || face->charmap->platform_id != TT_PLATFORM_MICROSOFT ||
        face->charmap->encoding_id != TT_MS_ID_SYMBOL_CS)
        return 0;
    FT_UInt glyph;
    FT_ULong first = FT_Get_First_Char(face, &glyph);
    return glyph != 0 && first >= 0xf000;
}

/* Sets the first charmap of the face for platform and encoding (-1: any). */
static int try_charmap(FT_Face face, int platform, int encoding)
{
    for (int k = 0; k < face->num_charmaps; k++) {
        FT_CharMap m = face->charmaps[k];
        if (m->platform_id == platform && (encoding < 0 || m->encoding_id == encoding) &&
            FT_Set_Charmap(face, m) == 0)
            return 1;
    }
    return 0;
}

/* The face's charmap as OpenSCAD 2021.01 chooses it (FontCache::find_face):
 * Unicode, else the first of a list that ends with symbol and 8-bit
 * charmaps. */
static void choose_charmap(FT_Face face)
{
    static const int order[][2] = {{TT_PLATFORM_MICROSOFT, TT_MS_ID_UNICODE_CS},
                                   {TT_PLATFORM_ISO, TT_ISO_ID_10646},
                                   {TT_PLATFORM_APPLE_UNICODE, -1},
                                   {TT_PLATFORM_MICROSOFT, TT_MS_ID_SYMBOL_CS},
                                   {TT_PLATFORM_MACINTOSH, TT_MAC_ID_ROMAN},
                                   {TT_PLATFORM_ISO, TT_ISO_ID_8859_1},
                                   {TT_PLATFORM_ISO, TT_ISO_ID_7BIT_ASCII}};
    if (FT_Select_Charmap(face, FT_ENCODING_UNICODE) == 0)
        return;
    for (size_t k = 0; k < sizeof order / sizeof order[0]; k++)
        if (try_charmap(face, order[k][0], order[k][1]))
            return;
}

/* The folders of OPENSCAD_FONT_PATH (':'-separated; those that are not
 * folders are passed over) added to fontconfig's fonts, once per process,
 * as OpenSCAD 2021.01's FontCache adds them before its first font. */
static void add_font_path(void)
{
    static atomic_int added;
    if (atomic_exchange(&added, 1))
        return;
    const char *path = getenv("OPENSCAD_FONT_PATH");
    char dir[4096];
    while (path && *path) {
        size_t len = strcspn(path, ":");
        struct stat st;
        if (len > 0 && len < sizeof dir) {
            memcpy(dir, path, len);
            dir[len] = 0;
            if (stat(dir, &st) == 0 && S_ISDIR(st.st_mode))
                FcConfigAppFontAddDir(NULL, (const FcChar8 *)dir);
        }
        path += len + (path[len] == ':');
    }
}

/* Opens the face fontconfig matches for name (OpenSCAD's find_face); on a
 * family fontconfig does not have, leaves a warning in note. */
static sc_status open_face(layout_ctx *c, FT_Library lib, const char *font, FT_Face *face)
{
    const char *start = font;
    while (*start && isspace((unsigned char)*start))
        start++;
    size_t len = strlen(start);
    while (len > 0 && isspace((unsigned char)start[len - 1]))
        len--;
    char *name = malloc(len + 1);
    if (!name)
        return nomem(c);
    memcpy(name, start, len);
    name[len] = 0;
    const char *lookup = len ? name : default_font;
    add_font_path();
    FcPattern *pattern = FcNameParse((const FcChar8 *)lookup);
    if (!pattern) {
        free(name);
        return fail(c, SC_ERR_SEMANTIC,
                    "text: font name '%s' is not a fontconfig pattern", font);
    }
    FcPatternAddBool(pattern, FC_OUTLINE, FcTrue);
    FcPatternAddBool(pattern, FC_SCALABLE, FcTrue);
    FcChar8 *wanted = NULL;
    FcPatternGetString(pattern, FC_FAMILY, 0, &wanted);
    char *wanted_copy = NULL;
    if (wanted) {
        size_t wl = strlen((const char *)wanted);
        if (!(wanted_copy = malloc(wl + 1))) {
            FcPatternDestroy(pattern);
            free(name);
            return nomem(c);
        }
        memcpy(wanted_copy, wanted, wl + 1);
    }
    FcConfigSubstitute(NULL, pattern, FcMatchPattern);
    FcDefaultSubstitute(pattern);
    FcResult result;
    FcPattern *match = FcFontMatch(NULL, pattern, &result);
    FcPatternDestroy(pattern);
    FcChar8 *file = NULL;
    int index = 0;
    sc_status st = SC_OK;
    if (!match || FcPatternGetString(match, FC_FILE, 0, &file) != FcResultMatch ||
        FcPatternGetInteger(match, FC_INDEX, 0, &index) != FcResultMatch) {
        st = fail(c, SC_ERR_SEMANTIC,
                  "text: no font matches '%s' (is fontconfig set up?)", lookup);
    } else if (FT_New_Face(lib, (const char *)file, index, face) != 0) {
        st = fail(c, SC_ERR_IO, "text: cannot open font file '%s'", (const char *)file);
    } else {
        choose_charmap(*face);
        if (wanted_copy) {
            int same = 0;
            FcChar8 *family = NULL;
            for (int i = 0;
                 FcPatternGetString(match, FC_FAMILY, i, &family) == FcResultMatch; i++)
                if (FcStrCmpIgnoreCase(family, (const FcChar8 *)wanted_copy) == 0)
                    same = 1;
            if (!same &&
                FcPatternGetString(match, FC_FAMILY, 0, &family) == FcResultMatch)
                put_note(c, "text: font '%s' was not found; using '%s'", wanted_copy,
                         (const char *)family);
        }
    }
    if (match)
        FcPatternDestroy(match);
    free(wanted_copy);
    free(name);
    return st;
}

sc_status spancast_text_register(const char *path, char *err, size_t err_size);

sc_status spancast_text_register(const char *path, char *err, size_t err_size)
{
    FILE *f = fopen(path, "rb");
    if (!f) {
        snprintf(err, err_size, "Can't register font '%s': %s", path, strerror(errno));
        return SC_ERR_IO;
    }
    fclose(f);
    if (!FcConfigAppFontAddFile(NULL, (const FcChar8 *)path)) {
        snprintf(err, err_size,
                 "Can't register font '%s': not a font fontconfig can read", path);
        return SC_ERR_IO;
    }
    return SC_OK;
}

/* ---- outlines ---- */

static int push_seg(text_shape *s, const outline_seg *seg)
{
    if (!grow_array32((void **)&s->segs, &s->seg_cap, s->seg_count + 1, sizeof *s->segs))
        return 0;
    s->segs[s->seg_count++] = *seg;
    return 1;
}

typedef struct decompose_state {
    text_shape *shape;
    double pen[2];
    int open; /* a contour has been started */
    int oom;
} decompose_state;

static void close_contour(decompose_state *d)
{
    text_shape *s = d->shape;
    if (!d->open)
        return;
    d->open = 0;
    if (s->seg_count == s->contour_start[s->contour_count])
        return; /* no segment: nothing to keep */
    s->contour_count++;
    s->contour_start[s->contour_count] = s->seg_count;
}

static int begin_contour(decompose_state *d)
{
    text_shape *s = d->shape;
    close_contour(d);
    if (!grow_array32((void **)&s->contour_start, &s->contour_cap, s->contour_count + 2,
                      sizeof *s->contour_start))
        return 0;
    s->contour_start[s->contour_count] = s->seg_count;
    d->open = 1;
    return 1;
}

static int ft_move_to(const FT_Vector *to, void *user)
{
    decompose_state *d = user;
    if (!begin_contour(d)) {
        d->oom = 1;
        return 1;
    }
    d->pen[0] = to->x / ft_scale;
    d->pen[1] = to->y / ft_scale;
    return 0;
}

static int add_curve(decompose_state *d, uint32_t degree, const FT_Vector *const *pts)
{
    if (!d->open && !begin_contour(d)) {
        d->oom = 1;
        return 1;
    }
    outline_seg seg;
    memset(&seg, 0, sizeof seg);
    seg.degree = degree;
    seg.x[0] = d->pen[0];
    seg.y[0] = d->pen[1];
    for (uint32_t i = 0; i < degree; i++) {
        seg.x[i + 1] = pts[i]->x / ft_scale;
        seg.y[i + 1] = pts[i]->y / ft_scale;
    }
    if (!push_seg(d->shape, &seg)) {
        d->oom = 1;
        return 1;
    }
    d->pen[0] = seg.x[degree];
    d->pen[1] = seg.y[degree];
    return 0;
}

static int ft_line_to(const FT_Vector *to, void *user)
{
    const FT_Vector *p[1] = {to};
    return add_curve(user, 1, p);
}

static int ft_conic_to(const FT_Vector *c1, const FT_Vector *to, void *user)
{
    const FT_Vector *p[2] = {c1, to};
    return add_curve(user, 2, p);
}

static int ft_cubic_to(const FT_Vector *c1, const FT_Vector *c2, const FT_Vector *to,
                       void *user)
{
    const FT_Vector *p[3] = {c1, c2, to};
    return add_curve(user, 3, p);
}

static int is_ignored_script(hb_script_t s)
{
    return s == HB_SCRIPT_COMMON || s == HB_SCRIPT_INHERITED || s == HB_SCRIPT_UNKNOWN ||
           s == HB_SCRIPT_INVALID;
}

/* OpenSCAD's detect_properties: the script and direction to shape with. */
static void detect(const model_text *a, hb_script_t *script, hb_direction_t *direction)
{
    *script = hb_script_from_string(a->script, -1);
    if (*script == HB_SCRIPT_INVALID) {
        hb_buffer_t *b = hb_buffer_create();
        hb_buffer_add_utf8(b, a->text, (int)a->length, 0, (int)a->length);
        unsigned count = 0;
        hb_glyph_info_t *info = hb_buffer_get_glyph_infos(b, &count);
        hb_script_t found = HB_SCRIPT_INVALID;
        for (unsigned i = 0; i < count; i++) {
            hb_script_t s =
                hb_unicode_script(hb_unicode_funcs_get_default(), info[i].codepoint);
            if (is_ignored_script(s))
                continue;
            if (found == HB_SCRIPT_INVALID)
                found = s;
            else if (found != s && found != HB_SCRIPT_UNKNOWN)
                found = HB_SCRIPT_UNKNOWN;
        }
        hb_buffer_destroy(b);
        *script = is_ignored_script(found) ? HB_SCRIPT_INVALID : found;
    }
    *direction = hb_direction_from_string(a->direction, -1);
    if (*direction == HB_DIRECTION_INVALID)
        *direction = hb_script_get_horizontal_direction(*script);
    if (*direction == HB_DIRECTION_INVALID)
        *direction = HB_DIRECTION_LTR;
}

/* Resizes *v to count pairs of doubles; on failure *v is kept. */
static int resize_pairs(double **v, uint32_t count)
{
    double *r = realloc(*v, 2 * (size_t)count * sizeof **v);
    if (!r)
        return 0;
    *v = r;
    return 1;
}

typedef struct glyph_rec {
    FT_Glyph glyph;
    double x_offset, y_offset, x_advance, y_advance; /* in 1.024e5 units */
} glyph_rec;

static sc_status shape_text(layout_ctx *c, const model_text *a, FT_Face face,
                            text_shape *out)
{
    if (FT_Set_Char_Size(face, 0, (FT_F26Dot6)ft_scale, 100, 100) != 0)
        return fail(c, SC_ERR_SEMANTIC, "text: cannot set the font size for '%s'",
                    a->font);
    hb_script_t script;
    hb_direction_t direction;
    detect(a, &script, &direction);
    hb_font_t *font = hb_ft_font_create(face, NULL);
    hb_buffer_t *buf = hb_buffer_create();
    hb_buffer_set_direction(buf, direction);
    hb_buffer_set_script(buf, script);
    hb_buffer_set_language(buf, hb_language_from_string(a->language, -1));
    hb_buffer_add_utf8(buf, a->text, (int)a->length, 0, (int)a->length);
    if (is_windows_symbol_font(face)) {
        /* OpenSCAD moves the characters below 0x100 to the 0xf000 page,
         * where a symbol font has them; the rest stay (FreetypeRenderer) */
        unsigned n = 0;
        hb_glyph_info_t *in = hb_buffer_get_glyph_infos(buf, &n);
        for (unsigned i = 0; i < n; i++)
            if (in[i].codepoint < 0x100)
                in[i].codepoint += 0xf000;
    }
    hb_shape(font, buf, NULL, 0);
    unsigned count = 0;
    hb_glyph_info_t *info = hb_buffer_get_glyph_infos(buf, &count);
    hb_glyph_position_t *pos = hb_buffer_get_glyph_positions(buf, &count);
    glyph_rec *g = calloc(count ? count : 1, sizeof *g);
    sc_status st = SC_OK;
    unsigned kept = 0;
    if (!g)
        st = nomem(c);
    for (unsigned i = 0; st == SC_OK && i < count; i++) {
        if (FT_Load_Glyph(face, info[i].codepoint, FT_LOAD_DEFAULT) != 0)
            continue; /* OpenSCAD logs and goes on */
        FT_Glyph glyph;
        if (FT_Get_Glyph(face->glyph, &glyph) != 0)
            continue;
        if (glyph->format != FT_GLYPH_FORMAT_OUTLINE) {
            FT_Done_Glyph(glyph);
            continue;
        }
        g[kept].glyph = glyph;
        g[kept].x_offset = pos[i].x_offset * hb_unscale;
        g[kept].y_offset = pos[i].y_offset * hb_unscale;
        g[kept].x_advance = pos[i].x_advance * hb_unscale;
        g[kept].y_advance = pos[i].y_advance * hb_unscale;
        kept++;
    }
    double width = 0, ascend = 0, descend = 0;
    for (unsigned i = 0; st == SC_OK && i < kept; i++) {
        FT_BBox box;
        FT_Glyph_Get_CBox(g[i].glyph, FT_GLYPH_BBOX_GRIDFIT, &box);
        if (HB_DIRECTION_IS_HORIZONTAL(direction)) {
            double asc = fmax(0.0, box.yMax * hb_unscale);
            double desc = fmax(0.0, -box.yMin * hb_unscale);
            width += g[i].x_advance * a->spacing;
            ascend = fmax(ascend, asc);
            descend = fmax(descend, desc);
        } else {
            double w = (box.xMax - box.xMin) * hb_unscale;
            width = fmax(width, w);
            ascend += g[i].y_advance * a->spacing;
        }
    }
    double x_offset = 0, y_offset = 0;
    if (strcmp(a->halign, "right") == 0)
        x_offset = -width;
    else if (strcmp(a->halign, "center") == 0)
        x_offset = -width / 2.0;
    else if (strcmp(a->halign, "left") != 0)
        put_note(c, "text: unknown halign '%s' (use \"left\", \"right\" or \"center\")%s",
                 a->halign, "");
    if (strcmp(a->valign, "top") == 0)
        y_offset = -ascend;
    else if (strcmp(a->valign, "center") == 0)
        y_offset = descend / 2.0 - ascend / 2.0;
    else if (strcmp(a->valign, "bottom") == 0)
        y_offset = descend;
    else if (strcmp(a->valign, "baseline") != 0)
        put_note(c,
                 "text: unknown valign '%s' (use \"baseline\", \"bottom\", \"top\" or "
                 "\"center\")%s",
                 a->valign, "");
    FT_Outline_Funcs funcs = {ft_move_to, ft_line_to, ft_conic_to, ft_cubic_to, 0, 0};
    double adv[2] = {0, 0};
    out->size = a->size;
    for (unsigned i = 0; st == SC_OK && i < kept; i++) {
        uint32_t gi = out->glyph_count;
        if (!grow_array32((void **)&out->glyph_start, &out->glyph_cap, gi + 2,
                          sizeof *out->glyph_start) ||
            !resize_pairs(&out->offset, out->glyph_cap) ||
            !resize_pairs(&out->advance, out->glyph_cap)) {
            st = nomem(c);
            break;
        }
        out->glyph_start[gi] = out->contour_count;
        decompose_state d = {out, {0, 0}, 0, 0};
        FT_Outline outline = ((FT_OutlineGlyph)g[i].glyph)->outline;
        FT_Outline_Decompose(&outline, &funcs, &d);
        close_contour(&d);
        if (d.oom) {
            st = nomem(c);
            break;
        }
        out->offset[2 * gi] = x_offset + g[i].x_offset;
        out->offset[2 * gi + 1] = y_offset + g[i].y_offset;
        out->advance[2 * gi] = adv[0];
        out->advance[2 * gi + 1] = adv[1];
        adv[0] += g[i].x_advance * a->spacing;
        adv[1] += g[i].y_advance * a->spacing;
        /* A glyph at a place that is not finite is not drawn, as OpenSCAD
         * 2021.01 draws none there: a spacing of inf or nan (a .scad's
         * 1/0) leaves the first glyph of left-aligned text, and none of
         * centred or right-aligned text (whose width is then not finite;
         * OpenSCAD aborts on those). */
        if (!(isfinite(out->offset[2 * gi]) && isfinite(out->offset[2 * gi + 1]) &&
              isfinite(out->advance[2 * gi]) && isfinite(out->advance[2 * gi + 1])) &&
            out->contour_count > out->glyph_start[gi]) {
            out->contour_count = out->glyph_start[gi];
            out->seg_count = out->contour_start[out->contour_count];
        }
        if (out->contour_count > out->glyph_start[gi]) {
            out->glyph_count++;
            out->glyph_start[out->glyph_count] = out->contour_count;
        }
    }
    for (unsigned i = 0; g && i < kept; i++)
        FT_Done_Glyph(g[i].glyph);
    free(g);
    hb_buffer_destroy(buf);
    hb_font_destroy(font);
    return st;
}

/* The entry point (text_layout_fn). */
text_layout_fn spancast_text_layout;
sc_status spancast_text_layout(const model_text *a, text_shape *out, char *note,
                               size_t note_size, char *err, size_t err_size)
{
    layout_ctx c = {note, err, note_size, err_size};
    FT_Library lib;
    if (FT_Init_FreeType(&lib) != 0)
        return fail(&c, SC_ERR_NOMEM, "text: cannot start FreeType");
    FT_Face face = NULL;
    sc_status st = open_face(&c, lib, a->font, &face);
    if (st == SC_OK)
        st = shape_text(&c, a, face, out);
    if (face)
        FT_Done_Face(face);
    FT_Done_FreeType(lib);
    return st;
}
