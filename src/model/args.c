/* Readers of a syntax node's arguments: see args.h. */
#include "model/args.h"

#include <math.h>
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
    const parse_value *v = model_arg(n, name, position);
    if (!v)
        return SC_OK;
    if (v->kind != PARSE_NUMBER)
        return model_wrong_type(c, n, name, v, "a number");
    *out = v->u.number;
    return SC_OK;
}

sc_status model_radius(const model_reader *r, const parse_node *n, const char *diameter,
                       const char *radius, int radius_position, double *out, int *given)
{
    /* Each argument looked up once (this runs for every sphere and three
     * times for every cylinder); the diameter's type is checked first. */
    const parse_value *d = model_arg(n, diameter, -1);
    const parse_value *rv = model_arg(n, radius, radius_position);
    *given = rv != NULL;
    if (d && d->kind != PARSE_NUMBER)
        return model_wrong_type(r, n, diameter, d, "a number");
    if (rv) {
        if (rv->kind != PARSE_NUMBER)
            return model_wrong_type(r, n, radius, rv, "a number");
        *out = rv->u.number;
    }
    if (d) {
        *out = d->u.number / 2;
        *given = 1;
    }
    return SC_OK;
}

sc_status model_read_sphere(const model_reader *r, const parse_node *n, double *radius,
                            model_resolution *res)
{
    int given;
    *radius = 1;
    parse_node_resolution(n, &res->fn, &res->fa, &res->fs);
    return model_radius(r, n, "d", "r", 0, radius, &given);
}

sc_status model_read_cylinder(const model_reader *r, const parse_node *n, double *h,
                              double *r1, double *r2, int *center, model_resolution *res)
{
    double radius = 1;
    int has_r = 0, has_r1 = 0, has_r2 = 0;
    *h = *r1 = *r2 = 1;
    *center = 0;
    parse_node_resolution(n, &res->fn, &res->fa, &res->fs);
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
    static const double id[4][4] = {
        {1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
    memcpy(a, id, sizeof id);
    const parse_value *v = model_arg(n, "m", 0);
    int ok = !v || (v->kind == PARSE_VECTOR && v->u.vector.count == 4);
    for (uint32_t r = 0; v && ok && r < 4; r++) {
        const parse_value *row = &v->u.vector.items[r];
        ok = row->kind == PARSE_VECTOR && row->u.vector.count == 4;
        for (uint32_t k = 0; ok && k < 4; k++) {
            ok = row->u.vector.items[k].kind == PARSE_NUMBER;
            if (ok)
                a[r][k] = row->u.vector.items[k].u.number;
        }
    }
    if (!ok)
        return err_set(c->error, SC_ERR_SEMANTIC, &n->loc,
                       "multmatrix: matrix must be 4x4 numbers");
    *not_finite = 0;
    for (int r = 0; r < 4; r++)
        for (int k = 0; k < 4; k++)
            *not_finite |= !isfinite(a[r][k]);
    if (*not_finite)
        return SC_OK;
    if (a[3][0] != 0 || a[3][1] != 0 || a[3][2] != 0 || a[3][3] != 1)
        return err_set(c->error, SC_ERR_SEMANTIC, &n->loc,
                       "multmatrix: bottom row must be [0, 0, 0, 1]");
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

sc_status model_read_square(const model_reader *c, const parse_node *n, double *sx,
                            double *sy, int *center)
{
    *sx = *sy = 1;
    *center = 0;
    const parse_value *v = model_arg(n, "size", 0);
    if (v && v->kind == PARSE_NUMBER) {
        *sx = *sy = v->u.number;
    } else if (v && v->kind == PARSE_VECTOR && v->u.vector.count == 2 &&
               v->u.vector.items[0].kind == PARSE_NUMBER &&
               v->u.vector.items[1].kind == PARSE_NUMBER) {
        *sx = v->u.vector.items[0].u.number;
        *sy = v->u.vector.items[1].u.number;
    } else if (v) {
        return model_wrong_type(c, n, "size", v, "a number or [x, y]");
    }
    const parse_value *cv = model_arg(n, "center", 1);
    if (cv && cv->kind != PARSE_BOOL)
        return model_wrong_type(c, n, "center", cv, "true or false");
    *center = cv ? cv->u.boolean : 0;
    return SC_OK;
}

sc_status model_bool(const model_reader *c, const parse_node *n, const char *name,
                     int position, int *out)
{
    const parse_value *v = model_arg(n, name, position);
    if (!v)
        return SC_OK;
    if (v->kind != PARSE_BOOL)
        return model_wrong_type(c, n, name, v, "true or false");
    *out = v->u.boolean;
    return SC_OK;
}

static const char polygon_points[] = "a vector of [x, y] points";

sc_status model_read_polygon(const model_reader *c, const parse_node *n,
                             const parse_value **points, const parse_value **paths)
{
    const parse_value *pts = model_arg(n, "points", 0), *ps = model_arg(n, "paths", 1);
    *points = pts;
    *paths = ps;
    if (!pts)
        return SC_OK;
    if (pts->kind != PARSE_VECTOR)
        return model_wrong_type(c, n, "points", pts, polygon_points);
    for (uint32_t i = 0; i < pts->u.vector.count; i++) {
        const parse_value *v = &pts->u.vector.items[i];
        if (v->kind != PARSE_VECTOR || v->u.vector.count != 2 ||
            v->u.vector.items[0].kind != PARSE_NUMBER ||
            v->u.vector.items[1].kind != PARSE_NUMBER ||
            !isfinite(v->u.vector.items[0].u.number) ||
            !isfinite(v->u.vector.items[1].u.number))
            return model_wrong_type(c, n, "points", v, polygon_points);
    }
    if (ps && ps->kind != PARSE_VECTOR)
        return model_wrong_type(c, n, "paths", ps, MODEL_POLYGON_PATHS);
    for (uint32_t k = 0; ps && k < ps->u.vector.count; k++) {
        if (ps->u.vector.items[k].kind != PARSE_VECTOR)
            return model_wrong_type(c, n, "paths", &ps->u.vector.items[k],
                                    MODEL_POLYGON_PATHS);
    }
    return SC_OK;
}

sc_status model_cube(const model_reader *c, const parse_node *n, double size[3],
                     int *center)
{
    size[0] = size[1] = size[2] = 1;
    *center = 0;
    const parse_value *v = model_arg(n, "size", 0);
    if (v && v->kind == PARSE_NUMBER) {
        size[0] = size[1] = size[2] = v->u.number;
    } else if (v) {
        int ok = v->kind == PARSE_VECTOR && v->u.vector.count == 3;
        for (uint32_t i = 0; ok && i < 3; i++) {
            ok = v->u.vector.items[i].kind == PARSE_NUMBER;
            if (ok)
                size[i] = v->u.vector.items[i].u.number;
        }
        if (!ok)
            return model_wrong_type(c, n, "size", v, "a number or a vector of 3 numbers");
    }
    return model_bool(c, n, "center", 1, center);
}

static const char faces_expected[] = "a vector of faces, each a vector of point indices";

sc_status model_read_faces(const model_reader *r, arena *mem, const parse_node *n,
                           const char *param, const parse_value *v, uint32_t point_count,
                           uint32_t min_points, model_node *out)
{
    if (v->kind != PARSE_VECTOR)
        return model_wrong_type(r, n, param, v, faces_expected);
    uint32_t count = v->u.vector.count, bad_count = 0;
    size_t total = 0;
    for (uint32_t f = 0; f < count; f++) {
        const parse_value *fv = &v->u.vector.items[f];
        if (fv->kind != PARSE_VECTOR)
            return model_wrong_type(r, n, param, fv, faces_expected);
        for (uint32_t i = 0; i < fv->u.vector.count; i++) {
            double x = model_index_value(&fv->u.vector.items[i]);
            bad_count += !(x >= 0 && x < (double)point_count);
        }
        total += fv->u.vector.count;
    }
    if (total > UINT32_MAX)
        return err_nomem(r->error, NULL);
    uint32_t *start = arena_calloc(mem, (size_t)count + 1, sizeof *start);
    uint32_t *indices = arena_calloc(mem, total ? total : 1, sizeof *indices);
    model_bad_index *bad = bad_count ? arena_calloc(mem, bad_count, sizeof *bad) : NULL;
    if (!start || !indices || (bad_count && !bad))
        return err_nomem(r->error, NULL);
    uint32_t k = 0, kept = 0, b = 0;
    for (uint32_t f = 0; f < count; f++) {
        const parse_value *fv = &v->u.vector.items[f];
        uint32_t first = k;
        for (uint32_t i = 0; i < fv->u.vector.count; i++) {
            const parse_value *iv = &fv->u.vector.items[i];
            double x = model_index_value(iv);
            if (x >= 0 && x < (double)point_count) {
                indices[k++] = (uint32_t)x;
            } else {
                bad[b].value = iv->kind == PARSE_NUMBER ? iv->u.number : 0;
                bad[b].face = f;
                bad[b].place = i;
                bad[b++].loc = model_loc(r, iv);
            }
        }
        if (k - first < min_points)
            k = first; /* left out */
        else
            start[kept++] = first;
    }
    start[kept] = k;
    out->u.polyhedron.indices = indices;
    out->u.polyhedron.face_start = start;
    out->u.polyhedron.face_count = kept;
    out->u.polyhedron.bad = bad;
    out->u.polyhedron.bad_count = bad_count;
    return SC_OK;
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

sc_status model_read_import(const model_reader *r, const parse_node *n, model_import *out)
{
    out->drawing = NULL; /* a mesh, also when the arguments are bad */
    const parse_arg *a = parse_node_arg(n, "file", 0);
    if (!a || a->value.kind != PARSE_STRING) {
        if (a && a->value.kind != PARSE_UNDEF)
            return model_wrong_type(r, n, "file", &a->value, "a file name");
        return err_set(r->error, SC_ERR_SEMANTIC, &n->loc,
                       "missing argument 'file' of 'import'");
    }
    const char *name = a->value.u.string.chars;
    sc_location loc = model_loc(r, &a->value);
    out->file = name;
    out->file_loc = loc;
    out->format = model_mesh_format_of(name);
    return SC_OK;
}

sc_status model_read_surface(const model_reader *r, const parse_node *n,
                             model_surface *out)
{
    const parse_value *file = model_arg(n, "file", 0);
    if (!file)
        return err_set(r->error, SC_ERR_SEMANTIC, &n->loc,
                       "missing argument 'file' of 'surface'");
    if (file->kind != PARSE_STRING)
        return model_wrong_type(r, n, "file", file, "a file name");
    const parse_value *v = model_arg(n, "center", 1);
    if (v && v->kind != PARSE_BOOL)
        return model_wrong_type(r, n, "center", v, "true or false");
    out->center = v ? v->u.boolean : 0;
    v = model_arg(n, "invert", -1);
    if (v && v->kind != PARSE_BOOL)
        return model_wrong_type(r, n, "invert", v, "true or false");
    out->invert = v ? v->u.boolean : 0;
    out->file = file->u.string.chars;
    out->file_loc = model_loc(r, file);
    return SC_OK;
}

sc_status model_read_resolution(const model_reader *r, const parse_node *n, double *fn,
                                double *fa, double *fs)
{
    *fn = 0;
    *fa = 12;
    *fs = 2;
    sc_status st;
    if ((st = model_number(r, n, "$fn", -1, fn)) != SC_OK ||
        (st = model_number(r, n, "$fa", -1, fa)) != SC_OK)
        return st;
    return model_number(r, n, "$fs", -1, fs);
}

sc_status model_read_circle(const model_reader *r, const parse_node *n, model_circle *out)
{
    out->r = 1;
    out->d = NAN;
    out->has_d = model_arg(n, "d", -1) != NULL;
    sc_status st;
    if ((st = model_number(r, n, "r", 0, &out->r)) != SC_OK ||
        (st = model_number(r, n, "d", -1, &out->d)) != SC_OK)
        return st;
    return model_read_resolution(r, n, &out->res.fn, &out->res.fa, &out->res.fs);
}
