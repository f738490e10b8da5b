/* hull(), minkowski() and resize(): the nodes whose result depends on the
 * geometry of their children, built from the children's points.
 *
 * Points. Each child leaf gives the points of the polyhedron OpenSCAD 2021.01
 * makes of it, carried into the hull node's frame by the multmatrix nodes
 * between: a cube its 8 corners; a polyhedron the points its faces use;
 * import, surface, linear_extrude and rotate_extrude (as in --faithful)
 * the vertices of their meshes (an import's closed or not); sphere
 * and cylinder OpenSCAD's polyhedra for their $fn, $fa, $fs (faithful.c's
 * rings and circles), in default mode as in --faithful, since OpenSCAD
 * hulls those polygons; a nested hull its children's points; a nested
 * minkowski its parts' sums; a nested resize its children scaled. group,
 * union, render, color and material pass their children through; '%' and
 * '*' children are left out. A difference or intersection is evaluated as
 * OpenSCAD evaluates it, to a CGAL Nef polyhedron (through the plugin of
 * nef.h, opened on the first one), whose vertices a hull takes. Every
 * other node is SC_ERR_UNSUPPORTED at its position.
 *
 * hull: the convex hull of all the points (hull3.c, exact orientation
 * tests), as a plane set, or as a mesh of its triangles when it has more
 * than PRIM_CONVEX_MAX_PLANES planes (the mesh leaf's box hierarchy keeps large
 * hulls fast). A flat or empty hull is the empty solid with a warning.
 *
 * minkowski: each child is a list of convex parts (a leaf or hull is one
 * part; a group of several gives several: A ⊕ (B ∪ C) = (A ⊕ B) ∪ (A ⊕ C)).
 * A polyhedron or mesh leaf is one part when it is convex: when its volume
 * is within 1e-6 of its hull's, or, a polyhedron, when OpenSCAD finds its
 * faces as written convex (polyset_convex); otherwise, and for a difference or
 * intersection, the parts are those of CGAL's convex decomposition of its
 * Nef polyhedron, as OpenSCAD's applyMinkowski splits non-convex children.
 * The sum of convex parts P and Q is the hull of the pairwise sums of their
 * vertices, so the result is the union, over every choice of one part per
 * child, of the hull of the sums (the parts are first reduced to their hull
 * vertices). Children without geometry are skipped, as OpenSCAD does.
 *
 * resize: OpenSCAD scales the child's mesh by newsize / size of its
 * bounding box. The box here is the support function h(u) = max u . x
 * over the child, in the six axis directions, which composes exactly:
 * union, hull: max over children; minkowski: sum over children; multmatrix
 * x -> M x + t: h(u) = h_child(M^T u) + u . t; sphere (exact mode):
 * r |u|; cylinder (exact): max over its end discs of z_k u_z + r_k
 * |(u_x, u_y)|; torus: R |(u_x, u_y)| + r |u|; point-built leaves: max over
 * their points; quadric and implicit: their clipping box's corners. So
 * the box is tight for all of these. A difference or intersection of two
 * or more solids is measured as OpenSCAD measures it, by the vertices of
 * its CGAL Nef polyhedron; only a check (no CGAL) takes the first child's
 * box, or the smallest of the children's, as upper bounds. The scales
 * follow OpenSCAD's PolySet::resize or, for a result OpenSCAD holds as a
 * Nef polyhedron (nef_result), CGAL_Nef_polyhedron::resize, which mirrors
 * by a negative size (docs/resize.md). 2D children are ignored, with
 * OpenSCAD's warnings from hull and minkowski (measuring is silent).
 *
 * The walks recurse with a depth guard (BUILD_HULL_MAX_DEPTH).
 */
#include "build/build_hull.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/cancel.h"
#include "base/error.h"
#include "base/grow.h"
#include "build/build_extrude_faithful.h"
#include "build/build_mesh.h"
#include "build/build_nef_cache.h"
#include "build/build_revolve.h"
#include "build/build_twod.h"
#include "build/nef.h"
#include "csg/hull3.h"
#include "csg/prim_mesh.h"
#include "model/lower_curved.h"
#include "model/args.h"
#include "model/faithful.h"

typedef struct pointset {
    vec3 *p;
    uint32_t count, cap;
} pointset;

typedef struct partlist {
    pointset *items;
    uint32_t count, cap;
} partlist;

typedef struct walk {
    const build_ctx *c;
    const char *owner; /* "hull", "minkowski" or "resize", for messages */
    int convex;        /* parts must be convex (minkowski) */
    build_resize_cache **cache;
    nef_plugin *nef; /* the CGAL plugin, opened on first use (handle NULL before) */
    int check;       /* only check the children: no mesh booleans */
    /* inside a union of several solids (a group's or a transform's
     * children), which OpenSCAD makes a CGAL Nef polyhedron of */
    int in_union;
    /* a minkowski's: set when a mesh among its children is not closed */
    int *not_closed;
    /* the node build_nef_evaluate evaluates, and what it says of its
     * operands (NULL elsewhere) */
    const model_node *top;
    build_nef_state *state;
    /* a minkowski's: where CGAL's convex decomposition of an operand
     * failed (solid_parts), for the minkowski to fall back as OpenSCAD's
     * does (minkowski_parts); NULL elsewhere */
    struct decompose_failure *failure;
    /* the transforms since the innermost union of several solids that
     * OpenSCAD makes a Nef polyhedron of, which moved a mesh's points
     * before it is tessellated and checked there (build_mesh_merge_moved);
     * NULL where no such union lies between: the walk's own m */
    const affine *since;
} walk;

/* The operand whose convex decomposition CGAL failed on (its name and
 * place: the walk's nodes may be copies), and CGAL's message. */
typedef struct decompose_failure {
    const char *name; /* NULL: none failed */
    sc_location loc;
    char why[512];
} decompose_failure;

/* Each resize node's matrix, computed once per build: a resize inside a
 * resize (or hull) would otherwise be measured again at every level above
 * it, exponentially in the nesting. Open addressing on the node's
 * address. */
struct build_resize_cache {
    const model_node **keys;
    affine *matrices;
    const char **warnings;
    size_t count, cap; /* cap is a power of two */
};

void build_resize_cache_free(build_resize_cache *cache)
{
    if (!cache)
        return;
    free(cache->keys);
    free(cache->matrices);
    free(cache->warnings);
    free(cache);
}

static size_t slot_of(const build_resize_cache *cache, const model_node *n)
{
    size_t h = (size_t)(uintptr_t)n;
    h ^= h >> 17;
    h *= (size_t)0x9e3779b97f4a7c15ull;
    size_t i = (h ^ (h >> 29)) & (cache->cap - 1);
    while (cache->keys[i] && cache->keys[i] != n)
        i = (i + 1) & (cache->cap - 1);
    return i;
}

static const affine *cache_find(const build_resize_cache *cache, const model_node *n,
                                const char **warning)
{
    if (!cache || !cache->cap)
        return NULL;
    size_t i = slot_of(cache, n);
    if (!cache->keys[i])
        return NULL;
    *warning = cache->warnings[i];
    return &cache->matrices[i];
}

/* Returns 0 when memory ran out. */
static int cache_put(build_resize_cache **slot, const model_node *n, const affine *m,
                     const char *warning)
{
    build_resize_cache *cache = *slot;
    if (!cache && !(cache = *slot = calloc(1, sizeof *cache)))
        return 0;
    if (2 * (cache->count + 1) > cache->cap) {
        build_resize_cache grown = {NULL, NULL, NULL, 0,
                                    cache->cap ? 2 * cache->cap : 64};
        grown.keys = calloc(grown.cap, sizeof *grown.keys);
        grown.matrices = malloc(grown.cap * sizeof *grown.matrices);
        grown.warnings = malloc(grown.cap * sizeof *grown.warnings);
        if (!grown.keys || !grown.matrices || !grown.warnings) {
            free(grown.keys);
            free(grown.matrices);
            free(grown.warnings);
            return 0;
        }
        for (size_t i = 0; i < cache->cap; i++) {
            if (!cache->keys[i])
                continue;
            size_t j = slot_of(&grown, cache->keys[i]);
            grown.keys[j] = cache->keys[i];
            grown.matrices[j] = cache->matrices[i];
            grown.warnings[j] = cache->warnings[i];
        }
        grown.count = cache->count;
        free(cache->keys);
        free(cache->matrices);
        free(cache->warnings);
        *cache = grown;
    }
    size_t i = slot_of(cache, n);
    cache->keys[i] = n;
    cache->matrices[i] = *m;
    cache->warnings[i] = warning;
    cache->count++;
    return 1;
}

static void parts_free(partlist *l)
{
    for (uint32_t i = 0; i < l->count; i++)
        free(l->items[i].p);
    free(l->items);
    memset(l, 0, sizeof *l);
}

static int add_point(pointset *s, vec3 p)
{
    if (!grow_array32((void **)&s->p, &s->cap, s->count + 1, sizeof *s->p))
        return 0;
    s->p[s->count++] = p;
    return 1;
}

/* A new, empty part at the end of l; NULL when memory ran out. */
static pointset *new_part(partlist *l)
{
    if (!grow_array32((void **)&l->items, &l->cap, l->count + 1, sizeof *l->items))
        return NULL;
    pointset *s = &l->items[l->count++];
    memset(s, 0, sizeof *s);
    return s;
}

static int positive_finite(double x)
{
    return x > 0 && isfinite(x);
}

/* ---- leaves as shapes ---- */

typedef enum shape_kind {
    SHAPE_NONE, /* no geometry */
    SHAPE_BOX,
    SHAPE_SPHERE,
    SHAPE_CYLINDER,
} shape_kind;

/* A cube, sphere or cylinder read from its arguments. */
typedef struct shape {
    shape_kind kind;
    vec3 lo, hi;           /* box */
    double r;              /* sphere */
    double z0, z1, r0, r1; /* cylinder */
    double fn, fa, fs;
} shape;

/* A cube, sphere or cylinder of the model (its error reported first). */
static sc_status read_shape(const build_ctx *c, const model_node *n, shape *s)
{
    memset(s, 0, sizeof *s);
    if (n->pending)
        return build_pending(c, n);
    if (n->kind == MODEL_CUBE) {
        const double *size = n->u.cube.size;
        if (!positive_finite(size[0]) || !positive_finite(size[1]) ||
            !positive_finite(size[2]))
            return SC_OK;
        vec3 sz = v3(size[0], size[1], size[2]);
        s->kind = SHAPE_BOX;
        s->lo = n->u.cube.center ? v3_scale(sz, -0.5) : v3(0, 0, 0);
        s->hi = n->u.cube.center ? v3_scale(sz, 0.5) : sz;
        return SC_OK;
    }
    if (n->kind == MODEL_SPHERE) {
        s->fn = n->u.sphere.res.fn;
        s->fa = n->u.sphere.res.fa;
        s->fs = n->u.sphere.res.fs;
        if (!positive_finite(n->u.sphere.r))
            return SC_OK;
        s->kind = SHAPE_SPHERE;
        s->r = n->u.sphere.r;
        return SC_OK;
    }
    double h = n->u.cylinder.h, r1 = n->u.cylinder.r1, r2 = n->u.cylinder.r2;
    s->fn = n->u.cylinder.res.fn;
    s->fa = n->u.cylinder.res.fa;
    s->fs = n->u.cylinder.res.fs;
    if (!positive_finite(h) || !(r1 >= 0 && r2 >= 0) || !isfinite(r1) || !isfinite(r2) ||
        (r1 == 0 && r2 == 0))
        return SC_OK;
    s->kind = SHAPE_CYLINDER;
    s->z0 = n->u.cylinder.center ? -h / 2 : 0;
    s->z1 = n->u.cylinder.center ? h / 2 : h;
    s->r0 = r1;
    s->r1 = r2;
    return SC_OK;
}

/* Point k of a circle of radius r with f fragments at height z, as
 * faithful.c places it. */
static vec3 circle_point(double r, long k, long f, double z)
{
    double phi = (360.0 * (double)k) / (double)f;
    return v3(r * faithful_cos_deg(phi), r * faithful_sin_deg(phi), z);
}

/* The vertices of OpenSCAD's polyhedron of shape s, through m. */
static sc_status shape_points(const walk *w, const model_node *n, const shape *s,
                              const affine *m, pointset *out)
{
    if (s->kind == SHAPE_BOX) {
        for (int k = 0; k < 8; k++) {
            vec3 p = v3(k & 1 ? s->hi.x : s->lo.x, k & 2 ? s->hi.y : s->lo.y,
                        k & 4 ? s->hi.z : s->lo.z);
            if (!add_point(out, affine_point(m, p)))
                return err_nomem((w->c)->error, (&n->loc));
        }
        return SC_OK;
    }
    int sphere = s->kind == SHAPE_SPHERE;
    double rmax = sphere ? s->r : fmax(s->r0, s->r1);
    long f = sphere ? faithful_sphere_fragments(rmax, s->fn, s->fs, s->fa)
                    : faithful_fragments(rmax, s->fn, s->fs, s->fa);
    if (f < 0)
        return err_set(w->c->error, SC_ERR_LIMIT, &n->loc,
                       "%s: $fn, $fa and $fs of radius %g give too many fragments (limit "
                       "is %d)",
                       w->owner, rmax,
                       sphere ? FAITHFUL_MAX_SPHERE_FRAGMENTS : FAITHFUL_MAX_FRAGMENTS);
    if (s->kind == SHAPE_SPHERE) {
        long rings = (f + 1) / 2;
        for (long i = 0; i < rings; i++) {
            double phi = (180.0 * ((double)i + 0.5)) / (double)rings;
            double radius = s->r * faithful_sin_deg(phi);
            double z = s->r * faithful_cos_deg(phi);
            for (long k = 0; k < f; k++) {
                if (!add_point(out, affine_point(m, circle_point(radius, k, f, z))))
                    return err_nomem((w->c)->error, (&n->loc));
            }
        }
        return SC_OK;
    }
    for (long k = 0; k < f; k++) {
        if (!add_point(out, affine_point(m, circle_point(s->r0, k, f, s->z0))) ||
            !add_point(out, affine_point(m, circle_point(s->r1, k, f, s->z1))))
            return err_nomem((w->c)->error, (&n->loc));
    }
    return SC_OK;
}

/* ---- polyhedra and meshes ---- */

/* The points a polyhedron's faces use, through m, and the volume its faces
 * enclose (fans about each face's first point). */
static sc_status polyhedron_points(const walk *w, const model_node *n, const affine *m,
                                   pointset *out, double *volume)
{
    const build_ctx *c = w->c;
    *volume = 0;
    if (n->pending)
        return build_pending(c, n);
    uint32_t np = n->u.polyhedron.point_count;
    vec3 *p = np ? malloc((size_t)np * sizeof *p) : NULL;
    unsigned char *used = np ? calloc(np, 1) : NULL;
    if (np && (!p || !used)) {
        free(p);
        free(used);
        return err_nomem(c->error, (&n->loc));
    }
    for (uint32_t i = 0; i < np; i++)
        p[i] = affine_point(m, n->u.polyhedron.points[i]);
    const uint32_t *start = n->u.polyhedron.face_start, *index = n->u.polyhedron.indices;
    double six = 0;
    for (uint32_t f = 0; f < n->u.polyhedron.face_count; f++) {
        uint32_t first = 0, prev = 0;
        for (uint32_t i = start[f]; i < start[f + 1]; i++) {
            uint32_t k = index[i];
            used[k] = 1;
            if (i == start[f])
                first = k;
            else if (i >= start[f] + 2)
                six += v3_dot(p[first], v3_cross(p[prev], p[k]));
            prev = k;
        }
    }
    sc_status st = SC_OK;
    for (uint32_t i = 0; i < np && st == SC_OK; i++) {
        if (used[i] && !add_point(out, p[i]))
            st = err_nomem(c->error, (&n->loc));
    }
    *volume = fabs(six) / 6;
    free(p);
    free(used);
    return st;
}

/* Whether OpenSCAD 2021.01 finds polyhedron n, carried into a minkowski's
 * frame by m, convex where applyMinkowski asks (PolySet::is_convex, which
 * is is_approximately_convex on the faces as written: not tessellated,
 * unlike the test before CGAL's builder, build_mesh.c's approx_convex).
 * Then OpenSCAD sums the hull of its points, though a face out of its
 * plane may make the solid itself not convex. The test
 * (build_mesh_convex_as_written), on the points through m (the PolySet's,
 * transformed before the minkowski), equal coordinates one point, and
 * each face as OpenSCAD holds it (back to front, and turned again when m
 * mirrors). Sets *convex; SC_OK, or out of memory. */
static sc_status polyset_convex(const walk *w, const model_node *n, const affine *m,
                                int *convex)
{
    *convex = 0;
    uint32_t np = n->u.polyhedron.point_count, nf = n->u.polyhedron.face_count;
    const uint32_t *start = n->u.polyhedron.face_start, *index = n->u.polyhedron.indices;
    size_t total = nf ? start[nf] : 0;
    if (!np || !nf)
        return SC_OK;
    for (uint32_t f = 0; f < nf; f++) {
        if (start[f + 1] - start[f] < 3)
            return SC_OK; /* never reached from the others */
    }
    build_mesh_keyed *sorted = malloc((size_t)np * sizeof *sorted);
    uint32_t *number = malloc((size_t)np * sizeof *number);
    vec3 *points = malloc((size_t)np * sizeof *points);
    uint32_t *indices = malloc((total ? total : 1) * sizeof *indices);
    sc_status st = SC_OK;
    if (!sorted || !number || !points || !indices) {
        st = err_nomem(w->c->error, &n->loc);
        goto done;
    }
    for (uint32_t i = 0; i < np; i++)
        sorted[i] = (build_mesh_keyed){affine_point(m, n->u.polyhedron.points[i]), i};
    qsort(sorted, np, sizeof *sorted, build_mesh_keyed_cmp);
    uint32_t id = 0;
    for (uint32_t i = 0; i < np; i++) {
        if (i &&
            !(sorted[i - 1].p.x == sorted[i].p.x && sorted[i - 1].p.y == sorted[i].p.y &&
              sorted[i - 1].p.z == sorted[i].p.z))
            id++;
        number[sorted[i].index] = id;
        points[id] = sorted[i].p;
    }
    /* OpenSCAD's order of face f's points: PolyhedronNode inserts each
     * point at the front; a mirroring transform reverses the faces again */
    int backward = !(affine_det(m) < 0);
    for (uint32_t f = 0; f < nf; f++) {
        for (uint32_t k = start[f]; k < start[f + 1]; k++)
            indices[k] = number[index[backward ? start[f + 1] - 1 - (k - start[f]) : k]];
    }
    int c = build_mesh_convex_as_written(points, id + 1, indices, start, nf);
    if (c < 0)
        st = err_nomem(w->c->error, &n->loc);
    else
        *convex = c;
done:
    free(sorted);
    free(number);
    free(points);
    free(indices);
    return st;
}

/* import, linear_extrude, rotate_extrude, surface: their mesh's corners
 * through m, and its volume. Extrusions are built as in --faithful, in
 * both modes: OpenSCAD hulls the vertices of its polygons, and the exact
 * leaves of default mode have none. A hull takes an imported mesh closed
 * or not, silently, as OpenSCAD 2021.01 hulls the corners of the mesh it
 * reads (build_import_mesh). A minkowski takes it as the polyhedron it
 * would be: closed_check has emptied the minkowski where CGAL takes no Nef
 * polyhedron of it, and CGAL takes some that are not closed (a face given
 * twice), which OpenSCAD sums. */
static sc_status mesh_prim(const walk *w, const model_node *n, prim *out,
                           const char **empty)
{
    memset(out, 0, sizeof *out);
    build_ctx fc = *w->c;
    fc.faithful = 1;
    /* a hull takes an extrusion's corners, closed or not; where OpenSCAD
     * makes a Nef polyhedron of it (a minkowski's operand, a union of
     * several), one its builder does not take (a pinched profile) is left
     * out, and a minkowski's empties the minkowski (closed_check) */
    fc.drawn_as_is = !w->in_union && !w->not_closed;
    model_kind kind = n->kind;
    if ((kind == MODEL_IMPORT || kind == MODEL_SURFACE) && n->pending)
        return build_pending(w->c, n);
    if (kind == MODEL_SURFACE)
        return build_surface(w->c, n->u.surface, out, empty);
    if (kind == MODEL_IMPORT)
        return build_import_mesh(w->c, n->u.import, out, empty);
    sc_status st = kind == MODEL_ROTATE_EXTRUDE
                       ? build_rotate_extrude(&fc, n, 1, out, empty)
                       : build_linear_extrude(&fc, n, 1, out, empty);
    if (st == SC_OK && *empty && !(*empty)[0] && w->not_closed && !w->in_union)
        *w->not_closed = 1; /* left out, with its warning */
    return st;
}

static sc_status mesh_points(const walk *w, const model_node *n, const affine *m,
                             pointset *out, double *volume)
{
    prim p;
    const char *empty = NULL;
    *volume = 0;
    sc_status st = mesh_prim(w, n, &p, &empty);
    if (st != SC_OK || empty || p.kind != PRIM_MESH)
        return st;
    const prim_mesh *mesh = p.u.mesh.mesh;
    double six = 0;
    for (uint32_t t = 0; t < mesh->tri_count; t++) {
        vec3 a = affine_point(m, mesh->v[3 * t]), b = affine_point(m, mesh->v[3 * t + 1]),
             cc = affine_point(m, mesh->v[3 * t + 2]);
        six += v3_dot(a, v3_cross(b, cc));
        if (!add_point(out, a) || !add_point(out, b) || !add_point(out, cc))
            return err_nomem((w->c)->error, (&n->loc));
    }
    *volume = fabs(six) / 6;
    return SC_OK;
}

/* A mesh n (an extrusion, import or surface) in a minkowski, under a
 * frame m that flattens it (a singular multmatrix above): OpenSCAD 2021.01
 * flattens its points and sums the hull of the flat points where it finds
 * the flat mesh convex, as a convex mesh stays. One that is not convex,
 * which OpenSCAD takes as CGAL finds it once flat (not closed, which
 * empties the whole sum, where seen), is left out with a warning. */
static sc_status flat_mesh_part(const walk *w, const model_node *n, const affine *m,
                                partlist *out)
{
    pointset set = {NULL, 0, 0};
    double volume = 0;
    int convex = 0;
    sc_status st = mesh_points(w, n, &affine_unmoved, &set, &volume);
    if (st == SC_OK && set.count) {
        hull3 h;
        hull3_status hs = hull3_compute(set.p, set.count, &h);
        if (hs == HULL3_NOMEM)
            st = err_nomem(w->c->error, &n->loc);
        else
            convex = hs == HULL3_OK &&
                     fabs(hull3_volume(&h) - volume) <= 1e-6 * hull3_volume(&h);
        hull3_free(&h);
    }
    if (st == SC_OK && set.count && !convex && !w->check)
        st =
            build_note(w->c, &n->loc,
                       "%s flattened by a singular multmatrix is not convex: left out of "
                       "minkowski (not supported yet)",
                       n->name);
    if (st == SC_OK && set.count && convex) {
        for (uint32_t i = 0; i < set.count; i++)
            set.p[i] = affine_point(m, set.p[i]);
        pointset *part = new_part(out);
        if (!part) {
            st = err_nomem(w->c->error, &n->loc);
        } else {
            *part = set;
            set.p = NULL;
        }
    }
    free(set.p);
    return st;
}

/* Where a mesh under m (the walk's frame) has moved to when a union of
 * several, or the hull or minkowski, takes it (w->since, else m): that
 * map, or NULL for none (or one that cannot be undone), and in *rest what
 * takes it on to the walk's frame (build_mesh_since). */
static const affine *moved_since(const walk *w, const affine *m, affine *rest)
{
    const affine *since = build_mesh_since(w->since, m, rest);
    return since && !affine_is_identity(since) ? since : NULL;
}

/* OpenSCAD 2021.01 takes a mesh into a CGAL Nef polyhedron in a union of
 * several solids and in a minkowski sum, and cannot when the mesh is not
 * closed: it prints "The given mesh is not closed! ..." and leaves the
 * mesh out of the union, or the whole minkowski empty. A hull takes the
 * corners of the mesh as they are. Whether n, a polyhedron or an import
 * of one object, is such a mesh in such a place: then its warning is
 * given (the error with --strict; nothing where the walk only checks),
 * *open is set, and for a minkowski *w->not_closed. Reads the file once
 * more for an import. */
static sc_status closed_check(const walk *w, const model_node *n, const affine *m,
                              int *open)
{
    const build_ctx *c = w->c;
    *open = 0;
    if ((!w->in_union && !w->not_closed) || n->pending)
        return SC_OK;
    /* the faces as the leaf merges them; their warnings, and a file that
     * does not open, are the leaf's (mesh_points) */
    sc_error sink = {SC_OK, "", 0, 0, ""};
    build_ctx quiet = *c;
    quiet.note = &sink;
    quiet.notes = NULL;
    quiet.strict = 0;
    quiet.faithful = 0;
    build_mesh_faces f;
    memset(&f, 0, sizeof f);
    const char *empty = NULL, *what = "polyhedron";
    const sc_location *loc = &n->loc;
    sc_status st;
    affine rest;
    quiet.moved = moved_since(w, m, &rest);
    if (n->kind == MODEL_POLYHEDRON) {
        st = build_mesh_merge_moved(&quiet, loc, 1, quiet.moved, n->u.polyhedron.points,
                                    n->u.polyhedron.point_count, n->u.polyhedron.indices,
                                    n->u.polyhedron.face_start,
                                    n->u.polyhedron.face_count, &f);
    } else {
        what = "imported mesh";
        loc = &n->u.import->file_loc;
        st = build_import_faces(&quiet, n->u.import, &empty, &f);
    }
    char why[SC_ERROR_MESSAGE_MAX - 160];
    const char *refusal = build_openscad_not_closed;
    /* a corner that is nan or inf: OpenSCAD reads the file, and CGAL finds
     * the mesh not closed */
    int sound = st == SC_OK && empty == build_import_not_finite
                    ? (snprintf(why, sizeof why,
                                "%s is not closed (a corner is not finite)", what),
                       0)
                : st != SC_OK || empty || !f.face_count
                    ? 1
                    : build_mesh_cgal_sound(&f, what, n->kind == MODEL_POLYHEDRON,
                                            w->in_union, why, sizeof why, &refusal);
    build_mesh_faces_free(&f);
    if (st != SC_OK) { /* the leaf's own error, found again where it is built */
        err_clear(c->error);
        return SC_OK;
    }
    if (sound < 0)
        return err_nomem(c->error, loc);
    if (sound)
        return SC_OK;
    *open = 1;
    if (w->check) /* only checked: said where it is built */
        return SC_OK;
    if (c->strict)
        return err_set(c->error, SC_ERR_SEMANTIC, loc, "%s", why);
    if (w->in_union)
        return build_note_left_out(
            c, loc, "%s; left out, as OpenSCAD leaves it out (\"%s\")", why, refusal);
    *w->not_closed = 1;
    return build_note(c, loc, "%s; the %s is empty, as OpenSCAD leaves it out (\"%s\")",
                      why, w->owner, refusal);
}

/* ---- the walk ---- */

/* multmatrix(m): the matrix, or 0 in *ok for a singular one (no geometry;
 * one removed for a nan or inf entry is the zero map: inner_frame). */
static sc_status read_matrix(const build_ctx *c, const model_node *n, affine *out,
                             int *ok)
{
    *ok = 1;
    if (n->pending)
        return build_pending(c, n);
    *out = *n->u.xform;
    affine inverse;
    *ok = affine_invert(out, &inverse);
    return SC_OK;
}

/* Whether n is a multmatrix removed for a nan or inf entry (model.h). */
static int removed(const model_node *n)
{
    return n->kind == MODEL_XFORM && n->not_finite;
}

/* group, union, render, color, material: the union of their children. */
static int is_group(model_kind kind)
{
    return kind == MODEL_UNION || kind == MODEL_COLOR || kind == MODEL_MATERIAL;
}

/* light, camera, background: no geometry. */
static int is_shading(model_kind kind)
{
    return kind == MODEL_LIGHT || kind == MODEL_CAMERA || kind == MODEL_BACKGROUND;
}

/* The leaves built as meshes: import, the extrusions, surface. */
static int is_mesh(model_kind kind)
{
    return kind == MODEL_IMPORT || kind == MODEL_LINEAR_EXTRUDE ||
           kind == MODEL_ROTATE_EXTRUDE || kind == MODEL_SURFACE;
}

static int skipped(const model_node *n)
{
    return (n->modifiers & (MODEL_MOD_DISABLE | MODEL_MOD_BACKGROUND)) != 0;
}

/* Whether n is 2D (a 2D shape, or an operation whose first child with a
 * dimension is 2D: build_dim), which a 3D hull, minkowski or resize
 * ignores as OpenSCAD 2021.01 does (its collectChildren3D); a projection
 * is, also one without a 3D child (no_geometry), so that check_2d reads
 * its children. */
static int is_2d(const model_node *n)
{
    return build_dim(n, 0) == 2;
}

/* Whether n is a projection without a 3D child (build_projects), of which
 * OpenSCAD 2021.01 makes no geometry: its children give their own
 * warnings, but it neither mixes nor is ignored, as in the 3D walk
 * (build.c). */
static int no_geometry(const model_node *n)
{
    return n->kind == MODEL_PROJECTION && !build_projects(n);
}

/* A 2D child n: checked through the 2D engine, for its errors (and the
 * warnings of its own subtree), and left out. *mixing (when mixing is not
 * NULL and *mixing is) becomes n when n is not empty. */
static sc_status check_2d(const walk *w, const model_node *n, const model_node **mixing)
{
    int empty;
    sc_status st = build_twod_check(w->c, n, &empty);
    if (mixing && !*mixing && !empty && !no_geometry(n))
        *mixing = n;
    return st;
}

/* OpenSCAD's warnings for the 2D children of parent, a 3D operation: after
 * the children's own, as it checks dimensions once its children are
 * evaluated, first that parent mixes them, at mixing (its first 2D child
 * that is not empty, or NULL: an empty one mixes nothing for OpenSCAD
 * 2021.01's isValidDim), then each ignored (build.c's flush_ignored). */
static sc_status warn_2d(const walk *w, const model_node *parent,
                         const model_node *mixing)
{
    sc_status st = SC_OK;
    if (mixing)
        st = build_mixing(w->c, &mixing->loc, 0);
    for (const model_node *n = parent->first_child; n && st == SC_OK; n = n->next) {
        if (skipped(n) || is_shading(n->kind) || !is_2d(n) || no_geometry(n))
            continue;
        st = build_ignoring(w->c, &n->loc, 0);
    }
    return st;
}

static sc_status depth_error(const walk *w, const model_node *n)
{
    return err_set(w->c->error, SC_ERR_LIMIT, &n->loc,
                   "too many nested nodes inside %s (limit is %d)", w->owner,
                   BUILD_HULL_MAX_DEPTH);
}

static sc_status minkowski_parts(const walk *w, const model_node *n, const affine *m,
                                 int depth, partlist *out, int *not_closed,
                                 const model_node **whole);
static sc_status collect_alone(const walk *w, const model_node *n,
                               const model_node *child, const affine *m, int depth,
                               partlist *out);
static sc_status resize_matrix(const walk *w, const model_node *n, int depth, affine *out,
                               const char **warning);
static sc_status solid_parts(const walk *w, const model_node *n, const affine *m,
                             int depth, partlist *out);
static sc_status collect(const walk *w, const model_node *parent, const affine *m,
                         int depth, partlist *out);

/* The walk w's children of n take, in *sub: in a union of several solids
 * where n unites them (unmoved since), else w's. */
static void enter_union(const walk *w, const model_node *n, walk *sub)
{
    *sub = *w;
    if (build_operands(n->kind, n->first_child) > 1) {
        sub->in_union = 1;
        sub->since = &affine_unmoved;
    }
}

/* Whether the frame m flattens what it carries (a singular multmatrix
 * above, inner_frame). */
static int flattening(const affine *m)
{
    affine inverse;
    return !affine_invert(m, &inverse);
}

/* Whether w collects the corners a hull or minkowski takes, which
 * inner_frame may flatten. */
static int takes_corners(const walk *w)
{
    return !strcmp(w->owner, "hull") || !strcmp(w->owner, "minkowski");
}

/* The frame of the children of a multmatrix or resize n under m: m after
 * n's own matrix, in *inner; 0 in *ok for a singular multmatrix (the
 * subtree has no geometry), but with flat where its children are a mesh,
 * whose points OpenSCAD 2021.01 flattens (PolySet::transform; a hull takes
 * them), where a Nef polyhedron is removed with OpenSCAD's warning
 * (CGAL_Nef_polyhedron::transform). With sub, also the walk its children
 * take (enter_union; where they are not united, w's since after n's
 * matrix, kept in *since). */
static sc_status inner_frame(const walk *w, const model_node *n, const affine *m,
                             int depth, affine *inner, walk *sub, affine *since, int flat,
                             int *ok)
{
    affine local;
    const char *warning = NULL;
    *ok = 1;
    /* a resize from the box of the meshes the walk takes, OpenSCAD's in
     * both modes, not of the exact solids */
    build_ctx meshes = *w->c;
    meshes.faithful = 1;
    walk measured = *w;
    measured.c = &meshes;
    sc_status st = n->kind == MODEL_XFORM
                       ? read_matrix(w->c, n, &local, ok)
                       : resize_matrix(&measured, n, depth, &local, &warning);
    if (st == SC_OK && removed(n)) {
        /* OpenSCAD 2021.01 evaluates the children first: their warnings
         * (not its check of their dimensions: collect), then the removal;
         * a minkowski inside them empties nothing out here */
        walk sub = *w;
        int not_closed = 0;
        if (sub.not_closed)
            sub.not_closed = &not_closed;
        partlist scratch = {NULL, 0, 0};
        st = collect(&sub, n, m, depth, &scratch);
        parts_free(&scratch);
        *ok = 0;
        return st == SC_OK ? build_xform_not_finite(w->c, n) : st;
    }
    if (st == SC_OK && !*ok && n->kind == MODEL_XFORM) {
        const char *removal;
        *ok = !build_singular_removes(n, &removal) && flat;
        if (removal && !w->check)
            st = build_note(w->c, &n->loc, "%s", removal);
    }
    if (st == SC_OK && *ok) {
        *inner = affine_mul(m, &local);
        if (sub) {
            enter_union(w, n, sub);
            if (w->since && build_operands(n->kind, n->first_child) <= 1) {
                *since = affine_mul(w->since, &local);
                sub->since = since;
            }
        }
    }
    return st;
}

/* A '%' child n (nothing for any other): no operand, but walked for the
 * warnings of its subtree, as OpenSCAD 2021.01's render evaluates a
 * background child before it leaves it out; its parent says nothing of
 * it. */
static sc_status background(const walk *w, const model_node *n, const affine *m,
                            int depth)
{
    if ((n->modifiers & (MODEL_MOD_DISABLE | MODEL_MOD_BACKGROUND)) !=
            MODEL_MOD_BACKGROUND ||
        is_shading(n->kind))
        return SC_OK;
    if (is_2d(n))
        return check_2d(w, n, NULL);
    /* n alone, as the child of a view of its parent (as minkowski_parts
     * walks each child), evaluated on its own: no part of the parent's
     * union or minkowski, so a mesh in it that is not closed is not
     * taken into CGAL there (nor empties the minkowski) */
    model_node view = *n;
    model_node lone = *n;
    lone.next = NULL;
    lone.modifiers &= ~MODEL_MOD_BACKGROUND;
    view.first_child = &lone;
    view.child_count = 1;
    walk sub = *w;
    sub.in_union = 0;
    sub.not_closed = NULL;
    partlist parts = {NULL, 0, 0};
    sc_status st = collect(&sub, &view, m, depth + 1, &parts);
    parts_free(&parts);
    return st;
}

/* Appends the convex parts (or, for a hull, point sets) of the children of
 * parent, through m, to out. */
static sc_status collect(const walk *w, const model_node *parent, const affine *m,
                         int depth, partlist *out)
{
    const build_ctx *c = w->c;
    if (depth > BUILD_HULL_MAX_DEPTH)
        return depth_error(w, parent);
    int any_2d = 0;
    const model_node *mixing = NULL; /* the first 2D child that is not empty */
    for (const model_node *n = parent->first_child; n; n = n->next) {
        model_kind kind = n->kind;
        sc_status st = SC_OK;
        if (skipped(n) || is_shading(kind)) {
            if ((st = background(w, n, m, depth)) != SC_OK)
                return st;
            continue;
        }
        if (is_2d(n)) {
            st = check_2d(w, n, &mixing);
            any_2d = 1;
        } else if (is_group(kind) || (kind == MODEL_MINKOWSKI &&
                                      build_operands(n->kind, n->first_child) == 1)) {
            /* a minkowski of one solid is that solid (build.c) */
            walk sub;
            enter_union(w, n, &sub);
            st = collect(&sub, n, m, depth + 1, out);
        } else if (kind == MODEL_XFORM || kind == MODEL_RESIZE) {
            affine inner, since;
            int ok;
            walk sub;
            st = inner_frame(w, n, m, depth + 1, &inner, &sub, &since, takes_corners(w),
                             &ok);
            if (st == SC_OK && ok)
                st = collect(&sub, n, &inner, depth + 1, out);
        } else if (kind == MODEL_CUBE || kind == MODEL_SPHERE || kind == MODEL_CYLINDER) {
            shape s;
            if ((st = read_shape(c, n, &s)) == SC_OK && s.kind != SHAPE_NONE) {
                pointset *part = new_part(out);
                st = part ? shape_points(w, n, &s, m, part)
                          : err_nomem(c->error, (&n->loc));
            }
        } else if (is_mesh(kind) && w->convex && flattening(m)) {
            st = flat_mesh_part(w, n, m, out);
        } else if (kind == MODEL_POLYHEDRON || is_mesh(kind)) {
            pointset set = {NULL, 0, 0};
            double volume = 0;
            int open = 0;
            if (kind == MODEL_POLYHEDRON && !w->check)
                st = build_bad_indices(c, n);
            if (st == SC_OK && (kind == MODEL_POLYHEDRON || kind == MODEL_IMPORT))
                st = closed_check(w, n, m, &open);
            if (st == SC_OK && !open)
                st = kind == MODEL_POLYHEDRON ? polyhedron_points(w, n, m, &set, &volume)
                                              : mesh_points(w, n, m, &set, &volume);
            /* OpenSCAD sums the hull of a polyhedron it finds convex; in
             * both modes, as a polyhedron is read as OpenSCAD reads it
             * (merged points, libtess2's diagonals) in both */
            int hulled = 0;
            if (st == SC_OK && w->convex && set.count && kind == MODEL_POLYHEDRON)
                st = polyset_convex(w, n, m, &hulled);
            if (st == SC_OK && w->convex && set.count && !hulled) {
                hull3 h;
                hull3_status hs = hull3_compute(set.p, set.count, &h);
                if (hs == HULL3_NOMEM) {
                    st = err_nomem(c->error, (&n->loc));
                } else if (hs == HULL3_OK && !(fabs(hull3_volume(&h) - volume) <=
                                               1e-6 * hull3_volume(&h))) {
                    /* Not convex: its convex parts, as OpenSCAD sums it. */
                    set.count = 0;
                    st = solid_parts(w, n, m, depth + 1, out);
                }
                hull3_free(&h);
            }
            pointset *part = NULL;
            if (st == SC_OK && set.count && !(part = new_part(out)))
                st = err_nomem(c->error, (&n->loc));
            if (part) {
                *part = set;
                set.p = NULL;
            }
            free(set.p);
        } else if (kind == MODEL_HULL) {
            walk inner = {c, "hull", 0,    w->cache, w->nef, w->check,
                          0, NULL,   NULL, NULL,     NULL,   NULL};
            partlist sub = {NULL, 0, 0};
            st = collect(&inner, n, m, depth + 1, &sub);
            pointset *part = NULL;
            if (st == SC_OK && sub.count && !(part = new_part(out)))
                st = err_nomem(c->error, (&n->loc));
            for (uint32_t i = 0; part && i < sub.count && st == SC_OK; i++) {
                for (uint32_t k = 0; k < sub.items[i].count && st == SC_OK; k++) {
                    if (!add_point(part, sub.items[i].p[k]))
                        st = err_nomem(c->error, (&n->loc));
                }
            }
            parts_free(&sub);
        } else if (kind == MODEL_MINKOWSKI) {
            int emptied; /* then it adds nothing, as an empty child adds nothing */
            const model_node *whole;
            st = minkowski_parts(w, n, m, depth + 1, out, &emptied, &whole);
            if (st == SC_OK && whole) /* its first child as it is */
                st = collect_alone(w, n, whole, m, depth + 1, out);
        } else if (kind == MODEL_DIFFERENCE || kind == MODEL_INTERSECTION) {
            st = solid_parts(w, n, m, depth + 1, out);
        } else {
            st = err_set(c->error, SC_ERR_UNSUPPORTED, &n->loc,
                         "'%s' inside %s is not supported yet", n->name, w->owner);
        }
        if (st != SC_OK)
            return st;
    }
    return any_2d && !removed(parent) ? warn_2d(w, parent, mixing) : SC_OK;
}

/* Replaces each part by the vertices of its hull. A flat part keeps its
 * points, or, where sums is set (the parts are sums of two), is dropped:
 * OpenSCAD 2021.01's applyMinkowski keeps of each sum's hull only the
 * corners neither on a line nor in a plane with their neighbours, and a
 * flat hull has none. */
static sc_status reduce(const walk *w, const model_node *n, partlist *l, int sums)
{
    uint32_t kept = 0;
    for (uint32_t i = 0; i < l->count; i++) {
        hull3 h;
        hull3_status hs = hull3_compute(l->items[i].p, l->items[i].count, &h);
        if (hs == HULL3_NOMEM)
            return err_nomem((w->c)->error, (&n->loc));
        if (hs == HULL3_RANGE)
            return err_set(w->c->error, SC_ERR_LIMIT, &n->loc,
                           "%s: too many points or a coordinate too large", w->owner);
        if (hs == HULL3_OK) {
            free(l->items[i].p);
            l->items[i].p = h.vertices;
            l->items[i].count = l->items[i].cap = h.vertex_count;
            h.vertices = NULL;
            hull3_free(&h);
        } else if (sums) {
            free(l->items[i].p);
            continue;
        }
        l->items[kept++] = l->items[i];
    }
    l->count = kept;
    return SC_OK;
}

/* What collect takes of child, a child of n, alone (through m). */
static sc_status collect_alone(const walk *w, const model_node *n,
                               const model_node *child, const affine *m, int depth,
                               partlist *out)
{
    /* collect walks the children of its argument: a one-child view of n */
    model_node view = *n;
    model_node lone = *child;
    lone.next = NULL;
    view.first_child = &lone;
    view.child_count = 1;
    return collect(w, &view, m, depth, out);
}

/* OpenSCAD 2021.01's minkowski falls back to CGAL's Nef minkowski_sum_3
 * when its own sum throws, and that sum decomposes both operands as the
 * first did; where CGAL's convex decomposition of an operand fails, it
 * keeps the sum so far ("CGAL error in CGALUtils::applyBinaryOperator
 * UNKNOWN"): the first child as it is when the decomposition of the first
 * or second fails, else the sum of the children before the one that
 * failed. The warning for failure f (an error with --strict, where the
 * walk keeps it). */
static sc_status decompose_warning(const walk *w, const decompose_failure *f,
                                   int first_alone)
{
    return build_note(w->c, &f->loc,
                      "minkowski: CGAL failed on '%s': %s; the result is %s, as "
                      "OpenSCAD keeps it (\"CGAL error in "
                      "CGALUtils::applyBinaryOperator UNKNOWN\")",
                      f->name, f->why,
                      first_alone ? "its first child alone"
                                  : "the sum of the children before it");
}

static int nef_result(const model_node *n, int depth);

/* Whether OpenSCAD 2021.01 holds the geometry of child, a minkowski's
 * child, as a mesh (PolySet): a leaf, hull or minkowski, or a group,
 * transform or boolean of one such solid; not a union or boolean of
 * several (a Nef polyhedron). */
static int polyset_operand(const model_node *child)
{
    model_kind kind = child->kind;
    if (is_group(kind) || kind == MODEL_XFORM || kind == MODEL_RESIZE ||
        kind == MODEL_DIFFERENCE || kind == MODEL_INTERSECTION)
        return !nef_result(child, 0);
    return 1;
}

/* The parts of minkowski node n (through m) appended to out; none, with
 * *not_closed set, when a mesh among its children is not closed
 * (closed_check). Where CGAL's convex decomposition of the first child
 * fails (decompose_warning), *whole is that child, for the caller to take
 * as it is, and out gets nothing. */
static sc_status minkowski_parts(const walk *w, const model_node *n, const affine *m,
                                 int depth, partlist *out, int *not_closed,
                                 const model_node **whole)
{
    *not_closed = 0;
    *whole = NULL;
    decompose_failure failure = {NULL, {NULL, 0, 0}, ""};
    walk inner = {w->c,
                  "minkowski",
                  1,
                  w->cache,
                  w->nef,
                  w->check,
                  0,
                  not_closed,
                  NULL,
                  NULL,
                  w->c->strict ? NULL : &failure,
                  NULL};
    partlist acc = {NULL, 0, 0};
    sc_status st = SC_OK;
    int first = 1, second = 0, summed = 0;
    if (depth > BUILD_HULL_MAX_DEPTH)
        return depth_error(w, n);
    /* The sum is made in n's own frame, as OpenSCAD makes it, and carried
     * through m at the end: there (faithful) each mesh operand is put on
     * OpenSCAD's grid (build_mesh_grid_align), the sum so far too when it is one part
     * and another child follows, as OpenSCAD's next step takes it as a
     * mesh. The parts of an operand OpenSCAD decomposes, or holds as a Nef
     * polyhedron, are not moved. */
    affine local = affine_identity();
    for (const model_node *child = n->first_child; child && st == SC_OK;
         child = child->next) {
        if (skipped(child)) {
            st = background(&inner, child, m, depth);
            continue;
        }
        partlist parts = {NULL, 0, 0};
        st = collect_alone(&inner, n, child, &local, depth + 1, &parts);
        if (st == SC_OK && w->c->faithful && parts.count == 1 && polyset_operand(child))
            st = build_mesh_grid_align(w->c, &n->loc, parts.items[0].p,
                                       parts.items[0].count);
        if (st == SC_OK)
            st = reduce(&inner, n, &parts, 0);
        if (st != SC_OK && failure.name) { /* the sum so far, as OpenSCAD's */
            parts_free(&parts);
            err_clear(w->c->error);
            st = decompose_warning(&inner, &failure, first || second);
            if (first)
                *whole = child;
            break;
        }
        if (st != SC_OK || parts.count == 0) {
            parts_free(&parts);
            continue;
        }
        if (first) {
            acc = parts;
            first = 0;
            second = 1;
            continue;
        }
        second = 0;
        if (summed && w->c->faithful && acc.count == 1 &&
            (st = build_mesh_grid_align(w->c, &n->loc, acc.items[0].p,
                                        acc.items[0].count)) != SC_OK) {
            parts_free(&parts);
            break;
        }
        summed = 1;
        /* acc ⊕ parts, part by part */
        uint64_t combos = (uint64_t)acc.count * parts.count;
        if (combos > BUILD_MINKOWSKI_MAX_PARTS) {
            st = err_set(w->c->error, SC_ERR_LIMIT, &n->loc,
                         "minkowski has too many convex parts (limit is %d)",
                         BUILD_MINKOWSKI_MAX_PARTS);
        }
        partlist next = {NULL, 0, 0};
        for (uint32_t i = 0; i < acc.count && st == SC_OK; i++) {
            for (uint32_t j = 0; j < parts.count && st == SC_OK; j++) {
                const pointset *a = &acc.items[i], *b = &parts.items[j];
                if ((uint64_t)a->count * b->count > HULL3_MAX_POINTS) {
                    st = err_set(w->c->error, SC_ERR_LIMIT, &n->loc,
                                 "minkowski: too many points (limit is %u)",
                                 HULL3_MAX_POINTS);
                    break;
                }
                pointset *s = new_part(&next);
                if (!s) {
                    st = err_nomem((w->c)->error, (&n->loc));
                    break;
                }
                for (uint32_t k = 0; k < a->count && st == SC_OK; k++) {
                    for (uint32_t l = 0; l < b->count; l++) {
                        if (!add_point(s, v3_add(a->p[k], b->p[l]))) {
                            st = err_nomem((w->c)->error, (&n->loc));
                            break;
                        }
                    }
                }
            }
        }
        parts_free(&parts);
        parts_free(&acc);
        acc = next;
        if (st == SC_OK)
            st = reduce(&inner, n, &acc, 1);
    }
    if (*not_closed)
        parts_free(&acc);
    for (uint32_t i = 0; i < acc.count && st == SC_OK; i++) {
        pointset *s = new_part(out);
        if (!s) {
            st = err_nomem((w->c)->error, (&n->loc));
            break;
        }
        *s = acc.items[i];
        acc.items[i].p = NULL;
        for (uint32_t k = 0; k < s->count; k++)
            s->p[k] = affine_point(m, s->p[k]);
    }
    parts_free(&acc);
    return st;
}

/* ---- booleans: CGAL's Nef polyhedra, through the plugin (nef.h) ---- */

/* The plugin, opened on the first boolean of the build. */
static sc_status nef_ready(const walk *w, const model_node *n)
{
    if (w->nef->handle)
        return SC_OK;
    char why[600];
    if (!nef_plugin_open(w->nef, why, sizeof why))
        return err_set(w->c->error, SC_ERR_UNSUPPORTED, &n->loc, "%s: %s", w->owner, why);
    return SC_OK;
}

/* A failure of the plugin as an error at n. */
static sc_status nef_error(const walk *w, const model_node *n, nef_status ns,
                           const char *why)
{
    if (ns == NEF_NOMEM)
        return err_nomem(w->c->error, &n->loc);
    if (ns == NEF_BAD_MESH)
        return err_set(w->c->error, SC_ERR_SEMANTIC, &n->loc,
                       "%s: '%s' is not a solid: %s", w->owner, n->name, why);
    return err_set(w->c->error, SC_ERR_SEMANTIC, &n->loc, "%s: CGAL failed on '%s': %s",
                   w->owner, n->name, why);
}

/* Point k of xyz (x, y, z triples) set to p. */
static void put_xyz(double *xyz, size_t k, vec3 p)
{
    xyz[3 * k] = p.x;
    xyz[3 * k + 1] = p.y;
    xyz[3 * k + 2] = p.z;
}

/* What the plugin made of n (ns, why) into *out: an error at n where it
 * failed, NULL for the empty solid. */
static sc_status nef_made(const walk *w, const model_node *n, nef_status ns,
                          const char *why, nef_solid **out)
{
    if (ns != NEF_OK)
        return nef_error(w, n, ns, why);
    if (w->nef->is_empty(*out)) {
        w->nef->release(*out);
        *out = NULL;
    }
    return SC_OK;
}

/* The Nef polyhedron of the closed mesh f through m (its faces as nef.h's
 * from_mesh takes them); *out NULL when it has no volume. */
static sc_status nef_mesh(const walk *w, const model_node *n, const affine *m,
                          const build_mesh_faces *f, nef_solid **out)
{
    *out = NULL;
    sc_status st = nef_ready(w, n);
    if (st != SC_OK)
        return st;
    double *xyz = malloc(((size_t)f->point_count * 3 + 1) * sizeof *xyz);
    if (!xyz)
        return err_nomem(w->c->error, &n->loc);
    for (uint32_t i = 0; i < f->point_count; i++)
        put_xyz(xyz, i, affine_point(m, f->points[i]));
    char why[512] = "";
    /* a polyhedron's faces reach CGAL as OpenSCAD's builder turns them,
     * before the rest of m moves its Nef polyhedron (nef.h) */
    int written = n->kind != MODEL_POLYHEDRON ? 0 : affine_det(m) < 0 ? 2 : 1;
    nef_status ns =
        w->nef->from_mesh(xyz, f->point_count, f->indices, f->face_start, f->face_loops,
                          f->face_count, written, out, why, sizeof why);
    free(xyz);
    return nef_made(w, n, ns, why, out);
}

/* Moves count points p of a mesh a CGAL operation takes, given in n's
 * frame, where OpenSCAD 2021.01 holds them as that operation takes the
 * mesh: through the transforms since the operation (build_mesh_since),
 * onto its grid of 2^-20 (build_mesh_grid_align: createPolyhedronFromPolySet
 * aligns every mesh it makes a Nef polyhedron of), and on through the rest
 * to the walk's frame (m in all). In both modes: this path is OpenSCAD's
 * evaluation, and a projection of it is the same in both. Where the
 * transforms cannot be undone (a flat mesh) the points are only moved. */
static sc_status cgal_points(const walk *w, const model_node *n, const affine *m, vec3 *p,
                             uint32_t count)
{
    affine rest;
    const affine *at = build_mesh_since(w->since, m, &rest);
    for (uint32_t i = 0; i < count; i++)
        p[i] = affine_point(at ? at : m, p[i]);
    if (!at)
        return SC_OK;
    sc_status st = build_mesh_grid_align(w->c, &n->loc, p, count);
    for (uint32_t i = 0; i < count; i++)
        p[i] = affine_point(&rest, p[i]);
    return st;
}

/* The solid of a convex point set (the hull of the points); NULL when it
 * is flat. m: the points are n's mesh in n's frame, its hull's corners
 * put where CGAL takes them (cgal_points) through m; NULL: they are where
 * they go. */
static sc_status nef_convex(const walk *w, const model_node *n, const affine *m,
                            const pointset *s, nef_solid **out)
{
    *out = NULL;
    hull3 h;
    hull3_status hs = hull3_compute(s->p, s->count, &h);
    if (hs == HULL3_NOMEM)
        return err_nomem(w->c->error, &n->loc);
    if (hs == HULL3_RANGE)
        return err_set(w->c->error, SC_ERR_LIMIT, &n->loc,
                       "%s: too many points or a coordinate too large", w->owner);
    if (hs == HULL3_FLAT)
        return SC_OK;
    uint32_t *start = malloc(((size_t)h.tri_count + 1) * sizeof *start);
    if (!start) {
        hull3_free(&h);
        return err_nomem(w->c->error, &n->loc);
    }
    for (uint32_t t = 0; t <= h.tri_count; t++)
        start[t] = 3 * t;
    sc_status st = m ? cgal_points(w, n, m, h.vertices, h.vertex_count) : SC_OK;
    affine id = affine_identity();
    build_mesh_faces f = {.points = h.vertices,
                          .point_count = h.vertex_count,
                          .indices = h.tris,
                          .face_start = start,
                          .face_count = h.tri_count};
    if (st == SC_OK)
        st = nef_mesh(w, n, &id, &f, out);
    free(start);
    hull3_free(&h);
    return st;
}

/* The solid of a polyhedron's faces f (as written, on the grid) through m
 * where OpenSCAD 2021.01 finds them convex (build_mesh_convex_for_cgal):
 * the convex hull of every face's corners, each face read back to front as
 * OpenSCAD reads it (nef.h's hull); none where they lie in one plane. */
static sc_status nef_hull_faces(const walk *w, const model_node *n, const affine *m,
                                const build_mesh_faces *f, nef_solid **out)
{
    *out = NULL;
    uint32_t count = f->face_start[f->face_count];
    double *xyz = malloc(((size_t)count * 3 + 1) * sizeof *xyz);
    if (!xyz)
        return err_nomem(w->c->error, &n->loc);
    uint32_t k = 0;
    for (uint32_t face = 0; face < f->face_count; face++)
        for (uint32_t i = f->face_start[face + 1]; i-- > f->face_start[face]; k++) {
            put_xyz(xyz, k, affine_point(m, f->points[f->indices[i]]));
        }
    char why[512] = "";
    nef_status ns = w->nef->hull(xyz, count, out, why, sizeof why);
    free(xyz);
    return nef_made(w, n, ns, why, out);
}

/* The solid of a mesh leaf's triangles through m: for a leaf whose faces
 * are its triangles (an AMF or 3MF object). */
static sc_status nef_leaf_mesh(const walk *w, const model_node *n, const affine *m,
                               const prim_mesh *mesh, nef_solid **out)
{
    uint32_t count = mesh->tri_count;
    uint32_t *index = malloc((size_t)count * 3 * sizeof *index);
    uint32_t *start = malloc(((size_t)count + 1) * sizeof *start);
    sc_status st;
    if (index && start) {
        for (uint32_t i = 0; i < 3 * count; i++)
            index[i] = i;
        for (uint32_t t = 0; t <= count; t++)
            start[t] = 3 * t;
        build_mesh_faces f = {.points = (vec3 *)mesh->v,
                              .point_count = 3 * count,
                              .indices = index,
                              .face_start = start,
                              .face_count = count};
        st = nef_mesh(w, n, m, &f, out);
    } else {
        st = err_nomem(w->c->error, &n->loc);
    }
    free(index);
    free(start);
    return st;
}

/* *acc = *acc op s, releasing s; NULL stands for the empty solid. Where
 * gave_up is not NULL, a boolean CGAL fails on (one of its assertions) is
 * taken as OpenSCAD 2021.01 takes it, without --strict: its error as a
 * warning at s's node, and *gave_up set. OpenSCAD's union
 * (CGALUtils::applyUnion3D) is then empty; its difference or intersection
 * (applyOperator3D) keeps the result before that operand (CGAL's failed
 * boolean leaves it as it was) and takes no later one. */
static sc_status nef_combine_lenient(const walk *w, const model_node *n, nef_solid **acc,
                                     nef_op op, nef_solid *s, int *gave_up)
{
    if (op == NEF_UNION && !*acc) {
        *acc = s;
        return SC_OK;
    }
    if (!s || !*acc) {
        if (op == NEF_INTERSECTION && *acc) {
            w->nef->release(*acc);
            *acc = NULL;
        }
        if (s)
            w->nef->release(s);
        return SC_OK;
    }
    /* Each Nef operation runs to its end once started; between them a
     * cancelled call stops. */
    if (cancel_poll()) {
        w->nef->release(s);
        return err_set(w->c->error, SC_ERR_CANCELLED, &n->loc, "%s: cancelled", w->owner);
    }
    char why[512] = "";
    nef_status ns = w->nef->apply(*acc, op, s, why, sizeof why);
    w->nef->release(s);
    if (ns == NEF_FAILED && gave_up && !w->c->strict) {
        *gave_up = 1;
        if (op == NEF_UNION) {
            w->nef->release(*acc);
            *acc = NULL;
            return build_note(
                w->c, &n->loc,
                "%s: CGAL failed on '%s': %s; the union is empty, as OpenSCAD "
                "leaves it (\"CGAL error in CGALUtils::applyUnion3D\")",
                w->owner, n->name, why);
        }
        const char *name = op == NEF_DIFFERENCE ? "difference" : "intersection";
        return build_note(w->c, &n->loc,
                          "%s: CGAL failed on '%s': %s; the %s is what it was before it, "
                          "as OpenSCAD keeps it (\"CGAL error in "
                          "CGALUtils::applyBinaryOperator %s\")",
                          w->owner, n->name, why, name, name);
    }
    if (ns != NEF_OK)
        return nef_error(w, n, ns, why);
    if (w->nef->is_empty(*acc)) {
        w->nef->release(*acc);
        *acc = NULL;
    }
    return SC_OK;
}

static sc_status nef_combine(const walk *w, const model_node *n, nef_solid **acc,
                             nef_op op, nef_solid *s)
{
    return nef_combine_lenient(w, n, acc, op, s, NULL);
}

static sc_status nef_node(const walk *w, const model_node *n, const affine *m, int depth,
                          nef_solid **out);

/* The faces of import, linear_extrude, rotate_extrude and surface that
 * CGAL takes, with the warnings and the empty case (*empty) of their leaf
 * (an import's points where moved takes them, or NULL).
 * The leaves' meshes fan each face, and each contour of a cap, about a
 * point: those fans overlap (a hole over its outline, the fan of a concave
 * outline over itself) or have triangles without area (along a straight
 * side), which a leaf's winding rule fills right but which make a Nef
 * polyhedron that is not valid, on which a later boolean crashed inside
 * CGAL. So CGAL gets the faces themselves: a linear_extrude's as
 * OpenSCAD's PolySet reaches CGAL, caps triangulated as OpenSCAD
 * triangulates them; the others with each cap one face with holes.
 * Extrusions are built as in --faithful, in both modes, as OpenSCAD's
 * polygons. */
static sc_status mesh_faces(const walk *w, const model_node *n, const affine *moved,
                            build_mesh_faces *faces, const char **empty)
{
    memset(faces, 0, sizeof *faces);
    build_ctx fc = *w->c;
    fc.faithful = 1;
    switch (n->kind) {
    case MODEL_IMPORT: {
        if (n->pending)
            return build_pending(w->c, n);
        build_ctx ic = *w->c;
        ic.moved = moved;
        return build_import_faces(&ic, n->u.import, empty, faces);
    }
    case MODEL_SURFACE:
        return n->pending ? build_pending(w->c, n)
                          : build_surface_faces(w->c, n->u.surface, faces, empty);
    case MODEL_ROTATE_EXTRUDE:
        return build_rotate_extrude_faces(w->c, n, faces, empty);
    default: {
        /* caps as OpenSCAD triangulates them, where CGAL takes them */
        sc_status st = w->check ? SC_OK : nef_ready(w, n);
        return st != SC_OK ? st
                           : build_linear_extrude_faces(&fc, n, faces, empty,
                                                        w->check ? NULL : w->nef);
    }
    }
}

/* The solid of the children of parent through m, combined by op: their
 * union, or for difference and intersection the first child minus, or
 * intersected with, each of the others. */
static sc_status nef_children(const walk *w, const model_node *parent, const affine *m,
                              int depth, nef_op op, nef_solid **out)
{
    *out = NULL;
    if (depth > BUILD_HULL_MAX_DEPTH)
        return depth_error(w, parent);
    int first = 1, gave_up = 0;
    const model_node *mixing = NULL; /* the first 2D child that is not empty */
    size_t mark = w->c->nefs ? build_nef_cache_mark(w->c->nefs) : 0;
    walk operands = *w; /* a boolean of several: OpenSCAD's Nef polyhedra */
    if (build_operands(parent->kind, parent->first_child) > 1)
        operands.since = &affine_unmoved;
    w = &operands;
    for (const model_node *n = parent->first_child; n; n = n->next) {
        if (skipped(n) || is_shading(n->kind)) {
            sc_status st = background(w, n, m, depth);
            if (st != SC_OK) {
                if (*out)
                    w->nef->release(*out);
                *out = NULL;
                return st;
            }
            continue;
        }
        nef_solid *s = NULL; /* a 2D child: the empty solid, as OpenSCAD ignores it */
        sc_status st = is_2d(n) ? check_2d(w, n, &mixing) : nef_node(w, n, m, depth, &s);
        if (parent == w->top && w->state) {
            if (first)
                w->state->first_empty = !s;
            else
                w->state->later_empty |= !s;
        }
        if (st == SC_OK && gave_up) /* OpenSCAD takes no later operand */
            w->nef->release(s);
        else if (st == SC_OK)
            st = nef_combine_lenient(w, n, out, first ? NEF_UNION : op, s, &gave_up);
        first = 0;
        if (st != SC_OK) {
            if (*out)
                w->nef->release(*out);
            *out = NULL;
            return st;
        }
    }
    sc_status st = warn_2d(w, parent, mixing);
    if (w->c->nefs) /* the parent has all its children */
        build_nef_cache_publish(w->c->nefs, mark);
    if (st != SC_OK && *out) {
        w->nef->release(*out);
        *out = NULL;
    }
    return st;
}

/* *out = a copy of solid (NULL: empty) through m, as OpenSCAD transforms
 * a Nef polyhedron (CGAL_Nef_polyhedron::transform); NULL when empty. */
static sc_status nef_moved(const walk *w, const model_node *n, const nef_solid *solid,
                           const affine *m, nef_solid **out)
{
    *out = NULL;
    if (!solid)
        return SC_OK;
    char why[512] = "";
    nef_status ns = w->nef->copy(solid, out, why, sizeof why);
    affine id = affine_identity();
    if (ns == NEF_OK && memcmp(m, &id, sizeof id) != 0)
        ns = w->nef->transform(*out, &m->m[0][0], why, sizeof why);
    if (ns != NEF_OK) {
        if (*out)
            w->nef->release(*out);
        *out = NULL;
        return nef_error(w, n, ns, why);
    }
    if (w->nef->is_empty(*out)) {
        w->nef->release(*out);
        *out = NULL;
    }
    return SC_OK;
}

/* The solid of difference or intersection n through m, evaluated in n's
 * own frame once per build (build_nef_cache.h), then carried by m, in
 * OpenSCAD's order: the boolean's Nef polyhedron first, then the
 * transforms above it. A subtree the cache does not key is evaluated
 * through m, as everywhere else. Without keep, a solid evaluated here is
 * not kept (a projection's own child). */
static sc_status nef_cached(const walk *w, const model_node *n, const affine *m,
                            int depth, nef_op op, int keep, nef_solid **out)
{
    build_nef_cache *cache = w->c->nefs;
    uint64_t hash;
    if (!build_nef_cache_key(n, &hash))
        return nef_children(w, n, m, depth, op, out);
    const nef_solid *found;
    if (build_nef_cache_find(cache, n, hash, &found))
        return nef_moved(w, n, found, m, out);
    nef_solid *solid = NULL;
    affine id = affine_identity();
    sc_status st = nef_children(w, n, &id, depth, op, &solid);
    if (st == SC_OK)
        st = nef_moved(w, n, solid, m, out);
    if (st != SC_OK) {
        if (solid)
            w->nef->release(solid);
        return st;
    }
    if (!build_nef_cache_put(cache, n, hash, solid, keep, w->nef)) {
        if (*out)
            w->nef->release(*out);
        *out = NULL;
        return err_nomem(w->c->error, &n->loc);
    }
    return SC_OK;
}

/* The solid of node n through m, as OpenSCAD evaluates a child of a hull
 * or minkowski to a Nef polyhedron; *out NULL for the empty solid. With
 * w->check, the subtree is only checked and *out stays NULL. */
static sc_status nef_node(const walk *w, const model_node *n, const affine *m, int depth,
                          nef_solid **out)
{
    const build_ctx *c = w->c;
    *out = NULL;
    if (depth > BUILD_HULL_MAX_DEPTH)
        return depth_error(w, n);
    model_kind kind = n->kind;
    sc_status st = SC_OK;
    if (is_2d(n))
        return check_2d(w, n, NULL); /* the empty solid, as OpenSCAD ignores it */
    if (is_group(kind))
        return nef_children(w, n, m, depth + 1, NEF_UNION, out);
    if ((kind == MODEL_DIFFERENCE || kind == MODEL_INTERSECTION) && c->nefs && !w->check)
        return nef_cached(w, n, m, depth + 1,
                          kind == MODEL_DIFFERENCE ? NEF_DIFFERENCE : NEF_INTERSECTION, 1,
                          out);
    if (kind == MODEL_DIFFERENCE)
        return nef_children(w, n, m, depth + 1, NEF_DIFFERENCE, out);
    if (kind == MODEL_INTERSECTION)
        return nef_children(w, n, m, depth + 1, NEF_INTERSECTION, out);
    if (kind == MODEL_XFORM || kind == MODEL_RESIZE) {
        affine inner, since;
        int ok;
        walk sub;
        st = inner_frame(w, n, m, depth + 1, &inner, &sub, &since, 0, &ok);
        if (st != SC_OK || !ok)
            return st;
        sub.in_union = w->in_union; /* nef_children unites them */
        return nef_children(&sub, n, &inner, depth + 1, NEF_UNION, out);
    }
    /* CGAL takes every mesh here, so one that is not closed is left out
     * as from a union (closed_check) */
    walk cgal = *w;
    cgal.in_union = 1;
    int open = 0;
    if (kind == MODEL_POLYHEDRON && !w->check && (st = build_bad_indices(c, n)) != SC_OK)
        return st;
    if (kind == MODEL_POLYHEDRON || (kind == MODEL_IMPORT && !n->pending)) {
        if ((st = closed_check(&cgal, n, m, &open)) != SC_OK || open)
            return st;
    }
    if (kind == MODEL_POLYHEDRON) {
        if (n->pending)
            return build_pending(c, n);
        uint32_t np = n->u.polyhedron.point_count;
        if (w->check || !np || !n->u.polyhedron.face_count)
            return SC_OK;
        /* its points merged as OpenSCAD merges them before CGAL sees them,
         * as for the leaf (build_mesh_merge), where they have moved to */
        build_mesh_faces f;
        affine rest;
        build_ctx snapped = *c; /* on the grid in both modes (cgal_points) */
        snapped.faithful = 1;
        snapped.drawn_as_is = 0;
        st = build_mesh_merge_moved(&snapped, &n->loc, 1, moved_since(w, m, &rest),
                                    n->u.polyhedron.points, np, n->u.polyhedron.indices,
                                    n->u.polyhedron.face_start,
                                    n->u.polyhedron.face_count, &f);
        int convex = st == SC_OK ? build_mesh_convex_for_cgal(&f, 1) : 0;
        if (convex < 0)
            st = err_nomem(c->error, &n->loc);
        else if (convex)
            st = nef_hull_faces(w, n, &rest, &f, out);
        if (st == SC_OK && !convex)
            st = build_mesh_cgal_faces(c, &n->loc, "polyhedron", &f, 1);
        if (st == SC_OK && !convex && f.face_count)
            st = nef_mesh(w, n, &rest, &f, out);
        build_mesh_faces_free(&f);
        return st;
    }
    if (kind == MODEL_IMPORT && !n->pending &&
        (n->u.import->format == MODEL_MESH_AMF ||
         n->u.import->format == MODEL_MESH_3MF)) {
        /* an AMF or 3MF file's objects, united as OpenSCAD unites them
         * (their faces are triangles, so the leaves' fans are the faces),
         * an open one left out as OpenSCAD leaves it out; an STL or OFF
         * file's faces, which need not be convex, go through mesh_faces
         * below */
        build_prims parts = {NULL, 0, 0};
        const char *empty = NULL;
        *out = NULL;
        build_ctx moved = *c; /* its points where they have moved to */
        affine rest;
        moved.moved = moved_since(w, m, &rest);
        st = build_import_solids(&moved, n->u.import, &parts, &empty);
        for (uint32_t i = 0; st == SC_OK && !w->check && i < parts.count; i++) {
            nef_solid *s = NULL;
            st = nef_leaf_mesh(w, n, &rest, parts.items[i].u.mesh.mesh, &s);
            if (st == SC_OK)
                st = nef_combine(w, n, out, NEF_UNION, s);
        }
        free(parts.items);
        return st;
    }
    if ((kind == MODEL_LINEAR_EXTRUDE || kind == MODEL_ROTATE_EXTRUDE) && !w->check) {
        /* CGAL's builder takes OpenSCAD's mesh of an extrusion, or not (a
         * pinched profile): then it is left out, with the warning, as from
         * a union (mesh_prim's check); the faces below are taken unchecked */
        prim p;
        const char *left_out = NULL;
        if ((st = mesh_prim(&cgal, n, &p, &left_out)) != SC_OK ||
            (left_out && !left_out[0]))
            return st;
    }
    if (is_mesh(kind)) {
        build_mesh_faces faces;
        const char *empty = NULL;
        affine rest = *m; /* an import's points where they have moved to */
        const affine *moved = kind == MODEL_IMPORT ? moved_since(w, m, &rest) : NULL;
        st = mesh_faces(w, n, moved, &faces, &empty);
        /* an STL or OFF file's faces, less those CGAL's builder skips, as
         * for a polyhedron */
        if (st == SC_OK && !empty && kind == MODEL_IMPORT && !w->check)
            st = build_mesh_cgal_faces(c, &n->u.import->file_loc, "imported mesh", &faces,
                                       0);
        if (st == SC_OK && !empty && faces.face_count && !w->check &&
            kind != MODEL_IMPORT) { /* an extrusion's or surface's, on the grid */
            vec3 *p = malloc(((size_t)faces.point_count + 1) * sizeof *p);
            build_mesh_faces on = faces;
            affine id = affine_identity();
            st = p ? SC_OK : err_nomem(c->error, &n->loc);
            if (st == SC_OK) {
                memcpy(p, faces.points, (size_t)faces.point_count * sizeof *p);
                on.points = p;
                st = cgal_points(w, n, m, p, faces.point_count);
            }
            if (st == SC_OK)
                st = nef_mesh(w, n, &id, &on, out);
            free(p);
        } else if (st == SC_OK && !empty && faces.face_count && !w->check) {
            st = nef_mesh(w, n, &rest, &faces, out);
        }
        build_mesh_faces_free(&faces);
        return st;
    }
    /* The convex ones: a shape, a hull, each part of a minkowski. A shape
     * and a hull are OpenSCAD's meshes, in their own frame (own) and put
     * on the grid where they have moved to (nef_convex); a minkowski's
     * parts come through m. */
    partlist parts = {NULL, 0, 0};
    affine own = affine_identity();
    int on_grid = kind != MODEL_MINKOWSKI;
    if (kind == MODEL_CUBE || kind == MODEL_SPHERE || kind == MODEL_CYLINDER) {
        shape s;
        if ((st = read_shape(c, n, &s)) == SC_OK && s.kind != SHAPE_NONE) {
            pointset *part = new_part(&parts);
            st = part ? shape_points(w, n, &s, &own, part) : err_nomem(c->error, &n->loc);
        }
    } else if (kind == MODEL_HULL) {
        walk inner = {c, "hull", 0,    w->cache, w->nef, w->check,
                      0, NULL,   NULL, NULL,     NULL,   NULL};
        partlist sub = {NULL, 0, 0};
        st = collect(&inner, n, &own, depth + 1, &sub);
        pointset *part = NULL;
        if (st == SC_OK && sub.count && !(part = new_part(&parts)))
            st = err_nomem(c->error, &n->loc);
        for (uint32_t i = 0; part && i < sub.count && st == SC_OK; i++) {
            for (uint32_t k = 0; k < sub.items[i].count && st == SC_OK; k++) {
                if (!add_point(part, sub.items[i].p[k]))
                    st = err_nomem(c->error, &n->loc);
            }
        }
        parts_free(&sub);
    } else if (kind == MODEL_MINKOWSKI) {
        int emptied; /* then nothing, as closed_check said */
        const model_node *whole;
        st = minkowski_parts(w, n, m, depth + 1, &parts, &emptied, &whole);
        if (st == SC_OK && whole) /* its first child as it is */
            st = nef_node(w, whole, m, depth + 1, out);
    } else {
        st = err_set(c->error, SC_ERR_UNSUPPORTED, &n->loc,
                     "'%s' inside %s is not supported yet", n->name, w->owner);
    }
    for (uint32_t i = 0; i < parts.count && st == SC_OK && !w->check; i++) {
        nef_solid *s = NULL;
        if ((st = nef_convex(w, n, on_grid ? m : NULL, &parts.items[i], &s)) == SC_OK)
            st = nef_combine(w, n, out, NEF_UNION, s);
    }
    parts_free(&parts);
    if (st != SC_OK && *out) {
        w->nef->release(*out);
        *out = NULL;
    }
    return st;
}

/* Makes every solid the cache recorded found: called where a hull's,
 * minkowski's or projection's walk ends, when every node below has all
 * its children. */
static void nef_publish(const build_ctx *c)
{
    if (c->nefs)
        build_nef_cache_publish(c->nefs, 0);
}

/* Appends to out what a hull or minkowski takes of node n (a boolean, or a
 * polyhedron or mesh that is not convex) through m: for a hull the
 * vertices of its solid, as one part; for a minkowski the vertices of each
 * part of CGAL's convex decomposition of it. */
static sc_status solid_parts(const walk *w, const model_node *n, const affine *m,
                             int depth, partlist *out)
{
    nef_solid *solid = NULL;
    sc_status st = w->check ? SC_OK : nef_ready(w, n);
    if (st == SC_OK)
        st = nef_node(w, n, m, depth, &solid);
    if (st != SC_OK || !solid)
        return st;
    nef_parts got = {NULL, NULL, 0};
    char why[512] = "";
    nef_status ns = w->convex ? w->nef->convex_parts(solid, &got, why, sizeof why)
                              : w->nef->vertices(solid, &got, why, sizeof why);
    w->nef->release(solid);
    if (ns == NEF_FAILED && w->convex && w->failure && !w->failure->name) {
        w->failure->name = n->name; /* for the minkowski to fall back on */
        w->failure->loc = n->loc;
        snprintf(w->failure->why, sizeof w->failure->why, "%s", why);
    }
    if (ns != NEF_OK)
        return nef_error(w, n, ns, why);
    for (uint32_t k = 0; k < got.count && st == SC_OK; k++) {
        pointset *part = new_part(out);
        if (!part) {
            st = err_nomem(w->c->error, &n->loc);
            break;
        }
        for (uint32_t i = got.start[k]; i < got.start[k + 1] && st == SC_OK; i++) {
            vec3 p = v3(got.points[3 * i], got.points[3 * i + 1], got.points[3 * i + 2]);
            if (!add_point(part, p))
                st = err_nomem(w->c->error, &n->loc);
        }
    }
    free(got.points);
    free(got.start);
    return st;
}

/* The end of build_nef_triangles and build_nef_section: what the plugin
 * gave back freed, the solid released, the plugin closed. */
static void nef_done(nef_plugin *nef, nef_solid *solid, nef_parts *got)
{
    free(got->points);
    free(got->start);
    if (solid)
        nef->release(solid);
    nef_plugin_close(nef);
}

sc_status build_nef_triangles(const build_ctx *c, const model_node *n, const char *owner,
                              build_resize_cache **cache, int own, vec3 **tris,
                              uint32_t *tri_count)
{
    *tris = NULL;
    *tri_count = 0;
    nef_plugin nef = {0};
    walk w = {c, owner, 0, cache, &nef, 0, 0, NULL, NULL, NULL, NULL, NULL};
    nef_solid *solid = NULL;
    affine id = affine_identity();
    sc_status st = nef_ready(&w, n);
    int boolean = n->kind == MODEL_DIFFERENCE || n->kind == MODEL_INTERSECTION;
    if (st == SC_OK && own && boolean && c->nefs)
        st = nef_cached(&w, n, &id, 1,
                        n->kind == MODEL_DIFFERENCE ? NEF_DIFFERENCE : NEF_INTERSECTION,
                        0, &solid);
    else if (st == SC_OK)
        st = nef_node(&w, n, &id, 0, &solid);
    nef_publish(c);
    build_imports_done(c, n);
    nef_parts got = {NULL, NULL, 0};
    if (st == SC_OK && solid) {
        char why[512] = "";
        nef_status ns = nef.triangles(solid, &got, why, sizeof why);
        if (ns != NEF_OK) {
            st = nef_error(&w, n, ns, why);
        } else if (got.count == 1 && got.start[1] >= 3) {
            uint32_t count = got.start[1] / 3;
            vec3 *v = malloc((size_t)count * 3 * sizeof *v);
            if (!v) {
                st = err_nomem(c->error, &n->loc);
            } else {
                for (uint32_t i = 0; i < 3 * count; i++)
                    v[i] = v3(got.points[3 * i], got.points[3 * i + 1],
                              got.points[3 * i + 2]);
                *tris = v;
                *tri_count = count;
            }
        }
    }
    nef_done(&nef, solid, &got);
    return st;
}

sc_status build_nef_section(const build_ctx *c, const model_node *n,
                            build_resize_cache **cache, twod_region *out, int *missed)
{
    *missed = 0;
    build_ctx quiet = *c; /* the projection's walk gave the warnings */
    quiet.notes = NULL;
    nef_plugin nef = {0};
    walk w = {&quiet, "projection", 0, cache, &nef, 0, 0, NULL, NULL, NULL, NULL, NULL};
    nef_solid *solid = NULL;
    affine id = affine_identity();
    sc_status st = nef_ready(&w, n);
    if (st == SC_OK)
        st = nef_children(&w, n, &id, 0, NEF_UNION, &solid);
    nef_publish(c);
    build_imports_done(c, n);
    nef_parts got = {NULL, NULL, 0};
    if (st == SC_OK && !solid) {
        *missed = 1;
    } else if (st == SC_OK) {
        char why[512] = "";
        nef_status ns = nef.section(solid, &got, missed, why, sizeof why);
        if (ns != NEF_OK)
            st = nef_error(&w, n, ns, why);
        else if (*missed == 2 && c->strict)
            st = err_set(c->error, SC_ERR_SEMANTIC, &n->loc,
                         "projection: CGAL error while flattening the section: %s", why);
        else if (*missed == 2 && c->notes)
            st = build_note(c, &n->loc,
                            "projection: CGAL error while flattening the section: %s",
                            why);
    }
    for (uint32_t k = 0; st == SC_OK && k < got.count; k++) {
        int ok = twod_begin_contour(out);
        for (uint32_t i = got.start[k]; ok && i < got.start[k + 1]; i++)
            ok = twod_add_point(out, got.points[3 * i], got.points[3 * i + 1]);
        if (ok)
            twod_end_contour(out);
        else
            st = build_twod_add_error(c, n, out);
    }
    nef_done(&nef, solid, &got);
    return st;
}

sc_status build_self_crossing(const build_ctx *c, const sc_location *at, nef_plugin *nef,
                              const vec3 *tris, uint32_t tri_count, int *crossing)
{
    *crossing = 0;
    char why[512] = "";
    if (!nef->handle && !nef_plugin_open(nef, why, sizeof why))
        return err_set(c->error, SC_ERR_UNSUPPORTED, at, "projection: %s", why);
    double *xyz = malloc(((size_t)tri_count * 9 + 1) * sizeof *xyz);
    sc_status st = xyz ? SC_OK : err_nomem(c->error, at);
    for (size_t i = 0; xyz && i < 3 * (size_t)tri_count; i++)
        put_xyz(xyz, i, tris[i]);
    nef_status ns = NEF_OK;
    if (st == SC_OK)
        ns = nef->self_crossing(xyz, tri_count, crossing, why, sizeof why);
    if (ns == NEF_NOMEM)
        st = err_nomem(c->error, at);
    else if (ns != NEF_OK)
        st = err_set(c->error, SC_ERR_SEMANTIC, at, "projection: CGAL failed: %s", why);
    free(xyz);
    return st;
}

int build_may_cross(const model_node *n)
{
    if (n->kind == MODEL_LINEAR_EXTRUDE)
        return n->u.linear_extrude->twist != 0 || n->u.linear_extrude->sx != 1 ||
               n->u.linear_extrude->sy != 1;
    return n->kind == MODEL_POLYHEDRON || n->kind == MODEL_IMPORT;
}

/* Appends the triangles of each face of f (through its points) to
 * *corners: a triangle as it is, a larger face (its outline and holes) as
 * CGAL's constrained triangulation of it in the plane of its largest
 * normal component, turned the face's way, so that the triangles overlap
 * nowhere and keep the mesh's orientation. */
static sc_status face_triangles(const walk *w, const model_node *n,
                                const build_mesh_faces *f, vec3 **corners,
                                uint32_t *count)
{
    size_t cap = 0;
    double *xy = NULL;
    uint32_t *start = NULL, *map = NULL;
    size_t xy_cap = 0, start_cap = 0, map_cap = 0;
    sc_status st = SC_OK;
    for (uint32_t k = 0; st == SC_OK && k < f->face_count; k++) {
        uint32_t lo = f->face_loops ? f->face_loops[k] : k;
        uint32_t hi = f->face_loops ? f->face_loops[k + 1] : k + 1;
        static const uint32_t one[3] = {0, 1, 2};
        uint32_t *tris = NULL, tri_count = 0, points = 0;
        const uint32_t *use = one;
        int reverse = 0;
        if (hi - lo == 1 && f->face_start[lo + 1] - f->face_start[lo] == 3) {
            if (!grow_array((void **)&map, &map_cap, 3, sizeof *map)) {
                st = err_nomem(w->c->error, &n->loc);
                break;
            }
            for (uint32_t j = 0; j < 3; j++)
                map[j] = f->indices[f->face_start[lo] + j];
            tri_count = 1;
        } else {
            vec3 normal = v3(0, 0, 0); /* Newell's, of every loop */
            for (uint32_t l = lo; l < hi; l++)
                for (uint32_t i = f->face_start[l]; i < f->face_start[l + 1]; i++) {
                    uint32_t j = i + 1 < f->face_start[l + 1] ? i + 1 : f->face_start[l];
                    normal = v3_add(normal, v3_newell(f->points[f->indices[i]],
                                                      f->points[f->indices[j]]));
                }
            double c[3] = {normal.x, normal.y, normal.z};
            int axis = fabs(c[1]) > fabs(c[0]) ? 1 : 0;
            axis = fabs(c[2]) > fabs(c[axis]) ? 2 : axis;
            int u = (axis + 1) % 3, v = (axis + 2) % 3;
            reverse = c[axis] < 0;
            uint32_t total = f->face_start[hi] - f->face_start[lo];
            if (!grow_array((void **)&xy, &xy_cap, 2 * (size_t)total, sizeof *xy) ||
                !grow_array((void **)&map, &map_cap, total, sizeof *map) ||
                !grow_array((void **)&start, &start_cap, (size_t)(hi - lo) + 1,
                            sizeof *start)) {
                st = err_nomem(w->c->error, &n->loc);
                break;
            }
            for (uint32_t l = lo; l < hi; l++) {
                start[l - lo] = points;
                for (uint32_t i = f->face_start[l]; i < f->face_start[l + 1]; i++) {
                    vec3 p = f->points[f->indices[i]];
                    double q[3] = {p.x, p.y, p.z};
                    xy[2 * points] = q[u];
                    xy[2 * points + 1] = q[v];
                    map[points++] = f->indices[i];
                }
            }
            start[hi - lo] = points;
            char why[512];
            nef_status ns = w->nef->tessellate(xy, start, hi - lo, &tris, &tri_count, why,
                                               sizeof why);
            use = tris;
            if (ns == NEF_NOMEM)
                st = err_nomem(w->c->error, &n->loc);
            else if (ns != NEF_OK)
                tri_count = 0; /* a face CGAL refuses: left out of the test */
        }
        if (st == SC_OK &&
            ((size_t)*count + tri_count > UINT32_MAX / 3 ||
             !grow_array((void **)corners, &cap, 3 * ((size_t)*count + tri_count),
                         sizeof **corners)))
            st = err_nomem(w->c->error, &n->loc);
        for (uint32_t t = 0; st == SC_OK && t < tri_count; t++) {
            vec3 *to = *corners + 3 * (size_t)*count;
            for (int j = 0; j < 3; j++)
                to[j] = f->points[map[use[3 * t + (reverse ? 2 - j : j)]]];
            ++*count;
        }
        free(tris);
    }
    free(xy);
    free(start);
    free(map);
    return st;
}

/* Whether leaf n (build_may_cross) passes through itself as CGAL takes it,
 * in its own frame: a linear_extrude's faces as OpenSCAD's PolySet (its
 * points on the grid, as CGAL's builder merges them), a polyhedron's or an
 * import's faces triangulated (face_triangles). A leaf that is empty or
 * not a closed surface does not. */
static sc_status leaf_crosses(const walk *w, const model_node *n, int *crossing)
{
    *crossing = 0;
    build_mesh_faces faces;
    memset(&faces, 0, sizeof faces);
    const char *empty = NULL;
    /* the node's own build gives its warnings and errors */
    sc_error sink = {SC_OK, "", 0, 0, ""};
    build_ctx quiet = *w->c;
    quiet.note = &sink;
    quiet.notes = NULL;
    quiet.strict = 0;
    walk q = *w;
    q.c = &quiet;
    if (n->pending)
        return SC_OK;
    sc_status st = nef_ready(w, n);
    if (st != SC_OK)
        return st;
    /* a mesh that is not closed: CGAL never takes it */
    walk probe = q;
    probe.in_union = 1;
    probe.check = 1;
    int open = 0;
    affine id = affine_identity();
    if (n->kind != MODEL_LINEAR_EXTRUDE)
        st = closed_check(&probe, n, &id, &open);
    if (st != SC_OK || open)
        return st;
    if (n->kind == MODEL_POLYHEDRON) {
        faces.points = (vec3 *)n->u.polyhedron.points;
        faces.point_count = n->u.polyhedron.point_count;
        faces.indices = (uint32_t *)n->u.polyhedron.indices;
        faces.face_start = (uint32_t *)n->u.polyhedron.face_start;
        faces.face_count = n->u.polyhedron.face_count;
    } else {
        st = mesh_faces(&q, n, NULL, &faces, &empty);
        if (st == SC_OK && !empty && n->kind == MODEL_LINEAR_EXTRUDE)
            st = build_mesh_grid_align(&quiet, &n->loc, faces.points, faces.point_count);
        if (st != SC_OK && st != SC_ERR_NOMEM) { /* found again where it is built */
            build_mesh_faces_free(&faces);
            err_clear(w->c->error);
            return SC_OK;
        }
    }
    vec3 *corners = NULL;
    uint32_t count = 0;
    if (st == SC_OK && !empty)
        st = face_triangles(w, n, &faces, &corners, &count);
    if (n->kind != MODEL_POLYHEDRON)
        build_mesh_faces_free(&faces);
    if (st == SC_OK && count)
        st = build_self_crossing(w->c, &n->loc, w->nef, corners, count, crossing);
    free(corners);
    return st;
}

/* Whether a leaf of n that CGAL takes when it evaluates n passes through
 * itself (leaf_crosses): below groups, colours, transforms and booleans,
 * not below a hull, minkowski or projection (each its own CGAL solid, or
 * 2D), nor a '%' or '*' part. */
static sc_status crossing_below(const walk *w, const model_node *parent, int depth,
                                int *crossing)
{
    if (depth > BUILD_HULL_MAX_DEPTH)
        return depth_error(w, parent);
    sc_status st = SC_OK;
    for (const model_node *n = parent->first_child; n && st == SC_OK && !*crossing;
         n = n->next) {
        if (skipped(n) || is_shading(n->kind) || is_2d(n))
            continue;
        if (build_may_cross(n))
            st = leaf_crosses(w, n, crossing);
        else if (!model_is_leaf(n->kind) && n->kind != MODEL_HULL &&
                 n->kind != MODEL_MINKOWSKI && n->kind != MODEL_PROJECTION)
            st = crossing_below(w, n, depth + 1, crossing);
    }
    return st;
}

static int nef_walkable(const model_node *n, int depth);

sc_status build_cgal_crossing(const build_ctx *c, const model_node *n, int *crossing)
{
    *crossing = 0;
    if (!nef_walkable(n, 0)) /* a node CGAL cannot take: drawn as it is */
        return SC_OK;
    /* the plugin is loaded at the first leaf that may cross (leaf_crosses) */
    nef_plugin nef = {0};
    walk w = {c, n->name, 0, NULL, &nef, 0, 0, NULL, NULL, NULL, NULL, NULL};
    sc_status st = crossing_below(&w, n, 0, crossing);
    nef_plugin_close(&nef);
    return st;
}

/* Whether the walk takes every node of 3D subtree n as OpenSCAD's: its
 * kinds (not spancast's own leaves, which OpenSCAD has no mesh of), none
 * with a pending argument error. A 2D subtree goes whole to the 2D
 * engine, which takes every 2D node. */
static int nef_walkable(const model_node *n, int depth)
{
    if (depth > BUILD_HULL_MAX_DEPTH)
        return 0;
    if ((n->modifiers & MODEL_MOD_DISABLE) || is_shading(n->kind) || is_2d(n))
        return 1;
    if (n->pending)
        return 0;
    switch (n->kind) {
    case MODEL_CUBE:
    case MODEL_SPHERE:
    case MODEL_CYLINDER:
    case MODEL_POLYHEDRON:
    case MODEL_IMPORT:
    case MODEL_LINEAR_EXTRUDE:
    case MODEL_ROTATE_EXTRUDE:
    case MODEL_SURFACE:
        return 1;
    case MODEL_UNION:
    case MODEL_COLOR:
    case MODEL_MATERIAL:
    case MODEL_XFORM:
    case MODEL_RESIZE:
    case MODEL_DIFFERENCE:
    case MODEL_INTERSECTION:
    case MODEL_HULL:
    case MODEL_MINKOWSKI:
        for (const model_node *k = n->first_child; k; k = k->next)
            if (!nef_walkable(k, depth + 1))
                return 0;
        return 1;
    default:
        return 0;
    }
}

sc_status build_nef_evaluate(const build_ctx *c, const model_node *n,
                             build_nef_state *out)
{
    memset(out, 0, sizeof *out);
    nef_plugin nef = {0};
    char why[600];
    if (!nef_walkable(n, 0) || !nef_plugin_open(&nef, why, sizeof why))
        return SC_OK;
    build_ctx own = *c;
    own.nefs = NULL; /* each operand evaluated here, for out's flags */
    build_resize_cache *cache = NULL;
    walk w = {&own, n->name, 0, &cache, &nef, 0, 0, NULL, n, out, NULL, NULL};
    nef_solid *solid = NULL;
    affine id = affine_identity();
    sc_status st = nef_node(&w, n, &id, 0, &solid);
    build_imports_done(c, n);
    out->walked = st == SC_OK;
    out->empty = !solid;
    if (solid)
        nef.release(solid);
    build_resize_cache_free(cache);
    nef_plugin_close(&nef);
    return st;
}

/* ---- emitting ---- */

static sc_status push_prim(const build_ctx *c, const model_node *n, build_prims *out,
                           const prim *p)
{
    if (!grow_array32((void **)&out->items, &out->cap, out->count + 1,
                      sizeof *out->items))
        return err_nomem(c->error, (&n->loc));
    out->items[out->count++] = *p;
    return SC_OK;
}

/* The hull of points as a leaf appended to out; *flat counts hulls
 * without volume. */
static sc_status emit_hull(const build_ctx *c, const model_node *n, const pointset *s,
                           build_prims *out, int *flat)
{
    hull3 h;
    hull3_status hs = hull3_compute(s->p, s->count, &h);
    if (hs == HULL3_NOMEM)
        return err_nomem(c->error, (&n->loc));
    if (hs == HULL3_RANGE)
        return err_set(c->error, SC_ERR_LIMIT, &n->loc,
                       "%s: too many points or a coordinate too large", n->name);
    if (hs == HULL3_FLAT) {
        (*flat)++;
        return SC_OK;
    }
    prim p;
    memset(&p, 0, sizeof p);
    sc_status st = SC_OK;
    if (h.plane_count <= PRIM_CONVEX_MAX_PLANES) {
        plane *planes = csg_builder_alloc(c->csg, (size_t)h.plane_count * sizeof *planes);
        if (!planes) {
            hull3_free(&h);
            return err_nomem(c->error, (&n->loc));
        }
        memcpy(planes, h.planes, (size_t)h.plane_count * sizeof *planes);
        p.kind = PRIM_CONVEX;
        p.u.convex.planes = planes;
        p.u.convex.count = h.plane_count;
        p.u.convex.bounds = h.bounds;
    } else {
        uint32_t *start = malloc(((size_t)h.tri_count + 1) * sizeof *start);
        if (!start) {
            hull3_free(&h);
            return err_nomem(c->error, (&n->loc));
        }
        for (uint32_t t = 0; t <= h.tri_count; t++)
            start[t] = 3 * t;
        const char *empty = NULL;
        /* convex: OpenSCAD hulls a convex mesh for CGAL, unchecked */
        build_ctx convex = *c;
        convex.drawn_as_is = 1;
        st = build_mesh_prim(&convex, &n->loc, n->name, 0, h.vertices, h.vertex_count,
                             h.tris, start, h.tri_count, &p, &empty);
        free(start);
        if (st == SC_OK && empty)
            (*flat)++;
        if (st != SC_OK || empty) {
            hull3_free(&h);
            return st;
        }
    }
    hull3_free(&h);
    return push_prim(c, n, out, &p);
}

sc_status build_hull_points(const build_ctx *c, const model_node *n, const vec3 *points,
                            uint32_t count, build_prims *out)
{
    pointset s = {(vec3 *)points, count, count};
    int flat = 0;
    return emit_hull(c, n, &s, out, &flat);
}

sc_status build_hull(const build_ctx *c, const model_node *n, int emit,
                     build_resize_cache **cache, build_prims *out, const char **empty)
{
    memset(out, 0, sizeof *out);
    nef_plugin nef = {0};
    walk w = {c, "hull", 0, cache, &nef, !emit, 0, NULL, NULL, NULL, NULL, NULL};
    partlist parts = {NULL, 0, 0};
    affine id = affine_identity();
    sc_status st = collect(&w, n, &id, 0, &parts);
    nef_publish(c);
    nef_plugin_close(&nef);
    build_imports_done(c, n);
    pointset all = {NULL, 0, 0};
    for (uint32_t i = 0; i < parts.count && st == SC_OK; i++) {
        for (uint32_t k = 0; k < parts.items[i].count && st == SC_OK; k++) {
            if (!add_point(&all, parts.items[i].p[k]))
                st = err_nomem(c->error, (&n->loc));
        }
    }
    parts_free(&parts);
    int flat = 0;
    if (st == SC_OK && emit)
        st = emit_hull(c, n, &all, out, &flat);
    free(all.p);
    if (st == SC_OK && emit && out->count == 0)
        *empty = "hull without volume is empty";
    return st;
}

sc_status build_minkowski(const build_ctx *c, const model_node *n, int emit,
                          build_resize_cache **cache, build_prims *out,
                          const char **empty)
{
    memset(out, 0, sizeof *out);
    nef_plugin nef = {0};
    walk w = {c, "minkowski", 1, cache, &nef, !emit, 0, NULL, NULL, NULL, NULL, NULL};
    partlist parts = {NULL, 0, 0};
    affine id = affine_identity();
    int not_closed;
    const model_node *whole;
    sc_status st = minkowski_parts(&w, n, &id, 0, &parts, &not_closed, &whole);
    nef_publish(c);
    nef_plugin_close(&nef);
    int flat = 0;
    for (uint32_t i = 0; i < parts.count && st == SC_OK && emit; i++)
        st = emit_hull(c, n, &parts.items[i], out, &flat);
    parts_free(&parts);
    if (st == SC_OK && emit && whole) { /* its first child as it is: CGAL's mesh */
        vec3 *corners;
        uint32_t tris;
        build_ctx quiet = *c; /* its warnings were given as it was decomposed */
        quiet.notes = NULL;
        st = build_nef_triangles(&quiet, whole, "minkowski", cache, 0, &corners, &tris);
        prim p;
        const char *none = NULL;
        if (st == SC_OK && tris)
            st = build_mesh_soup(c, &n->loc, n->name, corners, tris, &p, &none);
        if (st == SC_OK && tris && !none)
            st = push_prim(c, n, out, &p);
        free(corners);
    }
    build_imports_done(c, n);
    if (st == SC_OK && emit && out->count == 0) /* "": its warning was given */
        *empty = not_closed ? "" : "minkowski without volume is empty";
    return st;
}

/* ---- resize ---- */

/* Whether OpenSCAD 2021.01 evaluates the union of n's children to a CGAL
 * Nef polyhedron, rather than to a mesh (PolySet) or nothing: a union of
 * two or more solids is a Nef polyhedron, one solid is passed through as
 * it is; of that one a boolean, group, transform or resize is what its own
 * children's union is, and a leaf, hull or minkowski a mesh (minkowski
 * read as the sum of convex parts OpenSCAD makes one mesh of). */
static int nef_result(const model_node *n, int depth)
{
    int count = build_operands(n->kind, n->first_child), solids = 0;
    if (count != 1 || depth > BUILD_HULL_MAX_DEPTH)
        return count > 1;
    const model_node *only = NULL; /* the one operand, if a solid */
    for (const model_node *k = n->first_child; k; k = k->next) {
        if (skipped(k) || build_dim(k, 0) != 3)
            continue;
        if (!only)
            only = k;
        solids++;
    }
    if (solids > 1) /* the one that is not empty (build_operands) */
        for (only = n->first_child; only; only = only->next)
            if (!skipped(only) && build_dim(only, 0) == 3 && !build_node_empty(only))
                break;
    if (!only)
        return 0;
    model_kind kind = only->kind;
    if (is_group(kind) || kind == MODEL_XFORM || kind == MODEL_RESIZE ||
        kind == MODEL_DIFFERENCE || kind == MODEL_INTERSECTION)
        return nef_result(only, depth + 1);
    return 0;
}

int build_nef_result(const model_node *n)
{
    return nef_result(n, 0);
}

int build_singular_removes(const model_node *n, const char **warning)
{
    int nef = build_nef_result(n);
    *warning = nef && !build_node_empty(n)
                   ? "Scaling a 3D object with 0 - removing object"
                   : NULL;
    return nef;
}

/* The six support values of the children of parent through m: out[2k] =
 * max x_k, out[2k + 1] = max -x_k; -inf where there is nothing. */
static sc_status support(const walk *w, const model_node *parent, const affine *m,
                         int depth, double out[6]);

static void support_points(const pointset *s, double out[6])
{
    for (uint32_t i = 0; i < s->count; i++) {
        for (int k = 0; k < 3; k++) {
            double x = v3_get(s->p[i], k);
            out[2 * k] = fmax(out[2 * k], x);
            out[2 * k + 1] = fmax(out[2 * k + 1], -x);
        }
    }
}

/* Row k of m's linear part: the direction M^T e_k. */
static vec3 row(const affine *m, int k)
{
    return v3(m->m[k][0], m->m[k][1], m->m[k][2]);
}

static sc_status support_node(const walk *w, const model_node *n, const affine *m,
                              int depth, double out[6])
{
    const build_ctx *c = w->c;
    sc_status st = SC_OK;
    model_kind kind = n->kind;
    if (is_2d(n))
        return check_2d(w, n, NULL); /* ignored, as the walk that builds it warns */
    if (is_group(kind))
        return support(w, n, m, depth + 1, out);
    if (kind == MODEL_XFORM || kind == MODEL_RESIZE) {
        affine inner;
        int ok;
        st = inner_frame(w, n, m, depth + 1, &inner, NULL, NULL, 0, &ok);
        if (st != SC_OK || !ok)
            return st;
        return support(w, n, &inner, depth + 1, out);
    }
    if ((kind == MODEL_DIFFERENCE || kind == MODEL_INTERSECTION) && !w->check &&
        build_operands(n->kind, n->first_child) > 1) {
        /* OpenSCAD's box: that of the CGAL result's vertices */
        partlist parts = {NULL, 0, 0};
        st = solid_parts(w, n, m, depth + 1, &parts);
        for (uint32_t i = 0; i < parts.count && st == SC_OK; i++)
            support_points(&parts.items[i], out);
        parts_free(&parts);
        return st;
    }
    if (kind == MODEL_DIFFERENCE || kind == MODEL_INTERSECTION) {
        /* one child (or only checked): the first child's box bounds a
         * difference, the smallest child box an intersection */
        int first = 1;
        double acc[6] = {-INFINITY, -INFINITY, -INFINITY,
                         -INFINITY, -INFINITY, -INFINITY};
        for (const model_node *k = n->first_child; k; k = k->next) {
            if (skipped(k) || is_shading(k->kind))
                continue;
            double s[6] = {-INFINITY, -INFINITY, -INFINITY,
                           -INFINITY, -INFINITY, -INFINITY};
            if ((st = support_node(w, k, m, depth + 1, s)) != SC_OK)
                return st;
            for (int i = 0; i < 6; i++)
                acc[i] = first ? s[i] : fmin(acc[i], s[i]);
            first = 0;
            if (kind == MODEL_DIFFERENCE)
                break;
        }
        for (int i = 0; i < 6; i++)
            out[i] = fmax(out[i], acc[i]);
        return SC_OK;
    }
    if (kind == MODEL_MINKOWSKI) {
        double sum[6] = {0, 0, 0, 0, 0, 0};
        int any = 0;
        affine linear = *m;
        linear.m[0][3] = linear.m[1][3] = linear.m[2][3] = 0;
        for (const model_node *k = n->first_child; k; k = k->next) {
            if (skipped(k) || is_shading(k->kind))
                continue;
            double s[6] = {-INFINITY, -INFINITY, -INFINITY,
                           -INFINITY, -INFINITY, -INFINITY};
            if ((st = support_node(w, k, any ? &linear : m, depth + 1, s)) != SC_OK)
                return st;
            if (isinf(s[0]) && s[0] < 0)
                continue; /* no geometry: skipped, as OpenSCAD does */
            for (int i = 0; i < 6; i++)
                sum[i] += s[i];
            any = 1;
        }
        for (int i = 0; any && i < 6; i++)
            out[i] = fmax(out[i], sum[i]);
        return SC_OK;
    }
    vec3 t = v3(m->m[0][3], m->m[1][3], m->m[2][3]);
    if (!c->faithful && (kind == MODEL_SPHERE || kind == MODEL_CYLINDER)) {
        shape s;
        if ((st = read_shape(c, n, &s)) != SC_OK || s.kind == SHAPE_NONE)
            return st;
        for (int k = 0; k < 3; k++) {
            vec3 u = row(m, k);
            double h;
            if (s.kind == SHAPE_SPHERE) {
                h = s.r * v3_length(u);
                out[2 * k] = fmax(out[2 * k], v3_get(t, k) + h);
                out[2 * k + 1] = fmax(out[2 * k + 1], -v3_get(t, k) + h);
                continue;
            }
            double radial = hypot(u.x, u.y);
            for (int sign = 0; sign < 2; sign++) {
                double uz = sign ? -u.z : u.z, tk = sign ? -v3_get(t, k) : v3_get(t, k);
                h = fmax(s.z0 * uz + s.r0 * radial, s.z1 * uz + s.r1 * radial);
                out[2 * k + sign] = fmax(out[2 * k + sign], tk + h);
            }
        }
        return SC_OK;
    }
    if (kind == MODEL_TORUS || kind == MODEL_QUADRIC || kind == MODEL_IMPLICIT) {
        if (n->pending)
            return build_pending(c, n);
        if (kind == MODEL_TORUS) {
            const model_torus *torus = n->u.torus;
            if (torus->empty)
                return SC_OK;
            for (int k = 0; k < 3; k++) {
                vec3 u = row(m, k);
                double h = torus->r1 * hypot(u.x, u.y) + torus->r2 * v3_length(u);
                out[2 * k] = fmax(out[2 * k], v3_get(t, k) + h);
                out[2 * k + 1] = fmax(out[2 * k + 1], -v3_get(t, k) + h);
            }
            return SC_OK;
        }
        const char *empty =
            kind == MODEL_QUADRIC ? n->u.quadric->empty : n->u.implicit->empty;
        if (empty)
            return SC_OK;
        bbox box = kind == MODEL_QUADRIC ? n->u.quadric->box : n->u.implicit->box;
        pointset corners = {NULL, 0, 0};
        vec3 list[8];
        for (int k = 0; k < 8; k++)
            list[k] = affine_point(m, v3(k & 1 ? box.hi.x : box.lo.x,
                                         k & 2 ? box.hi.y : box.lo.y,
                                         k & 4 ? box.hi.z : box.lo.z));
        corners.p = list;
        corners.count = 8;
        support_points(&corners, out);
        return SC_OK;
    }
    /* Everything else through its points: cube, faithful sphere and
     * cylinder, polyhedron, meshes, hull. */
    model_node view;
    model_node lone = *n;
    lone.next = NULL;
    memset(&view, 0, sizeof view);
    view.name = "resize";
    view.loc = n->loc;
    view.first_child = &lone;
    view.child_count = 1;
    partlist parts = {NULL, 0, 0};
    st = collect(w, &view, m, depth + 1, &parts);
    for (uint32_t i = 0; i < parts.count && st == SC_OK; i++)
        support_points(&parts.items[i], out);
    parts_free(&parts);
    return st;
}

static sc_status support(const walk *w, const model_node *parent, const affine *m,
                         int depth, double out[6])
{
    if (depth > BUILD_HULL_MAX_DEPTH)
        return depth_error(w, parent);
    for (const model_node *n = parent->first_child; n; n = n->next) {
        if (skipped(n) || is_shading(n->kind))
            continue;
        sc_status st = support_node(w, n, m, depth, out);
        if (st != SC_OK)
            return st;
    }
    return SC_OK;
}

/* The matrix of resize node n, measured (once per build: see the cache) or
 * taken from the cache. */
static sc_status measure(const walk *w, const model_node *n, int depth, affine *out,
                         const char **warning);

static sc_status resize_matrix(const walk *w, const model_node *n, int depth, affine *out,
                               const char **warning)
{
    const affine *known = cache_find(*w->cache, n, warning);
    if (known) {
        *out = *known;
        return SC_OK;
    }
    /* Measuring is silent: the walk that builds the subtree gives its
     * warnings. */
    build_ctx quiet = *w->c;
    quiet.notes = NULL;
    walk silent = *w;
    silent.c = &quiet;
    sc_status st = measure(&silent, n, depth, out, warning);
    /* a check measures booleans by an upper bound (no CGAL): not kept */
    if (st == SC_OK && !w->check && !cache_put(w->cache, n, out, *warning))
        st = err_nomem((w->c)->error, (&n->loc));
    return st;
}

static sc_status measure(const walk *w, const model_node *n, int depth, affine *out,
                         const char **warning)
{
    const build_ctx *c = w->c;
    *out = affine_identity();
    if (n->pending)
        return build_pending(c, n);
    const double *size = n->u.resize->size, *autosize = n->u.resize->autosize;
    sc_status st;
    double s[6] = {-INFINITY, -INFINITY, -INFINITY, -INFINITY, -INFINITY, -INFINITY};
    if ((st = support(w, n, out, depth, s)) != SC_OK)
        return st;
    if (isinf(s[0]) && s[0] < 0)
        return SC_OK; /* no geometry: nothing to resize */
    /* OpenSCAD 2021.01 resizes a mesh (PolySet::resize) along the axes
     * whose new size is > 0, so a negative one is as 0; a CGAL Nef
     * polyhedron (CGAL_Nef_polyhedron::resize) along those whose new size
     * is not 0, so a negative one mirrors. The largest new size (the
     * first of equal ones) gives the auto scale. */
    int nef = nef_result(n, depth);
    double extent[3], scale[3] = {1, 1, 1};
    int given[3], largest = 0;
    for (int k = 0; k < 3; k++) {
        extent[k] = s[2 * k] + s[2 * k + 1];
        given[k] = nef ? size[k] != 0 : size[k] > 0;
        if ((nef ? given[k] : k > 0) && size[k] > size[largest])
            largest = k;
    }
    for (int k = 0; k < 3; k++) {
        if (!given[k])
            continue;
        if (!(extent[k] > 0)) {
            *warning = "resize in a direction normal to a flat object is not implemented";
            return SC_OK;
        }
        scale[k] = size[k] / extent[k];
    }
    double autoscale = given[largest] ? size[largest] / extent[largest] : 1;
    for (int k = 0; k < 3; k++) {
        if (autosize[k] != 0 && !given[k])
            scale[k] = autoscale;
        if (!(isfinite(scale[k]) && scale[k] != 0))
            return err_set(c->error, SC_ERR_SEMANTIC, &n->loc,
                           "resize: the scale is not finite");
        out->m[k][k] = scale[k];
    }
    return SC_OK;
}

sc_status build_resize(const build_ctx *c, const model_node *n,
                       build_resize_cache **cache, affine *out, const char **warning)
{
    nef_plugin nef = {0};
    walk w = {c, "resize", 0, cache, &nef, 0, 0, NULL, NULL, NULL, NULL, NULL};
    const model_node *measured = n->u.resize->measured ? n->u.resize->measured : n;
    sc_status st = resize_matrix(&w, measured, 0, out, warning);
    nef_plugin_close(&nef);
    return st;
}
