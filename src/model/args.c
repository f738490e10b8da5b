/* Readers of a syntax node's arguments: see args.h. */
#include "model/args.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"

void *model_lowerer_alloc(model_lowerer *l, size_t size)
{
    void *p = arena_calloc(l->mem, 1, size ? size : 1);
    l->nomem |= p == NULL;
    return p;
}

const parse_value *model_arg(const parse_node *n, const char *name, int position)
{
    const parse_arg *a = parse_node_arg(n, name, position);
    return a && a->value.kind != PARSE_UNDEF ? &a->value : NULL;
}

sc_location model_loc(const model_reader *c, const parse_value *v)
{
    sc_location loc = {c->file, v->line, v->column};
    return loc;
}

sc_status model_wrong_type(const model_reader *c, const parse_node *n, const char *param,
                           const parse_value *v, const char *expected)
{
    sc_location loc = model_loc(c, v);
    return err_set(c->error, SC_ERR_SEMANTIC, &loc,
                   "wrong type for argument '%s' of '%s' (expected %s)", param, n->name,
                   expected);
}

sc_status model_number(const model_reader *c, const parse_node *n, const char *name,
                       int position, double *out)
{
    (void)c;
    const parse_value *v = model_arg(n, name, position);
    if (v && v->kind == PARSE_NUMBER)
        *out = v->u.number;
    return SC_OK;
}

sc_status model_radius(const model_reader *r, const parse_node *n, const char *diameter,
                       const char *radius, int radius_position, double *out, int *given)
{
    /* Each argument looked up once (this runs for every sphere and three
     * times for every cylinder). */
    (void)r;
    const parse_value *d = model_arg(n, diameter, -1);
    const parse_value *rv = model_arg(n, radius, radius_position);
    *given = 0;
    if (d && d->kind == PARSE_NUMBER) {
        *out = d->u.number / 2;
        *given = 1;
    } else if (rv && rv->kind == PARSE_NUMBER) {
        *out = rv->u.number;
        *given = 1;
    }
    return SC_OK;
}

sc_status model_read_sphere(const model_reader *r, const parse_node *n, double *radius,
                            model_resolution *res)
{
    int given;
    *radius = 1;
    model_resolution_of(n, 1, &res->fn, &res->fa, &res->fs);
    return model_radius(r, n, "d", "r", 0, radius, &given);
}

sc_status model_read_cylinder(const model_reader *r, const parse_node *n, double *h,
                              double *r1, double *r2, int *center, model_resolution *res)
{
    double radius = 1;
    int has_r = 0, has_r1 = 0, has_r2 = 0;
    *h = *r1 = *r2 = 1;
    *center = 0;
    model_resolution_of(n, 1, &res->fn, &res->fa, &res->fs);
    sc_status st = model_number(r, n, "h", 0, h);
    if (st == SC_OK)
        st = model_radius(r, n, "d1", "r1", 1, r1, &has_r1);
    if (st == SC_OK)
        st = model_radius(r, n, "d2", "r2", 2, r2, &has_r2);
    if (st == SC_OK)
        st = model_radius(r, n, "d", "r", -1, &radius, &has_r);
    if (st == SC_OK)
        st = model_bool(r, n, "center", 3, center);
    if (!has_r1)
        *r1 = radius;
    if (!has_r2)
        *r2 = radius;
    return st;
}

sc_status model_matrix(const model_reader *c, const parse_node *n, double a[4][4],
                       int *not_finite)
{
    (void)c;
    static const double id[4][4] = {
        {1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
    memcpy(a, id, sizeof id);
    const parse_value *v = model_arg(n, "m", 0);
    uint32_t rows = v && v->kind == PARSE_VECTOR ? v->u.vector.count : 0;
    for (uint32_t r = 0; r < 4 && r < rows; r++) {
        const parse_value *row = &v->u.vector.items[r];
        uint32_t cols = row->kind == PARSE_VECTOR ? row->u.vector.count : 0;
        for (uint32_t k = 0; k < 4 && k < cols; k++)
            if (row->u.vector.items[k].kind == PARSE_NUMBER)
                a[r][k] = row->u.vector.items[k].u.number;
    }
    double w = a[3][3];
    if (w != 1)
        for (int r = 0; r < 4; r++)
            for (int k = 0; k < 4; k++)
                a[r][k] /= w;
    *not_finite = 0;
    for (int r = 0; r < 4; r++)
        for (int k = 0; k < 4; k++)
            *not_finite |= !isfinite(a[r][k]);
    return SC_OK;
}

sc_status model_read_xform(const model_reader *r, arena *mem, const parse_node *n,
                           const affine **out, int *not_finite)
{
    double m[4][4];
    sc_status st = model_matrix(r, n, m, not_finite);
    if (st != SC_OK)
        return st;
    affine *a = arena_alloc(mem, sizeof *a);
    if (!a)
        return err_nomem(r->error, NULL);
    for (int row = 0; row < 3; row++)
        for (int k = 0; k < 4; k++)
            a->m[row][k] = *not_finite ? 0 : m[row][k];
    *out = a;
    return SC_OK;
}

sc_status model_keep_pending(arena *mem, sc_status st, int nomem, const sc_error *pending,
                             model_node *out, sc_error *error)
{
    if (nomem || st == SC_ERR_NOMEM)
        return err_nomem(error, NULL);
    if (st == SC_OK)
        return SC_OK;
    sc_error *copy = arena_alloc(mem, sizeof *copy);
    if (!copy)
        return err_nomem(error, NULL);
    *copy = *pending;
    out->pending = copy;
    return SC_OK;
}

int model_size_value(const parse_value *v, uint32_t dims, double *out)
{
    if (v->kind == PARSE_NUMBER) {
        for (uint32_t i = 0; i < dims; i++)
            out[i] = v->u.number;
        return 1;
    }
    if (v->kind != PARSE_VECTOR || v->u.vector.count != dims)
        return 0;
    for (uint32_t i = 0; i < dims; i++)
        if (v->u.vector.items[i].kind != PARSE_NUMBER)
            return 0;
    for (uint32_t i = 0; i < dims; i++)
        out[i] = v->u.vector.items[i].u.number;
    return 1;
}

sc_status model_read_square(const model_reader *c, const parse_node *n, double *sx,
                            double *sy, int *center)
{
    double size[2] = {1, 1};
    const parse_value *v = model_arg(n, "size", 0);
    if (v)
        model_size_value(v, 2, size); /* else 1: model_check_params warns */
    *sx = size[0];
    *sy = size[1];
    *center = 0;
    return model_bool(c, n, "center", 1, center);
}

sc_status model_bool(const model_reader *c, const parse_node *n, const char *name,
                     int position, int *out)
{
    (void)c;
    const parse_value *v = model_arg(n, name, position);
    if (v && v->kind == PARSE_BOOL)
        *out = v->u.boolean;
    return SC_OK;
}

sc_status model_cube(const model_reader *c, const parse_node *n, double size[3],
                     int *center)
{
    size[0] = size[1] = size[2] = 1;
    *center = 0;
    const parse_value *v = model_arg(n, "size", 0);
    if (v)
        model_size_value(v, 3, size); /* else 1: model_check_params warns */
    return model_bool(c, n, "center", 1, center);
}

/* ---- OpenSCAD's echo of a value (value.cc, toEchoString) ---- */

typedef struct echo_text {
    char *buf;
    size_t size, len; /* len < size; buf[len] is the NUL */
    int full;         /* cut: ends in "..." */
} echo_text;

static void echo_put(echo_text *t, const char *s, size_t n)
{
    static const char cut[] = "...";
    if (t->full)
        return;
    if (t->len + n + sizeof cut > t->size) {
        memcpy(t->buf + t->len, cut, sizeof cut);
        t->len += sizeof cut - 1;
        t->full = 1;
        return;
    }
    memcpy(t->buf + t->len, s, n);
    t->len += n;
    t->buf[t->len] = 0;
}

/* Drops the trailing zeros of a decimal fraction, and its point when
 * nothing follows. */
static void trim_zeros(char *s)
{
    if (!strchr(s, '.'))
        return;
    size_t n = strlen(s);
    while (n && s[n - 1] == '0')
        s[--n] = 0;
    if (n && s[n - 1] == '.')
        s[--n] = 0;
}

/* A number as OpenSCAD 2021.01 writes it (DoubleConvert: double-conversion's
 * ToPrecision with 6 digits, trailing zeros dropped): positional from 1e-5
 * up to 1e6, else d.ddddde+X with the exponent's sign and no padding; -0
 * is 0. printf's %.5e rounds as ToPrecision does (correctly), and its
 * exponent is that of the rounded value, which decides the form. */
static void echo_number(echo_text *t, double x)
{
    char m[64];
    if (isnan(x) || isinf(x) || x == 0) {
        const char *name = isnan(x) ? "nan" : x == 0 ? "0" : x > 0 ? "inf" : "-inf";
        echo_put(t, name, strlen(name));
        return;
    }
    snprintf(m, sizeof m, "%.5e", x);
    char *e = strchr(m, 'e');
    int exponent = atoi(e + 1);
    if (exponent < -5 || exponent >= 6) {
        *e = 0;
        trim_zeros(m);
        size_t n = strlen(m);
        snprintf(m + n, sizeof m - n, "e%c%d", exponent < 0 ? '-' : '+', abs(exponent));
    } else {
        snprintf(m, sizeof m, "%.*f", 5 - exponent, x);
        trim_zeros(m);
    }
    echo_put(t, m, strlen(m));
}

static void echo_value(echo_text *t, const parse_value *v)
{
    switch (v->kind) {
    case PARSE_UNDEF:
        echo_put(t, "undef", 5);
        break;
    case PARSE_BOOL:
        echo_put(t, v->u.boolean ? "true" : "false", v->u.boolean ? 4 : 5);
        break;
    case PARSE_NUMBER:
        echo_number(t, v->u.number);
        break;
    case PARSE_STRING: /* quoted, its characters as they are */
        echo_put(t, "\"", 1);
        echo_put(t, v->u.string.chars, v->u.string.length);
        echo_put(t, "\"", 1);
        break;
    case PARSE_VECTOR:
        echo_put(t, "[", 1);
        /* the nesting is bounded by the text's size: each level is a '[' */
        for (uint32_t i = 0; i < v->u.vector.count && !t->full; i++) {
            if (i)
                echo_put(t, ", ", 2);
            echo_value(t, &v->u.vector.items[i]);
        }
        echo_put(t, "]", 1);
        break;
    }
}

size_t model_echo_into(char buf[MODEL_ECHO_MAX + 1], const parse_value *v)
{
    buf[0] = 0;
    echo_text t = {buf, MODEL_ECHO_MAX + 1, 0, 0};
    echo_value(&t, v);
    return t.len;
}

const char *model_echo_value(arena *mem, const parse_value *v)
{
    char buf[MODEL_ECHO_MAX + 1];
    size_t len = model_echo_into(buf, v);
    char *copy = arena_alloc(mem, len + 1);
    if (copy)
        memcpy(copy, buf, len + 1);
    return copy;
}

/* ---- polyhedron(points, faces) ---- */

/* Point i of pts as OpenSCAD 2021.01 converts it where a face reads it
 * (Value::getVec3 with z = 0 for [x, y], then every coordinate finite): 1
 * with the point in *out, else 0 (*not_finite: numbers, one not finite).
 * A pair that is not two numbers, which OpenSCAD's getVec3 takes without
 * setting x and y, is not one either. */
static int polyhedron_point(const parse_value *pv, vec3 *out, int *not_finite)
{
    *not_finite = 0;
    uint32_t count = pv->kind == PARSE_VECTOR ? pv->u.vector.count : 0;
    if (count != 2 && count != 3)
        return 0;
    double c[3] = {0, 0, 0};
    for (uint32_t k = 0; k < count; k++) {
        const parse_value *cv = &pv->u.vector.items[k];
        if (cv->kind != PARSE_NUMBER)
            return 0;
        c[k] = cv->u.number;
    }
    vec3 q = v3(c[0], c[1], c[2]);
    *not_finite = !v3_is_finite(q);
    if (!*not_finite)
        *out = q;
    return !*not_finite;
}

/* What one pass over the faces finds (polyhedron_walk). */
typedef struct face_walk {
    uint32_t kept, bad_count; /* faces kept, indices out of range */
    uint32_t degenerate;      /* faces of fewer than 3 points */
    size_t total;             /* indices kept */
    size_t room;              /* indices written: those kept, then a face left out */
} face_walk;

/* Reads the faces fv (NULL: none) over the points pts (count np; ok[i]
 * says whether point i converts) as OpenSCAD 2021.01 does, up to the
 * first point it cannot convert that a face reads; with out NULL only
 * counts (w), else fills out's faces and bad indices (allocated for w's
 * counts) and bad point. Returns 0, or 1 when it stopped at a bad point,
 * -1 when memory ran out. */
static int polyhedron_walk(const model_reader *r, arena *mem, const parse_value *fv,
                           const parse_value *pts, uint32_t np, const unsigned char *ok,
                           uint32_t min_points, face_walk *w, model_node *out)
{
    uint32_t count = fv ? fv->u.vector.count : 0, k = 0, kept = 0, b = 0, degenerate = 0;
    size_t room = 0;
    uint32_t *indices = out ? (uint32_t *)out->u.polyhedron.indices : NULL;
    uint32_t *start = out ? (uint32_t *)out->u.polyhedron.face_start : NULL;
    model_bad_index *bad = out ? (model_bad_index *)out->u.polyhedron.bad : NULL;
    int stopped = 0;
    for (uint32_t f = 0; f < count && !stopped; f++) {
        const parse_value *face = &fv->u.vector.items[f];
        uint32_t first = k, n = face->kind == PARSE_VECTOR ? face->u.vector.count : 0;
        for (uint32_t i = 0; i < n && !stopped; i++) {
            const parse_value *iv = &face->u.vector.items[i];
            double x = model_index_value(iv);
            if (!(x >= 0 && x < (double)np)) {
                if (bad) {
                    bad[b].value = iv->kind == PARSE_NUMBER ? iv->u.number : 0;
                    bad[b].face = f;
                    bad[b].place = i;
                    bad[b].loc = model_loc(r, iv);
                }
                b++;
                continue;
            }
            uint32_t at = (uint32_t)x;
            if (!ok[at]) {
                stopped = 1;
                if (!out)
                    break;
                model_bad_point *bp = arena_alloc(mem, sizeof *bp);
                vec3 unused;
                if (!bp)
                    return -1;
                bp->index = at;
                polyhedron_point(&pts->u.vector.items[at], &unused, &bp->not_finite);
                bp->loc = model_loc(r, &pts->u.vector.items[at]);
                bp->text = model_echo_value(mem, &pts->u.vector.items[at]);
                if (!bp->text)
                    return -1;
                out->u.polyhedron.bad_point = bp;
                break;
            }
            if (indices)
                indices[k] = at;
            k++;
        }
        if (k > room)
            room = k;
        if (k - first < 3 && degenerate++ == 0 && out) {
            out->u.polyhedron.degenerate_face = f;
            out->u.polyhedron.degenerate_loc = model_loc(r, face);
        }
        if (k - first < min_points) {
            k = first; /* left out */
        } else {
            if (start)
                start[kept] = first;
            kept++;
        }
    }
    if (start)
        start[kept] = k;
    w->kept = kept;
    w->bad_count = b;
    w->degenerate = degenerate;
    w->total = k;
    w->room = room;
    return stopped;
}

sc_status model_read_polyhedron(const model_reader *r, arena *mem, const parse_node *n,
                                uint32_t min_points, model_node *out)
{
    const parse_value *pts = model_arg(n, "points", 0);
    const parse_value *fv = model_arg(n, "faces", 1);
    if (!fv)
        fv = model_arg(n, "triangles", -1);
    if (pts && pts->kind != PARSE_VECTOR)
        pts = NULL; /* none */
    if (fv && fv->kind != PARSE_VECTOR)
        fv = NULL;
    uint32_t np = pts ? pts->u.vector.count : 0;
    vec3 *p = arena_calloc(mem, np ? np : 1, sizeof *p);
    unsigned char *ok = calloc(np ? np : 1, 1);
    if (!p || !ok) {
        free(ok);
        return err_nomem(r->error, NULL);
    }
    for (uint32_t i = 0; i < np; i++) {
        int not_finite;
        ok[i] =
            (unsigned char)polyhedron_point(&pts->u.vector.items[i], &p[i], &not_finite);
    }
    face_walk w;
    polyhedron_walk(r, mem, fv, pts, np, ok, min_points, &w, NULL);
    if (w.room > UINT32_MAX) {
        free(ok);
        return err_nomem(r->error, NULL);
    }
    uint32_t *start = arena_calloc(mem, (size_t)w.kept + 1, sizeof *start);
    /* room for the points of a face read before it is left out */
    uint32_t *indices = arena_calloc(mem, w.room ? w.room : 1, sizeof *indices);
    model_bad_index *bad =
        w.bad_count ? arena_calloc(mem, w.bad_count, sizeof *bad) : NULL;
    if (!start || !indices || (w.bad_count && !bad)) {
        free(ok);
        return err_nomem(r->error, NULL);
    }
    out->u.polyhedron.points = p;
    out->u.polyhedron.point_count = np;
    out->u.polyhedron.indices = indices;
    out->u.polyhedron.face_start = start;
    out->u.polyhedron.bad = bad;
    out->u.polyhedron.bad_count = w.bad_count;
    out->u.polyhedron.face_count = w.kept;
    out->u.polyhedron.degenerate = w.degenerate;
    out->u.polyhedron.bad_point = NULL;
    int st = polyhedron_walk(r, mem, fv, pts, np, ok, min_points, &w, out);
    free(ok);
    return st < 0 ? err_nomem(r->error, NULL) : SC_OK;
}

double model_index_value(const parse_value *v)
{
    return v->kind == PARSE_NUMBER ? trunc(v->u.number) : 0;
}

int model_has_suffix(const char *s, const char *suffix)
{
    size_t a = strlen(s), b = strlen(suffix);
    if (a < b)
        return 0;
    for (size_t i = 0; i < b; i++) {
        char x = s[a - b + i];
        if (x >= 'A' && x <= 'Z')
            x = (char)(x - 'A' + 'a');
        if (x != suffix[i])
            return 0;
    }
    return 1;
}

model_mesh_format model_mesh_format_of(const char *name)
{
    return model_has_suffix(name, ".stl")   ? MODEL_MESH_STL
           : model_has_suffix(name, ".off") ? MODEL_MESH_OFF
           : model_has_suffix(name, ".amf") ? MODEL_MESH_AMF
           : model_has_suffix(name, ".3mf") ? MODEL_MESH_3MF
                                            : MODEL_MESH_UNSUPPORTED;
}

int model_import_is_drawing(const parse_node *n)
{
    const parse_arg *a = parse_node_arg(n, "file", 0);
    if (!a || a->value.kind != PARSE_STRING)
        return 0;
    const char *name = a->value.u.string.chars;
    return model_has_suffix(name, ".dxf") || model_has_suffix(name, ".svg");
}

const char *model_string_value(arena *mem, const parse_value *v)
{
    return v->kind == PARSE_STRING ? v->u.string.chars : model_echo_value(mem, v);
}

sc_status model_read_import(const model_reader *r, arena *mem, const parse_node *n,
                            model_import *out)
{
    out->drawing = NULL; /* a mesh, also when the arguments are bad */
    const parse_arg *a = parse_node_arg(n, "file", 0);
    if (!a || a->value.kind == PARSE_UNDEF) {
        /* OpenSCAD imports the file "" (its export writes file = ""): an
         * unsupported format, warned of where the import is built */
        out->file = "";
        out->file_loc = n->loc;
        out->format = model_mesh_format_of("");
        return SC_OK;
    }
    const char *name = model_string_value(mem, &a->value);
    if (!name)
        return err_nomem(r->error, NULL);
    sc_location loc = model_loc(r, &a->value);
    out->file = name;
    out->file_loc = loc;
    out->format = model_mesh_format_of(name);
    return SC_OK;
}

sc_status model_read_surface(const model_reader *r, arena *mem, const parse_node *n,
                             model_surface *out)
{
    const parse_value *file = model_arg(n, "file", 0);
    out->center = out->invert = 0;
    model_bool(r, n, "center", 1, &out->center);
    model_bool(r, n, "invert", -1, &out->invert);
    /* no file: OpenSCAD reads the file "", which cannot be opened */
    out->file = file ? model_string_value(mem, file) : "";
    if (!out->file)
        return err_nomem(r->error, NULL);
    out->file_loc = file ? model_loc(r, file) : n->loc;
    return SC_OK;
}

sc_status model_read_resolution(const model_reader *r, const parse_node *n, double *fn,
                                double *fa, double *fs)
{
    (void)r;
    model_resolution_of(n, 0, fn, fa, fs);
    return SC_OK;
}

sc_status model_read_circle(const model_reader *r, const parse_node *n, model_circle *out)
{
    out->r = 1;
    out->d = NAN;
    const parse_value *d = model_arg(n, "d", -1);
    out->has_d = d && d->kind == PARSE_NUMBER;
    sc_status st;
    if ((st = model_number(r, n, "r", 0, &out->r)) != SC_OK ||
        (st = model_number(r, n, "d", -1, &out->d)) != SC_OK)
        return st;
    st = model_read_resolution(r, n, &out->res.fn, &out->res.fa, &out->res.fs);
    /* a primitive: OpenSCAD clamps them (model_check_params warns) */
    out->res.fa = out->res.fa < MODEL_F_MINIMUM ? MODEL_F_MINIMUM : out->res.fa;
    out->res.fs = out->res.fs < MODEL_F_MINIMUM ? MODEL_F_MINIMUM : out->res.fs;
    return st;
}
