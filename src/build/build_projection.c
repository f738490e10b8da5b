/* projection(cut = true | false) as OpenSCAD 2021.01 computes it
 * (GeometryEvaluator's projectionCut and projectionNoCut): a 2D region
 * from 3D children, in the projection node's frame.
 *
 * Meshes. OpenSCAD projects or cuts the polygon mesh of its children, so
 * every leaf here is OpenSCAD's mesh of it, in both modes, as a soup of
 * outward triangles in the projection's frame: a cube its 6 quads; a
 * sphere and a cylinder the rings and circles of their $fn, $fa, $fs
 * (faithful.c's rule); a polyhedron its faces (build_mesh.c's fans); an
 * import and surface their --faithful meshes; the extrusions, projected,
 * the faces of their --faithful meshes, each cap one face with its holes
 * (faces_soup), and cut, their meshes. A
 * transform with a negative determinant turns the triangles back outward.
 * A polyhedron or import that is not closed is projected as it is, every
 * face (it has no outward side), silently, as OpenSCAD projects any
 * mesh; a cut needs its Nef polyhedron, so an import that is not closed
 * is left out there with OpenSCAD's message as a warning (built_soup).
 *
 * cut = false: the union of every face projected onto z = 0, each turned
 * counter-clockwise (down-facing faces project clockwise), with non-zero
 * fill (twod_clip_union_nonzero): OpenSCAD's PolysetUtils::project and
 * its Clipper union. The same region comes from fewer faces: a closed
 * mesh's up-facing ones, with a face that is not convex taken whole
 * (up_faces), and a convex leaf's 2D hull (projected_faces). The
 * projection of a union is the union of the projections, so the faces of
 * every leaf below unions, groups, transforms, colours and resizes go into
 * one union. The projection of a
 * difference or intersection is not a 2D boolean of the children's
 * projections (a hole through a cube does not show from above unless it
 * goes through); OpenSCAD projects the mesh of the boolean's result. So
 * does this file: the boolean is evaluated to a CGAL Nef polyhedron
 * (build_nef_triangles, the path hull() and minkowski() take, with the
 * plugin loaded on first use) and its triangles are a leaf like any
 * other.
 *
 * cut = true: OpenSCAD intersects the Nef polyhedron of the union of the
 * children with the plane z = 0 and keeps the closed set, and its Nef
 * booleans keep lower-dimensional parts: a face lying in the plane is part
 * of the section (cube(10) cut at its bottom face is its 10 x 10 square),
 * two cubes that only touch in z = 0 intersect in their common face, and
 * a cube whose bottom face is in the plane, minus a cube below it that
 * touches that face, keeps the face with a hole where they touched. Seen
 * on OpenSCAD 2021.01 (docs/extrusions.md), all of these are the 2D
 * booleans of each leaf's closed section, so that is what is built: the
 * section of every leaf, with its faces in the plane, and the tree's
 * booleans on them in 2D. A leaf's closed section is the union of its
 * sections in the limits z -> 0 from above and from below (a point of
 * z = 0 in a closed solid has the solid just above it or just below it,
 * up to sets without area, which a 2D result does not have); the limit
 * from above treats a vertex at z = 0 as below the plane, the limit from
 * below as above it, and both sets of loops go into one non-zero union.
 *
 * A leaf's section: each triangle with vertices on both sides gives one
 * directed segment, from its edge that goes down through the plane to the
 * edge that comes up, which for outward triangles runs counter-clockwise
 * around the solid's section seen from +z. The point on an edge is
 * computed from its two ends in one fixed order, so the two triangles of
 * an edge give the same point to the bit, and the segments are chained
 * into loops by their end points. The loops' winding numbers are 1 inside
 * the section and 0 outside, so booleans take the non-zero union of each
 * child's loops; the union of a group is one non-zero union of all its
 * leaves' loops.
 *
 * A 2D child (build_dim) is left out as OpenSCAD 2021.01 leaves it out:
 * projection(cut = false) passes over it without a word, projection(cut =
 * true) and the 3D operations inside say "Ignoring 2D child object for 3D
 * operation" (and an operation inside first "Mixing 2D and 3D objects is
 * not supported", at its first 2D child that is not empty), once all the
 * children are walked; the child's own warnings come first. A projection
 * without a 3D child has no geometry, as in OpenSCAD (build_projects):
 * nothing is said of it, after its children's own warnings. '%' and '*' children are left
 * out, as OpenSCAD leaves out background children. torus, quadric and implicit have no
 * OpenSCAD mesh: errors at their position, never a silent skip. A minkowski is, in both
 * modes, the triangles of its CGAL result (the union of the sums of convex parts, as
 * build_hull.c computes it). A hull is the convex hull of the corners of its children's
 * meshes (OpenSCAD hulls their vertices), as triangles like any other leaf; a boolean or
 * minkowski inside that hull gives the vertices of its CGAL result.
 */
#include "build/build_projection.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "base/grow.h"
#include "build/build_extrude_faithful.h"
#include "build/build_hull.h"
#include "build/build_mesh.h"
#include "build/build_revolve.h"
#include "build/build_twod.h"
#include "csg/hull3.h"
#include "csg/prim_mesh.h"
#include "model/faithful.h"

/* Whether n is 2D, as OpenSCAD 2021.01 gives it a dimension (build_dim):
 * a 2D shape, an import of a .dxf or .svg drawing (2D wherever it stands),
 * or an operation whose first child with a dimension is 2D; not a
 * projection without a 3D child, which is no geometry (build_projects).
 * Such a child of a 3D operation is left out. */
static int flat(const model_node *n)
{
    return build_dim(n, 0) == 2 && (n->kind != MODEL_PROJECTION || build_projects(n));
}

/* Triangles, 3 corners each. */
typedef struct soup {
    vec3 *v;
    uint32_t count, cap; /* in triangles */
    int open;            /* from a mesh that is not closed: not outward */
    /* per triangle, the first triangle of the builder's face it was cut
     * from (an extrusion's cap with its holes is one face), or NULL where
     * each face is taken by its shared corners (up_faces) */
    uint32_t *face;
} soup;

typedef struct pwalk {
    const build_ctx *c;
    const model_node *proj;
    int cut;
    build_resize_cache *cache;
    int corners;  /* inside a hull: only the corners of meshes matter */
    int booleans; /* differences and intersections the walk is inside */
    int solid;    /* a leaf with faces outside them: the union is not empty */
    /* the transforms since the innermost boolean or union of several,
     * which OpenSCAD makes a Nef polyhedron of, as build_hull.c's walk's
     * (NULL where none lies between: the walk's own m) */
    const affine *since;
    /* cut: a leaf's mesh passes through itself (build_may_cross): the section is
     * then CGAL's, as OpenSCAD's (build_nef_section), and the leaves'
     * own sections are no longer made */
    int crossing;
    nef_plugin nef; /* for the test (build_self_crossing), loaded then */
} pwalk;

static int add_tri(soup *s, vec3 a, vec3 b, vec3 c)
{
    if (!grow_array32((void **)&s->v, &s->cap, s->count + 1, 3 * sizeof *s->v))
        return 0;
    s->v[3 * s->count] = a;
    s->v[3 * s->count + 1] = b;
    s->v[3 * s->count + 2] = c;
    s->count++;
    return 1;
}

/* A triangle of a convex shape with centre inside it, turned outward;
 * one without area is left out. 0 when memory runs out. */
static int add_outward(soup *s, vec3 centre, vec3 a, vec3 b, vec3 c)
{
    vec3 n = v3_cross(v3_sub(b, a), v3_sub(c, a));
    if (n.x == 0 && n.y == 0 && n.z == 0)
        return 1;
    if (v3_dot(n, v3_sub(a, centre)) < 0)
        return add_tri(s, a, c, b);
    return add_tri(s, a, b, c);
}

/* The planar convex quad a b c d (in cyclic order) as two outward
 * triangles. */
static int add_quad(soup *s, vec3 centre, vec3 a, vec3 b, vec3 c, vec3 d)
{
    return add_outward(s, centre, a, b, c) && add_outward(s, centre, a, c, d);
}

static int positive_finite(double x)
{
    return x > 0 && isfinite(x);
}

/* cube(size, center): OpenSCAD's 6 quads. */
static int cube_soup(const model_node *n, soup *s)
{
    const double *size = n->u.cube.size;
    if (!positive_finite(size[0]) || !positive_finite(size[1]) ||
        !positive_finite(size[2]))
        return 1;
    vec3 sz = v3(size[0], size[1], size[2]);
    vec3 lo = n->u.cube.center ? v3_scale(sz, -0.5) : v3(0, 0, 0);
    vec3 hi = n->u.cube.center ? v3_scale(sz, 0.5) : sz;
    vec3 p[8];
    for (int k = 0; k < 8; k++)
        p[k] = v3(k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z);
    static const int faces[6][4] = {{0, 1, 3, 2}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                    {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 3, 7, 5}};
    vec3 centre = v3_scale(v3_add(lo, hi), 0.5);
    for (int f = 0; f < 6; f++) {
        if (!add_quad(s, centre, p[faces[f][0]], p[faces[f][1]], p[faces[f][2]],
                      p[faces[f][3]]))
            return 0;
    }
    return 1;
}

/* Point k of a circle of radius r with f fragments at height z, as
 * faithful.c places it. */
static vec3 circle_point(double r, long k, long f, double z)
{
    double phi = (360.0 * (double)(k % f)) / (double)f;
    return v3(r * faithful_cos_deg(phi), r * faithful_sin_deg(phi), z);
}

static sc_status fragments_error(const pwalk *w, const model_node *n, double r, int limit)
{
    return err_set(w->c->error, SC_ERR_LIMIT, &n->loc,
                   "projection: $fn, $fa and $fs of radius %g give too many fragments "
                   "(limit is %d)",
                   r, limit);
}

/* The rings of radii[i] at heights z[i] (i < rings, top first), each of f
 * points, closed by caps: OpenSCAD's sphere and cylinder. */
static int rings_soup(const double *radii, const double *z, long rings, long f, soup *s)
{
    vec3 centre = v3(0, 0, (z[0] + z[rings - 1]) / 2);
    for (long k = 1; k + 1 < f; k++) {
        if (!add_outward(s, centre, circle_point(radii[0], 0, f, z[0]),
                         circle_point(radii[0], k, f, z[0]),
                         circle_point(radii[0], k + 1, f, z[0])) ||
            !add_outward(s, centre, circle_point(radii[rings - 1], 0, f, z[rings - 1]),
                         circle_point(radii[rings - 1], k, f, z[rings - 1]),
                         circle_point(radii[rings - 1], k + 1, f, z[rings - 1])))
            return 0;
    }
    for (long i = 0; i + 1 < rings; i++) {
        for (long k = 0; k < f; k++) {
            if (!add_quad(s, centre, circle_point(radii[i], k, f, z[i]),
                          circle_point(radii[i + 1], k, f, z[i + 1]),
                          circle_point(radii[i + 1], k + 1, f, z[i + 1]),
                          circle_point(radii[i], k + 1, f, z[i])))
                return 0;
        }
    }
    return 1;
}

static sc_status sphere_soup(const pwalk *w, const model_node *n, soup *s)
{
    double r = n->u.sphere.r;
    if (!positive_finite(r))
        return SC_OK;
    const model_resolution *res = &n->u.sphere.res;
    long f = faithful_sphere_fragments(r, res->fn, res->fs, res->fa);
    if (f < 0)
        return fragments_error(w, n, r, FAITHFUL_MAX_SPHERE_FRAGMENTS);
    long rings = (f + 1) / 2;
    double *radii = malloc((size_t)rings * 2 * sizeof *radii);
    if (!radii)
        return err_nomem(w->c->error, &n->loc);
    double *z = radii + rings;
    for (long i = 0; i < rings; i++) {
        double phi = (180.0 * ((double)i + 0.5)) / (double)rings;
        radii[i] = r * faithful_sin_deg(phi);
        z[i] = r * faithful_cos_deg(phi);
    }
    int ok = rings_soup(radii, z, rings, f, s);
    free(radii);
    return ok ? SC_OK : err_nomem(w->c->error, &n->loc);
}

static sc_status cylinder_soup(const pwalk *w, const model_node *n, soup *s)
{
    double h = n->u.cylinder.h, r1 = n->u.cylinder.r1, r2 = n->u.cylinder.r2;
    if (!positive_finite(h) || !(r1 >= 0 && r2 >= 0) || !isfinite(r1) || !isfinite(r2) ||
        (r1 == 0 && r2 == 0))
        return SC_OK;
    const model_resolution *res = &n->u.cylinder.res;
    long f = faithful_fragments(fmax(r1, r2), res->fn, res->fs, res->fa);
    if (f < 0)
        return fragments_error(w, n, fmax(r1, r2), FAITHFUL_MAX_FRAGMENTS);
    double z0 = n->u.cylinder.center ? -h / 2 : 0;
    double radii[2] = {r2, r1}, z[2] = {z0 + h, z0};
    return rings_soup(radii, z, 2, f, s) ? SC_OK : err_nomem(w->c->error, &n->loc);
}

/* The triangles of a mesh leaf (outward, as prim_mesh keeps them). */
/* The faces of an extrusion (build_linear_extrude_faces,
 * build_rotate_extrude_faces) as s's triangles: each loop in a fan, which,
 * like the leaf's own triangles, sums to the loop's signed area; every
 * triangle of one face, its outline and holes, keyed to the face in
 * s->face. 0 when memory runs out. */
static int faces_soup(const build_mesh_faces *f, soup *s)
{
    uint32_t loops = f->face_loops ? f->face_loops[f->face_count] : f->face_count;
    size_t total = s->count;
    for (uint32_t l = 0; l < loops; l++) {
        uint32_t len = f->face_start[l + 1] - f->face_start[l];
        total += len > 2 ? len - 2 : 0;
    }
    if (total > UINT32_MAX / 3)
        return 0;
    uint32_t *face = realloc(s->face, (total ? total : 1) * sizeof *face);
    if (!face)
        return 0;
    s->face = face;
    for (uint32_t t = 0; t < s->count; t++)
        face[t] = t;
    for (uint32_t k = 0; k < f->face_count; k++) {
        uint32_t first = s->count;
        uint32_t lo = f->face_loops ? f->face_loops[k] : k;
        uint32_t hi = f->face_loops ? f->face_loops[k + 1] : k + 1;
        for (uint32_t l = lo; l < hi; l++) {
            const uint32_t *loop = f->indices + f->face_start[l];
            uint32_t len = f->face_start[l + 1] - f->face_start[l];
            for (uint32_t i = 1; i + 1 < len; i++) {
                if (!add_tri(s, f->points[loop[0]], f->points[loop[i]],
                             f->points[loop[i + 1]]))
                    return 0;
                face[s->count - 1] = first;
            }
        }
    }
    return 1;
}

static int mesh_soup(const prim *p, soup *s)
{
    if (p->kind != PRIM_MESH)
        return 1;
    const prim_mesh *mesh = p->u.mesh.mesh;
    s->open |= mesh->parity;
    for (uint32_t t = 0; t < mesh->tri_count; t++) {
        if (!add_tri(s, mesh->v[3 * t], mesh->v[3 * t + 1], mesh->v[3 * t + 2]))
            return 0;
    }
    return 1;
}

/* polyhedron, import, surface, linear_extrude, rotate_extrude: their
 * meshes, the extrusions' as in --faithful (OpenSCAD's polygons). Without
 * cut, a polyhedron or import that is not closed is projected as it is,
 * silently, in both modes (and with --strict): OpenSCAD 2021.01 projects
 * the faces of the mesh it has without asking that it be closed, except
 * in a union of several, which it makes a Nef polyhedron of: there a mesh
 * CGAL's builder does not take (an extrusion's too) is left out with its
 * message as a warning, in both modes, as in a cut. A cut
 * needs a solid: a polyhedron (its points merged first, as OpenSCAD merges
 * them for its Nef polyhedron) or import that is not closed (for a
 * polyhedron, also one whose faces at a point make two fans) is left out
 * with OpenSCAD's message as a warning, in both modes (build_import), as
 * its Nef polyhedron cannot be made. Inside a hull, which takes only the
 * corners, a mesh is taken as it is in a cut too, as OpenSCAD hulls the
 * mesh and cuts the hull. */
static sc_status leaf_mesh(const pwalk *w, const build_ctx *c, const model_node *n,
                           const affine *moved, soup *s)
{
    if (n->pending)
        return build_pending(c, n);
    int solid = w->cut && !w->corners;
    /* OpenSCAD makes a Nef polyhedron of the mesh for a cut, and of a
     * union of several (w->since) without one: there CGAL's builder must
     * take it, and one it does not is left out with its warning, in both
     * modes; elsewhere OpenSCAD projects the mesh as it is */
    int nef = !w->corners && (w->cut || w->since);
    build_ctx fc = *c;
    fc.faithful = 1;
    fc.drawn_as_is &= !nef;
    build_ctx checked = *c; /* the polyhedron's Nef polyhedron, as CGAL's
                             * builder takes it */
    checked.faithful = 1;
    checked.drawn_as_is = 0;
    build_ctx loose = *c; /* the parity rule, without a warning */
    loose.faithful = 0;
    loose.strict = 0;
    loose.notes = NULL;
    prim p;
    memset(&p, 0, sizeof p);
    const char *empty = NULL;
    sc_status st;
    switch (n->kind) {
    case MODEL_POLYHEDRON:
        if ((st = build_bad_indices(c, n)) != SC_OK || n->u.polyhedron.face_count == 0)
            return st;
        if (solid) {
            /* its points merged as OpenSCAD merges them for the Nef
             * polyhedron (faces may use two copies of a point), as for
             * the leaf (build.c) */
            build_mesh_faces f;
            st = build_mesh_merge_moved(
                &checked, &n->loc, 1, moved, n->u.polyhedron.points,
                n->u.polyhedron.point_count, n->u.polyhedron.indices,
                n->u.polyhedron.face_start, n->u.polyhedron.face_count, &f);
            if (st == SC_OK && f.face_count)
                st = build_mesh_solid(&checked, &n->loc, "polyhedron", 1, c->strict, &f,
                                      &p, &empty);
            else if (st == SC_OK)
                empty = ""; /* no face left */
            build_mesh_faces_free(&f);
            break;
        }
        st = build_mesh_prim(nef ? &checked : &loose, &n->loc, "polyhedron", 1,
                             n->u.polyhedron.points, n->u.polyhedron.point_count,
                             n->u.polyhedron.indices, n->u.polyhedron.face_start,
                             n->u.polyhedron.face_count, &p, &empty);
        break;
    case MODEL_IMPORT: {
        build_ctx ic = *c;
        ic.moved = moved;
        st = nef ? build_import(&ic, n->u.import, &p, &empty)
                 : build_import_mesh(c, n->u.import, &p, &empty);
        break;
    }
    case MODEL_SURFACE:
        st = build_surface(c, n->u.surface, &p, &empty);
        break;
    case MODEL_ROTATE_EXTRUDE:
        st = build_rotate_extrude(&fc, n, 1, &p, &empty);
        break;
    default:
        st = build_linear_extrude(&fc, n, 1, &p, &empty);
        break;
    }
    if (st != SC_OK || empty)
        return st;
    if (w->cut || w->corners ||
        (n->kind != MODEL_LINEAR_EXTRUDE && n->kind != MODEL_ROTATE_EXTRUDE))
        return mesh_soup(&p, s) ? SC_OK : err_nomem(c->error, &n->loc);
    /* projected faces: the extrusion's own, so that a cap's holes, which
     * look the other way, are taken with its outline (up_faces), in
     * whatever plane it lies */
    if (p.kind == PRIM_MESH)
        s->open |= p.u.mesh.mesh->parity;
    build_mesh_faces f;
    st = n->kind == MODEL_ROTATE_EXTRUDE
             ? build_rotate_extrude_faces(&fc, n, &f, &empty)
             : build_linear_extrude_faces(&fc, n, &f, &empty, NULL);
    if (st == SC_OK && !empty && !faces_soup(&f, s))
        st = err_nomem(c->error, &n->loc);
    build_mesh_faces_free(&f);
    return st;
}

/* leaf_mesh, where a builder's warning (a mesh left out of a cut) goes to
 * the caller's note, or, where the caller takes none (a 2D model), to
 * c->notes. */
static sc_status built_soup(const pwalk *w, const model_node *n, const affine *moved,
                            soup *s)
{
    build_ctx c = *w->c;
    sc_error own = {SC_OK, "", 0, 0, ""};
    if (!c.note && c.notes)
        c.note = &own;
    sc_status st = leaf_mesh(w, &c, n, moved, s);
    if (st == SC_OK && own.message[0]) {
        sc_location at = {c.file, own.line, own.column};
        st = build_note(&c, &at, "%s", own.message);
    }
    return st;
}

static sc_status leaf_soup(pwalk *w, const model_node *n, const affine *moved, soup *s,
                           int depth);
static sc_status background(pwalk *w, const model_node *k, const affine *m, int depth);

/* resize node n's scale (build_resize) from the box of the meshes the
 * projection takes, OpenSCAD's in both modes, not of the exact solids. */
static sc_status meshes_resize(pwalk *w, const model_node *n, affine *local,
                               const char **warning)
{
    build_ctx meshes = *w->c;
    meshes.faithful = 1;
    return build_resize(&meshes, n, &w->cache, local, warning);
}

/* OpenSCAD 2021.01's warnings for the 2D children of parent, a hull
 * inside projection (a 3D operation there), which it leaves out: after the
 * children, as it checks dimensions once they are evaluated, first that
 * parent mixes them, at mixing (the first 2D child that is not empty; NULL
 * when none is), then each ignored (as build_hull.c's). */
static sc_status ignored_2d(const build_ctx *c, const model_node *parent,
                            const model_node *mixing)
{
    sc_status st = SC_OK;
    if (mixing)
        st = build_mixing(c, &mixing->loc, 0);
    for (const model_node *n = parent->first_child; n && st == SC_OK; n = n->next) {
        if ((n->modifiers & (MODEL_MOD_DISABLE | MODEL_MOD_BACKGROUND)) || !flat(n))
            continue;
        st = build_ignoring(c, &n->loc, 0);
    }
    return st;
}

/* A warning at loc: the caller's (c->note, which keeps the first), or,
 * where the caller takes none (a 2D model), one of c->notes. */
static sc_status say(const build_ctx *c, const sc_location *loc, const char *message)
{
    if (!c->note)
        return build_note(c, loc, "%s", message);
    if (!c->note->message[0])
        err_set(c->note, SC_OK, loc, "%s", message);
    return SC_OK;
}

/* The corners of the meshes below hull node parent (through m, in the
 * hull's frame) added to pts, as OpenSCAD hulls them: groups, colours,
 * transforms and resizes pass through; a boolean or minkowski gives the
 * vertices of its CGAL result. */
static sc_status hull_points(pwalk *w, const model_node *parent, const affine *m,
                             int depth, soup *pts)
{
    const build_ctx *c = w->c;
    if (depth > BUILD_PROJECTION_MAX_DEPTH)
        return err_set(c->error, SC_ERR_LIMIT, &parent->loc,
                       "too many nested nodes inside projection (limit is %d)",
                       BUILD_PROJECTION_MAX_DEPTH);
    const model_node *mixing = NULL; /* the first 2D child that is not empty */
    for (const model_node *n = parent->first_child; n; n = n->next) {
        model_kind kind = n->kind;
        sc_status st = SC_OK;
        if ((n->modifiers & (MODEL_MOD_DISABLE | MODEL_MOD_BACKGROUND)) ||
            kind == MODEL_LIGHT || kind == MODEL_CAMERA || kind == MODEL_BACKGROUND) {
            if ((st = background(w, n, m, depth)) != SC_OK)
                return st;
            continue;
        }
        if (n->pending && !flat(n))
            return build_pending(c, n);
        if (flat(n) || kind == MODEL_PROJECTION) {
            /* checked, then left out (ignored_2d); a projection that is not
             * flat is no geometry */
            int empty;
            st = build_twod_check(c, n, &empty);
            if (!mixing && !empty && flat(n))
                mixing = n;
        } else if (kind == MODEL_UNION || kind == MODEL_COLOR || kind == MODEL_MATERIAL) {
            st = hull_points(w, n, m, depth + 1, pts);
        } else if (kind == MODEL_XFORM || kind == MODEL_RESIZE) {
            affine local = kind == MODEL_XFORM ? *n->u.xform : affine_identity();
            const char *warning = NULL;
            if (kind == MODEL_RESIZE)
                st = meshes_resize(w, n, &local, &warning);
            if (st == SC_OK && warning)
                st = say(c, &n->loc, warning);
            affine inner = affine_mul(m, &local), inverse;
            if (kind == MODEL_XFORM && n->not_finite) {
                /* removed: its children's warnings first, without its
                 * check of their dimensions, then the removal (walk_node) */
                soup scratch = {NULL, 0, 0, 0, NULL};
                st = hull_points(w, n, m, depth + 1, &scratch);
                free(scratch.v);
                free(scratch.face);
                if (st == SC_OK)
                    st = build_xform_not_finite(c, n);
            } else if (st == SC_OK) {
                /* under a singular one, the hull takes a mesh's flattened
                 * points (repair_frame) */
                const char *removal = NULL;
                if (affine_invert(&inner, &inverse) ||
                    !build_singular_removes(n, &removal))
                    st = hull_points(w, n, &inner, depth + 1, pts);
                else if (removal)
                    st = say(c, &n->loc, removal);
            }
        } else {
            soup s = {NULL, 0, 0, 0, NULL};
            st = leaf_soup(w, n, NULL, &s, depth + 1);
            for (uint32_t i = 0; st == SC_OK && i < 3 * s.count; i += 3) {
                if (!add_tri(pts, affine_point(m, s.v[i]), affine_point(m, s.v[i + 1]),
                             affine_point(m, s.v[i + 2])))
                    st = err_nomem(c->error, &n->loc);
            }
            free(s.v);
            free(s.face);
        }
        if (st != SC_OK)
            return st;
    }
    if (parent->kind == MODEL_XFORM && parent->not_finite) /* removed: not checked */
        return SC_OK;
    return ignored_2d(c, parent, mixing);
}

/* hull(): the triangles of the convex hull of its children's mesh
 * corners (hull3.c, exact orientation tests), outward. A hull without
 * volume has no area seen from any side but its own plane's; it is left
 * out as OpenSCAD's empty 3D hull. */
static sc_status hull_soup(pwalk *w, const model_node *n, soup *s, int depth)
{
    const build_ctx *c = w->c;
    soup pts = {NULL, 0, 0, 0, NULL};
    affine id = affine_identity();
    int corners = w->corners;
    w->corners = 1;
    sc_status st = hull_points(w, n, &id, depth, &pts);
    w->corners = corners;
    hull3 h;
    hull3_status hs = HULL3_FLAT;
    if (st == SC_OK && pts.count)
        hs = hull3_compute(pts.v, 3 * pts.count, &h);
    free(pts.v);
    free(pts.face);
    if (st != SC_OK || hs == HULL3_FLAT)
        return st;
    if (hs == HULL3_NOMEM)
        return err_nomem(c->error, &n->loc);
    if (hs == HULL3_RANGE)
        return err_set(c->error, SC_ERR_LIMIT, &n->loc,
                       "hull: too many points or a coordinate too large");
    for (uint32_t t = 0; t < h.tri_count && st == SC_OK; t++) {
        const uint32_t *k = &h.tris[3 * t];
        if (!add_tri(s, h.vertices[k[0]], h.vertices[k[1]], h.vertices[k[2]]))
            st = err_nomem(c->error, &n->loc);
    }
    hull3_free(&h);
    return st;
}

/* A point of a Nef polyhedron as OpenSCAD's createPolySetFromNefPolyhedron3
 * hands it on: in single precision (its Vector3f). */
static vec3 single(vec3 p)
{
    return v3((float)p.x, (float)p.y, (float)p.z);
}

/* A boolean or minkowski: the triangles of its CGAL result
 * (build_nef_triangles), as OpenSCAD projects the polygons of the Nef
 * polyhedron it evaluates the child to, their points in single precision
 * as OpenSCAD's are (single). */
static sc_status nef_soup(pwalk *w, const model_node *n, soup *s)
{
    vec3 *tris = NULL;
    uint32_t count = 0;
    int own = 0; /* the projection's own child, which OpenSCAD does not cache */
    for (const model_node *k = w->proj->first_child; k && !own; k = k->next)
        own = k == n;
    sc_status st =
        build_nef_triangles(w->c, n, "projection", &w->cache, own, &tris, &count);
    for (uint32_t t = 0; st == SC_OK && t < count; t++) {
        if (!add_tri(s, single(tris[3 * t]), single(tris[3 * t + 1]),
                     single(tris[3 * t + 2])))
            st = err_nomem(w->c->error, &n->loc);
    }
    free(tris);
    return st;
}

/* The soup of leaf n in its own frame (or, for a polyhedron or import a
 * cut takes, where moved takes it: built_soup; moved NULL for none);
 * SC_ERR_UNSUPPORTED for leaves without an OpenSCAD mesh. */
static sc_status leaf_soup(pwalk *w, const model_node *n, const affine *moved, soup *s,
                           int depth)
{
    const build_ctx *c = w->c;
    switch (n->kind) {
    case MODEL_CUBE:
        if (n->pending)
            return build_pending(c, n);
        return cube_soup(n, s) ? SC_OK : err_nomem(c->error, &n->loc);
    case MODEL_SPHERE:
        return n->pending ? build_pending(c, n) : sphere_soup(w, n, s);
    case MODEL_CYLINDER:
        return n->pending ? build_pending(c, n) : cylinder_soup(w, n, s);
    case MODEL_POLYHEDRON:
    case MODEL_IMPORT:
    case MODEL_SURFACE:
    case MODEL_LINEAR_EXTRUDE:
    case MODEL_ROTATE_EXTRUDE:
        return built_soup(w, n, moved, s);
    case MODEL_HULL:
        return hull_soup(w, n, s, depth);
    case MODEL_DIFFERENCE:
    case MODEL_INTERSECTION:
    case MODEL_MINKOWSKI:
        return nef_soup(w, n, s);
    case MODEL_TORUS:
    case MODEL_QUADRIC:
    case MODEL_IMPLICIT:
        return err_set(c->error, SC_ERR_UNSUPPORTED, &n->loc,
                       "'%s' inside projection is not supported (it has no OpenSCAD "
                       "polygon mesh)",
                       n->name);
    default:
        return err_set(c->error, SC_ERR_UNSUPPORTED, &n->loc,
                       "'%s' inside projection is not supported yet", n->name);
    }
}

/* ---- sections ---- */

/* Whether z is on the solid's side of the plane for the limit from above
 * (up: the plane just above z = 0, so z = 0 is below it) or below. */
static int above(double z, int up)
{
    return up ? z > 0 : z >= 0;
}

/* The point of z = 0 on the edge p q (one end above, one below in the
 * limit's sense), the same to the bit for q p: an end at z = 0 is the
 * point itself. */
static void crossing(vec3 p, vec3 q, double xy[2])
{
    if (q.x < p.x || (q.x == p.x && (q.y < p.y || (q.y == p.y && q.z < p.z)))) {
        vec3 t = p;
        p = q;
        q = t;
    }
    if (p.z == 0 || q.z == 0) {
        vec3 at = p.z == 0 ? p : q;
        xy[0] = at.x;
        xy[1] = at.y;
        return;
    }
    double t = p.z / (p.z - q.z);
    xy[0] = p.x + t * (q.x - p.x);
    xy[1] = p.y + t * (q.y - p.y);
}

typedef struct segment {
    double s[2], e[2]; /* from s to e */
} segment;

static int point_less(const double *a, const double *b)
{
    return a[0] < b[0] || (a[0] == b[0] && a[1] < b[1]);
}

static int segment_cmp(const void *pa, const void *pb)
{
    const segment *a = pa, *b = pb;
    return point_less(a->s, b->s) ? -1 : point_less(b->s, a->s) ? 1 : 0;
}

/* The first segment not used starting at xy (segments sorted by start),
 * or count. */
static uint32_t next_from(const segment *seg, const unsigned char *used, uint32_t count,
                          const double *xy)
{
    uint32_t lo = 0, hi = count;
    while (lo < hi) {
        uint32_t mid = lo + (hi - lo) / 2;
        if (point_less(seg[mid].s, xy))
            lo = mid + 1;
        else
            hi = mid;
    }
    for (; lo < count && seg[lo].s[0] == xy[0] && seg[lo].s[1] == xy[1]; lo++) {
        if (!used[lo])
            return lo;
    }
    return count;
}

/* Adds the loops of soup s cut by z = 0 (limit up or down) to out. 0
 * when memory runs out or out is full. */
static int section_loops(const soup *s, int up, twod_region *out)
{
    segment *seg = s->count ? malloc((size_t)s->count * sizeof *seg) : NULL;
    if (s->count && !seg)
        return 0;
    uint32_t count = 0;
    for (uint32_t t = 0; t < s->count; t++) {
        const vec3 *v = &s->v[3 * t];
        int cls[3] = {above(v[0].z, up), above(v[1].z, up), above(v[2].z, up)};
        if (cls[0] == cls[1] && cls[1] == cls[2])
            continue;
        segment g;
        for (int k = 0; k < 3; k++) {
            int j = (k + 1) % 3;
            if (cls[k] && !cls[j])
                crossing(v[k], v[j], g.s);
            else if (!cls[k] && cls[j])
                crossing(v[k], v[j], g.e);
        }
        if (g.s[0] != g.e[0] || g.s[1] != g.e[1])
            seg[count++] = g;
    }
    unsigned char *used = count ? calloc(count, 1) : NULL;
    int ok = !count || used;
    if (ok && count)
        qsort(seg, count, sizeof *seg, segment_cmp);
    for (uint32_t i = 0; ok && i < count; i++) {
        if (used[i])
            continue;
        ok = twod_begin_contour(out) && twod_add_point(out, seg[i].s[0], seg[i].s[1]);
        uint32_t at = i;
        while (ok) {
            used[at] = 1;
            uint32_t next = next_from(seg, used, count, seg[at].e);
            if (next == count) {
                /* back at the start, or a loop an open mesh leaves open,
                 * closed here */
                ok = twod_add_point(out, seg[at].e[0], seg[at].e[1]);
                break;
            }
            ok = twod_add_point(out, seg[next].s[0], seg[next].s[1]);
            at = next;
        }
        if (ok)
            twod_end_contour(out);
    }
    free(used);
    free(seg);
    return ok;
}

static int append(twod_region *dst, const twod_region *src);

static int add_triangle(twod_region *out, const vec3 *v)
{
    if (!twod_begin_contour(out))
        return 0;
    for (int k = 0; k < 3; k++) {
        if (!twod_add_point(out, v[k].x, v[k].y))
            return 0;
    }
    twod_end_contour(out);
    return 1;
}

/* The faces of closed mesh s that look up, projected: each counter-
 * clockwise, and each hole of one clockwise; or with open, every face of
 * a mesh that is not closed (no face looks up over every point of it),
 * turned to look up: OpenSCAD's union of the projected faces. A face that is not convex
 * comes as a fan of triangles that overlap, some wound back (build_mesh.h),
 * whose signed sum is the face; alone, the back-wound ones look down and
 * the face would project whole over its notches. So the triangles that
 * share a corner and lie in one plane (normals within 1e-9 of parallel,
 * either way) are taken together: a group of triangles that all look up
 * is projected as they are (open: each turned counter-clockwise), one
 * with some wound back (open: after the group is turned to look up, by
 * the sign of its area) by the union of its triangles where their winding
 * number is positive. A closed mesh's triangle t is also taken with
 * triangle s->face[t] (an extrusion's cap, whose outline and holes share
 * no corner). 0 when memory runs out or the clipper fails. */
static int up_faces(const soup *s, int open, twod_region *out)
{
    uint32_t n = s->count;
    const uint32_t *plane = open ? NULL : s->face;
    vec3 *normal = malloc((size_t)(n ? n : 1) * sizeof *normal);
    uint32_t *parent = malloc((size_t)(n ? n : 1) * sizeof *parent);
    build_mesh_keyed *corners = malloc((size_t)(n ? n : 1) * 3 * sizeof *corners);
    uint32_t *next = malloc((size_t)(n ? n : 1) * sizeof *next);
    unsigned char *mixed = calloc(n ? n : 1, 1);
    int ok = normal && parent && corners && next && mixed;
    for (uint32_t t = 0; ok && t < n; t++) {
        const vec3 *v = &s->v[3 * t];
        normal[t] = v3_normalize(v3_cross(v3_sub(v[1], v[0]), v3_sub(v[2], v[0])));
        parent[t] = t;
        for (int k = 0; k < 3; k++)
            corners[3 * t + k] = (build_mesh_keyed){v[k], t};
    }
    if (ok)
        qsort(corners, 3 * (size_t)n, sizeof *corners, build_mesh_keyed_cmp);
    /* at each corner, each triangle joins one in its plane: the
     * triangles about it sorted by their normal turned up (x, then the
     * number), each compared with those before it whose x is within the
     * tolerance's angle (|dot| >= 1 - 1e-9 is within 4.5e-5 radians), so
     * that the many planes about a cone's apex are not compared pairwise */
    build_mesh_keyed *about = ok ? malloc((size_t)(n ? n : 1) * sizeof *about) : NULL;
    ok = ok && about;
    for (size_t i = 0; ok && i < 3 * (size_t)n;) {
        size_t j = i;
        uint32_t count = 0;
        for (; j < 3 * (size_t)n && corners[j].p.x == corners[i].p.x &&
               corners[j].p.y == corners[i].p.y && corners[j].p.z == corners[i].p.z;
             j++) {
            uint32_t t = corners[j].index;
            if (fabs(normal[t].z) > 0) /* upright: projects to nothing */
                about[count++] = (build_mesh_keyed){
                    normal[t].z > 0 ? normal[t] : v3_scale(normal[t], -1), t};
        }
        if (count > 1)
            qsort(about, count, sizeof *about, build_mesh_keyed_cmp);
        for (uint32_t a = 1; a < count; a++) {
            uint32_t t = about[a].index;
            for (uint32_t b = a; b-- > 0 && about[a].p.x - about[b].p.x <= 1e-4;) {
                if (fabs(v3_dot(normal[about[b].index], normal[t])) >= 1 - 1e-9) {
                    parent[build_mesh_piece(parent, t)] =
                        build_mesh_piece(parent, about[b].index);
                    break;
                }
            }
        }
        i = j;
    }
    free(about);
    for (uint32_t t = 0; ok && plane && t < n; t++)
        if (plane[t] != t)
            parent[build_mesh_piece(parent, t)] = build_mesh_piece(parent, plane[t]);
    /* a group with a triangle wound back (its normal down where another's
     * is up) */
    for (uint32_t t = 0; ok && t < n; t++) {
        uint32_t g = build_mesh_piece(parent, t);
        mixed[g] |= (unsigned char)(normal[t].z > 0 ? 1 : normal[t].z < 0 ? 2 : 0);
    }
    for (uint32_t t = 0; ok && t < n; t++) {
        uint32_t g = build_mesh_piece(parent, t);
        const vec3 *v = &s->v[3 * t];
        if (mixed[g] == 1 || (open && mixed[g] == 2))
            ok = add_triangle(out, (vec3[3]){v[0], normal[t].z > 0 ? v[1] : v[2],
                                             normal[t].z > 0 ? v[2] : v[1]});
    }
    /* the mixed groups' triangles, listed from each root */
    for (uint32_t t = 0; ok && t < n; t++)
        next[t] = UINT32_MAX;
    for (uint32_t t = n; ok && t-- > 0;) {
        uint32_t g = build_mesh_piece(parent, t);
        if (mixed[g] == 3 && t != g && normal[t].z != 0) {
            next[t] = next[g];
            next[g] = t;
        }
    }
    for (uint32_t g = 0; ok && g < n; g++) {
        if (mixed[g] != 3 || build_mesh_piece(parent, g) != g)
            continue;
        /* open: the face turned to look up first (its triangles' signed
         * areas summed) */
        double area = 0;
        for (uint32_t t = g; open && t != UINT32_MAX; t = next[t]) {
            const vec3 *v = &s->v[3 * t];
            area += v3_cross(v3_sub(v[1], v[0]), v3_sub(v[2], v[0])).z;
        }
        twod_region face;
        twod_init(&face);
        for (uint32_t t = g; ok && t != UINT32_MAX; t = next[t]) {
            const vec3 *v = &s->v[3 * t];
            ok = add_triangle(&face, area < 0 ? (vec3[3]){v[0], v[2], v[1]} : v);
        }
        ok = ok && twod_clip_union_positive(&face) == TWOD_CLIP_OK && append(out, &face);
        twod_free(&face);
    }
    free(normal);
    free(parent);
    free(corners);
    free(next);
    free(mixed);
    return ok;
}

/* Adds the outline of s seen along z to out. The union of every face's
 * projection (OpenSCAD's) is, for a closed mesh, the union of its faces
 * that look up (a vertical line through the solid meets its top at such a
 * face), up to sets without area: half the faces, and no front face
 * overlapping a back one, which is what makes the clipper slow. A convex
 * leaf (convex set) is the 2D hull of its corners, the same region. */
static int projected_faces(const soup *s, int convex, twod_region *out)
{
    if (s->open) /* no outward side: every face, turned counter-clockwise */
        return up_faces(s, 1, out);
    if (convex) {
        double *xy = s->count ? malloc((size_t)s->count * 6 * sizeof *xy) : NULL;
        if (s->count && !xy)
            return 0;
        for (uint32_t i = 0; i < 3 * s->count; i++) {
            xy[2 * i] = s->v[i].x;
            xy[2 * i + 1] = s->v[i].y;
        }
        twod_region hull;
        twod_init(&hull);
        int ok = twod_hull(xy, 3 * s->count, &hull);
        free(xy);
        for (uint32_t k = 0; ok && k < hull.contour_count; k++) {
            ok = twod_begin_contour(out);
            for (uint32_t i = hull.start[k]; ok && i < hull.start[k + 1]; i++)
                ok = twod_add_point(out, hull.xy[2 * i], hull.xy[2 * i + 1]);
            if (ok)
                twod_end_contour(out);
        }
        twod_free(&hull);
        return ok;
    }
    return up_faces(s, 0, out);
}

/* ---- the walk ---- */

static sc_status clip_error(const pwalk *w, const model_node *n, int code,
                            const twod_region *r)
{
    if (code == TWOD_CLIP_OK)
        return SC_OK;
    if (code == TWOD_CLIP_RANGE)
        return err_set(w->c->error, SC_ERR_LIMIT, &n->loc,
                       "projection: coordinates out of range (limit is %g)",
                       TWOD_MAX_COORD);
    if (code == TWOD_CLIP_TOO_MANY)
        return build_twod_add_error(w->c, w->proj, r);
    return err_nomem(w->c->error, &n->loc);
}

static sc_status add_error(const pwalk *w, const twod_region *r)
{
    return build_twod_add_error(w->c, w->proj, r);
}

/* The union of a cut's oriented loops in r (node n's), in place, off the
 * clipper's grid: OpenSCAD 2021.01 cuts its Nef polyhedron exactly and
 * hands on the section's points as they are (CGALUtils::project), not
 * passed through the clipper, so each corner the union keeps takes back
 * the point it had (twod_restore_points); where the union crosses two
 * loops, the crossing stays on the grid. OpenSCAD marks the section
 * sanitized all the same (convertToPolygon2d), outlines counter-clockwise
 * and holes clockwise, so a minkowski sum or an offset of it keeps each
 * hole's direction: a hole is not filled. */
static sc_status exact_union(const pwalk *w, const model_node *n, twod_region *r)
{
    twod_region from;
    twod_init(&from);
    sc_status st = append(&from, r) ? SC_OK : add_error(w, r);
    if (st == SC_OK)
        st = clip_error(w, n, twod_clip_union_nonzero(r, 0), r);
    if (st == SC_OK && !twod_restore_points(r, &from))
        st = err_nomem(w->c->error, &n->loc);
    r->sanitized = 1;
    twod_free(&from);
    return st;
}

/* Adds contour copies of src to dst. */
static int append(twod_region *dst, const twod_region *src)
{
    for (uint32_t k = 0; k < src->contour_count; k++) {
        if (!twod_begin_contour(dst))
            return 0;
        for (uint32_t i = src->start[k]; i < src->start[k + 1]; i++) {
            if (!twod_add_point(dst, src->xy[2 * i], src->xy[2 * i + 1]))
                return 0;
        }
        twod_end_contour(dst);
    }
    return 1;
}

/* Leaves whose mesh is convex. */
static int convex_leaf(model_kind kind)
{
    return kind == MODEL_CUBE || kind == MODEL_SPHERE || kind == MODEL_CYLINDER ||
           kind == MODEL_HULL;
}

/* Moves soup s by since and snaps its points to OpenSCAD's grid as
 * build_mesh_merge snaps a mesh CGAL takes (PolySet::quantizeVertices, in
 * createNefPolyhedronFromGeometry), triangles left without area dropped:
 * a shape's, an extrusion's or a hull's mesh where a cut takes it. */
static sc_status snap_soup(const pwalk *w, const model_node *n, const affine *since,
                           soup *s)
{
    build_ctx cut = *w->c;
    cut.faithful = 1;
    cut.drawn_as_is = 0;
    uint32_t corners = 3 * s->count;
    uint32_t *indices = malloc((size_t)corners * sizeof *indices);
    uint32_t *start = malloc(((size_t)s->count + 1) * sizeof *start);
    sc_status st = indices && start ? SC_OK : err_nomem(w->c->error, &n->loc);
    build_mesh_faces f;
    memset(&f, 0, sizeof f);
    for (uint32_t i = 0; st == SC_OK && i < corners; i++)
        indices[i] = i;
    for (uint32_t t = 0; st == SC_OK && t <= s->count; t++)
        start[t] = 3 * t;
    if (st == SC_OK)
        st = build_mesh_merge_moved(&cut, &n->loc, 0, since, s->v, corners, indices,
                                    start, s->count, &f);
    if (st == SC_OK) {
        s->count = 0;
        for (uint32_t t = 0; t < f.face_count; t++) {
            const uint32_t *k = &f.indices[f.face_start[t]];
            if (f.face_start[t + 1] - f.face_start[t] == 3 &&
                !add_tri(s, f.points[k[0]], f.points[k[1]], f.points[k[2]])) {
                st = err_nomem(w->c->error, &n->loc);
                break;
            }
        }
    }
    build_mesh_faces_free(&f);
    free(indices);
    free(start);
    return st;
}

/* The faces of polyhedron n through m added to out, as OpenSCAD 2021.01
 * projects a mesh (PolysetUtils::project): each face's outline, turned
 * counter-clockwise, a face without area left out; the projection unites
 * them. For a polyhedron without volume (a sheet given both ways), of
 * which the mesh builder makes no triangles, and one with a face out of
 * its plane (warped_face), whose outline is not the union of the
 * triangles it is split into. 0 when memory runs out. */
static int face_outlines(const model_node *n, const affine *m, twod_region *out)
{
    const vec3 *points = n->u.polyhedron.points;
    const uint32_t *index = n->u.polyhedron.indices;
    const uint32_t *start = n->u.polyhedron.face_start;
    for (uint32_t f = 0; f < n->u.polyhedron.face_count; f++) {
        uint32_t s = start[f], e = start[f + 1];
        double area = 0; /* twice the signed area, seen from above */
        for (uint32_t i = s; i < e; i++) {
            vec3 a = affine_point(m, points[index[i]]);
            vec3 b = affine_point(m, points[index[i + 1 < e ? i + 1 : s]]);
            area += a.x * b.y - b.x * a.y;
        }
        if (e - s < 3 || !(area > 0 || area < 0))
            continue;
        if (!twod_begin_contour(out))
            return 0;
        for (uint32_t k = 0; k < e - s; k++) {
            vec3 a = affine_point(m, points[index[area > 0 ? s + k : e - 1 - k]]);
            if (!twod_add_point(out, a.x, a.y))
                return 0;
        }
        twod_end_contour(out);
    }
    return 1;
}

/* Whether a face of polyhedron n (four points or more) leaves its plane:
 * a point farther than 1e-9 of the face's size from the plane through
 * its first point across its Newell normal. */
static int warped_face(const model_node *n)
{
    const vec3 *points = n->u.polyhedron.points;
    const uint32_t *index = n->u.polyhedron.indices;
    const uint32_t *start = n->u.polyhedron.face_start;
    for (uint32_t f = 0; f < n->u.polyhedron.face_count; f++) {
        uint32_t s = start[f], e = start[f + 1];
        if (e - s < 4)
            continue;
        vec3 normal = v3(0, 0, 0);
        double size = 0;
        for (uint32_t i = s; i < e; i++) {
            vec3 a = points[index[i]], b = points[index[i + 1 < e ? i + 1 : s]];
            normal = v3_add(normal, v3_newell(a, b));
            size = fmax(size, v3_max_abs(v3_sub(a, points[index[s]])));
        }
        double length = v3_length(normal);
        if (!(length > 0))
            continue;
        normal = v3_scale(normal, 1 / length);
        for (uint32_t i = s + 1; i < e; i++)
            if (fabs(v3_dot(normal, v3_sub(points[index[i]], points[index[s]]))) >
                1e-9 * size)
                return 1;
    }
    return 0;
}

/* Adds leaf n's loops (cut) or projected faces to out. */
static sc_status leaf(pwalk *w, const model_node *n, const affine *m, int depth,
                      twod_region *out)
{
    soup s = {NULL, 0, 0, 0, NULL};
    /* a leaf the cut takes: OpenSCAD makes its Nef polyhedron where its
     * points have moved to (w->since), snapped there; a polyhedron or
     * import is also split and checked there (built_soup) */
    const affine *since = NULL;
    affine rest = *m;
    if (w->cut && !w->corners)
        since = build_mesh_since(w->since, m, &rest);
    m = &rest;
    int meshed = n->kind == MODEL_POLYHEDRON || n->kind == MODEL_IMPORT;
    sc_status st = leaf_soup(w, n, meshed ? since : NULL, &s, depth);
    if (st == SC_OK && since && !meshed && s.count)
        st = snap_soup(w, n, since, &s);
    w->solid |= s.count && !w->booleans;
    if (st == SC_OK && s.count) {
        int flip = affine_det(m) < 0;
        for (uint32_t t = 0; t < s.count; t++) {
            vec3 *v = &s.v[3 * t];
            vec3 a = affine_point(m, v[0]), b = affine_point(m, v[1]),
                 c = affine_point(m, v[2]);
            v[0] = a;
            v[1] = flip ? c : b;
            v[2] = flip ? b : c;
        }
        /* a cut through a mesh that passes through itself: OpenSCAD's
         * CGAL section of a Nef polyhedron CGAL makes of it, whatever
         * that is there, which no rule here follows */
        if (w->cut && !w->corners && !w->crossing && build_may_cross(n) &&
            (st = build_self_crossing(w->c, &n->loc, &w->nef, s.v, s.count,
                                      &w->crossing)) != SC_OK) {
            free(s.face);
            free(s.v);
            return st;
        }
        /* a polyhedron's face out of its plane projects as OpenSCAD
         * projects it, its outline whole, not as the triangles it is
         * split into: then every face's outline (face_outlines); in a
         * union of several OpenSCAD projects the triangles of CGAL's
         * Nef polyhedron of it */
        int ok = w->crossing ? 1
                 : w->cut    ? section_loops(&s, 1, out) && section_loops(&s, 0, out)
                 : n->kind == MODEL_POLYHEDRON && !w->since && !s.open && warped_face(n)
                     ? face_outlines(n, m, out)
                     : projected_faces(&s, convex_leaf(n->kind), out);
        if (!ok)
            st = add_error(w, out);
    } else if (st == SC_OK && !w->cut && !w->since && n->kind == MODEL_POLYHEDRON &&
               n->u.polyhedron.face_count && !face_outlines(n, m, out)) {
        st = err_nomem(w->c->error, &n->loc); /* a polyhedron without volume */
    }
    free(s.face);
    free(s.v);
    return st;
}

static sc_status walk_node(pwalk *w, const model_node *n, const affine *m, int depth,
                           twod_region *out);

static int skipped(const model_node *n)
{
    return (n->modifiers & (MODEL_MOD_DISABLE | MODEL_MOD_BACKGROUND)) != 0 ||
           n->kind == MODEL_LIGHT || n->kind == MODEL_CAMERA ||
           n->kind == MODEL_BACKGROUND;
}

/* A '%' child k (nothing for any other): no operand, but walked for the
 * warnings of its subtree, as OpenSCAD 2021.01's render evaluates a
 * background child before it leaves it out; its parent says nothing of
 * it. */
static sc_status background(pwalk *w, const model_node *k, const affine *m, int depth)
{
    if ((k->modifiers & (MODEL_MOD_DISABLE | MODEL_MOD_BACKGROUND)) !=
            MODEL_MOD_BACKGROUND ||
        k->kind == MODEL_LIGHT || k->kind == MODEL_CAMERA || k->kind == MODEL_BACKGROUND)
        return SC_OK;
    if (flat(k) || k->kind == MODEL_PROJECTION)
        return build_twod_check(w->c, k, NULL);
    twod_region scratch;
    twod_init(&scratch);
    sc_status st = walk_node(w, k, m, depth + 1, &scratch);
    twod_free(&scratch);
    return st;
}

/* The children of n, the projection itself or a 3D operation in it,
 * walked into out. Its 2D children are checked (build_twod_check) and left out,
 * with OpenSCAD 2021.01's warnings once all are walked: a 3D operation's
 * (ignored_2d); none from projection(cut = false), which passes over a 2D
 * child; from projection(cut = true), which unites its children as a 3D
 * operation without checking that they mix, each ignored. */
static sc_status walk_children(pwalk *w, const model_node *n, const affine *m, int depth,
                               twod_region *out)
{
    const model_node *mixing = NULL; /* the first 2D child that is not empty */
    for (const model_node *k = n->first_child; k; k = k->next) {
        sc_status st;
        if (skipped(k)) {
            if ((st = background(w, k, m, depth)) != SC_OK)
                return st;
            continue;
        }
        if (flat(k) || k->kind == MODEL_PROJECTION) {
            /* a projection that is not flat is no geometry */
            int empty;
            st = build_twod_check(w->c, k, &empty);
            if (!mixing && !empty && flat(k))
                mixing = k;
        } else {
            st = walk_node(w, k, m, depth + 1, out);
        }
        if (st != SC_OK)
            return st;
    }
    if (n == w->proj)
        return w->cut ? ignored_2d(w->c, n, NULL) : SC_OK;
    if (n->kind == MODEL_XFORM && n->not_finite) /* removed: not checked (walk_node) */
        return SC_OK;
    return ignored_2d(w->c, n, mixing);
}

/* difference or intersection n (cut only): each child's loops united on
 * their own, the boolean of them in 2D, the result's contours (outer
 * counter-clockwise, holes clockwise: winding 1 inside, 0 outside) added
 * to out. */
static sc_status boolean(pwalk *w, const model_node *n, const affine *m, int depth,
                         twod_region *out)
{
    uint32_t count = 0;
    for (const model_node *k = n->first_child; k; k = k->next)
        count += !skipped(k) && !flat(k);
    if (count == 0)
        return SC_OK;
    twod_region *parts = calloc(count, sizeof *parts);
    twod_region **list = calloc(count, sizeof *list);
    twod_region from; /* the parts' loops, before the clipper's grid */
    twod_init(&from);
    sc_status st = parts && list ? SC_OK : err_nomem(w->c->error, &n->loc);
    uint32_t i = 0;
    const model_node *mixing = NULL; /* the first 2D child that is not empty */
    for (const model_node *k = n->first_child; k && st == SC_OK; k = k->next) {
        if (skipped(k)) {
            st = background(w, k, m, depth);
            continue;
        }
        if (flat(k)) {
            int empty;
            st = build_twod_check(w->c, k, &empty);
            if (!mixing && !empty)
                mixing = k;
            continue;
        }
        twod_region *part = &parts[i];
        list[i++] = part;
        twod_init(part);
        st = walk_node(w, k, m, depth + 1, part);
        if (st == SC_OK && !append(&from, part))
            st = add_error(w, part);
        if (st == SC_OK)
            st = clip_error(w, k, twod_clip_union_nonzero(part, 0), part);
    }
    if (st == SC_OK)
        st = ignored_2d(w->c, n, mixing);
    twod_op op = n->kind == MODEL_DIFFERENCE ? TWOD_DIFFERENCE : TWOD_INTERSECTION;
    twod_region result;
    twod_init(&result);
    if (st == SC_OK)
        st = clip_error(w, n, twod_clip_apply(list, count, op, &result), &result);
    /* OpenSCAD's boolean of Nef polyhedra is exact: the corners kept take
     * back their points (exact_union) */
    if (st == SC_OK && !twod_restore_points(&result, &from))
        st = err_nomem(w->c->error, &n->loc);
    twod_free(&from);
    if (st == SC_OK && !append(out, &result))
        st = add_error(w, out);
    twod_free(&result);
    for (uint32_t j = 0; parts && j < i; j++)
        twod_free(&parts[j]);
    free(parts);
    free(list);
    return st;
}

static sc_status walk_moved(pwalk *w, const model_node *n, const affine *m, int depth,
                            twod_region *out);

static sc_status walk_node(pwalk *w, const model_node *n, const affine *m, int depth,
                           twod_region *out)
{
    const build_ctx *c = w->c;
    if (depth > BUILD_PROJECTION_MAX_DEPTH)
        return err_set(c->error, SC_ERR_LIMIT, &n->loc,
                       "too many nested nodes inside projection (limit is %d)",
                       BUILD_PROJECTION_MAX_DEPTH);
    model_kind kind = n->kind;
    if (n->pending && !flat(n))
        return build_pending(c, n);
    if (flat(n) || kind == MODEL_PROJECTION) /* its parent warns (walk_children) */
        return build_twod_check(c, n, NULL);
    const affine *since = w->since;
    sc_status st = walk_moved(w, n, m, depth, out);
    w->since = since;
    return st;
}

/* A singular multmatrix n, where inner (the frame of its children) is
 * singular: OpenSCAD 2021.01 flattens a mesh's points (PolySet::transform)
 * and projects the faces of the flat mesh, but removes a Nef polyhedron
 * (CGAL_Nef_polyhedron::transform, with its warning). Without cut, the
 * outline of a flattened mesh is that of the solid under any frame with
 * inner's x and y rows, so inner's z row becomes their cross product:
 * 1 when that frame can be inverted, for n's children to be walked in
 * it; 0 where the frame has no z row to give (the x and y rows are
 * parallel, and the outline has no area), under a cut (the section of a
 * flat mesh, a CGAL Nef polyhedron of it, is not taken) or where the
 * children are a Nef polyhedron (with *removal, build_singular_removes). */
static int repair_frame(const pwalk *w, const model_node *n, affine *inner,
                        const char **removal)
{
    affine inverse;
    if (build_singular_removes(n, removal) || w->cut)
        return 0;
    vec3 x = v3(inner->m[0][0], inner->m[0][1], inner->m[0][2]);
    vec3 y = v3(inner->m[1][0], inner->m[1][1], inner->m[1][2]);
    vec3 z = v3_cross(x, y);
    affine repaired = *inner;
    repaired.m[2][0] = z.x;
    repaired.m[2][1] = z.y;
    repaired.m[2][2] = z.z;
    repaired.m[2][3] = 0;
    if (!affine_invert(&repaired, &inverse))
        return 0;
    *inner = repaired;
    return 1;
}

/* walk_node, with w->since as n leaves it for its children. */
static sc_status walk_moved(pwalk *w, const model_node *n, const affine *m, int depth,
                            twod_region *out)
{
    const build_ctx *c = w->c;
    model_kind kind = n->kind;
    affine since;
    if (build_operands(n->kind, n->first_child) > 1)
        w->since = &affine_unmoved; /* OpenSCAD's Nef polyhedron of them */
    switch (kind) {
    case MODEL_UNION:
    case MODEL_COLOR:
    case MODEL_MATERIAL:
        return walk_children(w, n, m, depth, out);
    case MODEL_XFORM:
    case MODEL_RESIZE: {
        affine local;
        sc_status st = SC_OK;
        if (kind == MODEL_XFORM && n->not_finite) {
            /* removed for a nan or inf entry: OpenSCAD 2021.01 evaluates
             * the children first (their warnings, not its check of their
             * dimensions: walk_children), then says so */
            twod_region scratch;
            twod_init(&scratch);
            st = walk_children(w, n, m, depth, &scratch);
            twod_free(&scratch);
            return st == SC_OK ? build_xform_not_finite(c, n) : st;
        }
        if (kind == MODEL_XFORM) {
            local = *n->u.xform;
        } else {
            const char *warning = NULL;
            st = meshes_resize(w, n, &local, &warning);
            if (st == SC_OK && warning)
                st = say(c, &n->loc, warning);
        }
        affine inner = affine_mul(m, &local), inverse;
        if (st != SC_OK)
            return st;
        const char *removal = NULL;
        if (!affine_invert(&inner, &inverse) && !repair_frame(w, n, &inner, &removal))
            return removal ? say(c, &n->loc, removal) : SC_OK;
        if (w->since && build_operands(n->kind, n->first_child) <= 1) {
            since = affine_mul(w->since, &local);
            w->since = &since;
        }
        return walk_children(w, n, &inner, depth, out);
    }
    case MODEL_DIFFERENCE:
    case MODEL_INTERSECTION:
        if (!w->cut)
            return leaf(w, n, m, depth, out); /* the boolean's mesh */
        {
            w->booleans++;
            sc_status st = boolean(w, n, m, depth, out);
            w->booleans--;
            return st;
        }
    default:
        return leaf(w, n, m, depth, out);
    }
}

sc_status build_projection(const build_ctx *c, const model_node *n, twod_region *out)
{
    twod_clear(out);
    if (n->pending)
        return build_pending(c, n);
    pwalk w = {c, n, n->u.projection.cut, NULL, 0, 0, 0, NULL, 0, {0}};
    affine id = affine_identity();
    sc_status st = walk_children(&w, n, &id, 0, out);
    int missed = w.solid && !w.crossing; /* "Projection() failed." when empty */
    nef_plugin_close(&w.nef);
    if (st == SC_OK && w.crossing) {
        twod_clear(out);
        st = build_nef_section(c, n, &w.cache, out, &missed);
    }
    if (st == SC_OK && w.cut)
        st = exact_union(&w, n, out);
    else if (st == SC_OK)
        st = clip_error(&w, n, twod_clip_union_nonzero(out, 2), out);
    /* a solid that z = 0 misses: OpenSCAD's warning (CGALUtils::project),
     * said where the union of the children is known not to be empty */
    if (st == SC_OK && w.cut && missed == 1 && !out->contour_count && c->notes)
        st = build_note(c, &n->loc, "Projection() failed.");
    build_resize_cache_free(w.cache);
    return st;
}
