/* Lowering in the 2D context (model.h): the arguments of the 2D nodes
 * below an extrusion, each node's first argument error kept in the node
 * (pending) rather than ending the lowering, since each builder of 2D
 * subtrees reads a node's arguments at its own point of its walk (an
 * offset after its children, a square before them).
 *
 * The checks, their order and their messages are the ones the 2D readers
 * have always made: model/args.c's readers (an argument of OpenSCAD's of
 * the wrong kind is its default, as OpenSCAD 2021.01 reads it, with no
 * error: model_check_params gives OpenSCAD's warnings), then per kind
 *   polygon   points as OpenSCAD 2021.01 reads them (lower_polygon: a
 *             bad one empties it, for the builder to warn of); each path
 *             entry one of the points (model_index_value), in path
 *             order; one out of range is listed (model.h)
 *   offset    r, then $fn, $fa, $fs, then (without r) delta and chamfer
 *   import    a file name, .dxf or .svg (otherwise the builder names the
 *             operation that asked), then $fn, $fa, $fs, layer, origin
 *             [x, y], scale, center and dpi (as OpenSCAD: center true only
 *             when true, a bad dpi the default), origin and scale finite
 *   linear_extrude, rotate_extrude with file: the arguments above, then
 *             file, $fn, $fa, $fs, layer, origin; the drawing becomes the
 *             node's only child (extrude_file)
 *   projection  cut (true only when true, by name or first)
 *   resize    as in the points context (lower_points.c)
 *   cube, sphere, cylinder, polyhedron
 *             as in the points context, for their size only (lower_solid):
 *             an argument error leaves the node unsized, not pending
 *   text      text, size, font, direction, language, script, halign,
 *             valign, spacing, $fn, $fa, $fs (each of another kind its
 *             default); at most
 *             MODEL_MAX_TEXT_BYTES bytes without a NUL
 */
#include "model/lower_twod.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "model/args.h"
#include "model/lower_points.h"
#include "twod/twod.h"

static sc_status lower_square(model_lowerer *l, const parse_node *n, model_node *out)
{
    model_square *s = model_lowerer_alloc(l, sizeof *s);
    if (!s)
        return SC_ERR_NOMEM;
    out->u.square = s;
    return model_read_square(&l->r, n, &s->sx, &s->sy, &s->center);
}

static sc_status lower_circle(model_lowerer *l, const parse_node *n, model_node *out)
{
    model_circle *c = model_lowerer_alloc(l, sizeof *c);
    if (!c)
        return SC_ERR_NOMEM;
    out->u.circle = c;
    return model_read_circle(&l->r, n, c);
}

/* The paths' indices, in path order (a path that is not a vector is an
 * empty one); those out of range left out, and listed in p->bad. */
static sc_status read_paths(model_lowerer *l, const parse_value *paths, model_polygon *p)
{
    uint32_t count = paths->u.vector.count;
    size_t total = 0;
    for (uint32_t k = 0; k < count; k++) {
        const parse_value *path = &paths->u.vector.items[k];
        total += path->kind == PARSE_VECTOR ? path->u.vector.count : 0;
    }
    uint32_t *start = arena_calloc(l->mem, (size_t)count + 1, sizeof *start);
    uint32_t *index = arena_calloc(l->mem, total ? total : 1, sizeof *index);
    model_bad_index *bad = arena_calloc(l->mem, total ? total : 1, sizeof *bad);
    if (!start || !index || !bad || total > UINT32_MAX) {
        l->nomem = 1;
        return SC_ERR_NOMEM;
    }
    p->path_start = start;
    p->index = index;
    p->bad = bad;
    uint32_t at = 0;
    for (uint32_t k = 0; k < count; k++) {
        const parse_value *path = &paths->u.vector.items[k];
        uint32_t n = path->kind == PARSE_VECTOR ? path->u.vector.count : 0;
        start[k] = at;
        p->path_count = k + 1;
        for (uint32_t i = 0; i < n; i++) {
            const parse_value *v = &path->u.vector.items[i];
            double x = model_index_value(v);
            if (x >= 0 && x < (double)p->point_count) {
                index[at++] = (uint32_t)x;
                continue;
            }
            model_bad_index *b = &bad[p->bad_count++];
            b->value = v->kind == PARSE_NUMBER ? v->u.number : 0; /* as written */
            b->face = k;
            b->place = i;
            b->loc = model_loc(&l->r, v);
        }
    }
    start[count] = at;
    return SC_OK;
}

/* Point v of a polygon as OpenSCAD 2021.01 converts it (Value::getVec2,
 * then not infinite): 1 with x, y in xy (a nan among them, which the
 * clipper's range check then refuses: polygon_range), else 0
 * (*not_finite: numbers, one infinite). */
static int polygon_point(const parse_value *v, double xy[2], int *not_finite)
{
    *not_finite = 0;
    if (v->kind != PARSE_VECTOR || v->u.vector.count != 2 ||
        v->u.vector.items[0].kind != PARSE_NUMBER ||
        v->u.vector.items[1].kind != PARSE_NUMBER)
        return 0;
    double x = v->u.vector.items[0].u.number, y = v->u.vector.items[1].u.number;
    /* an infinite coordinate fails OpenSCAD's conversion (getVec2 and its
     * isinf test); a nan passes it, and the clipper refuses its outline
     * (polygon_range) */
    *not_finite = isinf(x) || isinf(y);
    xy[0] = x;
    xy[1] = y;
    return !*not_finite;
}

/* p->range_bad: the first outline, in OpenSCAD's order, that Clipper
 * refuses (twod_clipper_outline), which ends its AddPaths: that outline and
 * those after it are left out. OpenSCAD's outlines: one per path, or,
 * without paths or with an empty vector of them, one of all the points. */
static sc_status polygon_range(model_lowerer *l, model_polygon *p)
{
    /* Only a coordinate of 2^46 or more (2^62 at the scale of 2^16) can be
     * refused: a polygon without one needs no conversion. */
    int large = 0;
    for (size_t i = 0; i < 2 * (size_t)p->point_count && !large; i++)
        large = !twod_in_range(p->xy[i]);
    if (!large)
        return SC_OK;
    int paths = p->has_paths && p->path_count > 0;
    uint32_t count = paths ? p->path_count : 1, longest = paths ? 0 : p->point_count;
    for (uint32_t k = 0; paths && k < count; k++)
        if (p->path_start[k + 1] - p->path_start[k] > longest)
            longest = p->path_start[k + 1] - p->path_start[k];
    int64_t *pt = malloc(2 * (size_t)(longest ? longest : 1) * sizeof *pt);
    if (!pt) {
        l->nomem = 1;
        return SC_ERR_NOMEM;
    }
    for (uint32_t k = 0; k < count && !p->range_bad; k++) {
        const uint32_t *index = paths ? &p->index[p->path_start[k]] : NULL;
        uint32_t n = paths ? p->path_start[k + 1] - p->path_start[k] : p->point_count;
        if (twod_clipper_outline(p->xy, index, n, 0, pt) == TWOD_OUTLINE_REFUSED)
            p->range_bad = k + 1;
    }
    free(pt);
    return SC_OK;
}

/* polygon(points, paths) as OpenSCAD 2021.01 reads it (primitives.cc):
 * points that are not a vector are none; the first point that is not
 * [x, y] of numbers empties the polygon (bad_point, for the builder's
 * warning); paths that are not a vector are none (all the points). */
static sc_status lower_polygon(model_lowerer *l, const parse_node *n, model_node *out)
{
    model_polygon *p = model_lowerer_alloc(l, sizeof *p);
    if (!p)
        return SC_ERR_NOMEM;
    out->u.polygon = p;
    const parse_value *pts = model_arg(n, "points", 0), *paths = model_arg(n, "paths", 1);
    if (!pts)
        return SC_OK;
    uint32_t np = pts->kind == PARSE_VECTOR ? pts->u.vector.count : 0;
    double *xy = arena_alloc(l->mem, (np ? np : 1) * 2 * sizeof *xy);
    if (!xy) {
        l->nomem = 1;
        return SC_ERR_NOMEM;
    }
    for (uint32_t i = 0; i < np; i++) {
        const parse_value *v = &pts->u.vector.items[i];
        int not_finite;
        if (polygon_point(v, &xy[2 * i], &not_finite))
            continue;
        model_bad_point *bp = model_lowerer_alloc(l, sizeof *bp);
        const char *text = bp ? model_echo_value(l->mem, v) : NULL;
        if (!text) {
            l->nomem = 1;
            return SC_ERR_NOMEM;
        }
        bp->index = i;
        bp->not_finite = not_finite;
        bp->loc = model_loc(&l->r, v);
        bp->text = text;
        p->bad_point = bp; /* and no points: empty */
        return SC_OK;
    }
    p->xy = xy;
    p->point_count = np;
    p->has_points = 1;
    if (paths && paths->kind == PARSE_VECTOR) {
        p->has_paths = 1;
        sc_status st = read_paths(l, paths, p);
        if (st != SC_OK)
            return st;
    }
    return polygon_range(l, p);
}

static sc_status number(model_lowerer *l, const parse_node *n, const char *name,
                        int position, double *out, int *given)
{
    if (given) {
        const parse_value *v = model_arg(n, name, position);
        *given = v && v->kind == PARSE_NUMBER; /* else OpenSCAD passes over it */
    }
    return model_number(&l->r, n, name, position, out);
}

static sc_status lower_offset(model_lowerer *l, const parse_node *n, model_node *out)
{
    model_offset *o = model_lowerer_alloc(l, sizeof *o);
    if (!o)
        return SC_ERR_NOMEM;
    out->u.offset = o;
    model_resolution *res = &o->res;
    o->delta = 1;
    sc_status st;
    if ((st = number(l, n, "r", 0, &o->delta, &o->has_r)) != SC_OK ||
        (st = model_read_resolution(&l->r, n, &res->fn, &res->fa, &res->fs)) != SC_OK)
        return st;
    if (!o->has_r &&
        ((st = number(l, n, "delta", -1, &o->delta, &o->has_delta)) != SC_OK ||
         (st = model_bool(&l->r, n, "chamfer", -1, &o->chamfer)) != SC_OK))
        return st;
    return SC_OK; /* a size that is not finite draws nothing (build_twod.c) */
}

/* layer, origin [x, y], $fn, $fa, $fs of a drawing read from n (an import,
 * or an extrusion's file form); origin finite. */
static sc_status drawing_options(model_lowerer *l, const parse_node *n, model_drawing *d)
{
    model_resolution *res = &d->res;
    sc_status st = model_read_resolution(&l->r, n, &res->fn, &res->fa, &res->fs);
    if (st != SC_OK)
        return st;
    /* as OpenSCAD 2021.01 reads them: a layer of another kind as its text,
     * an origin that is not [x, y] of numbers [0, 0] (model_check_params
     * warns of it) */
    const parse_value *layer = model_arg(n, "layer", -1);
    d->layer = layer ? model_string_value(l->mem, layer) : NULL;
    if (layer && !d->layer) {
        l->nomem = 1;
        return SC_ERR_NOMEM;
    }
    const parse_value *origin = model_arg(n, "origin", -1);
    if (origin && origin->kind == PARSE_VECTOR)
        model_size_value(origin, 2, d->origin);
    return SC_OK;
}

/* The file argument, as OpenSCAD 2021.01 takes it (model_string_value),
 * into d->file and d->file_loc; the drawing's format from its suffix. */
static sc_status drawing_file(model_lowerer *l, const parse_value *file, model_drawing *d)
{
    d->file = model_string_value(l->mem, file); /* as OpenSCAD takes it */
    if (!d->file) {
        l->nomem = 1;
        return SC_ERR_NOMEM;
    }
    d->file_loc = model_loc(&l->r, file);
    d->format = model_has_suffix(d->file, ".svg") ? MODEL_DRAWING_SVG : MODEL_DRAWING_DXF;
    return SC_OK;
}

/* A DXF drawing's origin or scale that is not finite (a .scad's 1/0 or 0/0,
 * which OpenSCAD's export writes as inf or nan) into d->far; an SVG reads
 * neither. */
static void far_drawing(model_drawing *d)
{
    d->far = d->format == MODEL_DRAWING_DXF &&
             !(isfinite(d->origin[0]) && isfinite(d->origin[1]) && isfinite(d->scale));
}

static sc_status lower_drawing(model_lowerer *l, const parse_node *n, model_node *out)
{
    model_drawing *d = model_lowerer_alloc(l, sizeof *d);
    if (!d)
        return SC_ERR_NOMEM;
    out->u.drawing = d;
    d->scale = 1;
    d->dpi = MODEL_SVG_DPI;
    const parse_value *file = model_arg(n, "file", 0);
    if (!file) {
        /* OpenSCAD imports the file "": no drawing, so a 3D child */
        d->file = "";
        d->file_loc = n->loc;
        d->not_2d = 1;
        return SC_OK;
    }
    sc_status st = drawing_file(l, file, d);
    if (st != SC_OK)
        return st;
    if (!model_has_suffix(d->file, ".dxf") && !model_has_suffix(d->file, ".svg")) {
        d->not_2d = 1;
        return SC_OK;
    }
    if ((st = drawing_options(l, n, d)) != SC_OK ||
        (st = number(l, n, "scale", -1, &d->scale, NULL)) != SC_OK)
        return st;
    /* OpenSCAD 2021.01 (import.cc): center is true only when given true,
     * a scale <= 0 is 1, a dpi below 0.001 (or nan) the default; an
     * infinite one makes a length without unit 0 (import_svg.cc) */
    const parse_value *center = model_arg(n, "center", -1);
    d->center = center && center->kind == PARSE_BOOL && center->u.boolean;
    const parse_value *dpi = model_arg(n, "dpi", -1);
    if (dpi && dpi->kind == PARSE_NUMBER && dpi->u.number >= 0.001)
        d->dpi = dpi->u.number;
    if (d->scale <= 0)
        d->scale = 1;
    far_drawing(d);
    return SC_OK;
}

/* The file form of an extrusion, linear_extrude(file = "x.dxf", layer,
 * origin, scale, ...) and rotate_extrude(file, layer, origin, scale, ...),
 * which OpenSCAD 2021.01 still reads (deprecated): the drawing read as a
 * DXF whatever its name, whose scale is the given one (linear_extrude's
 * scale [x, y] takes x, and scales the top as well), in place of the
 * children, which OpenSCAD then leaves out. Lowered as a child import()
 * node, the only child of out. */
static sc_status extrude_file(model_lowerer *l, const parse_node *n,
                              const parse_value *file, double scale, model_node *out)
{
    model_drawing *d = model_lowerer_alloc(l, sizeof *d);
    model_node *child = model_lowerer_alloc(l, sizeof *child);
    if (!d || !child)
        return SC_ERR_NOMEM;
    d->scale = 1;
    d->dpi = MODEL_SVG_DPI;
    sc_status st = drawing_file(l, file, d);
    if (st == SC_OK)
        st = drawing_options(l, n, d);
    if (st != SC_OK)
        return st;
    d->format = MODEL_DRAWING_DXF;
    d->scale = scale;
    far_drawing(d);
    child->kind = MODEL_IMPORT;
    child->name = n->name;
    child->loc = n->loc;
    child->u.drawing = d;
    out->first_child = child;
    out->child_count = 1;
    return SC_OK;
}

/* A string argument into *out, left alone (OpenSCAD's default) when it is
 * absent or not a string, as OpenSCAD 2021.01 reads text()'s. */
static sc_status string(model_lowerer *l, const parse_node *n, const char *name,
                        int position, const char **out)
{
    (void)l;
    const parse_value *v = model_arg(n, name, position);
    if (v && v->kind == PARSE_STRING)
        *out = v->u.string.chars;
    return SC_OK;
}

static sc_status lower_text(model_lowerer *l, const parse_node *n, model_node *out)
{
    model_text *a = model_lowerer_alloc(l, sizeof *a);
    if (!a)
        return SC_ERR_NOMEM;
    out->u.text = a;
    a->text = "";
    a->size = 10;
    a->spacing = 1;
    a->res = (model_resolution){0, 12, 2};
    a->font = a->direction = a->script = "";
    a->language = "en";
    a->halign = "left";
    a->valign = "baseline";
    model_resolution *res = &a->res;
    sc_status st;
    if ((st = string(l, n, "text", 0, &a->text)) != SC_OK ||
        (st = model_number(&l->r, n, "size", 1, &a->size)) != SC_OK ||
        (st = string(l, n, "font", 2, &a->font)) != SC_OK ||
        (st = string(l, n, "direction", -1, &a->direction)) != SC_OK ||
        (st = string(l, n, "language", -1, &a->language)) != SC_OK ||
        (st = string(l, n, "script", -1, &a->script)) != SC_OK ||
        (st = string(l, n, "halign", -1, &a->halign)) != SC_OK ||
        (st = string(l, n, "valign", -1, &a->valign)) != SC_OK ||
        (st = model_number(&l->r, n, "spacing", -1, &a->spacing)) != SC_OK ||
        (st = model_read_resolution(&l->r, n, &res->fn, &res->fa, &res->fs)) != SC_OK)
        return st;
    const parse_value *tv = model_arg(n, "text", 0);
    a->length = tv && tv->kind == PARSE_STRING ? tv->u.string.length : 0;
    if (a->length > MODEL_MAX_TEXT_BYTES) {
        sc_location loc = model_loc(&l->r, tv);
        return err_set(l->r.error, SC_ERR_LIMIT, &loc,
                       "text is too long (%zu bytes; limit is %d)", a->length,
                       MODEL_MAX_TEXT_BYTES);
    }
    if (memchr(a->text, 0, a->length)) {
        sc_location loc = model_loc(&l->r, tv);
        return err_set(l->r.error, SC_ERR_SEMANTIC, &loc, "text must not contain a NUL");
    }
    /* a size that is not finite draws nothing (build_text.c), a spacing
     * that is not finite no glyph after the first (text_freetype.c) */
    return SC_OK;
}

/* height and center, all the exact builders read. */
static sc_status exact_extrude_args(model_lowerer *l, const parse_node *n,
                                    model_linear_extrude *e)
{
    sc_status st = model_number(&l->r, n, "height", 0, &e->height);
    if (st == SC_OK)
        st = model_bool(&l->r, n, "center", 1, &e->center);
    return st;
}

/* The faithful builder's arguments, in its order. */
static sc_status faithful_extrude_args(model_lowerer *l, const parse_node *n,
                                       model_linear_extrude *e)
{
    model_resolution *res = &e->res;
    sc_status st;
    if ((st = model_number(&l->r, n, "height", 0, &e->height)) != SC_OK ||
        (st = model_number(&l->r, n, "twist", -1, &e->twist)) != SC_OK ||
        (st = model_number(&l->r, n, "slices", -1, &e->slices)) != SC_OK ||
        (st = model_read_resolution(&l->r, n, &res->fn, &res->fa, &res->fs)) != SC_OK ||
        (st = model_bool(&l->r, n, "center", 1, &e->center)) != SC_OK)
        return st;
    /* a scale of another kind is [1, 1], without a word (OpenSCAD 2021.01) */
    const parse_value *sv = model_arg(n, "scale", -1);
    double scale[2] = {1, 1};
    if (sv)
        model_size_value(sv, 2, scale);
    e->sx = scale[0];
    e->sy = scale[1];
    if (!isfinite(e->sx) || !isfinite(e->sy)) {
        sc_location loc = model_loc(&l->r, sv);
        return err_set(l->r.error, SC_ERR_SEMANTIC, &loc,
                       "linear_extrude: scale must be finite");
    }
    if (!isfinite(e->twist)) {
        sc_location loc = model_loc(&l->r, model_arg(n, "twist", -1));
        return err_set(l->r.error, SC_ERR_SEMANTIC, &loc,
                       "linear_extrude: twist must be finite");
    }
    /* OpenSCAD: negative scales are 0, slices are truncated to an integer
     * and count when positive, a non-finite slice count is not given */
    e->sx = e->sx < 0 ? 0 : e->sx;
    e->sy = e->sy < 0 ? 0 : e->sy;
    e->slices = isfinite(e->slices) && e->slices >= 1 ? trunc(e->slices) : 0;
    if (e->slices > MODEL_MAX_SLICES) {
        sc_location loc = model_loc(&l->r, model_arg(n, "slices", -1));
        return err_set(l->r.error, SC_ERR_LIMIT, &loc,
                       "linear_extrude: %g slices are too many (limit is %.0f)",
                       e->slices, MODEL_MAX_SLICES);
    }
    return SC_OK;
}

/* Twist absent or 0, scale absent, 1 or [1, 1] (as OpenSCAD reads them),
 * whatever else is wrong. */
static int plain_extrude(const parse_node *n)
{
    /* a twist or scale that is not one is the default (0, [1, 1]) */
    const parse_value *twist = model_arg(n, "twist", -1);
    if (twist && twist->kind == PARSE_NUMBER && twist->u.number != 0)
        return 0;
    const parse_value *sv = model_arg(n, "scale", -1);
    double scale[2] = {1, 1};
    if (sv)
        model_size_value(sv, 2, scale);
    return scale[0] == 1 && scale[1] == 1;
}

static sc_status lower_linear_extrude(model_lowerer *l, const parse_node *n,
                                      model_node *out)
{
    model_linear_extrude *e = model_lowerer_alloc(l, sizeof *e);
    sc_error *exact = arena_alloc(l->mem, sizeof *exact);
    if (!e || !exact) {
        l->nomem = 1;
        return SC_ERR_NOMEM;
    }
    out->u.linear_extrude = e;
    e->height = 100;
    e->sx = e->sy = 1;
    e->res = (model_resolution){0, 12, 2};
    e->plain = plain_extrude(n);
    sc_error *outer = l->r.error;
    l->r.error = exact;
    if (exact_extrude_args(l, n, e) != SC_OK)
        e->exact_error = exact;
    l->r.error = outer;
    sc_status st = faithful_extrude_args(l, n, e);
    /* a file that is not a string is none to linear_extrude (OpenSCAD
     * 2021.01 extrudes the children), unlike rotate_extrude's */
    const parse_value *file = model_arg(n, "file", -1);
    if (st == SC_OK && file && file->kind == PARSE_STRING)
        st = extrude_file(l, n, file, e->sx, out);
    return st;
}

static sc_status lower_rotate_extrude(model_lowerer *l, const parse_node *n,
                                      model_node *out)
{
    model_rotate_extrude *e = model_lowerer_alloc(l, sizeof *e);
    if (!e)
        return SC_ERR_NOMEM;
    out->u.rotate_extrude = e;
    e->angle = 360;
    e->res = (model_resolution){0, 12, 2};
    model_resolution *res = &e->res;
    sc_status st;
    if ((st = model_number(&l->r, n, "angle", -1, &e->angle)) != SC_OK ||
        (st = model_read_resolution(&l->r, n, &res->fn, &res->fa, &res->fs)) != SC_OK)
        return st;
    const parse_value *file = model_arg(n, "file", -1);
    if (!file)
        return SC_OK;
    /* OpenSCAD 2021.01 (rotateextrude.cc): a scale <= 0 is 1 */
    double scale = 1;
    if ((st = number(l, n, "scale", -1, &scale, NULL)) != SC_OK)
        return st;
    return extrude_file(l, n, file, scale <= 0 ? 1 : scale, out);
}

/* projection(cut = false, convexity): OpenSCAD takes cut by name or
 * first, true only when it is true; convexity, of any kind, is of no use
 * to spancast. */
static sc_status lower_projection(model_lowerer *l, const parse_node *n, model_node *out)
{
    out->u.projection.cut = 0;
    return model_bool(&l->r, n, "cut", 0, &out->u.projection.cut);
}

/* multmatrix(m) below an extrusion: the builders take its xy part. */
static sc_status lower_matrix(model_lowerer *l, const parse_node *n, model_node *out)
{
    return model_read_xform(&l->r, l->mem, n, &out->u.xform, &out->not_finite);
}

sc_status model_import_drawing(arena *mem, const char *file, const parse_node *n,
                               model_node *out, sc_error *error)
{
    model_node drawn = *out;
    drawn.kind = MODEL_IMPORT;
    sc_status st = model_twod_args(mem, file, n, &drawn, error);
    if (st != SC_OK)
        return st;
    model_import *import = arena_calloc(mem, 1, sizeof *import);
    if (!import)
        return err_nomem(error, NULL);
    /* the file is a string (model_import_is_drawing), read first */
    import->file = drawn.u.drawing->file;
    import->file_loc = drawn.u.drawing->file_loc;
    import->drawing = drawn.u.drawing;
    out->u.import = import;
    out->pending = drawn.pending;
    return SC_OK;
}

/* A solid among 2D nodes, which the 2D builders leave out: its size read as
 * in the points context, only to tell whether OpenSCAD's geometry of it is
 * empty (build_presence). An argument error is no error here, as the node
 * is never built: the node is then unsized, its size unknown. */
static sc_status lower_solid(arena *mem, const char *file, const parse_node *n,
                             model_node *out, sc_error *error)
{
    model_node read = *out;
    sc_status st = model_points_args(mem, file, n, &read, error);
    if (st != SC_OK)
        return st;
    if (read.pending) {
        out->unsized = 1;
        return SC_OK;
    }
    *out = read;
    return SC_OK;
}

sc_status model_twod_args(arena *mem, const char *file, const parse_node *n,
                          model_node *out, sc_error *error)
{
    sc_error pending;
    model_lowerer l = {mem, {file, &pending}, 0};
    sc_status st = SC_OK;
    switch (out->kind) {
    case MODEL_SQUARE:
        st = lower_square(&l, n, out);
        break;
    case MODEL_CIRCLE:
        st = lower_circle(&l, n, out);
        break;
    case MODEL_POLYGON:
        st = lower_polygon(&l, n, out);
        break;
    case MODEL_OFFSET:
        st = lower_offset(&l, n, out);
        break;
    case MODEL_IMPORT:
        st = lower_drawing(&l, n, out);
        break;
    case MODEL_TEXT:
        st = lower_text(&l, n, out);
        break;
    case MODEL_XFORM:
        st = lower_matrix(&l, n, out);
        break;
    case MODEL_PROJECTION:
        st = lower_projection(&l, n, out);
        break;
    case MODEL_RESIZE: /* read as in the points context */
        return model_points_args(mem, file, n, out, error);
    case MODEL_LINEAR_EXTRUDE:
        st = lower_linear_extrude(&l, n, out);
        break;
    case MODEL_ROTATE_EXTRUDE:
        st = lower_rotate_extrude(&l, n, out);
        break;
    case MODEL_CUBE:
    case MODEL_SPHERE:
    case MODEL_CYLINDER:
    case MODEL_POLYHEDRON:
        return lower_solid(mem, file, n, out, error);
    default:
        break;
    }
    return model_keep_pending(mem, st, l.nomem, &pending, out, error);
}
