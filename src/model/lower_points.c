/* Lowering in the points context (model.h): the nodes below hull,
 * minkowski and resize, whose builder (build/build_hull.c) reads each
 * node where its walk reaches it, in file order, and names no node it
 * cannot take before it gets there; so each node's first argument error
 * is kept in it (pending) and lowering goes on.
 *
 * The checks, their order and their messages are the hull builder's:
 *   cube, sphere, cylinder, multmatrix, import, surface, torus, quadric,
 *                implicit      as in the main model (model/args.c,
 *                              lower_curved.c)
 *   polyhedron   as in the main model (model_read_polyhedron), every
 *                face kept whatever its size
 *   resize       as OpenSCAD 2021.01 reads it (read_triple): newsize's
 *                entries numbers, finite (a negative one kept), others 0;
 *                auto true, false or a vector read by truth
 *   linear_extrude, rotate_extrude, the 2D shapes (not import)
 *                as in the 2D context (lower_twod.c): a hull,
 *                minkowski or resize of 2D children is 2D
 *                (build_twod.c), and a 3D one checks the 2D children it
 *                ignores
 * group, union, render, color and material take no arguments here, nor
 * do hull and minkowski.
 */
#include "model/lower_points.h"

#include <math.h>
#include <string.h>

#include "base/error.h"
#include "model/args.h"
#include "model/lower_curved.h"
#include "model/lower_twod.h"

static sc_status lower_polyhedron(model_lowerer *l, const parse_node *n, model_node *out)
{
    sc_status st = model_read_polyhedron(&l->r, l->mem, n, 0, out);
    if (st == SC_ERR_NOMEM)
        l->nomem = 1;
    return st;
}

/* v as OpenSCAD 2021.01's Value::toBool takes it: true, a number other
 * than 0, a string or a vector that is not empty. */
static int truth(const parse_value *v)
{
    switch (v->kind) {
    case PARSE_BOOL:
        return v->u.boolean;
    case PARSE_NUMBER:
        return v->u.number != 0;
    case PARSE_STRING:
        return v->u.string.length != 0;
    case PARSE_VECTOR:
        return v->u.vector.count != 0;
    default:
        return 0;
    }
}

/* A vector of up to 3 numbers (newsize) or flags (auto), as OpenSCAD
 * 2021.01 reads them without a word: newsize's entries that are not
 * numbers are 0, as is all of it when it is not a vector; auto is all
 * true or false when it is true or false, else each entry's truth
 * (truth), and all false when it is not a vector either. A number that is
 * not finite is an error. */
static sc_status read_triple(model_lowerer *l, const parse_node *n, const char *name,
                             int position, int flags, double out[3])
{
    const parse_value *v = model_arg(n, name, position);
    if (!v)
        return SC_OK;
    if (flags && v->kind == PARSE_BOOL) {
        out[0] = out[1] = out[2] = v->u.boolean;
        return SC_OK;
    }
    if (v->kind != PARSE_VECTOR)
        return SC_OK;
    for (uint32_t i = 0; i < v->u.vector.count && i < 3; i++) {
        const parse_value *item = &v->u.vector.items[i];
        if (!flags && item->kind == PARSE_NUMBER && !isfinite(item->u.number))
            return model_wrong_type(&l->r, n, name, item, "a vector of finite numbers");
        if (flags)
            out[i] = truth(item);
        else if (item->kind == PARSE_NUMBER)
            out[i] = item->u.number;
    }
    return SC_OK;
}

static sc_status lower_resize(model_lowerer *l, const parse_node *n, model_node *out)
{
    model_resize *r = model_lowerer_alloc(l, sizeof *r);
    if (!r)
        return SC_ERR_NOMEM;
    out->u.resize = r;
    sc_status st = read_triple(l, n, "newsize", 0, 0, r->size);
    if (st == SC_OK)
        st = read_triple(l, n, "auto", 1, 1, r->autosize);
    /* A negative size is kept: OpenSCAD 2021.01 reads it as 0 for a mesh
     * or a 2D shape, and mirrors a CGAL result by it (build_hull.c). */
    return st;
}

static sc_status lower_matrix(model_lowerer *l, const parse_node *n, model_node *out)
{
    return model_read_xform(&l->r, l->mem, n, &out->u.xform, &out->not_finite);
}

static sc_status lower_leaf(model_lowerer *l, const parse_node *n, model_node *out)
{
    switch (out->kind) {
    case MODEL_CUBE:
        return model_cube(&l->r, n, out->u.cube.size, &out->u.cube.center);
    case MODEL_SPHERE:
        return model_read_sphere(&l->r, n, &out->u.sphere.r, &out->u.sphere.res);
    case MODEL_CYLINDER:
        return model_read_cylinder(&l->r, n, &out->u.cylinder.h, &out->u.cylinder.r1,
                                   &out->u.cylinder.r2, &out->u.cylinder.center,
                                   &out->u.cylinder.res);
    case MODEL_IMPORT: {
        model_import *import = model_lowerer_alloc(l, sizeof *import);
        if (!import)
            return SC_ERR_NOMEM;
        out->u.import = import;
        return model_read_import(&l->r, l->mem, n, import);
    }
    case MODEL_SURFACE: {
        model_surface *surface = model_lowerer_alloc(l, sizeof *surface);
        if (!surface)
            return SC_ERR_NOMEM;
        out->u.surface = surface;
        return model_read_surface(&l->r, l->mem, n, surface);
    }
    case MODEL_TORUS: {
        model_torus *t = model_lowerer_alloc(l, sizeof *t);
        if (!t)
            return SC_ERR_NOMEM;
        out->u.torus = t;
        return model_read_torus(&l->r, n, t);
    }
    case MODEL_QUADRIC: {
        model_quadric *q = model_lowerer_alloc(l, sizeof *q);
        if (!q)
            return SC_ERR_NOMEM;
        out->u.quadric = q;
        return model_read_quadric(&l->r, n, q);
    }
    case MODEL_IMPLICIT: {
        model_implicit *f = model_lowerer_alloc(l, sizeof *f);
        if (!f)
            return SC_ERR_NOMEM;
        out->u.implicit = f;
        return model_read_implicit(&l->r, n, f);
    }
    default:
        return SC_OK;
    }
}

sc_status model_points_args(arena *mem, const char *file, const parse_node *n,
                            model_node *out, sc_error *error)
{
    /* the extrusions, and 2D shapes (a 2D hull or resize, or one a 3D
     * operation ignores), are read as in the 2D context */
    if (out->kind == MODEL_LINEAR_EXTRUDE || out->kind == MODEL_ROTATE_EXTRUDE ||
        model_is_2d(out->kind))
        return model_twod_args(mem, file, n, out, error);
    if (out->kind == MODEL_IMPORT && model_import_is_drawing(n))
        return model_import_drawing(mem, file, n, out, error);
    sc_error pending;
    model_lowerer l = {mem, {file, &pending}, 0};
    sc_status st;
    if (out->kind == MODEL_POLYHEDRON)
        st = lower_polyhedron(&l, n, out);
    else if (out->kind == MODEL_RESIZE)
        st = lower_resize(&l, n, out);
    else if (out->kind == MODEL_XFORM)
        st = lower_matrix(&l, n, out);
    else
        st = lower_leaf(&l, n, out);
    return model_keep_pending(mem, st, l.nomem, &pending, out, error);
}
