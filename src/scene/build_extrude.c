/* linear_extrude(height, center) of 2D children, without twist or scale,
 * built as a prism mesh (build_mesh.c, prim_mesh.c).
 *
 * The 2D children are gathered as closed paths in the plane: square (exact),
 * polygon with or without paths (exact), circle as the polygon OpenSCAD
 * makes for its $fn, $fa, $fs (faithful: OpenSCAD's own extrusion is that
 * polygon too), under group, union, render, color and multmatrix (its xy
 * part). Within one polygon the paths are oriented by nesting (a path
 * inside an odd number of the polygon's other paths is a hole, wound
 * clockwise; the others counter-clockwise), which is OpenSCAD's even-odd
 * reading of polygon paths. Each path becomes a prism: its points at z0
 * and z1 (0 and height, or -height/2 and height/2 centred), a wall quad
 * per edge and the path itself as bottom and top face. The mesh leaf
 * splits the caps into fans and counts crossings by winding number, so a
 * non-convex path is right (its fan's overlaps cancel), a hole subtracts
 * (its winding is -1 inside) and the union of overlapping children is
 * where the winding is positive. The prisms are exact for polygons: a ray
 * meets the planes of the walls and caps where the solid's faces are.
 *
 * Other 2D nodes (difference, intersection, offset, text, ...) inside an
 * extrusion, and twist or scale, are "not supported yet" at their position.
 * The walk over the children recurses with a depth guard
 * (BUILD_EXTRUDE_MAX_DEPTH).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "base/grow.h"
#include "scene/build_mesh.h"
#include "scene/build_text.h"
#include "scene/faithful.h"

enum { BUILD_EXTRUDE_MAX_DEPTH = 1000 };

typedef struct paths2d {
    double *xy; /* 2 per point */
    uint32_t count, cap;
    uint32_t *start; /* path p is points start[p] .. start[p + 1] - 1 */
    int *hole;       /* per path */
    uint32_t paths, paths_cap;
} paths2d;

typedef struct affine2 {
    double m[2][3];
} affine2;

static sc_status nomem(const build_ctx *c, const parse_node *n)
{
    return err_set(c->error, SC_ERR_NOMEM, &n->loc, "out of memory");
}

static int begin_path(paths2d *p)
{
    if (!grow_array32((void **)&p->start, &p->paths_cap, p->paths + 2,
                      sizeof *p->start) ||
        !(p->hole = realloc(p->hole, (size_t)p->paths_cap * sizeof *p->hole)))
        return 0;
    p->start[p->paths] = p->count;
    p->hole[p->paths] = 0;
    p->paths++;
    p->start[p->paths] = p->count;
    return 1;
}

static int add_point(paths2d *p, const affine2 *m, double x, double y)
{
    uint32_t need = 2 * (p->count + 1);
    uint32_t cap2 = p->cap * 2;
    if (need > cap2) {
        uint32_t cap = p->cap;
        if (!grow_array32((void **)&p->xy, &cap, need, sizeof *p->xy))
            return 0;
        p->cap = cap / 2;
    }
    p->xy[2 * p->count] = m->m[0][0] * x + m->m[0][1] * y + m->m[0][2];
    p->xy[2 * p->count + 1] = m->m[1][0] * x + m->m[1][1] * y + m->m[1][2];
    p->count++;
    p->start[p->paths] = p->count;
    return 1;
}

static double path_area(const paths2d *p, uint32_t k)
{
    double a = 0;
    uint32_t s = p->start[k], e = p->start[k + 1];
    for (uint32_t i = s; i < e; i++) {
        uint32_t j = i + 1 < e ? i + 1 : s;
        a += p->xy[2 * i] * p->xy[2 * j + 1] - p->xy[2 * j] * p->xy[2 * i + 1];
    }
    return a / 2;
}

/* Even-odd: is (x, y) inside path k? */
static int in_path(const paths2d *p, uint32_t k, double x, double y)
{
    int in = 0;
    uint32_t s = p->start[k], e = p->start[k + 1];
    for (uint32_t i = s; i < e; i++) {
        uint32_t j = i + 1 < e ? i + 1 : s;
        double xi = p->xy[2 * i], yi = p->xy[2 * i + 1];
        double xj = p->xy[2 * j], yj = p->xy[2 * j + 1];
        if ((yi > y) != (yj > y) && x < xi + (y - yi) * (xj - xi) / (yj - yi))
            in = !in;
    }
    return in;
}

static sc_status get_number(const build_ctx *c, const parse_node *n, const char *name,
                            int position, double *out)
{
    const parse_value *v = build_arg(n, name, position);
    if (!v)
        return SC_OK;
    if (v->kind != PARSE_NUMBER)
        return build_wrong_type(c, n, name, v, "a number");
    *out = v->u.number;
    return SC_OK;
}

static sc_status read_square(const build_ctx *c, const parse_node *n, const affine2 *m,
                             paths2d *p)
{
    double sx = 1, sy = 1;
    int center = 0;
    const parse_value *v = build_arg(n, "size", 0);
    if (v && v->kind == PARSE_NUMBER) {
        sx = sy = v->u.number;
    } else if (v && v->kind == PARSE_VECTOR && v->u.vector.count == 2 &&
               v->u.vector.items[0].kind == PARSE_NUMBER &&
               v->u.vector.items[1].kind == PARSE_NUMBER) {
        sx = v->u.vector.items[0].u.number;
        sy = v->u.vector.items[1].u.number;
    } else if (v) {
        return build_wrong_type(c, n, "size", v, "a number or [x, y]");
    }
    const parse_value *cv = build_arg(n, "center", 1);
    if (cv && cv->kind != PARSE_BOOL)
        return build_wrong_type(c, n, "center", cv, "true or false");
    center = cv ? cv->u.boolean : 0;
    if (!(sx > 0 && sy > 0 && isfinite(sx) && isfinite(sy)))
        return SC_OK; /* no area */
    double x0 = center ? -sx / 2 : 0, y0 = center ? -sy / 2 : 0;
    if (!begin_path(p) || !add_point(p, m, x0, y0) || !add_point(p, m, x0 + sx, y0) ||
        !add_point(p, m, x0 + sx, y0 + sy) || !add_point(p, m, x0, y0 + sy))
        return nomem(c, n);
    return SC_OK;
}

static sc_status read_circle(const build_ctx *c, const parse_node *n, const affine2 *m,
                             paths2d *p)
{
    double r = 1, d = NAN, fn = 0, fa = 12, fs = 2;
    sc_status st;
    if ((st = get_number(c, n, "r", 0, &r)) != SC_OK ||
        (st = get_number(c, n, "d", -1, &d)) != SC_OK ||
        (st = get_number(c, n, "$fn", -1, &fn)) != SC_OK ||
        (st = get_number(c, n, "$fa", -1, &fa)) != SC_OK ||
        (st = get_number(c, n, "$fs", -1, &fs)) != SC_OK)
        return st;
    if (!isnan(d))
        r = d / 2;
    if (!(r > 0 && isfinite(r)))
        return SC_OK;
    long f = faithful_fragments(r, fn, fs, fa);
    if (f < 0)
        return err_set(c->error, SC_ERR_LIMIT, &n->loc,
                       "circle has too many fragments (limit is %d)",
                       FAITHFUL_MAX_FRAGMENTS);
    if (!begin_path(p))
        return nomem(c, n);
    for (long k = 0; k < f; k++) {
        double a = 360.0 * (double)k / (double)f;
        if (!add_point(p, m, r * faithful_cos_deg(a), r * faithful_sin_deg(a)))
            return nomem(c, n);
    }
    return SC_OK;
}

static const char polygon_points[] = "a vector of [x, y] points";
static const char polygon_paths[] = "a vector of paths, each a vector of point indices";

static sc_status read_polygon(const build_ctx *c, const parse_node *n, const affine2 *m,
                              paths2d *p)
{
    const parse_value *pts = build_arg(n, "points", 0), *paths = build_arg(n, "paths", 1);
    if (!pts)
        return SC_OK;
    if (pts->kind != PARSE_VECTOR)
        return build_wrong_type(c, n, "points", pts, polygon_points);
    uint32_t np = pts->u.vector.count;
    for (uint32_t i = 0; i < np; i++) {
        const parse_value *v = &pts->u.vector.items[i];
        if (v->kind != PARSE_VECTOR || v->u.vector.count != 2 ||
            v->u.vector.items[0].kind != PARSE_NUMBER ||
            v->u.vector.items[1].kind != PARSE_NUMBER ||
            !isfinite(v->u.vector.items[0].u.number) ||
            !isfinite(v->u.vector.items[1].u.number))
            return build_wrong_type(c, n, "points", v, polygon_points);
    }
    if (paths && paths->kind != PARSE_VECTOR)
        return build_wrong_type(c, n, "paths", paths, polygon_paths);
    uint32_t first = p->paths;
    uint32_t count = paths ? paths->u.vector.count : 1;
    for (uint32_t k = 0; k < count; k++) {
        const parse_value *path = paths ? &paths->u.vector.items[k] : NULL;
        if (path && path->kind != PARSE_VECTOR)
            return build_wrong_type(c, n, "paths", path, polygon_paths);
        uint32_t len = path ? path->u.vector.count : np;
        if (!begin_path(p))
            return nomem(c, n);
        for (uint32_t i = 0; i < len; i++) {
            uint32_t index = i;
            if (path) {
                const parse_value *iv = &path->u.vector.items[i];
                if (iv->kind != PARSE_NUMBER || iv->u.number != floor(iv->u.number) ||
                    iv->u.number < 0 || iv->u.number >= np) {
                    sc_location loc = build_loc(c, iv);
                    return err_set(c->error, SC_ERR_SEMANTIC, &loc,
                                   "polygon path %u: point index is not one of the %u "
                                   "points",
                                   k, np);
                }
                index = (uint32_t)iv->u.number;
            }
            const parse_value *v = &pts->u.vector.items[index];
            if (!add_point(p, m, v->u.vector.items[0].u.number,
                           v->u.vector.items[1].u.number))
                return nomem(c, n);
        }
    }
    /* holes by nesting within this polygon */
    for (uint32_t k = first; k < p->paths; k++) {
        if (p->start[k + 1] - p->start[k] < 3)
            continue;
        double x = p->xy[2 * p->start[k]], y = p->xy[2 * p->start[k] + 1];
        int depth = 0;
        for (uint32_t j = first; j < p->paths; j++)
            if (j != k && p->start[j + 1] - p->start[j] >= 3 && in_path(p, j, x, y))
                depth++;
        p->hole[k] = depth % 2;
    }
    return SC_OK;
}

static sc_status gather(const build_ctx *c, const parse_node *n, const affine2 *m,
                        paths2d *p, int depth)
{
    if (depth > BUILD_EXTRUDE_MAX_DEPTH)
        return err_set(c->error, SC_ERR_LIMIT, &n->loc,
                       "too many nested nodes in linear_extrude (limit is %d)",
                       BUILD_EXTRUDE_MAX_DEPTH);
    if (n->modifiers & (PARSE_MOD_DISABLE | PARSE_MOD_BACKGROUND))
        return SC_OK;
    const char *name = n->name;
    if (strcmp(name, "square") == 0)
        return read_square(c, n, m, p);
    if (strcmp(name, "circle") == 0)
        return read_circle(c, n, m, p);
    if (strcmp(name, "polygon") == 0)
        return read_polygon(c, n, m, p);
    affine2 inner = *m;
    if (strcmp(name, "multmatrix") == 0) {
        const parse_value *v = build_arg(n, "m", 0);
        double a[4][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
        int ok = !v || (v->kind == PARSE_VECTOR && v->u.vector.count == 4);
        for (uint32_t r = 0; v && ok && r < 4; r++) {
            const parse_value *row = &v->u.vector.items[r];
            ok = row->kind == PARSE_VECTOR && row->u.vector.count == 4;
            for (uint32_t k = 0; ok && k < 4; k++) {
                ok = row->u.vector.items[k].kind == PARSE_NUMBER &&
                     isfinite(row->u.vector.items[k].u.number);
                if (ok)
                    a[r][k] = row->u.vector.items[k].u.number;
            }
        }
        if (!ok)
            return err_set(c->error, SC_ERR_SEMANTIC, &n->loc,
                           "multmatrix: matrix must be 4x4 numbers");
        /* inner = m after the matrix's xy part */
        for (int r = 0; r < 2; r++)
            for (int k = 0; k < 3; k++)
                inner.m[r][k] = m->m[r][0] * (k < 2 ? a[0][k] : a[0][3]) +
                                m->m[r][1] * (k < 2 ? a[1][k] : a[1][3]) +
                                (k == 2 ? m->m[r][2] : 0);
    } else if (strcmp(name, "group") != 0 && strcmp(name, "union") != 0 &&
               strcmp(name, "render") != 0 && strcmp(name, "color") != 0) {
        return err_set(c->error, SC_ERR_UNSUPPORTED, &n->loc,
                       "'%s' inside linear_extrude is not supported yet", name);
    }
    for (const parse_node *k = n->first_child; k; k = k->next) {
        sc_status st = gather(c, k, &inner, p, depth + 1);
        if (st != SC_OK)
            return st;
    }
    return SC_OK;
}

sc_status build_linear_extrude(const build_ctx *c, const parse_node *n, int emit,
                               prim *out, const char **empty)
{
    double height = 100, twist = 0;
    sc_status st;
    if ((st = get_number(c, n, "height", 0, &height)) != SC_OK ||
        (st = get_number(c, n, "twist", -1, &twist)) != SC_OK)
        return st;
    const parse_value *cv = build_arg(n, "center", 1);
    if (cv && cv->kind != PARSE_BOOL)
        return build_wrong_type(c, n, "center", cv, "true or false");
    int center = cv ? cv->u.boolean : 0;
    if (twist != 0)
        return err_set(c->error, SC_ERR_UNSUPPORTED, &n->loc,
                       "linear_extrude with twist is not supported yet");
    const parse_value *sv = build_arg(n, "scale", -1);
    if (sv) {
        int one = (sv->kind == PARSE_NUMBER && sv->u.number == 1) ||
                  (sv->kind == PARSE_VECTOR && sv->u.vector.count == 2 &&
                   sv->u.vector.items[0].kind == PARSE_NUMBER &&
                   sv->u.vector.items[0].u.number == 1 &&
                   sv->u.vector.items[1].kind == PARSE_NUMBER &&
                   sv->u.vector.items[1].u.number == 1);
        if (!one)
            return err_set(c->error, SC_ERR_UNSUPPORTED, &n->loc,
                           "linear_extrude with scale is not supported yet");
    }
    if (build_text_wanted(n)) /* text children: build_text.c */
        return build_text_extrude(c, n, height, center, emit, out, empty);
    paths2d p;
    memset(&p, 0, sizeof p);
    affine2 id = {{{1, 0, 0}, {0, 1, 0}}};
    for (const parse_node *k = n->first_child; k && st == SC_OK; k = k->next)
        st = gather(c, k, &id, &p, 1);
    if (st == SC_OK && emit) {
        double z0 = center ? -height / 2 : 0, z1 = z0 + height;
        double area = 0;
        for (uint32_t k = 0; k < p.paths; k++)
            area += fabs(path_area(&p, k));
        if (!(height > 0 && isfinite(height)) || !(area > 0)) {
            *empty = "linear_extrude without height or area is empty";
        } else {
            vec3 *pts = malloc((size_t)2 * (p.count ? p.count : 1) * sizeof *pts);
            /* per path: two caps and one wall per edge, 4 indices a wall */
            uint32_t *idx =
                malloc(((size_t)2 * p.count + 4 * (size_t)p.count + 1) * sizeof *idx);
            uint32_t *fs =
                malloc(((size_t)2 * p.paths + (size_t)p.count + 1) * sizeof *fs);
            if (!pts || !idx || !fs) {
                st = nomem(c, n);
            } else {
                uint32_t ni = 0, nf = 0;
                for (uint32_t i = 0; i < p.count; i++) {
                    pts[i] = v3(p.xy[2 * i], p.xy[2 * i + 1], z0);
                    pts[p.count + i] = v3(p.xy[2 * i], p.xy[2 * i + 1], z1);
                }
                for (uint32_t k = 0; k < p.paths; k++) {
                    uint32_t s = p.start[k], e = p.start[k + 1], len = e - s;
                    if (len < 3)
                        continue;
                    /* counter-clockwise outlines, clockwise holes */
                    int reverse = (path_area(&p, k) > 0) == p.hole[k];
                    fs[nf++] = ni; /* top: the path as wound */
                    for (uint32_t i = 0; i < len; i++)
                        idx[ni++] = p.count + s + (reverse ? len - 1 - i : i);
                    fs[nf++] = ni; /* bottom: the other way */
                    for (uint32_t i = 0; i < len; i++)
                        idx[ni++] = s + (reverse ? i : len - 1 - i);
                    for (uint32_t i = 0; i < len; i++) {
                        uint32_t a = s + (reverse ? len - 1 - i : i);
                        uint32_t b =
                            s + (reverse ? (2 * len - 2 - i) % len : (i + 1) % len);
                        fs[nf++] = ni;
                        idx[ni++] = a;
                        idx[ni++] = b;
                        idx[ni++] = p.count + b;
                        idx[ni++] = p.count + a;
                    }
                }
                fs[nf] = ni;
                st = build_mesh_prim(c, &n->loc, "linear_extrude", pts, 2 * p.count, idx,
                                     fs, nf, out, empty);
            }
            free(pts);
            free(idx);
            free(fs);
        }
    }
    free(p.xy);
    free(p.start);
    free(p.hole);
    return st;
}
