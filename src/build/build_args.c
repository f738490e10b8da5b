/* What the builders of 2D subtrees share (build_ctx.h): the pending
 * argument error of a node, the warnings of a walk, a multmatrix removed
 * for a nan or inf entry, a child of the other dimension left out, and the
 * 2D part of a multmatrix. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "base/error.h"
#include "base/grow.h"
#include "build/build_ctx.h"

sc_status build_pending(const build_ctx *c, const model_node *n)
{
    *c->error = *n->pending;
    return n->pending->status;
}

sc_status build_notes_add(build_notes *notes, sc_error *error, const sc_location *loc,
                          const char *format, va_list args)
{
    char message[SC_ERROR_MESSAGE_MAX];
    vsnprintf(message, sizeof message, format, args);
    if (!message[0]) /* an empty warning: a part left out, its reason given before */
        return SC_OK;
    if (!grow_array((void **)&notes->items, &notes->cap, notes->count + 1,
                    sizeof *notes->items))
        return err_nomem(error, NULL);
    err_set(&notes->items[notes->count++], SC_OK, loc, "%s", message);
    return SC_OK;
}

build_notes_place build_notes_here(const build_ctx *c)
{
    build_notes_place at = {0, 0};
    if (c->notes) {
        at.count = c->notes->count;
        at.left_out = c->notes->left_out;
    }
    return at;
}

void build_notes_rewind(const build_ctx *c, build_notes_place at)
{
    if (c->notes) {
        c->notes->count = at.count;
        c->notes->left_out = at.left_out;
    }
}

sc_status build_note(const build_ctx *c, const sc_location *loc, const char *format, ...)
{
    if (!c->notes)
        return SC_OK;
    va_list args;
    va_start(args, format);
    sc_status st = build_notes_add(c->notes, c->error, loc, format, args);
    va_end(args);
    return st;
}

static sc_status charge(const build_ctx *c, const sc_location *loc, const char *what,
                        size_t count, int bound)
{
    if (!c->triangles_left)
        return SC_OK;
    if (count > *c->triangles_left)
        return err_set(
            c->error, SC_ERR_LIMIT, loc,
            "%s: too many mesh triangles (%s%zu more, past the limit of %zu in "
            "one model)",
            what, bound ? "at least " : "", count, c->max_triangles);
    if (!bound)
        *c->triangles_left -= count;
    return SC_OK;
}

sc_status build_charge_triangles(const build_ctx *c, const sc_location *loc,
                                 const char *what, size_t count)
{
    return charge(c, loc, what, count, 0);
}

sc_status build_check_triangles(const build_ctx *c, const sc_location *loc,
                                const char *what, size_t count)
{
    return charge(c, loc, what, count, 1);
}

sc_status build_note_left_out(const build_ctx *c, const sc_location *loc,
                              const char *format, ...)
{
    if (!c->notes)
        return SC_OK;
    c->notes->left_out++;
    va_list args;
    va_start(args, format);
    sc_status st = build_notes_add(c->notes, c->error, loc, format, args);
    va_end(args);
    return st;
}

sc_status build_file_not_opened(const build_ctx *c, const sc_location *loc,
                                const char *what, const char *path, const char *why)
{
    if (c->strict)
        return err_set(c->error, SC_ERR_IO, loc, "Can't open %s file '%s': %s", what,
                       path, why);
    return build_note_left_out(c, loc,
                               "Can't open %s file '%s': %s; the import is empty, as "
                               "OpenSCAD leaves it out (--strict makes it an error)",
                               what, path, why);
}

static sc_status bad_indices(const build_ctx *c, const model_node *n)
{
    int polygon = n->kind == MODEL_POLYGON;
    const model_bad_index *bad = polygon ? n->u.polygon->bad : n->u.polyhedron.bad;
    uint32_t count = polygon ? n->u.polygon->bad_count : n->u.polyhedron.bad_count;
    uint32_t points = polygon ? n->u.polygon->point_count : n->u.polyhedron.point_count;
    sc_status st = SC_OK;
    for (uint32_t i = 0; i < count && st == SC_OK; i++) {
        const model_bad_index *b = &bad[i];
        double x = isfinite(b->value) ? trunc(b->value) : b->value;
        if (c->strict)
            return err_set(c->error, SC_ERR_SEMANTIC, &b->loc,
                           "%s %u: point index %g is out of range (%u points)",
                           polygon ? "polygon path" : "polyhedron face", b->face, x,
                           points);
        /* counted as left out: a shape it leaves without area is not
         * warned of again, as OpenSCAD prints only this */
        st = build_note_left_out(c, &b->loc,
                                 "Point index %g is out of bounds (from %s[%u][%u])", x,
                                 polygon ? "paths" : "faces", b->face, b->place);
    }
    const model_bad_point *p =
        polygon ? n->u.polygon->bad_point : n->u.polyhedron.bad_point;
    if (st == SC_OK && polygon && n->u.polygon->range_bad) {
        /* the outlines OpenSCAD's clipper refuses (model.h), after the
         * indices, as it sanitizes the polygon it made */
        if (c->strict)
            return err_set(c->error, SC_ERR_LIMIT, &n->loc,
                           "polygon: coordinates out of the clipper's range");
        st = build_note_left_out(c, &n->loc,
                                 "Range check failed for polygon. skipping (the outline "
                                 "and those after it, as OpenSCAD leaves them out; "
                                 "--strict makes it an error)");
    }
    if (st != SC_OK || !p)
        return st;
    if (c->strict && p->not_finite && !polygon)
        return err_set(c->error, SC_ERR_SEMANTIC, &p->loc,
                       "polyhedron point %u is not finite", p->index);
    if (c->strict)
        return err_set(c->error, SC_ERR_SEMANTIC, &p->loc,
                       "wrong type for argument 'points' of '%s' (expected a vector of "
                       "[x, y%s] points)",
                       n->name, polygon ? "" : ", z");
    /* OpenSCAD's error, after which it renders the rest; counted as left
     * out, as the index warnings are */
    return build_note_left_out(
        c, &p->loc,
        "Unable to convert points[%u] = %s to a vec%d of numbers; %s "
        "(--strict makes it an error)",
        p->index, p->text, polygon ? 2 : 3,
        polygon ? "the polygon is empty, as OpenSCAD leaves it out"
                : "the polyhedron keeps the faces before it, as "
                  "OpenSCAD does");
}

sc_status build_bad_indices(const build_ctx *c, const model_node *n)
{
    if ((n->kind != MODEL_POLYGON && n->kind != MODEL_POLYHEDRON) || n->pending ||
        !c->notes)
        return SC_OK;
    sc_status st = bad_indices(c, n);
    uint32_t degenerate = n->kind == MODEL_POLYHEDRON ? n->u.polyhedron.degenerate : 0;
    if (st != SC_OK || degenerate == 0)
        return st;
    /* OpenSCAD's warning, as its tessellation meets them (tessellate_faces),
     * after those of the indices and points, where the first is */
    const sc_location *loc = &n->u.polyhedron.degenerate_loc;
    uint32_t face = n->u.polyhedron.degenerate_face;
    if (c->strict)
        return err_set(c->error, SC_ERR_SEMANTIC, loc,
                       "polyhedron face %u has fewer than 3 points", face);
    if (degenerate == 1)
        return build_note(c, loc,
                          "PolySet has degenerate polygons (faces[%u] has fewer than 3 "
                          "points; left out, as OpenSCAD leaves it out)",
                          face);
    return build_note(c, loc,
                      "PolySet has degenerate polygons (faces[%u] and %u more have fewer "
                      "than 3 points; left out, as OpenSCAD leaves them out)",
                      face, degenerate - 1);
}

sc_status build_xform_not_finite(const build_ctx *c, const model_node *n)
{
    if (n->kind != MODEL_XFORM || !n->not_finite || !c->notes)
        return SC_OK;
    if (c->strict)
        return err_set(c->error, SC_ERR_SEMANTIC, &n->loc,
                       "multmatrix: matrix entries must be finite");
    return build_note(c, &n->loc,
                      "Transformation matrix contains Not-a-Number and/or Infinity - "
                      "removing object.");
}

sc_status build_xform_flat_2d(const build_ctx *c, const model_node *n)
{
    if (!c->notes)
        return SC_OK;
    return build_note(c, &n->loc, "Scaling a 2D object with 0 - removing object");
}

/* With --strict the error for a child of the other dimension, which
 * OpenSCAD 2021.01 leaves out with its warnings: spancast's words, as for
 * the other strict errors (OpenSCAD's "Ignoring ..." says what it does,
 * not what is wrong). */
static sc_status other_dim(const build_ctx *c, const sc_location *loc, int in_2d)
{
    return err_set(c->error, SC_ERR_SEMANTIC, loc, "%s child object in a %s operation",
                   in_2d ? "3D" : "2D", in_2d ? "2D" : "3D");
}

sc_status build_mixing(const build_ctx *c, const sc_location *loc, int in_2d)
{
    if (!c->notes)
        return SC_OK;
    if (c->strict)
        return other_dim(c, loc, in_2d);
    return build_note(c, loc, "Mixing 2D and 3D objects is not supported");
}

sc_status build_ignoring(const build_ctx *c, const sc_location *loc, int in_2d)
{
    if (!c->notes)
        return SC_OK;
    if (c->strict)
        return other_dim(c, loc, in_2d);
    return build_note(c, loc, "Ignoring %s child object for %s operation",
                      in_2d ? "3D" : "2D", in_2d ? "2D" : "3D");
}

void build_matrix_xy(const affine *a, const double outer[2][3], double inner[2][3])
{
    double o[2][3];
    memcpy(o, outer, sizeof o); /* inner may be outer */
    for (int r = 0; r < 2; r++) {
        inner[r][0] = o[r][0] * a->m[0][0] + o[r][1] * a->m[1][0];
        inner[r][1] = o[r][0] * a->m[0][1] + o[r][1] * a->m[1][1];
        inner[r][2] = o[r][0] * a->m[0][3] + o[r][1] * a->m[1][3] + o[r][2];
    }
}
