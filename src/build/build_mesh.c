/* Building mesh leaves: the polyhedra that are not convex, and
 * import("file.stl" | "file.off" | "file.amf" | "file.3mf").
 *
 * Polyhedra and imports are read as OpenSCAD 2021.01 reads them: their
 * points merged on its grid of 2^-20 (build_mesh_merge), non-planar faces
 * split into the triangles its libtess2 triangulation makes
 * (build_mesh_quad_diagonal, build_mesh_face_triangles), planar ones of
 * five or more points into fans about their first point. A solid needs a mesh
 * that is closed (every undirected edge in exactly two faces) and
 * consistently oriented (those two faces run along the edge in opposite
 * directions). One that is not is a warning naming an offending edge, and
 * then left out in faithful mode where OpenSCAD hands it to CGAL (an
 * operation of two or more operands, a render(): build_ctx.drawn_as_is),
 * as OpenSCAD leaves it out of its CGAL operations, or built with the
 * parity rule (prim_mesh.h) in exact mode, and in faithful mode where
 * OpenSCAD draws it as it is, so the user still sees it; with --strict it
 * is an error. The meshes other builders make (extrusions, surface,
 * hull: build_mesh_prim) are treated the same way; in faithful mode,
 * where OpenSCAD hands such a mesh to CGAL, it is checked again with its
 * points merged on the grid, as CGAL's polyhedron builder takes it (a
 * profile pinched at a point extrudes to an edge of four faces there).
 * The builders that take only an import's corners or faces (hull,
 * projection without cut: build_import_mesh) take one
 * that is not closed as it is, silently, as OpenSCAD hulls and projects
 * the mesh it reads; a cut or CGAL boolean, which needs a solid, leaves it
 * out with the warning in both modes (build_import). Which way the faces
 * wind does not matter: OpenSCAD lists them clockwise seen from outside,
 * STL and OFF files usually the other way, so the sign of the enclosed
 * volume (divergence theorem, sum of a . (b x c) / 6 over the triangles,
 * about a point of each shell for accuracy) decides, and a mesh whose
 * volume is negative is turned inside out. A mesh without volume is
 * empty, with a warning. Where a fan of a non-convex face overlaps itself,
 * the winding number of prim_mesh.c cancels the overlap.
 *
 * Files: binary STL is recognised by its size (84 + 50 n bytes for the n
 * triangles its header announces), anything else starting with "solid" is
 * read as ASCII STL (every "vertex x y z"), and .off files as OFF (header,
 * counts, points, then faces as "k i1 .. ik" with any colour after them).
 * STL repeats each corner per triangle; corners with equal coordinates are
 * merged, so the edge checks above apply. AMF and 3MF files are read by
 * amf.c and threemf.h; each object of theirs is a mesh of its own, checked
 * and turned as above on its own, and the caller unites them, as OpenSCAD
 * 2021.01 unites them with CGAL (an object that is not closed is then left
 * out in faithful mode, as CGAL cannot take it). Paths are relative to the
 * directory of the file being read, as OpenSCAD resolves them.
 */
#include "build/build_mesh.h"

#include <ctype.h>
#include <errno.h>
#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "base/error.h"
#include "base/grow.h"
#include "base/sort.h"
#include "build/build_hull.h"
#include "build/nef.h"
#include "build/tess_mend.h"
#include "build/tess_sweep.h"
#include "csg/prim_mesh.h"
#include "formats/amf.h"
#include "formats/file.h"
#include "formats/threemf.h"

/* Point i of f as messages give it (f->written). */
static vec3 shown_point(const build_mesh_faces *f, uint32_t i)
{
    return f->written ? f->written[i] : f->points[i];
}

/* An edge for messages: point numbers, or for a file (whose points an STL
 * does not number) the coordinates of its ends. */
static const char *edge_name(char *buf, size_t size, const vec3 *points,
                             int by_coordinates, uint64_t edge)
{
    uint32_t p = (uint32_t)(edge >> 32), q = (uint32_t)(edge & 0xffffffffu);
    if (by_coordinates)
        snprintf(buf, size, "(%g, %g, %g)-(%g, %g, %g)", points[p].x, points[p].y,
                 points[p].z, points[q].x, points[q].y, points[q].z);
    else
        snprintf(buf, size, "%u-%u", p, q);
    return buf;
}

/* Closed and consistently oriented: returns 1, or 0 with what is wrong
 * (naming an edge) in why; -1 when memory ran out. names (or NULL): the
 * number in the file of each point, by which a numbered mesh's edges are
 * checked and named. */
static int mesh_sound(const char *what, int numbered, const vec3 *points,
                      const uint32_t *names, const uint32_t *indices,
                      const uint32_t *face_start, uint32_t face_count, char *why,
                      size_t size)
{
    int by_coordinates = !numbered;
    char name[256];
    uint32_t total = face_start[face_count];
    uint64_t *directed = malloc((size_t)(total ? total : 1) * sizeof *directed);
    uint64_t *undirected = malloc((size_t)(total ? total : 1) * sizeof *undirected);
    if (!directed || !undirected) {
        free(directed);
        free(undirected);
        return -1;
    }
    size_t count = 0;
    for (uint32_t f = 0; f < face_count; f++) {
        uint32_t s = face_start[f], e = face_start[f + 1];
        for (uint32_t i = s; i < e; i++) {
            uint32_t p = indices[i], q = indices[i + 1 < e ? i + 1 : s];
            if (p == q)
                continue;
            if (names && numbered) { /* edges in the file's numbers, as named */
                p = names[p];
                q = names[q];
            }
            directed[count] = (uint64_t)p << 32 | q;
            undirected[count++] = p < q ? (uint64_t)p << 32 | q : (uint64_t)q << 32 | p;
        }
    }
    if (!sort_u64(directed, count) || !sort_u64(undirected, count)) {
        free(directed);
        free(undirected);
        return -1;
    }
    int sound = 1;
    for (size_t i = 0; i < count && sound;) {
        size_t j = i;
        while (j < count && undirected[j] == undirected[i])
            j++;
        if (j - i != 2) {
            snprintf(why, size, "%s is not closed (edge %s is used by %zu face%s)", what,
                     edge_name(name, sizeof name, points, by_coordinates, undirected[i]),
                     j - i, j - i == 1 ? "" : "s");
            sound = 0;
        }
        i = j;
    }
    for (size_t i = 0; i + 1 < count && sound; i++) {
        if (directed[i] == directed[i + 1]) {
            snprintf(why, size,
                     "%s is not consistently oriented (edge %s runs the same way in "
                     "two faces)",
                     what,
                     edge_name(name, sizeof name, points, by_coordinates, directed[i]));
            sound = 0;
        }
    }
    free(directed);
    free(undirected);
    return sound;
}

/* An edge of a face or triangle, for build_mesh_pieces and approx_convex:
 * its ends (p << 32 | q), its face, and the point after q in the face. */
typedef struct face_edge {
    uint64_t key;
    uint32_t face, next;
} face_edge;

static int face_edge_cmp(const void *a, const void *b)
{
    const face_edge *x = a, *y = b;
    return x->key < y->key ? -1 : x->key > y->key;
}

uint32_t build_mesh_piece(uint32_t *parent, uint32_t f)
{
    while (parent[f] != f)
        f = parent[f] = parent[parent[f]];
    return f;
}

int build_mesh_pieces(const uint32_t *indices, const uint32_t *face_start,
                      uint32_t face_count, uint32_t *parent)
{
    size_t total = face_start ? face_start[face_count] : 3 * (size_t)face_count;
    face_edge *edges = malloc((total ? total : 1) * sizeof *edges);
    if (!edges)
        return 0;
    for (uint32_t f = 0; f < face_count; f++) {
        parent[f] = f;
        size_t s = face_start ? face_start[f] : 3 * (size_t)f;
        size_t e = face_start ? face_start[f + 1] : s + 3;
        for (size_t i = s; i < e; i++) {
            uint64_t p = indices[i], q = indices[i + 1 < e ? i + 1 : s];
            edges[i] = (face_edge){p < q ? p << 32 | q : q << 32 | p, f, 0};
        }
    }
    qsort(edges, total, sizeof *edges, face_edge_cmp);
    for (size_t i = 1; i < total; i++)
        if (edges[i].key == edges[i - 1].key)
            parent[build_mesh_piece(parent, edges[i].face)] =
                build_mesh_piece(parent, edges[i - 1].face);
    free(edges);
    return 1;
}

/* Whether box a lies within box b. */
static int box_within(const bbox *a, const bbox *b)
{
    return a->lo.x >= b->lo.x && a->lo.y >= b->lo.y && a->lo.z >= b->lo.z &&
           a->hi.x <= b->hi.x && a->hi.y <= b->hi.y && a->hi.z <= b->hi.z;
}

/* The shells of a closed mesh (its triangles joined by their edges),
 * each one's volume taken about a point of its own (its first triangle's
 * first corner), so that a small shell far from another keeps its digits:
 * six times the signed volume of the whole in *total; the sum of the
 * shells' volumes, each counted positive, in *volume; in *magnitude the
 * sum of the terms' sizes (|a| |b x c| over the triangles, each about its
 * shell's point), of which a flat shell's volume is rounding noise.
 * *mixed when they turn different ways where a global turn cannot mend
 * it: a shell enclosing volume of the sign opposite to the whole's that
 * does not lie within the box of a shell of the whole's sign, where it
 * would be a cavity. 0 when memory runs out. */
static int shell_volumes(const vec3 *points, const uint32_t *tris, size_t k,
                         double *total, int *mixed, double *volume, double *magnitude)
{
    uint32_t *parent = malloc((k ? k : 1) * sizeof *parent);
    double *shell = calloc(k ? k : 1, sizeof *shell);
    bbox *box = malloc((k ? k : 1) * sizeof *box);
    if (!parent || !shell || !box ||
        !build_mesh_pieces(tris, NULL, (uint32_t)k, parent)) {
        free(parent);
        free(shell);
        free(box);
        return 0;
    }
    for (size_t i = 0; i < k; i++)
        box[i] = bbox_empty();
    *magnitude = 0;
    for (size_t i = 0; i < k; i++) {
        uint32_t r = build_mesh_piece(parent, (uint32_t)i);
        vec3 at = points[tris[3 * r]];
        vec3 a = v3_sub(points[tris[3 * i]], at);
        vec3 b = v3_sub(points[tris[3 * i + 1]], at);
        vec3 d = v3_sub(points[tris[3 * i + 2]], at);
        vec3 bd = v3_cross(b, d);
        shell[r] += v3_dot(a, bd);
        *magnitude += v3_length(a) * v3_length(bd);
        for (int j = 0; j < 3; j++)
            box[r] = bbox_add_point(box[r], points[tris[3 * i + j]]);
    }
    *total = 0;
    for (size_t i = 0; i < k; i++)
        if (parent[i] == i)
            *total += shell[i];
    *volume = 0;
    *mixed = 0;
    size_t shells = 0; /* the roots, gathered at the front of parent */
    for (size_t i = 0; i < k; i++)
        if (parent[i] == i)
            parent[shells++] = (uint32_t)i;
    for (size_t a = 0; a < shells; a++) {
        uint32_t i = parent[a];
        *volume += fabs(shell[i]);
        /* against the whole (a whole of 0: shells that cancel, each
         * against the other) */
        if (!(shell[i] * *total < 0 || (*total == 0 && shell[i] != 0)) || *mixed)
            continue;
        int cavity = 0; /* within the box of a shell turned the mesh's way */
        for (size_t b = 0; b < shells && !cavity; b++)
            cavity =
                shell[parent[b]] * *total > 0 && box_within(&box[i], &box[parent[b]]);
        *mixed = !cavity;
    }
    free(parent);
    free(shell);
    free(box);
    return 1;
}

/* The leaf of tri_count triangles (three indices into points each, wound
 * alike): a closed mesh is turned outward by the sign of its volume, and a
 * mesh without volume is empty (*empty); parity says the mesh is not sound
 * and takes the parity rule (prim_mesh.h), its triangles as they come, and
 * is empty only without area. A closed mesh whose shells turn different
 * ways (a cube and a copy of it wound the other way; shell_volumes) takes
 * the parity rule too, which makes each shell solid and a shell inside
 * another a hollow, as CGAL's Nef polyhedron of it does and as OpenSCAD
 * draws its faces; its volume is its shells'. */
static sc_status finish_mesh(const build_ctx *c, const sc_location *loc, int numbered,
                             const vec3 *points, uint32_t point_count, uint32_t *tris,
                             size_t k, int parity, prim *out, const char **empty)
{
    bbox box = bbox_empty();
    for (uint32_t i = 0; i < point_count; i++)
        box = bbox_add_point(box, points[i]);
    vec3 centre = v3_scale(v3_add(box.lo, box.hi), 0.5);
    double area = 0; /* the parity rule's test only */
    for (size_t i = 0; parity && i < k; i++) {
        vec3 a = v3_sub(points[tris[3 * i]], centre);
        vec3 b = v3_sub(points[tris[3 * i + 1]], centre);
        vec3 d = v3_sub(points[tris[3 * i + 2]], centre);
        area += v3_length(v3_cross(v3_sub(b, a), v3_sub(d, a)));
    }
    /* flat: a volume that is rounding noise of its terms (a thin solid's
     * is not, however long: a tetrahedron 2e6 long and 2 wide has 1e-7 of
     * them) */
    int mixed = 0;
    double volume = 0, shells = 0, magnitude = 0;
    if (!parity && !shell_volumes(points, tris, k, &volume, &mixed, &shells, &magnitude))
        return err_nomem(c->error, loc);
    vec3 ext = v3_sub(box.hi, box.lo);
    double size = fmax(ext.x, fmax(ext.y, ext.z));
    if (parity ? !(area > 1e-24 * size * size) : !(shells > 1e-12 * magnitude)) {
        *empty = numbered ? "polyhedron without volume is empty"
                          : "imported mesh without volume is empty";
        return SC_OK;
    }
    if (volume < 0 && !parity) {
        for (size_t i = 0; i < k; i++) {
            uint32_t t = tris[3 * i + 1];
            tris[3 * i + 1] = tris[3 * i + 2];
            tris[3 * i + 2] = t;
        }
    }
    const prim_mesh *m =
        prim_mesh_create_rule(c->csg, points, tris, (uint32_t)k, parity || mixed);
    if (!m)
        return err_nomem(c->error, loc);
    memset(out, 0, sizeof *out);
    out->kind = PRIM_MESH;
    out->u.mesh.mesh = m;
    return SC_OK;
}

const char build_openscad_not_closed[] =
    "The given mesh is not closed! Unable to convert to CGAL_Nef_Polyhedron.";
const char build_openscad_invalid[] =
    "The given mesh is invalid! Unable to convert to CGAL_Nef_Polyhedron.";
const char build_import_not_finite[] = "";
/* Its message where CGAL's Nef polyhedron fails an assertion (plane_lost). */
static const char openscad_assertion[] =
    "CGAL error in CGAL_Nef_polyhedron3(): CGAL ERROR: assertion violation!";

/* The triangles of the fans over faces (face_start, face_count: n - 2 for
 * a face of n points; every face here has 3 or more) into *count, as a
 * mesh leaf holds them: more than fit in its uint32 indices is the error
 * "what has too many faces"; else they are charged to c's triangle budget
 * (build_charge_triangles), whose error it returns. */
static sc_status charge_fans(const build_ctx *c, const sc_location *loc, const char *what,
                             const uint32_t *face_start, uint32_t face_count,
                             size_t *count)
{
    size_t triangles = 0;
    for (uint32_t f = 0; f < face_count; f++) {
        uint32_t n = face_start[f + 1] - face_start[f];
        triangles += n > 2 ? n - 2 : 0;
    }
    *count = triangles;
    if (triangles > UINT32_MAX / 3)
        return err_set(c->error, SC_ERR_LIMIT, loc, "%s has too many faces", what);
    return build_charge_triangles(c, loc, what, triangles);
}

/* The triangles of the polygon loop[lo .. hi], closed by the chord from
 * hi to lo: lo, mid, hi, then the loops on either side, appended to tris
 * from *k. Like a fan, the triangles' signed areas sum to the polygon's
 * whatever its shape; unlike a fan, whose slivers all span the polygon and
 * each lie in the way of every ray the hierarchy sends near it, they are
 * small along the rim and few across it (a 200-gon cap drew its
 * extrusion in 0.65 s as a fan, against 0.36 s for the same cylinder). */
static void halves(const uint32_t *loop, uint32_t lo, uint32_t hi, uint32_t *tris,
                   size_t *k)
{
    while (hi - lo >= 2) {
        uint32_t mid = lo + (hi - lo) / 2;
        tris[3 * *k] = loop[lo];
        tris[3 * *k + 1] = loop[mid];
        tris[3 * *k + 2] = loop[hi];
        (*k)++;
        halves(loop, lo, mid, tris, k);
        lo = mid;
    }
}

/* A corner of a face at point v, between the points before and after it. */
typedef struct corner {
    uint32_t v, prev, next;
} corner;

static int corner_cmp(const void *a, const void *b)
{
    const corner *x = a, *y = b;
    if (x->v != y->v)
        return x->v < y->v ? -1 : 1;
    return x->prev < y->prev ? -1 : x->prev > y->prev;
}

/* On a mesh whose edges are sound (mesh_sound): whether the faces about
 * each point make one fan, as CGAL's polyhedron builder needs (it skips a
 * face that would join a second fan to a point, so such a mesh comes out
 * "not closed"): 1, 0 with the point in why, -1 when memory ran out. Going
 * round a point, the corner whose next point is b is followed by the one
 * whose previous point is b. */
static int fans_whole(const build_mesh_faces *f, const char *what, int numbered,
                      char *why, size_t size)
{
    uint32_t total = f->face_start[f->face_count];
    corner *cs = malloc((size_t)(total ? total : 1) * sizeof *cs);
    if (!cs)
        return -1;
    size_t n = 0;
    for (uint32_t k = 0; k < f->face_count; k++) {
        uint32_t s = f->face_start[k], e = f->face_start[k + 1];
        for (uint32_t i = s; i < e; i++)
            cs[n++] = (corner){f->indices[i], f->indices[i > s ? i - 1 : e - 1],
                               f->indices[i + 1 < e ? i + 1 : s]};
    }
    qsort(cs, n, sizeof *cs, corner_cmp);
    int whole = 1;
    for (size_t lo = 0; lo < n && whole;) {
        size_t hi = lo;
        while (hi < n && cs[hi].v == cs[lo].v)
            hi++;
        size_t at = lo, steps = 0;
        do {
            corner key = {cs[lo].v, cs[at].next, 0};
            const corner *to = bsearch(&key, cs + lo, hi - lo, sizeof *cs, corner_cmp);
            if (!to)
                break;
            at = (size_t)(to - cs);
            steps++;
        } while (at != lo && steps <= hi - lo);
        if (at != lo || steps != hi - lo) {
            vec3 p = shown_point(f, cs[lo].v);
            if (numbered && f->names)
                snprintf(
                    why, size,
                    "%s is not closed (its faces at point %u make more than one fan)",
                    what, f->names[cs[lo].v]);
            else
                snprintf(why, size,
                         "%s is not closed (its faces at (%g, %g, %g) make more than one "
                         "fan)",
                         what, p.x, p.y, p.z);
            whole = 0;
        }
        lo = hi;
    }
    free(cs);
    return whole;
}

static uint32_t *openscad_numbers(const build_mesh_faces *f, int reversed);
/* Where OpenSCAD's tessellation fans the quad v[0..4) of f from: 0 or 1
 * (the diagonal from v[0] or from v[1]); numbers: OpenSCAD's numbers of
 * f's points (openscad_numbers), made here when first needed. -1 when
 * memory runs out. */
static int quad_first(const build_mesh_faces *f, const uint32_t *v, int numbered,
                      uint32_t **numbers);

/* Whether OpenSCAD 2021.01 finds f convex (is_approximately_convex, on
 * the faces as its tessellation cleans them, a quad as the two triangles
 * it makes of it, which fold where the quad is out of its plane, and
 * faces of more points whole): every edge runs once each
 * way, every fold between two faces turns outward or by less than 0.1
 * degrees, and every face is reached from the first. Such a mesh it takes
 * as the convex hull of its points, without CGAL's polyhedron builder.
 * reversed: f's faces are a polyhedron's, which OpenSCAD reads back to
 * front, so that they turn the other way. 1, 0, or -1 when memory runs
 * out. */
static int convex_faces(const build_mesh_faces *f, int reversed, int split);

static int approx_convex(const build_mesh_faces *f, int reversed)
{
    return convex_faces(f, reversed, 1);
}

int build_mesh_convex_for_cgal(const build_mesh_faces *f, int reversed)
{
    return approx_convex(f, reversed);
}

int build_mesh_convex_as_written(const vec3 *points, uint32_t point_count,
                                 const uint32_t *indices, const uint32_t *face_start,
                                 uint32_t face_count)
{
    build_mesh_faces f;
    memset(&f, 0, sizeof f);
    f.points = (vec3 *)points; /* read only */
    f.point_count = point_count;
    f.indices = (uint32_t *)indices;
    f.face_start = (uint32_t *)face_start;
    f.face_count = face_count;
    return convex_faces(&f, 0, 0);
}

/* approx_convex, each quad split (split) or every face whole. */
static int convex_faces(const build_mesh_faces *f, int reversed, int split)
{
    /* the pieces: the faces, each quad as the two triangles OpenSCAD's
     * tessellation makes of it (a quad out of its plane folds there) */
    uint32_t total = f->face_start[f->face_count], pieces = 0;
    for (uint32_t k = 0; k < f->face_count; k++)
        pieces += split && f->face_start[k + 1] - f->face_start[k] == 4 ? 2 : 1;
    size_t corners = (size_t)total + 2 * (size_t)pieces; /* a split quad has 6 */
    face_edge *edges = malloc((corners ? corners : 1) * sizeof *edges);
    uint32_t *piece = malloc((corners ? corners : 1) * sizeof *piece);
    uint32_t *start = malloc(((size_t)pieces + 1) * sizeof *start);
    vec3 *normal = malloc((size_t)(pieces ? pieces : 1) * sizeof *normal);
    uint32_t *parent = malloc((size_t)(pieces ? pieces : 1) * sizeof *parent);
    uint32_t *numbers = NULL;
    int convex = -1;
    if (!edges || !piece || !start || !normal || !parent)
        goto done;
    uint32_t at = 0, count = 0;
    for (uint32_t k = 0; k < f->face_count; k++) {
        const uint32_t *v = &f->indices[f->face_start[k]];
        uint32_t n = f->face_start[k + 1] - f->face_start[k];
        if (n != 4 || !split) {
            start[count++] = at;
            for (uint32_t j = 0; j < n; j++)
                piece[at++] = v[j];
            continue;
        }
        int first = quad_first(f, v, reversed, &numbers);
        if (first < 0)
            goto done;
        for (uint32_t t = 0; t < 2; t++) {
            start[count++] = at;
            piece[at++] = v[first];
            piece[at++] = v[(first + 1 + t) % 4];
            piece[at++] = v[(first + 2 + t) % 4];
        }
    }
    start[count] = at;
    size_t n = 0;
    for (uint32_t k = 0; k < count; k++) {
        uint32_t s = start[k], e = start[k + 1];
        vec3 sum = v3(0, 0, 0);
        for (uint32_t i = s; i < e; i++) {
            uint32_t j = i + 1 < e ? i + 1 : s, l = j + 1 < e ? j + 1 : s;
            vec3 a = f->points[piece[i]], b = f->points[piece[j]];
            sum = v3_add(sum, v3_newell(a, b));
            edges[n++] = (face_edge){(uint64_t)piece[i] << 32 | piece[j], k, piece[l]};
        }
        normal[k] = reversed ? v3_scale(sum, -1) : sum;
        parent[k] = k;
    }
    qsort(edges, n, sizeof *edges, face_edge_cmp);
    const double most = cos(0.1 * 3.14159265358979323846 / 180); /* 0.1 degrees */
    convex = 1;
    for (size_t i = 0; i + 1 < n && convex; i++)
        convex = edges[i].key != edges[i + 1].key; /* an edge run twice one way */
    for (size_t i = 0; i < n && convex; i++) {
        face_edge key = {edges[i].key << 32 | edges[i].key >> 32, 0, 0};
        const face_edge *other = bsearch(&key, edges, n, sizeof *edges, face_edge_cmp);
        if (!other) {
            convex = 0; /* not closed */
            break;
        }
        uint32_t g = other->face, k = edges[i].face;
        vec3 u = normal[g], v = normal[k];
        vec3 on = f->points[piece[start[g]]];
        if (v3_dot(u, v3_sub(f->points[edges[i].next], on)) > 0 &&
            v3_dot(u, v) / (v3_length(u) * v3_length(v)) < most)
            convex = 0; /* a fold inward */
        uint32_t a = build_mesh_piece(parent, g), b = build_mesh_piece(parent, k);
        parent[a] = b;
    }
    for (uint32_t k = 1; k < count && convex; k++)
        convex = build_mesh_piece(parent, k) == build_mesh_piece(parent, 0);
done:
    free(edges);
    free(piece);
    free(start);
    free(normal);
    free(parent);
    free(numbers);
    return convex;
}

/* A set of directed edges (p << 32 | q), by open addressing. */
typedef struct edge_set {
    uint64_t *keys; /* UINT64_MAX: free */
    size_t mask;
} edge_set;

static size_t edge_slot(const edge_set *s, uint64_t key)
{
    size_t i = (size_t)((key * 0x9e3779b97f4a7c15u) >> 17) & s->mask;
    while (s->keys[i] != UINT64_MAX && s->keys[i] != key)
        i = (i + 1) & s->mask;
    return i;
}

static int edge_in(const edge_set *s, uint32_t p, uint32_t q)
{
    uint64_t key = (uint64_t)p << 32 | q;
    return s->keys[edge_slot(s, key)] == key;
}

/* Why CGAL's polyhedron builder (its test_facet) refuses face k of f,
 * given the faces it has taken: 0 when it takes it; else the point (in
 * *at) that the face passes through twice (1), that starts an edge a face
 * taken runs the same way (2), or where the faces taken already close
 * round (3). used[v]: 1 when point v is on a face taken; open[v]: the edges at v
 * with one face taken; met[v]: k + 1 once the face has passed point v. */
static int builder_refuses(const build_mesh_faces *f, const edge_set *edges,
                           const uint8_t *used, const uint32_t *open, uint32_t *met,
                           uint32_t k, uint32_t *at)
{
    uint32_t s = f->face_start[k], e = f->face_start[k + 1];
    if (f->twice && f->twice[k] != UINT32_MAX) {
        *at = f->twice[k];
        return 1;
    }
    for (uint32_t i = s; i < e; i++) {
        uint32_t p = f->indices[i], q = f->indices[i + 1 < e ? i + 1 : s];
        *at = p;
        if (met[p] == k + 1) /* met before in this face */
            return 1;
        met[p] = k + 1;
        if (edge_in(edges, p, q))
            return 2;
        if (used[p] == 1 && !open[p])
            return 3;
    }
    return 0;
}

/* What CGAL's polyhedron builder did with a mesh's faces (builder_whole). */
typedef struct builder_run {
    uint8_t *taken;       /* NULL, or 1 for each face taken */
    int refusal;          /* the first refusal (builder_refuses), or 0 */
    uint32_t face, point; /* its face and point */
} builder_run;

/* The first refusal of run, as "<subject> passes through point 3 twice". */
static void refusal_text(const build_mesh_faces *f, int numbered, const builder_run *run,
                         const char *subject, char *out, size_t size)
{
    static const char *const before[] = {"", "passes through point ",
                                         "runs an edge from point ", "meets point "};
    static const char *const after[] = {"", " twice", " the way a face before it does",
                                        " where the faces before it close"};
    char point[96];
    vec3 p = shown_point(f, run->point);
    if (numbered)
        snprintf(point, sizeof point, "%u", f->names ? f->names[run->point] : run->point);
    else
        snprintf(point, sizeof point, "(%g, %g, %g)", p.x, p.y, p.z);
    snprintf(out, size, "%s %s%s%s", subject, before[run->refusal], point,
             after[run->refusal]);
}

/* The faces of f that taken marks, in order, into into's indices and
 * face_start (and twice, where both have it), which have room for all of
 * f's; into may be f. Sets into->face_count. */
static void faces_taken(const build_mesh_faces *f, const uint8_t *taken,
                        build_mesh_faces *into)
{
    uint32_t n = 0, count = 0, faces = f->face_count;
    for (uint32_t k = 0; k < faces; k++) {
        uint32_t s = f->face_start[k], e = f->face_start[k + 1];
        if (!taken[k])
            continue;
        if (f->twice && into->twice)
            into->twice[count] = f->twice[k];
        into->face_start[count++] = n;
        for (uint32_t i = s; i < e; i++)
            into->indices[n++] = f->indices[i];
    }
    into->face_start[count] = n;
    into->face_count = count;
}

/* OpenSCAD 2021.01 hands a mesh to CGAL face by face (createPolyhedron-
 * FromPolySet, in the order of its faces) and CGAL's builder skips a face
 * it refuses (builder_refuses); the mesh is then "not closed" if an edge
 * has one face, and "invalid" if a point is on no face taken. 1 when it is
 * neither; 0 with why and the message in *openscad; -1 when memory runs
 * out. run says which faces it took, and why it refused the first it did. After the faces
 * taken, a point whose faces make more than one fan is not closed (fans_whole). what and
 * numbered name the mesh and its points in why. */
/* CGAL's polyhedron builder on f's faces in order, each face taken unless
 * builder_refuses it: take[k] says which; run its first refusal; *border
 * the first point on an edge with one face taken, *unused the first point
 * on faces but none taken (UINT32_MAX: none), *skipped how many faces it
 * refused. 0, or -1 when memory runs out. */
static int builder_take(const build_mesh_faces *f, uint8_t *take, builder_run *run,
                        uint32_t *border, uint32_t *unused, uint32_t *skipped)
{
    uint32_t total = f->face_start[f->face_count];
    size_t slots = 16;
    while (slots < 2 * (size_t)total + 2)
        slots *= 2;
    edge_set edges = {malloc(slots * sizeof *edges.keys), slots - 1};
    uint8_t *used = calloc(f->point_count ? f->point_count : 1, 1);
    uint32_t *open = calloc(f->point_count ? f->point_count : 1, sizeof *open);
    uint32_t *met = calloc(f->point_count ? f->point_count : 1, sizeof *met);
    int st = edges.keys && used && open && met ? 0 : -1;
    for (size_t i = 0; st == 0 && i < slots; i++)
        edges.keys[i] = UINT64_MAX;
    for (uint32_t i = 0; st == 0 && i < total; i++)
        used[f->indices[i]] = 2; /* a point of the mesh: on a face, taken or not */
    *skipped = 0;
    run->refusal = 0;
    for (uint32_t k = 0; st == 0 && k < f->face_count; k++) {
        uint32_t at;
        int no = builder_refuses(f, &edges, used, open, met, k, &at);
        take[k] = !no;
        if (no) {
            if (!run->refusal) {
                run->refusal = no;
                run->face = k;
                run->point = at;
            }
            (*skipped)++;
            continue;
        }
        uint32_t s = f->face_start[k], e = f->face_start[k + 1];
        for (uint32_t i = s; i < e; i++) {
            uint32_t p = f->indices[i], q = f->indices[i + 1 < e ? i + 1 : s];
            uint64_t key = (uint64_t)p << 32 | q;
            edges.keys[edge_slot(&edges, key)] = key;
            if (edge_in(&edges, q, p)) {
                open[p]--;
                open[q]--;
            } else {
                open[p]++;
                open[q]++;
            }
            used[p] = 1;
        }
    }
    *border = *unused = UINT32_MAX;
    for (uint32_t v = 0; st == 0 && v < f->point_count; v++) {
        if (open[v] && *border == UINT32_MAX)
            *border = v;
        if (used[v] == 2 && *unused == UINT32_MAX)
            *unused = v;
    }
    free(edges.keys);
    free(used);
    free(open);
    free(met);
    return st;
}

static int builder_whole(const build_mesh_faces *f, const char *what, int numbered,
                         char *why, size_t size, builder_run *run, const char **openscad)
{
    uint32_t total = f->face_start[f->face_count];
    uint8_t *mine = run->taken ? NULL : malloc(f->face_count ? f->face_count : 1);
    uint8_t *take = run->taken ? run->taken : mine;
    uint32_t border, unused, skipped;
    if (!take || builder_take(f, take, run, &border, &unused, &skipped) < 0) {
        free(mine);
        return -1;
    }
    int whole = -1;
    if (border != UINT32_MAX) {
        *openscad = build_openscad_not_closed;
        whole = build_mesh_sound(f, what, numbered, why, size);
        if (whole > 0 && run->refusal) { /* sound, but the builder skipped a face */
            char reason[160];
            refusal_text(f, numbered, run, "a face", reason, sizeof reason);
            snprintf(why, size, "%s is not closed (%s, and CGAL's builder skips it)",
                     what, reason);
            whole = 0;
        } else if (whole > 0) {
            whole = fans_whole(f, what, numbered, why, size);
        }
    } else if (unused != UINT32_MAX) {
        *openscad = build_openscad_invalid;
        vec3 p = shown_point(f, unused);
        if (numbered && f->names)
            snprintf(why, size, "%s is invalid (no face CGAL takes uses point %u)", what,
                     f->names[unused]);
        else
            snprintf(why, size,
                     "%s is invalid (no face CGAL takes uses the point (%g, %g, %g))",
                     what, p.x, p.y, p.z);
        whole = 0;
    } else if (!skipped) {
        *openscad = build_openscad_not_closed;
        whole = fans_whole(f, what, numbered, why, size);
    } else {
        *openscad = build_openscad_not_closed;
        build_mesh_faces kept = *f;
        kept.indices = malloc((size_t)(total ? total : 1) * sizeof *kept.indices);
        kept.face_start = malloc(((size_t)f->face_count + 1) * sizeof *kept.face_start);
        kept.twice = NULL;
        if (kept.indices && kept.face_start) {
            faces_taken(f, take, &kept);
            whole = fans_whole(&kept, what, numbered, why, size);
        }
        free(kept.indices);
        free(kept.face_start);
    }
    free(mine);
    return whole;
}

/* A point keyed for caps_split: by its x (sorting a cap's points), or by
 * where along an edge it lies; i is its number. */
typedef struct cap_key {
    double key;
    uint32_t i;
} cap_key;

static int cap_key_cmp(const void *a, const void *b)
{
    const cap_key *p = a, *q = b;
    return p->key < q->key ? -1 : p->key > q->key ? 1 : (p->i > q->i) - (p->i < q->i);
}

/* The points of cps[0 .. m) (a cap's, sorted by x) that lie on the
 * edge a-b: within 2^-22 of it and more than 2^-20 (OpenSCAD's grid) from
 * its ends, into stops in order along it; their count. */
static size_t edge_stops(const vec3 *points, const cap_key *cps, size_t m, vec3 a, vec3 b,
                         cap_key *stops)
{
    const double near = 0x1p-22, apart = 0x1p-20;
    vec3 ab = v3_sub(b, a);
    double len2 = v3_dot(ab, ab);
    if (!(len2 > 0))
        return 0;
    double xlo = fmin(a.x, b.x) - near, xhi = fmax(a.x, b.x) + near;
    size_t lo = 0, hi = m, count = 0;
    while (lo < hi) { /* the first point at xlo or beyond */
        size_t mid = lo + (hi - lo) / 2;
        if (cps[mid].key < xlo)
            lo = mid + 1;
        else
            hi = mid;
    }
    for (size_t q = lo; q < m && cps[q].key <= xhi; q++) {
        if (q > lo && cps[q].i == cps[q - 1].i)
            continue;
        vec3 ap = v3_sub(points[cps[q].i], a);
        double t = v3_dot(ap, ab) / len2;
        if (t > 0 && t < 1 && v3_length(ap) > apart &&
            v3_length(v3_sub(points[cps[q].i], b)) > apart &&
            v3_length(v3_sub(ap, v3_scale(ab, t))) <= near)
            stops[count++] = (cap_key){t, cps[q].i};
    }
    qsort(stops, count, sizeof *stops, cap_key_cmp);
    return count;
}

/* ch's faces with each cap's edges split where OpenSCAD's tessellation of
 * that cap splits them (build_mesh_checks): at each point of the same cap
 * on the edge (edge_stops); the caps' faces first, as OpenSCAD appends
 * them before the sides. Into *indices and *face_start (malloc'd), and
 * the first edge split and the point (a, b, p) into split, or UINT32_MAX
 * in split[0]; 0 when memory runs out. */
static int caps_split(const vec3 *points, const build_mesh_checks *ch, uint32_t **indices,
                      uint32_t **face_start, uint32_t split[3])
{
    split[0] = UINT32_MAX;
    uint32_t total = ch->face_start[ch->face_count];
    size_t cap = (size_t)total + 16, n = 0, counts[3] = {0, 0, 0};
    uint32_t *out = malloc(cap * sizeof *out);
    uint32_t *starts = malloc(((size_t)ch->face_count + 1) * sizeof *starts);
    cap_key *cps = malloc((size_t)(total ? total : 1) * sizeof *cps);
    cap_key *stops = malloc((size_t)(total ? total : 1) * sizeof *stops);
    int ok = out && starts && cps && stops;
    /* the points of cap 1, then of cap 2, each sorted by x */
    for (uint32_t k = 0; ok && k < ch->face_count; k++)
        if (ch->cap_of[k] == 1 || ch->cap_of[k] == 2)
            counts[ch->cap_of[k]] += ch->face_start[k + 1] - ch->face_start[k];
    size_t at[3] = {0, 0, counts[1]};
    for (uint32_t k = 0; ok && k < ch->face_count; k++)
        if (ch->cap_of[k] == 1 || ch->cap_of[k] == 2)
            for (uint32_t j = ch->face_start[k]; j < ch->face_start[k + 1]; j++)
                cps[at[ch->cap_of[k]]++] =
                    (cap_key){points[ch->indices[j]].x, ch->indices[j]};
    if (ok) {
        qsort(cps, counts[1], sizeof *cps, cap_key_cmp);
        qsort(cps + counts[1], counts[2], sizeof *cps, cap_key_cmp);
    }
    /* the first cap's faces, then the second's, then the others, as
     * OpenSCAD's extrusions append them */
    uint32_t made = 0;
    for (uint64_t step = 0; step < 3 * (uint64_t)ch->face_count; step++) {
        uint32_t k = (uint32_t)(step % ch->face_count);
        uint8_t which = ch->cap_of[k];
        if (!ok || (which == 1 || which == 2 ? which - 1u : 2u) != step / ch->face_count)
            continue;
        uint32_t s = ch->face_start[k], e = ch->face_start[k + 1];
        starts[made++] = (uint32_t)n;
        for (uint32_t j = s; ok && j < e; j++) {
            uint32_t a = ch->indices[j], b = ch->indices[j + 1 < e ? j + 1 : s];
            size_t count = which == 1 || which == 2
                               ? edge_stops(points, cps + (which == 2 ? counts[1] : 0),
                                            counts[which], points[a], points[b], stops)
                               : 0;
            if (n + 1 + count > UINT32_MAX ||
                !grow_array((void **)&out, &cap, n + 1 + count, sizeof *out)) {
                ok = 0;
                break;
            }
            out[n++] = a;
            for (size_t q = 0; q < count; q++)
                out[n++] = stops[q].i;
            if (count && split[0] == UINT32_MAX) {
                split[0] = a;
                split[1] = b;
                split[2] = stops[0].i;
            }
        }
    }
    if (ok)
        starts[ch->face_count] = (uint32_t)n;
    free(cps);
    free(stops);
    if (!ok) {
        free(out);
        free(starts);
        return 0;
    }
    *indices = out;
    *face_start = starts;
    return 1;
}

/* Whether a builder's mesh, closed as built, is still closed where OpenSCAD
 * 2021.01 hands it to CGAL: its polyhedron builder merges the points on
 * the 2^-20 grid (build_mesh_merge) and skips a face that would give an
 * edge a third face or a point a second fan of faces, so a profile whose
 * outlines touch at a point (a pinch) extrudes to a mesh that is "not
 * closed", as does one scaled to a point over a profile with a hole. 1, 0
 * with why, or -1 when memory ran out. */
static int sound_on_grid(const build_ctx *c, const sc_location *loc, const char *what,
                         int numbered, const vec3 *points, uint32_t point_count,
                         const uint32_t *indices, const uint32_t *face_start,
                         uint32_t face_count, char *why, size_t size,
                         const char **openscad)
{
    build_mesh_faces f;
    sc_error quiet = {SC_OK, "", 0, 0, ""};
    build_ctx merge = *c;
    merge.error = &quiet;
    if (build_mesh_merge(&merge, loc, 0, points, point_count, indices, face_start,
                         face_count, &f) != SC_OK)
        return -1;
    int sound = f.face_count
                    ? build_mesh_cgal_sound(&f, what, numbered, 0, why, size, openscad)
                    : 1;
    build_mesh_faces_free(&f);
    return sound;
}

sc_status build_mesh_prim(const build_ctx *c, const sc_location *loc, const char *what,
                          int numbered, const vec3 *points, uint32_t point_count,
                          const uint32_t *indices, const uint32_t *face_start,
                          uint32_t face_count, prim *out, const char **empty)
{
    build_mesh_checks as_built = {indices, face_start, face_count, NULL};
    return build_mesh_prim_checked(c, loc, what, numbered, points, point_count, indices,
                                   face_start, face_count, &as_built, out, empty);
}

sc_status build_mesh_prim_checked(const build_ctx *c, const sc_location *loc,
                                  const char *what, int numbered, const vec3 *points,
                                  uint32_t point_count, const uint32_t *indices,
                                  const uint32_t *face_start, uint32_t face_count,
                                  const build_mesh_checks *openscad, prim *out,
                                  const char **empty)
{
    size_t tri_count;
    sc_status st = charge_fans(c, loc, what, face_start, face_count, &tri_count);
    if (st != SC_OK)
        return st;
    char why[SC_ERROR_MESSAGE_MAX];
    /* sound: the mesh drawn takes the winding rule, else parity; closed:
     * OpenSCAD's mesh is, which a mended one is as built (its splits may
     * give an edge four faces) */
    int sound = mesh_sound(what, numbered, points, NULL, indices, face_start, face_count,
                           why, sizeof why);
    int closed = openscad->indices != indices ? (sound >= 0) : sound;
    const char *refusal = build_openscad_not_closed;
    if (closed > 0 && c->faithful && !c->drawn_as_is) {
        uint32_t *split = NULL, *split_start = NULL, first[3] = {UINT32_MAX, 0, 0};
        if (openscad->cap_of &&
            !caps_split(points, openscad, &split, &split_start, first))
            closed = -1;
        else
            closed = sound_on_grid(c, loc, what, numbered, points, point_count,
                                   split ? split : openscad->indices,
                                   split ? split_start : openscad->face_start,
                                   openscad->face_count, why, sizeof why, &refusal);
        free(split);
        free(split_start);
        if (closed == 0 && first[0] != UINT32_MAX) {
            vec3 a = points[first[0]], b = points[first[1]], p = points[first[2]];
            snprintf(why, sizeof why,
                     "%s is not closed (its cap's edge (%g, %g, %g)-(%g, %g, %g) passes "
                     "through its point (%g, %g, %g), where OpenSCAD's tessellation "
                     "splits the cap but not the side)",
                     what, a.x, a.y, a.z, b.x, b.y, b.z, p.x, p.y, p.z);
        }
    }
    if (sound < 0 || closed < 0)
        return err_nomem(c->error, loc);
    if (!closed && c->strict)
        return err_set(c->error, SC_ERR_SEMANTIC, loc, "%s", why);
    if (!closed && c->faithful && !c->drawn_as_is) {
        *empty = ""; /* the reason is the warning */
        return build_note(c, loc, "%s; left out, as OpenSCAD leaves it out (\"%s\")", why,
                          refusal);
    }
    uint32_t *tris = malloc((tri_count ? tri_count : 1) * 3 * sizeof *tris);
    if (!tris)
        return err_nomem(c->error, loc);
    size_t k = 0;
    for (uint32_t f = 0; f < face_count; f++) {
        uint32_t s = face_start[f], e = face_start[f + 1];
        if (!numbered && e - s > 4) {
            halves(indices + s, 0, e - s - 1, tris, &k);
            continue;
        }
        for (uint32_t i = s + 1; i + 1 < e; i++) {
            tris[3 * k] = indices[s];
            tris[3 * k + 1] = indices[i];
            tris[3 * k + 2] = indices[i + 1];
            k++;
        }
    }
    st = finish_mesh(c, loc, numbered, points, point_count, tris, k, !sound, out, empty);
    free(tris);
    if (st == SC_OK && !closed && !*empty)
        st = build_note(
            c, loc, "%s; rendered by the parity rule (--strict makes it an error)", why);
    return st;
}

/* ---- OpenSCAD's triangulation of a quadrilateral ----
 *
 * OpenSCAD 2021.01 (PolysetUtils::tessellate_faces) casts the points of
 * each face to float and hands faces of four or more points to libtess2
 * with TESS_CONSTRAINED_DELAUNAY_TRIANGLES and no normal. For a quad whose
 * projection is simple, what libtess2 does comes down to this:
 *  - The normal (ComputeNormal): the axis of widest extent of the points,
 *    its first lowest and first highest point in libtess2's vertex list,
 *    and of the points the one making the largest triangle with those two
 *    (the first of equals); the normal is that cross product. libtess2's
 *    list holds the contour's points from the second on, then the first,
 *    and OpenSCAD's contour is the face reversed (PolyhedronNode inserts
 *    each point at the front), so a face p0 p1 p2 p3 is listed p2 p1 p0 p3.
 *  - The projection (tessProjectPolygon): i = the normal's largest
 *    component (the first of equals), s = x_(i+1), t = +-x_(i+2) by the
 *    sign of the normal's component i; then t is negated when the
 *    contour's signed area in (s, t) is negative (CheckOrientation), so the
 *    contour runs counter-clockwise: the face itself runs clockwise.
 *  - The first triangulation (tessMeshTessellateMonoRegion): with L the
 *    least and R the greatest point in (s, t) lexicographic order, the
 *    diagonal is the other two points when L and R are opposite, else R to
 *    the neighbour of L that is not R.
 *  - The Delaunay refinement (tessMeshRefineDelaunay): the diagonal is
 *    flipped when the two angles facing it sum to pi + 0.01 or more
 *    (tesedgeIsLocallyDelaunay), each angle the acos of a cosine computed
 *    in float. The 0.01 is the tie rule: between the two, within 0.01 of
 *    a circle through all four points, the first triangulation stays.
 * All of it in float, as libtess2 computes (TESSreal). A quad whose
 * projection crosses itself (a bow tie) is cut by libtess2 at the crossing
 * and OpenSCAD mends the result in an order that depends on its hash
 * tables: build_mesh_solid splits those by bowtie_ear instead. */

#define TESS_PI 3.14159265358979323846

static int vert_leq(const float *s, const float *t, int a, int b)
{
    return s[a] < s[b] || (s[a] == s[b] && t[a] <= t[b]);
}

/* The angle at v1 between v0 - v1 and v2 - v1, as libtess2's calcAngle. */
static float tess_angle(const float *s, const float *t, int v0, int v1, int v2)
{
    float a0 = s[v2] - s[v1], a1 = t[v2] - t[v1];
    float b0 = s[v0] - s[v1], b1 = t[v0] - t[v1];
    float num = a0 * b0 + a1 * b1;
    float den =
        (float)(sqrt((double)(a0 * a0 + a1 * a1)) * sqrt((double)(b0 * b0 + b1 * b1)));
    if (den > 0.0f)
        num /= den;
    if (num < -1.0f)
        num = -1.0f;
    if (num > 1.0f)
        num = 1.0f;
    return (float)acos((double)num);
}

/* libtess2's projection of the polygon p[0..n) (n <= TESS_MAX_POINTS) into
 * s[k], t[k] (k a position in p), in float: the normal as ComputeNormal
 * finds it on libtess2's vertex list, which holds the contour from its
 * second point on, then its first; the contour is p reversed when
 * reversed (a polyhedron's face). The t axis is not yet turned for the
 * contour's orientation. Returns 0 when a point is beyond float or the
 * points lie on a line (no area either way). */
static int tess_project(const vec3 *p, uint32_t n, int reversed, float *s, float *t)
{
    float small[16][3];
    float(*v)[3] = n <= 16 ? small : malloc((size_t)n * sizeof *v);
    if (!v)
        return 0;
    for (uint32_t k = 0; k < n; k++) {
        if (!(v3_max_abs(p[k]) <= FLT_MAX)) { /* beyond float, as beyond OpenSCAD */
            if (v != small)
                free(v);
            return 0;
        }
        v[k][0] = (float)p[k].x;
        v[k][1] = (float)p[k].y;
        v[k][2] = (float)p[k].z;
    }
    /* listed j: contour point j + 1, then contour point 0 */
#define LISTED(j) (reversed ? n - 1 - ((j) + 1) % n : ((j) + 1) % n)
    float lo[3], hi[3];
    uint32_t lo_at[3], hi_at[3];
    for (int a = 0; a < 3; a++) {
        lo[a] = hi[a] = v[LISTED(0)][a];
        lo_at[a] = hi_at[a] = LISTED(0);
    }
    for (uint32_t j = 0; j < n; j++) {
        uint32_t k = LISTED(j);
        for (int a = 0; a < 3; a++) {
            if (v[k][a] < lo[a]) {
                lo[a] = v[k][a];
                lo_at[a] = k;
            }
            if (v[k][a] > hi[a]) {
                hi[a] = v[k][a];
                hi_at[a] = k;
            }
        }
    }
    int i = 0;
    if (hi[1] - lo[1] > hi[0] - lo[0])
        i = 1;
    if (hi[2] - lo[2] > hi[i] - lo[i])
        i = 2;
    float norm[3] = {0, 0, 1};
    if (lo[i] < hi[i]) {
        const float *v1 = v[lo_at[i]], *v2 = v[hi_at[i]];
        float d1[3] = {v1[0] - v2[0], v1[1] - v2[1], v1[2] - v2[2]};
        float most = 0;
        for (uint32_t j = 0; j < n; j++) {
            const float *q = v[LISTED(j)];
            float d2[3] = {q[0] - v2[0], q[1] - v2[1], q[2] - v2[2]};
            float c[3] = {d1[1] * d2[2] - d1[2] * d2[1], d1[2] * d2[0] - d1[0] * d2[2],
                          d1[0] * d2[1] - d1[1] * d2[0]};
            float len2 = c[0] * c[0] + c[1] * c[1] + c[2] * c[2];
            if (len2 > most) {
                most = len2;
                memcpy(norm, c, sizeof norm);
            }
        }
        if (most <= 0) {
            if (v != small)
                free(v);
            return 0;
        }
    }
#undef LISTED
    int axis = 0;
    if (fabsf(norm[1]) > fabsf(norm[0]))
        axis = 1;
    if (fabsf(norm[2]) > fabsf(norm[axis]))
        axis = 2;
    for (uint32_t k = 0; k < n; k++) {
        s[k] = v[k][(axis + 1) % 3];
        t[k] = norm[axis] > 0 ? v[k][(axis + 2) % 3] : -v[k][(axis + 2) % 3];
    }
    if (v != small)
        free(v);
    return 1;
}

int build_mesh_quad_diagonal(const vec3 q[4], int reversed)
{
    static const int lists[2][4] = {{1, 2, 3, 0}, {2, 1, 0, 3}};
    const int *listed = lists[reversed != 0];
    float s[4], t[4];
    if (!tess_project(q, 4, reversed, s, t))
        return 0;
    /* the contour: p3 p2 p1 p0 when reversed, else p0 p1 p2 p3 */
    float area = 0;
    for (int j = 0; j < 4; j++) {
        int a = reversed ? 3 - j : j, b = reversed ? (a + 3) % 4 : (a + 1) % 4;
        area += (s[a] - s[b]) * (t[a] + t[b]);
    }
    if (area < 0)
        for (int k = 0; k < 4; k++)
            t[k] = -t[k];
    /* Two neighbours on one point of the projection: libtess2 merges them
     * into the one it lists first and makes one triangle, and OpenSCAD
     * mends the sliver between the two; the diagonal runs from that one. */
    for (int k = 0; k < 4; k++) {
        int k1 = (k + 1) % 4;
        if (s[k] == s[k1] && t[k] == t[k1]) {
            for (int j = 0; j < 4; j++)
                if (listed[j] == k || listed[j] == k1)
                    return listed[j] % 2;
        }
    }
    /* One reflex corner (a quad that is not convex in projection): the
     * only diagonal inside is the one from it. */
    int reflex = -1, reflexes = 0;
    for (int k = 0; k < 4; k++) {
        int p = (k + 3) % 4, n = (k + 1) % 4;
        double turn = ((double)s[k] - s[p]) * ((double)t[n] - t[k]) -
                      ((double)t[k] - t[p]) * ((double)s[n] - s[k]);
        if (reversed ? turn > 0 : turn < 0) {
            reflex = k;
            reflexes++;
        }
    }
    if (reflexes == 1)
        return reflex % 2;
    int least = 0, most_at = 0;
    for (int k = 1; k < 4; k++) {
        if (!vert_leq(s, t, least, k))
            least = k;
        if (vert_leq(s, t, most_at, k))
            most_at = k;
    }
    /* 0: the diagonal p0-p2, 1: p1-p3. L and R opposite: the other two;
     * else R and the other neighbour of L, which face each other. */
    int diagonal = (least + 2) % 4 == most_at ? (least + 1) % 2 : most_at % 2;
    int a = diagonal, c = diagonal + 2, b = (diagonal + 1) % 4, d = (diagonal + 3) % 4;
    float sum = tess_angle(s, t, a, b, c) + tess_angle(s, t, a, d, c);
    if (!((double)sum < TESS_PI + 0.01))
        diagonal = 1 - diagonal;
    return diagonal;
}

/* ---- bow ties ----
 *
 * A quad whose projection crosses itself is cut by libtess2 at the
 * crossing (TESS_WINDING_ODD keeps both lobes), so every triangle it
 * returns has the new point, and OpenSCAD 2021.01
 * (GeometryUtils::tessellatePolygonWithHoles) drops them all. It then
 * fills the face's four edges, left in its edge table, with ears
 * (tess_mend.h), in the order of its hash tables. Checked against
 * OpenSCAD 2021.01's STL export: 268 of 268 bow ties of five seeded
 * twisted rings. */

/* The point of a bow tie (its position in g, OpenSCAD's numbers of the
 * quad's points in the order OpenSCAD holds the face) at which OpenSCAD
 * cuts its first ear, whose diagonal is the one not through it; -1 when
 * memory runs out. */
static int bowtie_ear(const uint32_t g[4])
{
    uint32_t ears[6];
    long made = tess_mend(g, 4, NULL, 0, ears, 2);
    if (made < 0)
        return made == -1 ? -1 : 0; /* the loop of four always closes */
    return (int)ears[1];
}

int build_mesh_quad_crosses(const vec3 q[4], int reversed)
{
    float s[4], t[4];
    if (!tess_project(q, 4, reversed, s, t))
        return 0;
    for (int k = 0; k < 2; k++) { /* edges k, k + 1 against k + 2, k + 3 */
        int a = k, b = k + 1, c = k + 2, d = (k + 3) % 4;
        double d1 = ((double)s[b] - s[a]) * ((double)t[c] - t[a]) -
                    ((double)t[b] - t[a]) * ((double)s[c] - s[a]);
        double d2 = ((double)s[b] - s[a]) * ((double)t[d] - t[a]) -
                    ((double)t[b] - t[a]) * ((double)s[d] - s[a]);
        double d3 = ((double)s[d] - s[c]) * ((double)t[a] - t[c]) -
                    ((double)t[d] - t[c]) * ((double)s[a] - s[c]);
        double d4 = ((double)s[d] - s[c]) * ((double)t[b] - t[c]) -
                    ((double)t[d] - t[c]) * ((double)s[b] - s[c]);
        if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) &&
            ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)))
            return 1;
    }
    return 0;
}

/* ---- OpenSCAD's triangulation of larger faces ----
 *
 * A face of five or more points goes to libtess2 like a quad: projected
 * as above (tess_project), its contour turned counter-clockwise, then
 * swept into monotone regions, each region triangulated
 * (tessMeshTessellateMonoRegion), and the triangles refined by edge flips
 * (tessMeshRefineDelaunay). An edge is flipped when the two angles
 * facing it sum to pi + 0.01 or more, and three of the four edges around
 * it go back on the stack (the copy OpenSCAD 2021.01 bundles stops its
 * loop at three). Where no four points lie within that tolerance of one
 * circle and the loop leaves no edge behind, the result is the
 * constrained Delaunay triangulation, whatever the first triangulation
 * was. Elsewhere the first triangulation and the order of the flips
 * decide, so both are followed as libtess2 does them: a small half-edge
 * mesh with libtess2's own operations (tessMeshConnect,
 * tessMeshFlipEdge), its order of faces (a new face goes just before the
 * face it was cut from) and its stack of edges.
 *
 * A projection that is monotone along s (one leftmost and one rightmost
 * point in (s, t) order, which every convex one is) is a single region:
 * libtess2's sweep adds no edge inside it, and the region is split by
 * libtess2's monotone rule, exactly. Any other projection is swept as
 * libtess2 sweeps it, on its own mesh (tess_sweep.c), so that its faces
 * come in libtess2's order, points on one point merged, points on other
 * edges spliced into them and edges that cross cut at a new point, as
 * libtess2 does; where that sweep gives up on a simple polygon, the
 * diagonals inside the polygon are made in libtess2's order (tess_sweep,
 * below). Then each region as above, OpenSCAD's dropping of the
 * triangles with a new point, and its mending of the loops left
 * (tess_mend.h). Checked against libtess2's own source and OpenSCAD's
 * mending (docs/meshes.md). */

#define TESS_MAX_POINTS 4096u /* larger non-planar faces are fans */

typedef struct tess_mesh {
    float *s, *t;  /* the points, by contour position (then those libtess2
                    * makes where edges cross, up to n) */
    uint32_t *org; /* per half-edge; the other half of e is e ^ 1 */
    uint32_t *lnext, *lprev, *lface;
    unsigned char *mark;
    uint32_t edges;      /* half-edges in use */
    uint32_t *face_next; /* the face list; face 0 is its head */
    uint32_t *face_prev, *face_edge;
    unsigned char *inside;
    uint32_t faces;
    uint32_t edge_cap, face_cap; /* the arrays' sizes */
    uint32_t point_cap;          /* room in s and t */
    int full;                    /* a cut found no room: not a simple polygon */
} tess_mesh;

enum { TESS_HEAD, TESS_OUTSIDE, TESS_REGION };

#define TESS_DST(m, e) ((m)->org[(e) ^ 1u])

static int tess_leq(const tess_mesh *m, uint32_t a, uint32_t b)
{
    return m->s[a] < m->s[b] || (m->s[a] == m->s[b] && m->t[a] <= m->t[b]);
}

/* libtess2's EdgeSign (tesedgeSign), in float. */
static float tess_edge_sign(const tess_mesh *m, uint32_t u, uint32_t v, uint32_t w)
{
    float gap_l = m->s[v] - m->s[u], gap_r = m->s[w] - m->s[v];
    if (gap_l + gap_r > 0)
        return (m->t[v] - m->t[w]) * gap_l + (m->t[v] - m->t[u]) * gap_r;
    return 0;
}

/* tessMeshConnect within one face: a new edge from the end of e_org to
 * the start of e_dst; the loop from e_dst round to e_org becomes a new
 * face just before the old one in the list. Returns the new half-edge
 * (its other half stays in the old face). */
static uint32_t tess_connect(tess_mesh *m, uint32_t e_org, uint32_t e_dst)
{
    if (m->edges + 2 > m->edge_cap || m->faces + 1 > m->face_cap) {
        m->full = 1;
        return e_dst ^ 1u;
    }
    uint32_t e = m->edges, sym = e + 1;
    m->edges += 2;
    uint32_t face = m->lface[e_org];
    uint32_t after = m->lnext[e_org], before = m->lprev[e_dst];
    m->org[e] = TESS_DST(m, e_org);
    m->org[sym] = m->org[e_dst];
    m->mark[e] = m->mark[sym] = 0;
    m->lnext[e_org] = e;
    m->lprev[e] = e_org;
    m->lnext[e] = e_dst;
    m->lprev[e_dst] = e;
    m->lnext[before] = sym;
    m->lprev[sym] = before;
    m->lnext[sym] = after;
    m->lprev[after] = sym;
    m->lface[sym] = face;
    m->face_edge[face] = sym;
    uint32_t f = m->faces++;
    m->face_prev[f] = m->face_prev[face];
    m->face_next[m->face_prev[face]] = f;
    m->face_next[f] = face;
    m->face_prev[face] = f;
    m->face_edge[f] = e;
    m->inside[f] = m->inside[face];
    uint32_t x = e;
    do {
        m->lface[x] = f;
        x = m->lnext[x];
    } while (x != e);
    return e;
}

/* tessMeshTessellateMonoRegion on the region face. Returns 0 when it
 * makes no progress (the region was not monotone after all). */
static int tess_mono_region(tess_mesh *m, uint32_t face, uint32_t n)
{
    uint32_t up = m->face_edge[face];
    long guard = 4 * (long)n + 8;
    while (tess_leq(m, TESS_DST(m, up), m->org[up]) && guard-- > 0)
        up = m->lprev[up];
    while (tess_leq(m, m->org[up], TESS_DST(m, up)) && guard-- > 0)
        up = m->lnext[up];
    uint32_t lo = m->lprev[up];
    while (m->lnext[up] != lo) {
        if (guard-- <= 0 || m->full)
            return 0;
        if (tess_leq(m, TESS_DST(m, up), m->org[lo])) {
            while (!m->full && m->lnext[lo] != up &&
                   (tess_leq(m, TESS_DST(m, m->lnext[lo]), m->org[m->lnext[lo]]) ||
                    tess_edge_sign(m, m->org[lo], TESS_DST(m, lo),
                                   TESS_DST(m, m->lnext[lo])) <= 0))
                lo = tess_connect(m, m->lnext[lo], lo) ^ 1u;
            lo = m->lprev[lo];
        } else {
            while (!m->full && m->lnext[lo] != up &&
                   (tess_leq(m, m->org[m->lprev[up]], TESS_DST(m, m->lprev[up])) ||
                    tess_edge_sign(m, TESS_DST(m, up), m->org[up],
                                   m->org[m->lprev[up]]) >= 0))
                up = tess_connect(m, up, m->lprev[up]) ^ 1u;
            up = m->lnext[up];
        }
    }
    while (!m->full && m->lnext[m->lnext[lo]] != up)
        lo = tess_connect(m, m->lnext[lo], lo) ^ 1u;
    return !m->full;
}

static double tess_cross(const tess_mesh *m, uint32_t a, uint32_t b, uint32_t c)
{
    return ((double)m->s[b] - m->s[a]) * ((double)m->t[c] - m->t[a]) -
           ((double)m->t[b] - m->t[a]) * ((double)m->s[c] - m->s[a]);
}

/* tessMeshDelete of the edge whose half e runs from right to left (as an
 * edge of libtess2's sweep): the face left of e, below the edge, joins the
 * face above and leaves the list. */
static void tess_delete(tess_mesh *m, uint32_t e)
{
    uint32_t sym = e ^ 1u, dead = m->lface[e], kept = m->lface[sym];
    m->lnext[m->lprev[e]] = m->lnext[sym];
    m->lprev[m->lnext[sym]] = m->lprev[e];
    m->lnext[m->lprev[sym]] = m->lnext[e];
    m->lprev[m->lnext[e]] = m->lprev[sym];
    uint32_t start = m->lnext[sym];
    m->face_edge[kept] = start;
    uint32_t x = start;
    do {
        m->lface[x] = kept;
        x = m->lnext[x];
    } while (x != start);
    if (dead != kept) {
        m->face_next[m->face_prev[dead]] = m->face_next[dead];
        m->face_prev[m->face_next[dead]] = m->face_prev[dead];
    }
    m->lface[e] = m->lface[sym] = TESS_HEAD; /* gone: in no inside face */
}

/* The half-edge of an inside face that ends at a and from whose corner the
 * segment a-b leaves into the face; UINT32_MAX when there is none. */
static uint32_t tess_corner(const tess_mesh *m, uint32_t a, uint32_t b)
{
    for (uint32_t e = 0; e < m->edges; e++) {
        if (TESS_DST(m, e) != a || !m->inside[m->lface[e]])
            continue;
        uint32_t before = m->org[e], after = TESS_DST(m, m->lnext[e]);
        double ux = (double)m->s[a] - m->s[before], uy = (double)m->t[a] - m->t[before];
        double wx = (double)m->s[after] - m->s[a], wy = (double)m->t[after] - m->t[a];
        double dx = (double)m->s[b] - m->s[a], dy = (double)m->t[b] - m->t[a];
        double turn = ux * wy - uy * wx;
        double from_w = wx * dy - wy * dx;    /* d left of the way out */
        double to_back = dx * -uy - dy * -ux; /* d right of the way back */
        int in = turn > 0 ? from_w > 0 && to_back > 0 : from_w > 0 || to_back > 0;
        if (in)
            return e;
    }
    return UINT32_MAX;
}

/* tessMeshConnect of a to b inside the face both corners share: the new
 * face, left of a -> b, goes before the old one. Returns the half-edge
 * from a to b, or UINT32_MAX when no face holds the segment. */
static uint32_t tess_link(tess_mesh *m, uint32_t a, uint32_t b)
{
    uint32_t into_a = tess_corner(m, a, b);
    if (into_a == UINT32_MAX)
        return UINT32_MAX;
    for (uint32_t e = m->lnext[into_a]; e != into_a; e = m->lnext[e])
        if (m->org[e] == b) {
            uint32_t made = tess_connect(m, into_a, e);
            return m->full ? UINT32_MAX : made;
        }
    return UINT32_MAX;
}

/* An edge crossing the sweep line: right and left ends (contour points),
 * whether it is a temporary edge of a right vertex (libtess2's
 * fixUpperEdge) and its half-edge from left to right in the mesh, and
 * whether the region below it is inside. */
typedef struct tess_active {
    uint32_t right, left, half;
    int fix, inside;
} tess_active;

#define TESS_NONE UINT32_MAX /* a sentinel's end: beyond every point */

/* 1 when point v lies above the active edge a (libtess2's EdgeSign). */
static int tess_above(const tess_mesh *m, const tess_active *a, uint32_t v)
{
    return tess_edge_sign(m, a->left, v, a->right) > 0;
}

/* VertLeq with the sentinels' far ends. */
static int tess_leq_far(const tess_mesh *m, uint32_t a, uint32_t b, int far_left)
{
    if (a == TESS_NONE || b == TESS_NONE)
        return far_left ? a == TESS_NONE : b == TESS_NONE;
    return tess_leq(m, a, b);
}

/* Replaces the temporary edge act[k] by a real one between v and its left
 * end (libtess2's connect, drawn from v when from_v, then FixUpperEdge).
 * Returns 0 on failure. */
static int tess_fix(tess_mesh *m, tess_active *act, uint32_t k, uint32_t v, int from_v)
{
    tess_active *a = &act[k];
    if (a->inside) {
        uint32_t half = from_v ? tess_link(m, v, a->left) : tess_link(m, a->left, v);
        if (half == TESS_NONE)
            return 0;
        if (a->half != TESS_NONE)
            tess_delete(m, a->half ^ 1u);
    }
    a->right = v;
    a->fix = 0;
    a->half = TESS_NONE;
    return 1;
}

/* Where libtess2's own sweep (tess_sweep.c) gives up: over a simple
 * polygon (contour 0 .. n - 1, counter-clockwise, no two points equal),
 * the diagonals its ConnectLeftVertex, ConnectRightVertex and
 * FixUpperEdge add to the inside, in its order; its temporary edges
 * outside, which also move faces in its list, are not made. Each face
 * left is monotone. Returns 0 on failure, -1 when out of memory. */
static int tess_sweep(tess_mesh *m, uint32_t n)
{
    uint32_t *order = malloc(n * sizeof *order);
    tess_active *act = malloc((2 * (size_t)n + 2) * sizeof *act);
    if (!order || !act) {
        free(order);
        free(act);
        return -1;
    }
    for (uint32_t i = 0; i < n; i++)
        order[i] = i;
    for (uint32_t i = 1; i < n; i++) /* insertion sort in (s, t) order */
        for (uint32_t j = i; j > 0 && !tess_leq(m, order[j - 1], order[j]); j--) {
            uint32_t x = order[j];
            order[j] = order[j - 1];
            order[j - 1] = x;
        }
    uint32_t count = 0;
    int ok = 1;
    for (uint32_t q = 0; ok && q < n; q++) {
        uint32_t v = order[q], prev = (v + n - 1) % n, next = (v + 1) % n;
        uint32_t i = 0;
        while (i < count && act[i].right != v)
            i++;
        if (i == count) { /* no edge ends here: a left vertex */
            uint32_t k = 0;
            while (k < count && !tess_above(m, &act[k], v))
                k++;
            int inside = k > 0 && act[k - 1].inside;
            uint32_t up_left = k > 0 ? act[k - 1].left : TESS_NONE;
            uint32_t lo_left = k < count ? act[k].left : TESS_NONE;
            /* reg = VertLeq(eLo->Dst, eUp->Dst) ? regUp : regLo */
            int use_up = tess_leq_far(m, lo_left, up_left, 1);
            if (use_up && k == 0)
                use_up = 0;
            if (!use_up && k == count)
                use_up = 1;
            uint32_t r = use_up ? k - 1 : k;
            int fix = r < count && act[r].fix;
            if (inside || fix) {
                if (fix) {
                    ok = tess_fix(m, act, r, v, use_up);
                    i = r;
                } else {
                    uint32_t helper = act[r].left;
                    uint32_t half =
                        use_up ? tess_link(m, v, helper) : tess_link(m, helper, v);
                    ok = half != TESS_NONE;
                    memmove(&act[k + 1], &act[k], (count - k) * sizeof *act);
                    act[k] = (tess_active){v, helper, TESS_NONE, 0, inside};
                    count++;
                    i = k;
                }
            } else {
                i = k; /* nothing ends at v: its right edges go in at k */
                goto add_right;
            }
        }
        /* the edges ending at v are act[i .. j) */
        if (ok && i > 0 && act[i - 1].fix && act[i - 1].right != v) {
            ok = tess_fix(m, act, i - 1, v, 1); /* TopLeftRegion */
            i--;
        }
        uint32_t j = i;
        while (ok && j < count && act[j].right == v)
            j++;
        while (ok && j < count && act[j].fix &&
               act[j].right != v) { /* FinishLeftRegions */
            ok = tess_fix(m, act, j, v, 1);
            j++;
        }
        if (!ok)
            break;
        memmove(&act[i], &act[j], (count - j) * sizeof *act);
        count -= j - i;
    add_right:;
        int prev_right = tess_leq(m, v, prev), next_right = tess_leq(m, v, next);
        if (!prev_right && !next_right) {
            /* ConnectRightVertex: to the nearer right end above or below */
            uint32_t up_right = i > 0 ? act[i - 1].right : TESS_NONE;
            uint32_t lo_right = i < count ? act[i].right : TESS_NONE;
            uint32_t target =
                tess_leq_far(m, lo_right, up_right, 0) ? lo_right : up_right;
            int inside = i > 0 && act[i - 1].inside;
            uint32_t half = TESS_NONE;
            if (inside) {
                if (target == TESS_NONE)
                    ok = 0;
                else
                    half = tess_link(m, v, target);
                ok = ok && half != TESS_NONE;
            }
            memmove(&act[i + 1], &act[i], (count - i) * sizeof *act);
            act[i] = (tess_active){target, v, half, 1, inside};
            count++;
            continue;
        }
        /* the right-going edges, upper first; the region below the edge
         * from a to b is inside when the contour runs right to left there */
        tess_active add[2];
        uint32_t adds = 0;
        if (next_right)
            add[adds++] = (tess_active){next, v, TESS_NONE, 0, 0};
        if (prev_right)
            add[adds++] = (tess_active){prev, v, TESS_NONE, 0, 1};
        if (adds == 2) {
            /* order by slope: the edge to the point further left decides */
            int next_up = tess_leq(m, next, prev) ? tess_edge_sign(m, v, next, prev) > 0
                                                  : tess_edge_sign(m, v, prev, next) < 0;
            if (!next_up) {
                tess_active x = add[0];
                add[0] = add[1];
                add[1] = x;
            }
        }
        memmove(&act[i + adds], &act[i], (count - i) * sizeof *act);
        memcpy(&act[i], add, adds * sizeof *add);
        count += adds;
    }
    free(order);
    free(act);
    return ok;
}

/* Each inside face split by the monotone rule, in the order of
 * libtess2's face list (tessMeshTessellateInterior). */
static int tess_mono_regions(tess_mesh *m, uint32_t n)
{
    for (uint32_t f = m->face_next[TESS_HEAD]; f != TESS_HEAD;) {
        uint32_t next = m->face_next[f];
        if (m->inside[f] && !tess_mono_region(m, f, n))
            return 0;
        f = next;
    }
    return 1;
}

/* libtess2's own sweep (tess_sweep.h) in m, when the polygon is in
 * general position for it and m has room: 1, or 0 (m as it was), or -1
 * when memory runs out. */
static int tess_sweep_libtess(tess_mesh *m, uint32_t n)
{
    tess_swept w;
    int got = tess_sweep_faithful(m->s, m->t, n, &w);
    if (got <= 0)
        return got;
    /* the monotone splits add at most one edge and face per point */
    if (n + w.extra > m->point_cap || w.edges + 2 * n > m->edge_cap ||
        w.faces + n > m->face_cap) {
        tess_swept_free(&w);
        return 0;
    }
    for (uint32_t k = 0; k < w.extra; k++) { /* point n + 1 + k: n + k here */
        m->s[n + k] = w.extra_s[k];
        m->t[n + k] = w.extra_t[k];
    }
    for (uint32_t e = 0; e < w.edges; e++) {
        /* a sentinel's point: outside; a point made where edges cross */
        m->org[e] = w.org[e] < n ? w.org[e] : w.org[e] == n ? 0 : w.org[e] - 1;
        m->lnext[e] = w.lnext[e];
        m->lprev[w.lnext[e]] = e;
        m->lface[e] = w.lface[e];
        m->mark[e] = 0;
    }
    for (uint32_t f = 0; f < w.faces; f++) {
        m->face_next[f] = w.face_next[f];
        m->face_prev[f] = w.face_prev[f];
        m->face_edge[f] = w.face_edge[f];
        m->inside[f] = w.inside[f];
    }
    m->edges = w.edges;
    m->faces = w.faces;
    tess_swept_free(&w);
    return 1;
}

/* The sweep, libtess2's own where it can be followed (own: the contour is
 * the face's, no point merged away), else the diagonals inside the
 * polygon in its order; then each region by the monotone rule. */
static int tess_sweep_regions(tess_mesh *m, uint32_t n, int own)
{
    int ok = own ? tess_sweep_libtess(m, n) : 0;
    if (ok == 0)
        ok = tess_sweep(m, n);
    return ok > 0 ? tess_mono_regions(m, n) : ok;
}

static int tess_internal(const tess_mesh *m, uint32_t e)
{
    return m->inside[m->lface[e ^ 1u]];
}

/* tesedgeIsLocallyDelaunay: the angles facing e in its two triangles sum
 * to less than pi + 0.01. */
static int tess_locally_delaunay(const tess_mesh *m, uint32_t e)
{
    uint32_t a = m->org[e], b = TESS_DST(m, e);
    uint32_t left = m->org[m->lnext[m->lnext[e]]];
    uint32_t right = m->org[m->lnext[m->lnext[e ^ 1u]]];
    float sum = tess_angle(m->s, m->t, (int)a, (int)left, (int)b) +
                tess_angle(m->s, m->t, (int)b, (int)right, (int)a);
    return (double)sum < TESS_PI + 0.01;
}

/* tessMeshFlipEdge: e becomes the other diagonal of its two triangles. */
static void tess_flip(tess_mesh *m, uint32_t a0)
{
    uint32_t a1 = m->lnext[a0], a2 = m->lnext[a1];
    uint32_t b0 = a0 ^ 1u, b1 = m->lnext[b0], b2 = m->lnext[b1];
    uint32_t fa = m->lface[a0], fb = m->lface[b0];
    m->org[a0] = m->org[b2];
    m->org[b0] = m->org[a2];
    m->lnext[a0] = a2;
    m->lnext[a2] = b1;
    m->lnext[b1] = a0;
    m->lnext[b0] = b2;
    m->lnext[b2] = a1;
    m->lnext[a1] = b0;
    m->lprev[a2] = a0;
    m->lprev[b1] = a2;
    m->lprev[a0] = b1;
    m->lprev[b2] = b0;
    m->lprev[a1] = b2;
    m->lprev[b0] = a1;
    m->lface[a1] = fb;
    m->lface[b1] = fa;
    m->face_edge[fa] = a0;
    m->face_edge[fb] = b0;
}

/* tessMeshRefineDelaunay, its stack, and a bound on the flips that
 * OpenSCAD 2021.01's copy does not have (later libtess2 added the same,
 * to end loops that would not). */
static void tess_refine(tess_mesh *m, uint32_t *stack)
{
    uint32_t top = 0;
    long faces = 0;
    for (uint32_t f = m->face_next[TESS_HEAD]; f != TESS_HEAD; f = m->face_next[f]) {
        if (!m->inside[f])
            continue;
        uint32_t e = m->face_edge[f];
        do {
            m->mark[e] = (unsigned char)tess_internal(m, e);
            if (m->mark[e] && !m->mark[e ^ 1u])
                stack[top++] = e;
            e = m->lnext[e];
        } while (e != m->face_edge[f]);
        faces++;
    }
    for (long iter = 0; top > 0 && iter < faces * faces; iter++) {
        uint32_t e = stack[--top];
        m->mark[e] = m->mark[e ^ 1u] = 0;
        if (tess_locally_delaunay(m, e))
            continue;
        tess_flip(m, e);
        /* the edges around the flipped one go back on the stack, but the
         * copy OpenSCAD 2021.01 bundles stops at three of the four: not
         * the last, e->Sym->Lprev */
        uint32_t around[3] = {m->lnext[e], m->lprev[e], m->lnext[e ^ 1u]};
        for (int i = 0; i < 3; i++) {
            if (!m->mark[around[i]] && tess_internal(m, around[i])) {
                m->mark[around[i]] = m->mark[around[i] ^ 1u] = 1;
                stack[top++] = around[i];
            }
        }
    }
}

/* 1 when segments ab and cd share a point (in double from float). */
static int tess_segments_meet(const tess_mesh *m, uint32_t a, uint32_t b, uint32_t c,
                              uint32_t d)
{
    double d1 = tess_cross(m, a, b, c), d2 = tess_cross(m, a, b, d);
    double d3 = tess_cross(m, c, d, a), d4 = tess_cross(m, c, d, b);
    if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) &&
        ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)))
        return 1;
    /* collinear touching: a point of one on the other */
    const uint32_t ends[4][3] = {{a, b, c}, {a, b, d}, {c, d, a}, {c, d, b}};
    const double sides[4] = {d1, d2, d3, d4};
    for (int i = 0; i < 4; i++) {
        uint32_t p = ends[i][0], q = ends[i][1], r = ends[i][2];
        if (sides[i] == 0 && fminf(m->s[p], m->s[q]) <= m->s[r] &&
            m->s[r] <= fmaxf(m->s[p], m->s[q]) && fminf(m->t[p], m->t[q]) <= m->t[r] &&
            m->t[r] <= fmaxf(m->t[p], m->t[q]))
            return 1;
    }
    return 0;
}

/* 1 when the contour (positions 0 .. n - 1 in order) is a simple polygon:
 * no two points on one point of the plane, no two edges meeting but
 * neighbours at their common point, no edge folding back on the last. */
static int tess_simple(const tess_mesh *m, uint32_t n)
{
    for (uint32_t i = 0; i < n; i++) {
        uint32_t i1 = (i + 1) % n, i2 = (i + 2) % n;
        if (m->s[i] == m->s[i1] && m->t[i] == m->t[i1])
            return 0;
        if (tess_cross(m, i, i1, i2) == 0 &&
            ((double)m->s[i1] - m->s[i]) * ((double)m->s[i2] - m->s[i1]) +
                    ((double)m->t[i1] - m->t[i]) * ((double)m->t[i2] - m->t[i1]) <
                0)
            return 0;
        for (uint32_t j = i + 2; j < n; j++) {
            if ((j + 1) % n == i)
                continue;
            if (tess_segments_meet(m, i, i1, j, (j + 1) % n))
                return 0;
        }
    }
    return 1;
}

/* 1 when the contour has one least and one greatest point in (s, t) order
 * among its neighbours: a single monotone region for libtess2's sweep. */
static int tess_monotone(const tess_mesh *m, uint32_t n)
{
    uint32_t peaks = 0;
    for (uint32_t i = 0; i < n; i++) {
        uint32_t p = (i + n - 1) % n, q = (i + 1) % n;
        if (tess_leq(m, p, i) && tess_leq(m, q, i))
            peaks++;
    }
    return peaks == 1;
}

/* v in ascending order: three points of a face in the order of the face,
 * which for a triangle of a split of a simple polygon is its winding. */
static void sort3(uint32_t v[3])
{
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 2 - i; j++)
            if (v[j] > v[j + 1]) {
                uint32_t x = v[j];
                v[j] = v[j + 1];
                v[j + 1] = x;
            }
}

/* The whole contour of a face that is not a simple polygon in projection
 * (ps, pt; contour point j is vertex n - 1 - j when reversed; t times
 * sign, so that it runs counter-clockwise) into m's arrays s, t and
 * contour, swept by libtess2's own sweep, which merges points that are
 * one, splices points on other edges and cuts edges that cross as
 * libtess2 does, and each region split by the monotone rule: 1 with the
 * regions in m, 0 where that sweep gives up, -1 when memory runs out. */
static int tess_whole(tess_mesh *m, const float *ps, const float *pt, uint32_t n,
                      int reversed, float sign, float *s, float *t, uint32_t *contour)
{
    for (uint32_t j = 0; j < n; j++) {
        uint32_t a = reversed ? n - 1 - j : j;
        contour[j] = j;
        s[j] = ps[a];
        t[j] = sign * pt[a];
    }
    int ok = tess_sweep_libtess(m, n);
    return ok > 0 ? tess_mono_regions(m, n) : ok;
}

/* Whether contour points j and j + 1 of the face are one point of the
 * projection ps, pt (contour point j is vertex n - 1 - j when reversed). */
static int tess_pair(const float *ps, const float *pt, uint32_t n, int reversed,
                     uint32_t j)
{
    uint32_t a = reversed ? n - 1 - j : j,
             b = reversed ? n - 1 - (j + 1) % n : (j + 1) % n;
    return ps[a] == ps[b] && pt[a] == pt[b];
}

/* The contour point libtess2 drops where it merges contour points j and
 * j + 1: the later into the earlier, but 0 into 1, as its list runs from
 * point 1 round to 0. */
static uint32_t tess_dropped(uint32_t n, uint32_t j)
{
    return j == 0 ? 0 : (j + 1) % n;
}

/* The triangles of the face, in OpenSCAD's order of edges (tess_mend.h):
 * the count triangles in tris (contour points, each from its face's
 * anEdge, as libtess2 lists them) mended with the loops OpenSCAD cuts
 * into ears, where number (NULL: the contour points) gives OpenSCAD's
 * number of each contour point: how many into tris (room for cap), n - 2
 * or, where edges cross, more; 0 where OpenSCAD's loops do not close or
 * make fewer or more than cap; -1 when memory runs out. */
static long tess_mended(const uint32_t *number, uint32_t n, uint32_t count,
                        uint32_t *tris, uint32_t cap)
{
    uint32_t *face = malloc((size_t)n * sizeof *face);
    uint32_t *out = malloc(3 * (size_t)cap * sizeof *out);
    long made = face && out ? 0 : -1;
    for (uint32_t j = 0; face && j < n; j++)
        face[j] = number ? number[j] : j;
    if (made == 0)
        made = tess_mend(face, n, tris, count, out, cap);
    if (made >= (long)(n - 2))
        memcpy(tris, out, 3 * (size_t)made * sizeof *tris);
    free(face);
    free(out);
    return made == -1 ? -1 : made >= (long)(n - 2) ? made : 0;
}

int build_mesh_face_triangles(const vec3 *p, uint32_t n, int reversed,
                              const uint32_t *numbers, uint32_t *tris, uint32_t cap,
                              uint32_t *written)
{
    *written = n >= 3 ? n - 2 : 0;
    for (uint32_t j = 1; j + 1 < n; j++) { /* the fan, unless replaced below */
        tris[3 * (j - 1)] = 0;
        tris[3 * (j - 1) + 1] = j;
        tris[3 * (j - 1) + 2] = j + 1;
    }
    if (n < 4 || n > TESS_MAX_POINTS)
        return n == 3;
    if (n == 4) {
        uint32_t d = (uint32_t)build_mesh_quad_diagonal(p, reversed);
        for (uint32_t j = 0; j < 2; j++) {
            tris[3 * j] = d;
            tris[3 * j + 1] = (d + j + 1) % 4;
            tris[3 * j + 2] = (d + j + 2) % 4;
        }
        return 1;
    }
    /* room for 4 n points made where edges cross, and their edges */
    uint32_t points = 5 * n, half_edges = 10 * points + 32, faces = 4 * points + 16;
    /* one block: s, t by face position, then by vertex (float); the
     * uint32_t arrays (the last OpenSCAD's numbers by contour point); the
     * marks */
    size_t words =
        4 * (size_t)n + 2 * (size_t)points + 5 * (size_t)half_edges + 3 * (size_t)faces;
    uint32_t *block = malloc(words * sizeof(uint32_t) + half_edges + faces);
    if (!block)
        return -1;
    float *ps = (float *)block, *pt = ps + n; /* float and uint32_t: both 4 bytes */
    float *s = pt + n, *t = s + points;
    uint32_t *contour =
        block + 2 * n + 2 * points; /* vertex k: contour point contour[k] */
    tess_mesh m = {
        .s = s, .t = t, .edge_cap = half_edges, .face_cap = faces, .point_cap = points};
    uint32_t *w = contour + n;
    m.org = w;
    m.lnext = w + half_edges;
    m.lprev = w + 2 * half_edges;
    m.lface = w + 3 * half_edges;
    uint32_t *stack = w + 4 * half_edges;
    m.face_next = w + 5 * half_edges;
    m.face_prev = m.face_next + faces;
    m.face_edge = m.face_prev + faces;
    uint32_t *number = m.face_edge + faces;
    m.mark = (unsigned char *)(block + words);
    m.inside = m.mark + half_edges;
    /* contour point j is p[n - 1 - j] when reversed */
#define AT(j) (reversed ? n - 1 - (j) : (j))
    for (uint32_t j = 0; numbers && j < n; j++)
        number[j] = numbers[AT(j)];
    int ok = tess_project(p, n, reversed, ps, pt);
    float sign = 1;
    if (ok) {
        float area = 0;
        for (uint32_t j = 0; j < n; j++) {
            uint32_t a = AT(j), b = AT((j + 1) % n);
            area += (ps[a] - ps[b]) * (pt[a] + pt[b]);
        }
        sign = area < 0 ? -1.0f : 1.0f;
        ok = area != 0;
    }
    /* Neighbours on one point of the projection (contour points j, j + 1):
     * libtess2 merges them, one into the other (tess_dropped), and
     * triangulates the rest; OpenSCAD mends the loops left between the
     * merged points and their neighbours (tess_mend.h). */
    uint32_t pairs = 0, merged = UINT32_MAX;
    for (uint32_t j = 0; ok && j < n; j++)
        if (tess_pair(ps, pt, n, reversed, j)) {
            merged = j;
            pairs++;
        }
    uint32_t dropped = pairs == 1 ? tess_dropped(n, merged) : UINT32_MAX;
    /* First libtess2's own sweep of the whole contour, which merges the
     * pairs as libtess2 does (tess_sweep.h); where it gives up, the
     * contour without the one dropped of a single pair, swept as below. */
    int whole =
        ok && pairs >= 1 ? tess_whole(&m, ps, pt, n, reversed, sign, s, t, contour) : 0;
    if (whole < 0) {
        free(block);
        return -1;
    }
    uint32_t count = whole ? n - pairs : 0;
    for (uint32_t j = 0; ok && !whole && j < n; j++) {
        if (j == dropped)
            continue;
        contour[count] = j;
        s[count] = ps[AT(j)];
        t[count] = sign * pt[AT(j)];
        count++;
    }
    int simple = !whole && ok && pairs <= 1 && count >= 3 && tess_simple(&m, count);
    if (!whole && !simple && ok && pairs == 0) {
        /* a projection that touches itself: libtess2's sweep merges the
         * points that are one */
        whole = tess_whole(&m, ps, pt, n, reversed, sign, s, t, contour);
        if (whole < 0) {
            free(block);
            return -1;
        }
    }
    ok = whole || simple;
    if (ok && !whole) {
        for (uint32_t j = 0; j < count; j++) {
            uint32_t e = 2 * j, next = 2 * ((j + 1) % count);
            uint32_t prev = 2 * ((j + count - 1) % count);
            m.org[e] = j;
            m.org[e + 1] = (j + 1) % count;
            m.lnext[e] = next;
            m.lprev[e] = prev;
            m.lnext[e + 1] = prev + 1;
            m.lprev[e + 1] = next + 1;
            m.lface[e] = TESS_REGION;
            m.lface[e + 1] = TESS_OUTSIDE;
            m.mark[e] = m.mark[e + 1] = 0;
        }
        m.edges = 2 * count;
        m.face_next[TESS_HEAD] = TESS_REGION;
        m.face_prev[TESS_HEAD] = TESS_REGION;
        m.face_next[TESS_REGION] = m.face_prev[TESS_REGION] = TESS_HEAD;
        m.face_edge[TESS_REGION] = 0;
        m.face_edge[TESS_OUTSIDE] = 1;
        m.inside[TESS_HEAD] = m.inside[TESS_OUTSIDE] = 0;
        m.inside[TESS_REGION] = 1;
        m.faces = 3;
        if (count == 3)
            ok = 1;
        else if (tess_monotone(&m, count))
            ok = tess_mono_region(&m, TESS_REGION, count);
        else
            ok = tess_sweep_regions(&m, count, pairs == 0);
        uint32_t live = 0;
        for (uint32_t f = m.face_next[TESS_HEAD]; f != TESS_HEAD; f = m.face_next[f])
            live += m.inside[f];
        if (ok < 0) {
            free(block);
            return -1;
        }
        ok = ok && live == count - 2;
    }
    if (ok) {
        tess_refine(&m, stack);
        /* libtess2's triangles, as it lists them, but those with a point
         * made where edges cross, which OpenSCAD drops */
        uint32_t k = 0, points = whole ? n : count;
        for (uint32_t f = m.face_next[TESS_HEAD]; ok && f != TESS_HEAD;
             f = m.face_next[f]) {
            uint32_t e = m.face_edge[f], v[3];
            for (int i = 0; i < 3; i++, e = m.lnext[e])
                v[i] = m.org[e];
            if (!m.inside[f] || v[0] >= points || v[1] >= points || v[2] >= points)
                continue;
            if (k == cap) {
                ok = 0;
                break;
            }
            for (int i = 0; i < 3; i++)
                tris[3 * k + i] = contour[v[i]];
            k++;
        }
        if (ok && whole) {
            long made = tess_mended(numbers ? number : NULL, n, k, tris, cap);
            ok = made > 0 ? 1 : (int)made;
            if (made > 0)
                *written = (uint32_t)made;
        } else if (pairs == 1) { /* the one sliver, a loop of three edges */
            tris[3 * k] = merged;
            tris[3 * k + 1] = (merged + 1) % n;
            tris[3 * k + 2] =
                dropped == merged ? (merged + n - 1) % n : (dropped + 1) % n;
        }
        for (uint32_t j = 0; ok > 0 && j < *written; j++) {
            for (int i = 0; i < 3; i++)
                tris[3 * j + i] = AT(tris[3 * j + i]);
            sort3(&tris[3 * j]);
        }
    }
#undef AT
    free(block);
    if (ok <= 0) {
        *written = n - 2;
        for (uint32_t j = 1; j + 1 < n; j++) { /* the fan */
            tris[3 * (j - 1)] = 0;
            tris[3 * (j - 1) + 1] = j;
            tris[3 * (j - 1) + 2] = j + 1;
        }
    }
    return ok;
}

/* ---- merging points as OpenSCAD does ----
 *
 * OpenSCAD snaps every point of a polyhedron to a grid of 2^-20
 * (Grid3d with GRID_FINE, PolySet::quantizeVertices) before CGAL sees it:
 * the cell of a point is its coordinates over 2^-20 truncated toward zero;
 * a point whose cell is taken joins that cell's point, else it joins the
 * nearest taken cell among the 26 around it (the first in x, y, z order
 * of equals), else it takes its cell. So a point becomes one with any
 * point before it in the same or a neighbouring cell, which is how BOSL's
 * patches, with a copy of each corner per face, close up. */

typedef struct grid_slot {
    int64_t key[3];
    uint32_t point; /* UINT32_MAX: empty */
} grid_slot;

/* occupied: one bit per hashed block of 16 x 16 x 16 cells, set once a
 * cell in the block is taken, so that a point whose neighbourhood lies in
 * blocks without a taken cell skips the 26 lookups around it (a bit shared
 * by two blocks only costs those lookups). */
typedef struct grid {
    grid_slot *slots;
    size_t mask;
    uint64_t *occupied; /* 8 (mask + 1) bits: at most one in 16 set */
} grid;

static size_t grid_hash(const int64_t k[3])
{
    uint64_t h = (uint64_t)k[0] * 0x9e3779b97f4a7c15u;
    h ^= (uint64_t)k[1] * 0xc2b2ae3d27d4eb4fu + (h << 6) + (h >> 2);
    h ^= (uint64_t)k[2] * 0x165667b19e3779f9u + (h << 6) + (h >> 2);
    return (size_t)(h ^ (h >> 29));
}

/* The block of cell coordinate k: floor(k / 16). */
static int64_t grid_block(int64_t k)
{
    return k >= 0 ? k / 16 : -1 - (-1 - k) / 16;
}

static size_t grid_block_bit(const grid *g, int64_t bx, int64_t by, int64_t bz)
{
    const int64_t b[3] = {bx, by, bz};
    return grid_hash(b) & (8 * g->mask + 7);
}

/* Whether a cell next to k (or k) may be taken: 0 when none is. */
static int grid_near_taken(const grid *g, const int64_t k[3])
{
    int64_t lo[3], hi[3];
    for (int a = 0; a < 3; a++) {
        lo[a] = grid_block(k[a] - 1);
        hi[a] = grid_block(k[a] + 1);
    }
    for (int64_t x = lo[0]; x <= hi[0]; x++)
        for (int64_t y = lo[1]; y <= hi[1]; y++)
            for (int64_t z = lo[2]; z <= hi[2]; z++) {
                size_t bit = grid_block_bit(g, x, y, z);
                if (g->occupied[bit / 64] >> (bit % 64) & 1)
                    return 1;
            }
    return 0;
}

static grid_slot *grid_find(const grid *g, const int64_t k[3])
{
    for (size_t i = grid_hash(k) & g->mask;; i = (i + 1) & g->mask) {
        grid_slot *s = &g->slots[i];
        if (s->point == UINT32_MAX ||
            (s->key[0] == k[0] && s->key[1] == k[1] && s->key[2] == k[2]))
            return s;
    }
}

void build_mesh_faces_free(build_mesh_faces *f)
{
    if (f->lent) { /* the build's files own them */
        memset(f, 0, sizeof *f);
        return;
    }
    free(f->points);
    free(f->names);
    free(f->indices);
    free(f->face_start);
    free(f->face_loops);
    free(f->twice);
    free(f->written);
    memset(f, 0, sizeof *f);
}

/* Where the merged point of a point p goes: p itself in exact mode and
 * where OpenSCAD draws the mesh as it is (no CGAL operation takes it), and
 * where faithful mode hands it to CGAL (snap_float) OpenSCAD's snapped
 * point, its cell's corner as float; a point past 2^40 (a million million), whose cell
 * does not fit an integer comfortably, stays as it is. k gets the cell; 0 is returned for
 * a point that is not gridded. */
/* grid_place's snap: none, the cell's corner as float, or exactly. */
enum { SNAP_NONE, SNAP_FLOAT, SNAP_EXACT };

static int grid_place(vec3 p, int snap, int64_t k[3], vec3 *q)
{
    const double cell = 1.0 / 1048576.0; /* OpenSCAD's GRID_FINE, 2^-20 */
    *q = p;
    if (!(fabs(p.x) < 0x1p40 && fabs(p.y) < 0x1p40 && fabs(p.z) < 0x1p40))
        return 0;
    k[0] = (int64_t)(p.x / cell);
    k[1] = (int64_t)(p.y / cell);
    k[2] = (int64_t)(p.z / cell);
    if (snap == SNAP_FLOAT)
        *q = v3((float)((double)k[0] * cell), (float)((double)k[1] * cell),
                (float)((double)k[2] * cell));
    else if (snap == SNAP_EXACT)
        *q = v3((double)k[0] * cell, (double)k[1] * cell, (double)k[2] * cell);
    return 1;
}

int build_mesh_snap(double v, double *out)
{
    int64_t k[3];
    vec3 q;
    int in = grid_place(v3(v, 0, 0), SNAP_FLOAT, k, &q);
    *out = q.x;
    return in;
}

/* The slot of cell k's point in g, or of the nearest taken cell around k
 * (Grid3d's order), where either is taken; else k's empty slot, for the
 * caller to take (grid_take). */
static grid_slot *grid_lookup(const grid *g, const int64_t k[3])
{
    grid_slot *slot = grid_find(g, k);
    if (slot->point != UINT32_MAX || !grid_near_taken(g, k))
        return slot;
    int best = 10;
    grid_slot *near = NULL;
    for (int64_t dx = -1; dx <= 1; dx++)
        for (int64_t dy = -1; dy <= 1; dy++)
            for (int64_t dz = -1; dz <= 1; dz++) {
                int64_t j[3] = {k[0] + dx, k[1] + dy, k[2] + dz};
                int d = (int)(dx * dx + dy * dy + dz * dz);
                if (d == 0 || d >= best)
                    continue;
                grid_slot *o = grid_find(g, j);
                if (o->point != UINT32_MAX) {
                    best = d;
                    near = o;
                }
            }
    return near ? near : slot;
}

/* Cell k's empty slot (grid_lookup) taken by point u. */
static void grid_take(grid *g, grid_slot *slot, const int64_t k[3], uint32_t u)
{
    memcpy(slot->key, k, sizeof slot->key);
    slot->point = u;
    size_t bit = grid_block_bit(g, grid_block(k[0]), grid_block(k[1]), grid_block(k[2]));
    g->occupied[bit / 64] |= (uint64_t)1 << (bit % 64);
}

/* A grid of room for count points; 0 when memory runs out (nothing to
 * free then). */
static int grid_init(grid *g, uint32_t count)
{
    size_t slots = 16;
    while (slots < 2 * (size_t)count + 2)
        slots *= 2;
    g->slots = malloc(slots * sizeof *g->slots);
    g->mask = slots - 1;
    g->occupied = calloc(slots / 8, sizeof(uint64_t));
    if (!g->slots || !g->occupied) {
        free(g->slots);
        free(g->occupied);
        g->slots = NULL;
        g->occupied = NULL;
        return 0;
    }
    for (size_t i = 0; i < slots; i++)
        g->slots[i].point = UINT32_MAX;
    return 1;
}

/* The merged point of point i (grid above): its index in f. */
static int grid_point(grid *g, build_mesh_faces *f, const vec3 *points, uint32_t i,
                      int snap_float, uint32_t *merged)
{
    int64_t k[3];
    vec3 q;
    grid_slot *slot = NULL;
    if (grid_place(points[i], snap_float ? SNAP_FLOAT : SNAP_NONE, k, &q)) {
        slot = grid_lookup(g, k);
        if (slot->point != UINT32_MAX) {
            *merged = slot->point;
            return 1;
        }
    }
    uint32_t u = f->point_count++;
    f->points[u] = q;
    f->names[u] = i;
    if (slot)
        grid_take(g, slot, k, u);
    *merged = u;
    return 1;
}

sc_status build_mesh_grid_align(const build_ctx *c, const sc_location *loc, vec3 *p,
                                uint32_t count)
{
    grid g;
    if (!grid_init(&g, count))
        return err_nomem(c->error, loc);
    for (uint32_t i = 0; i < count; i++) {
        int64_t k[3];
        vec3 q;
        if (!grid_place(p[i], SNAP_EXACT, k, &q))
            continue;
        grid_slot *slot = grid_lookup(&g, k);
        if (slot->point != UINT32_MAX) {
            p[i] = p[slot->point];
        } else {
            p[i] = q;
            grid_take(&g, slot, k, i);
        }
    }
    free(g.slots);
    free(g.occupied);
    return SC_OK;
}

sc_status build_mesh_merge(const build_ctx *c, const sc_location *loc, int reversed,
                           const vec3 *points, uint32_t point_count,
                           const uint32_t *indices, const uint32_t *face_start,
                           uint32_t face_count, build_mesh_faces *f)
{
    memset(f, 0, sizeof *f);
    uint32_t total = face_start[face_count];
    grid g = {NULL, 0, NULL};
    int gridded = grid_init(&g, point_count);
    uint32_t *map = malloc((size_t)(point_count ? point_count : 1) * sizeof *map);
    f->points = malloc((size_t)(point_count ? point_count : 1) * sizeof *f->points);
    f->names = malloc((size_t)(point_count ? point_count : 1) * sizeof *f->names);
    f->indices = malloc((size_t)(total ? total : 1) * sizeof *f->indices);
    f->face_start = malloc(((size_t)face_count + 1) * sizeof *f->face_start);
    f->twice = malloc((size_t)(face_count ? face_count : 1) * sizeof *f->twice);
    if (!gridded || !map || !f->points || !f->names || !f->indices || !f->face_start ||
        !f->twice) {
        free(g.slots);
        free(g.occupied);
        free(map);
        build_mesh_faces_free(f);
        return err_nomem(c->error, loc);
    }
    for (uint32_t i = 0; i < point_count; i++)
        map[i] = UINT32_MAX;
    /* Points in the order OpenSCAD meets them: face by face, each face
     * reversed for a polyhedron (see build_mesh_quad_diagonal). */
    for (uint32_t face = 0; face < face_count; face++) {
        uint32_t s = face_start[face], e = face_start[face + 1];
        for (uint32_t j = s; j < e; j++) {
            uint32_t i = indices[reversed ? e - 1 - (j - s) : j];
            if (map[i] == UINT32_MAX)
                grid_point(&g, f, points, i, c->faithful && !c->drawn_as_is, &map[i]);
        }
    }
    uint32_t *seen = calloc(f->point_count ? f->point_count : 1, sizeof *seen);
    if (!seen) {
        free(g.slots);
        free(g.occupied);
        free(map);
        build_mesh_faces_free(f);
        return err_nomem(c->error, loc);
    }
    /* Faces on the merged points, cleaned as OpenSCAD cleans them
     * (tessellatePolygonWithHoles): a point repeated next to itself and a
     * null ear (a b a) go; a face left with fewer than 3 points goes. */
    uint32_t at = 0;
    for (uint32_t face = 0; face < face_count; face++) {
        uint32_t s = face_start[face], e = face_start[face + 1];
        uint32_t *v = &f->indices[at];
        uint32_t n = 0;
        for (uint32_t j = s; j < e; j++)
            v[n++] = map[indices[j]];
        /* the point OpenSCAD's face, without its points repeated next to
         * each other (quantizeVertices), passes through twice */
        uint32_t twice = UINT32_MAX;
        for (uint32_t j = 0; j < n && twice == UINT32_MAX; j++) {
            if (v[j] == v[(j + n - 1) % n])
                continue; /* its run is counted once, where it starts */
            if (seen[v[j]] == face + 1)
                twice = v[j];
            seen[v[j]] = face + 1;
        }
        uint32_t i = 0;
        while (n >= 3 && i < n) {
            if (v[i] == v[(i + 1) % n]) {
                memmove(&v[i], &v[i + 1], (size_t)(n - i - 1) * sizeof *v);
                n--;
            } else if (v[(i + n - 1) % n] == v[(i + 1) % n]) {
                if (i == 0) { /* OpenSCAD's index wraps here: it stops */
                    memmove(&v[0], &v[2], (size_t)(n - 2) * sizeof *v);
                    n -= 2;
                    break;
                }
                memmove(&v[i - 1], &v[i + 1], (size_t)(n - i - 1) * sizeof *v);
                n -= 2;
                i--;
            } else {
                i++;
            }
        }
        if (n < 3)
            continue;
        f->twice[f->face_count] = twice;
        f->face_start[f->face_count++] = at;
        at += n;
    }
    f->face_start[f->face_count] = at;
    free(seen);
    free(g.slots);
    free(g.occupied);
    free(map);
    return SC_OK;
}

const affine *build_mesh_since(const affine *since, const affine *m, affine *rest)
{
    const affine *at = since ? since : m;
    affine undo;
    if (!affine_invert(at, &undo)) {
        *rest = *m;
        return NULL;
    }
    *rest = since ? affine_mul(m, &undo) : affine_unmoved;
    return at;
}

sc_status build_mesh_merge_moved(const build_ctx *c, const sc_location *loc, int reversed,
                                 const affine *moved, const vec3 *points,
                                 uint32_t point_count, const uint32_t *indices,
                                 const uint32_t *face_start, uint32_t face_count,
                                 build_mesh_faces *f)
{
    if (!moved)
        return build_mesh_merge(c, loc, reversed, points, point_count, indices,
                                face_start, face_count, f);
    memset(f, 0, sizeof *f);
    uint32_t total = face_start[face_count];
    int mirrored = affine_det(moved) < 0;
    vec3 *p = malloc((size_t)(point_count ? point_count : 1) * sizeof *p);
    uint32_t *turned =
        mirrored ? malloc((size_t)(total ? total : 1) * sizeof *turned) : NULL;
    sc_status st = SC_OK;
    if (!p || (mirrored && !turned)) {
        st = err_nomem(c->error, loc);
    } else {
        for (uint32_t k = 0; k < point_count; k++)
            p[k] = affine_point(moved, points[k]);
        for (uint32_t i = 0; mirrored && i < face_count; i++) {
            uint32_t first = face_start[i], end = face_start[i + 1];
            for (uint32_t k = first; k < end; k++)
                turned[k] = indices[first + end - 1 - k];
        }
        st = build_mesh_merge(c, loc, reversed, p, point_count,
                              mirrored ? turned : indices, face_start, face_count, f);
        /* messages name the points where they are written */
        if (st == SC_OK && f->names &&
            !(f->written = malloc((f->point_count ? f->point_count : 1) * sizeof *p))) {
            build_mesh_faces_free(f);
            st = err_nomem(c->error, loc);
        }
        for (uint32_t k = 0; st == SC_OK && f->names && k < f->point_count; k++)
            f->written[k] = points[f->names[k]];
    }
    free(p);
    free(turned);
    return st;
}

int build_mesh_sound(const build_mesh_faces *f, const char *what, int numbered, char *why,
                     size_t size)
{
    return mesh_sound(what, numbered, f->written ? f->written : f->points, f->names,
                      f->indices, f->face_start, f->face_count, why, size);
}

/* Whether OpenSCAD 2021.01 loses the closed mesh f (the faces CGAL's
 * builder takes marked in taken) on one of CGAL's assertions about a face
 * out of its plane, which it does not answer by triangulating the faces
 * (nef.h's plane_check): 1, with why and *openscad; 0 when it does not (a
 * mesh of triangles, or of faces in their planes, never does); -1 when
 * memory runs out; -2 when the plugin does not load (why in err).
 * CGAL's builder is given the faces as OpenSCAD holds them, reversed (a
 * polyhedron's as written, an import's back to front), and the points in
 * the order that walk meets them. */
static int plane_lost(const build_mesh_faces *f, const char *what, int numbered,
                      const uint8_t *taken, char *why, size_t size, const char **openscad,
                      char *err, size_t err_size)
{
    uint32_t faces = 0, total = 0, big = 0;
    for (uint32_t k = 0; k < f->face_count; k++) {
        uint32_t n = f->face_start[k + 1] - f->face_start[k];
        if (!taken[k])
            continue;
        faces++;
        total += n;
        big |= n > 3;
    }
    if (!big)
        return 0;
    uint32_t *number =
        malloc((size_t)(f->point_count ? f->point_count : 1) * sizeof *number);
    uint32_t *point =
        malloc((size_t)(f->point_count ? f->point_count : 1) * sizeof *point);
    double *xyz = malloc(((size_t)f->point_count * 3 + 1) * sizeof *xyz);
    uint32_t *indices = malloc((size_t)(total ? total : 1) * sizeof *indices);
    uint32_t *starts = malloc(((size_t)faces + 1) * sizeof *starts);
    int lost = -1;
    if (!number || !point || !xyz || !indices || !starts)
        goto done;
    for (uint32_t i = 0; i < f->point_count; i++)
        number[i] = UINT32_MAX;
    uint32_t next = 0, at = 0, count = 0;
    for (uint32_t k = 0; k < f->face_count; k++) {
        uint32_t s = f->face_start[k], n = f->face_start[k + 1] - s;
        if (taken[k])
            starts[count++] = at;
        for (uint32_t j = 0; j < n; j++) {
            uint32_t p = f->indices[s + (numbered ? j : n - 1 - j)];
            if (number[p] == UINT32_MAX) {
                point[next] = p;
                xyz[3 * next] = f->points[p].x;
                xyz[3 * next + 1] = f->points[p].y;
                xyz[3 * next + 2] = f->points[p].z;
                number[p] = next++;
            }
            if (taken[k])
                indices[at++] = number[p];
        }
    }
    starts[count] = at;
    nef_plugin nef;
    if (!nef_plugin_open(&nef, err, err_size)) {
        lost = -2;
        goto done;
    }
    int verdict = 0;
    uint32_t where[2] = {0, 0};
    err[0] = '\0';
    nef_status ns = nef.plane_check(xyz, next, indices, starts, count, &verdict, where,
                                    err, err_size);
    nef_plugin_close(&nef);
    if (ns == NEF_NOMEM)
        goto done;
    lost = ns == NEF_OK && verdict == 2;
    if (lost) {
        uint32_t p = point[where[1] < next ? where[1] : 0];
        vec3 at_point = shown_point(f, p);
        if (numbered && f->names)
            snprintf(why, size,
                     "%s has a face out of its plane at point %u (CGAL's assertion %s "
                     "fails there, and OpenSCAD does not triangulate and try again)",
                     what, f->names[p], err);
        else
            snprintf(
                why, size,
                "%s has a face out of its plane at (%g, %g, %g) (CGAL's assertion %s "
                "fails there, and OpenSCAD does not triangulate and try again)",
                what, at_point.x, at_point.y, at_point.z, err);
        *openscad = openscad_assertion;
    }
done:
    free(number);
    free(point);
    free(xyz);
    free(indices);
    free(starts);
    return lost;
}

/* OpenSCAD 2021.01's verdict on f where its CGAL path takes it (as
 * build_mesh_cgal_sound says): 2 when OpenSCAD finds f convex and takes
 * its hull without the builder; 1 when sound; 0 with why and *openscad;
 * -1 when memory runs out; -2 when planes and the plugin does not load
 * (why says so). With taken, *taken is the faces CGAL's builder takes
 * (malloc'd; NULL unless 0 or 1). */
static int cgal_verdict(const build_mesh_faces *f, const char *what, int numbered,
                        int planes, uint8_t **taken, char *why, size_t size,
                        const char **openscad)
{
    if (taken)
        *taken = NULL;
    int convex = approx_convex(f, numbered);
    if (convex != 0)
        return convex > 0 ? 2 : -1;
    uint8_t *mask = planes || taken ? malloc(f->face_count ? f->face_count : 1) : NULL;
    if ((planes || taken) && !mask)
        return -1;
    builder_run run = {mask, 0, 0, 0};
    int sound = builder_whole(f, what, numbered, why, size, &run, openscad);
    if (sound > 0 && planes) {
        char err[SC_ERROR_MESSAGE_MAX];
        int lost =
            plane_lost(f, what, numbered, mask, why, size, openscad, err, sizeof err);
        if (lost == -2)
            snprintf(why, size, "%s", err);
        sound = lost == 0 ? 1 : lost == 1 ? 0 : lost;
    }
    if (taken && sound >= 0)
        *taken = mask;
    else
        free(mask);
    return sound;
}

int build_mesh_cgal_sound(const build_mesh_faces *f, const char *what, int numbered,
                          int planes, char *why, size_t size, const char **openscad)
{
    int sound = cgal_verdict(f, what, numbered, planes, NULL, why, size, openscad);
    return sound == 2 || sound == -2 ? 1 : sound; /* no plugin: as the builder says */
}

/* A copy of the n bytes at p (malloc'd; NULL for none, or when memory
 * runs out: *ok = 0). */
static void *copied(const void *p, size_t n, int *ok)
{
    if (!p)
        return NULL;
    void *q = malloc(n ? n : 1);
    if (!q)
        *ok = 0;
    else
        memcpy(q, p, n);
    return q;
}

/* f, lent from the build's files, made its own (copies of its arrays),
 * so that it may change; 0 when memory runs out, f as it was. */
static int faces_own(build_mesh_faces *f)
{
    int ok = 1;
    size_t total = f->face_start[f->face_count];
    build_mesh_faces own = *f;
    own.points = copied(f->points, f->point_count * sizeof *f->points, &ok);
    own.names = copied(f->names, f->point_count * sizeof *f->names, &ok);
    own.indices = copied(f->indices, total * sizeof *f->indices, &ok);
    own.face_start =
        copied(f->face_start, ((size_t)f->face_count + 1) * sizeof *f->face_start, &ok);
    own.face_loops =
        copied(f->face_loops, ((size_t)f->face_count + 1) * sizeof *f->face_loops, &ok);
    own.twice = copied(f->twice, f->face_count * sizeof *f->twice, &ok);
    own.written = copied(f->written, f->point_count * sizeof *f->written, &ok);
    own.lent = 0;
    if (!ok) {
        build_mesh_faces_free(&own);
        return 0;
    }
    *f = own;
    return 1;
}

/* Drops from f the faces CGAL's builder skips, unless OpenSCAD finds f
 * convex (reversed: a polyhedron's faces, as approx_convex). 0 when
 * memory runs out. */
static int cgal_keep(build_mesh_faces *f, int reversed)
{
    uint8_t *taken;
    char why[8];
    const char *openscad;
    int sound = cgal_verdict(f, "", reversed, 0, &taken, why, sizeof why, &openscad);
    if (sound == 2)
        return 1;
    if (sound < 0)
        return 0;
    uint32_t kept = 0;
    for (uint32_t k = 0; k < f->face_count; k++)
        kept += taken[k];
    int ok = kept == f->face_count || !f->lent || faces_own(f);
    if (ok && kept < f->face_count)
        faces_taken(f, taken, f);
    free(taken);
    return ok;
}

int build_mesh_cgal_closed(const build_ctx *c, const build_mesh_faces *f,
                           const char *what, int numbered, char *why, size_t size)
{
    const char *openscad;
    return c->faithful && !c->drawn_as_is
               ? build_mesh_cgal_sound(f, what, numbered, 1, why, size, &openscad)
               : build_mesh_sound(f, what, numbered, why, size);
}

/* OpenSCAD's number of each point of f as its tessellation numbers them
 * (tessellate_faces): in the order it first meets them, face by face, each
 * face as OpenSCAD holds it (back to front when reversed). malloc'd; NULL
 * when memory runs out. */
static uint32_t *openscad_numbers(const build_mesh_faces *f, int reversed)
{
    uint32_t *numbers =
        malloc((size_t)(f->point_count ? f->point_count : 1) * sizeof *numbers);
    if (!numbers)
        return NULL;
    for (uint32_t i = 0; i < f->point_count; i++)
        numbers[i] = UINT32_MAX;
    uint32_t next = 0;
    for (uint32_t i = 0; i < f->face_count; i++) {
        uint32_t s = f->face_start[i], n = f->face_start[i + 1] - s;
        for (uint32_t j = 0; j < n; j++) {
            uint32_t p = f->indices[s + (reversed ? n - 1 - j : j)];
            if (numbers[p] == UINT32_MAX)
                numbers[p] = next++;
        }
    }
    return numbers;
}

static int quad_first(const build_mesh_faces *f, const uint32_t *v, int numbered,
                      uint32_t **numbers)
{
    vec3 q[4] = {f->points[v[0]], f->points[v[1]], f->points[v[2]], f->points[v[3]]};
    if (!build_mesh_quad_crosses(q, numbered))
        return build_mesh_quad_diagonal(q, numbered);
    if (!*numbers && !(*numbers = openscad_numbers(f, numbered)))
        return -1;
    uint32_t g[4];
    for (int j = 0; j < 4; j++)
        g[j] = (*numbers)[v[numbered ? 3 - j : j]];
    int ear = bowtie_ear(g);
    return ear < 0 ? -1 : ((numbered ? 3 - ear : ear) + 1) % 2;
}

/* 1 when the face v[0..n) lies in one plane to float's resolution: every
 * point within 2^-23 of the face's extent from the plane through its
 * first point along Newell's normal. Any split of such a face is the same
 * surface to far below the depth rule, and the fan costs nothing. */
static int face_planar(const vec3 *points, const uint32_t *v, uint32_t n)
{
    vec3 normal = v3(0, 0, 0);
    bbox box = bbox_empty();
    for (uint32_t j = 0; j < n; j++) {
        vec3 a = points[v[j]], b = points[v[(j + 1) % n]];
        normal = v3_add(normal, v3_newell(a, b));
        box = bbox_add_point(box, a);
    }
    double length = v3_length(normal);
    vec3 ext = v3_sub(box.hi, box.lo);
    double size = fmax(ext.x, fmax(ext.y, ext.z));
    if (!(length > 0))
        return 1; /* no area: nothing to choose */
    double most = 0x1p-23 * size * length;
    for (uint32_t j = 1; j < n; j++)
        if (!(fabs(v3_dot(normal, v3_sub(points[v[j]], points[v[0]]))) <= most))
            return 0;
    return 1;
}

/* The triangles OpenSCAD 2021.01 makes of f's faces (those taken marks, or
 * all): a quad split on the diagonal its tessellation takes (quad_first),
 * a face of more points out of its plane as the tessellation splits it
 * (build_mesh_face_triangles), any other face fanned. tri_count: the
 * triangles already charged for all of f's faces (n - 2 each); with
 * charge, the triangles a mended face makes beyond those are charged too.
 * Into *out (malloc'd, three points a triangle) and *count. */
static sc_status openscad_triangles(const build_ctx *c, const sc_location *loc,
                                    const char *what, const build_mesh_faces *f,
                                    int numbered, const uint8_t *taken, size_t tri_count,
                                    int charge, uint32_t **out, size_t *count)
{
    size_t tri_cap = (tri_count ? tri_count : 1) * 3; /* in indices */
    uint32_t *tris = malloc(tri_cap * sizeof *tris);
    if (!tris)
        return err_nomem(c->error, loc);
    size_t k = 0;
    sc_status st = SC_OK;
    vec3 *corners = NULL; /* a face's points, for the larger faces */
    uint32_t *local = NULL, corner_cap = 0;
    uint32_t *numbers = NULL; /* OpenSCAD's numbers of the points (tess_mend.h) */
    int oom = 0;
    size_t planned = 0; /* the triangles charged for the faces so far */
    for (uint32_t i = 0; i < f->face_count && !oom; i++) {
        const uint32_t *v = &f->indices[f->face_start[i]];
        uint32_t n = f->face_start[i + 1] - f->face_start[i];
        uint32_t first = 0;
        planned += n > 2 ? n - 2 : 0;
        if (taken && !taken[i])
            continue;
        if (n == 4) {
            int q = quad_first(f, v, numbered, &numbers);
            if (q < 0) {
                oom = 1;
                break;
            }
            first = (uint32_t)q;
        } else if (n > 4 && !face_planar(f->points, v, n)) {
            if (n > corner_cap) {
                free(corners);
                free(local);
                corners = malloc((size_t)n * sizeof *corners);
                /* room for the triangles (more than n - 2 where
                 * OpenSCAD mends a face that crosses itself), then the
                 * numbers */
                local = malloc(13 * (size_t)n * sizeof *local);
                corner_cap = n;
                if (!corners || !local) {
                    oom = 1;
                    break;
                }
            }
            if (!numbers && !(numbers = openscad_numbers(f, numbered))) {
                oom = 1;
                break;
            }
            uint32_t *face_numbers = local + 12 * n, made;
            for (uint32_t j = 0; j < n; j++) {
                corners[j] = f->points[v[j]];
                face_numbers[j] = numbers[v[j]];
            }
            if (build_mesh_face_triangles(corners, n, numbered, face_numbers, local,
                                          4 * n, &made) < 0) {
                oom = 1;
                break;
            }
            if (made > n - 2) { /* charged as n - 2 above */
                st =
                    charge ? build_charge_triangles(c, loc, what, made - (n - 2)) : SC_OK;
                if (st != SC_OK)
                    break;
                if (!grow_array((void **)&tris, &tri_cap,
                                3 * (k + made + tri_count - planned), sizeof *tris)) {
                    oom = 1;
                    break;
                }
            }
            for (uint32_t j = 0; j < 3 * made; j++)
                tris[3 * k + j] = v[local[j]];
            k += made;
            continue;
        }
        /* a fan about point `first`: for a quad, its diagonal */
        for (uint32_t j = 1; j + 1 < n; j++) {
            tris[3 * k] = v[first];
            tris[3 * k + 1] = v[(first + j) % n];
            tris[3 * k + 2] = v[(first + j + 1) % n];
            k++;
        }
    }
    free(corners);
    free(local);
    free(numbers);
    if (oom || st != SC_OK) {
        free(tris);
        return oom ? err_nomem(c->error, loc) : st;
    }
    *out = tris;
    *count = k;
    return SC_OK;
}

/* f's quads and faces out of their planes made OpenSCAD's triangles
 * (build_mesh_cgal_faces). */
static sc_status cgal_triangles(const build_ctx *c, const sc_location *loc,
                                const char *what, build_mesh_faces *f, int numbered)
{
    /* split: the quads and the faces out of their planes; the others stay
     * whole (the plugin triangulates a face in its plane, which a fan of
     * one that is not convex would overlap) */
    size_t tri_count = 0, whole = 0;
    uint8_t *split = malloc(f->face_count ? f->face_count : 1);
    if (!split)
        return err_nomem(c->error, loc);
    for (uint32_t i = 0; i < f->face_count; i++) {
        const uint32_t *v = &f->indices[f->face_start[i]];
        uint32_t n = f->face_start[i + 1] - f->face_start[i];
        split[i] = n == 4 || (n > 4 && !face_planar(f->points, v, n));
        tri_count += n > 2 ? n - 2 : 0;
        whole += split[i] ? 0 : n;
    }
    uint32_t *tris;
    size_t k;
    sc_status st =
        openscad_triangles(c, loc, what, f, numbered, split, tri_count, 0, &tris, &k);
    if (st != SC_OK) {
        free(split);
        return st;
    }
    size_t faces = k + f->face_count, total = 3 * k + whole;
    uint32_t *indices = total < UINT32_MAX ? malloc((total + 1) * sizeof *indices) : NULL;
    uint32_t *starts = malloc((faces + 1) * sizeof *starts);
    if (!indices || !starts || (f->lent && !faces_own(f))) {
        free(split);
        free(tris);
        free(indices);
        free(starts);
        return err_nomem(c->error, loc);
    }
    size_t at = 0, count = 0;
    for (uint32_t i = 0; i < f->face_count; i++) {
        if (split[i])
            continue;
        starts[count++] = (uint32_t)at;
        for (uint32_t j = f->face_start[i]; j < f->face_start[i + 1]; j++)
            indices[at++] = f->indices[j];
    }
    for (size_t t = 0; t < k; t++) {
        starts[count++] = (uint32_t)at;
        for (int j = 0; j < 3; j++)
            indices[at++] = tris[3 * t + j];
    }
    starts[count] = (uint32_t)at;
    free(split);
    free(tris);
    free(f->indices);
    free(f->face_start);
    free(f->face_loops);
    free(f->twice);
    f->indices = indices;
    f->face_start = starts;
    f->face_loops = NULL;
    f->twice = NULL;
    f->face_count = (uint32_t)count;
    return SC_OK;
}

sc_status build_mesh_cgal_faces(const build_ctx *c, const sc_location *loc,
                                const char *what, build_mesh_faces *f, int numbered)
{
    if (!cgal_keep(f, numbered))
        return err_nomem(c->error, loc);
    return f->face_count ? cgal_triangles(c, loc, what, f, numbered) : SC_OK;
}

sc_status build_mesh_solid(const build_ctx *c, const sc_location *loc, const char *what,
                           int numbered, int strict, const build_mesh_faces *f, prim *out,
                           const char **empty)
{
    size_t tri_count;
    sc_status charged =
        charge_fans(c, loc, what, f->face_start, f->face_count, &tri_count);
    if (charged != SC_OK)
        return charged;
    char why[SC_ERROR_MESSAGE_MAX - 160];
    /* taken: the faces CGAL's builder takes, which are all that OpenSCAD's
     * boolean sees of a mesh it finds closed (a face given twice, say); a
     * mesh OpenSCAD finds convex it takes whole, as its hull */
    uint8_t *taken = NULL;
    const char *refusal = build_openscad_not_closed;
    int sound =
        c->faithful && !c->drawn_as_is
            ? cgal_verdict(f, what, numbered, 1, &taken, why, sizeof why, &refusal)
            : 2;
    int cgal = sound != 2;
    if (sound == 2)
        sound = build_mesh_sound(f, what, numbered, why, sizeof why);
    if (sound == -2)
        return err_set(c->error, SC_ERR_UNSUPPORTED, loc, "%s: %s", what, why);
    if (sound < 0) {
        free(taken);
        return err_nomem(c->error, loc);
    }
    if (!sound && (strict || !c->note)) {
        free(taken);
        return err_set(c->error, SC_ERR_SEMANTIC, loc, "%s", why);
    }
    if (!sound && cgal) {
        free(taken);
        err_set(c->note, SC_OK, loc, "%s; left out, as OpenSCAD leaves it out (\"%s\")",
                why, refusal);
        *empty = "";
        return SC_OK;
    }
    uint32_t *tris;
    size_t k;
    sc_status st =
        openscad_triangles(c, loc, what, f, numbered, taken, tri_count, 1, &tris, &k);
    free(taken);
    if (st != SC_OK)
        return st;
    st = finish_mesh(c, loc, numbered, f->points, f->point_count, tris, k, !sound, out,
                     empty);
    free(tris);
    if (st == SC_OK && !sound && !*empty)
        err_set(c->note, SC_OK, loc,
                "%s; rendered by the parity rule (--strict makes it an error)", why);
    return st;
}

/* ---- files ---- */

typedef struct mesh_file {
    vec3 *points;
    uint32_t point_count, point_cap;
    uint32_t *indices, *face_start;
    uint32_t index_count, index_cap, face_count, face_cap;
    uint32_t *lines; /* NULL, or each face's line in the file (OFF) */
} mesh_file;

static void mesh_file_free(mesh_file *m)
{
    free(m->lines);
    free(m->points);
    free(m->indices);
    free(m->face_start);
}

static int add_point(mesh_file *m, vec3 p)
{
    if (!grow_array32((void **)&m->points, &m->point_cap, m->point_count + 1,
                      sizeof(vec3)))
        return 0;
    m->points[m->point_count++] = p;
    return 1;
}

static int add_index(mesh_file *m, uint32_t i)
{
    if (!grow_array32((void **)&m->indices, &m->index_cap, m->index_count + 1,
                      sizeof(uint32_t)))
        return 0;
    m->indices[m->index_count++] = i;
    return 1;
}

/* Starts a face at the current index; the sentinel after the last face is
 * written by finish_faces. */
static int start_face(mesh_file *m)
{
    if (!grow_array32((void **)&m->face_start, &m->face_cap, m->face_count + 2,
                      sizeof(uint32_t)))
        return 0;
    m->face_start[m->face_count++] = m->index_count;
    return 1;
}

static int finish_faces(mesh_file *m)
{
    if (!grow_array32((void **)&m->face_start, &m->face_cap, m->face_count + 1,
                      sizeof(uint32_t)))
        return 0;
    m->face_start[m->face_count] = m->index_count;
    return 1;
}

int build_mesh_keyed_cmp(const void *a, const void *b)
{
    const build_mesh_keyed *x = a, *y = b;
    if (x->p.x != y->p.x)
        return x->p.x < y->p.x ? -1 : 1;
    if (x->p.y != y->p.y)
        return x->p.y < y->p.y ? -1 : 1;
    if (x->p.z != y->p.z)
        return x->p.z < y->p.z ? -1 : 1;
    return x->index < y->index ? -1 : x->index > y->index;
}

/* A coordinate's bits for hashing, with -0 as 0 (the two are equal). */
static uint64_t coordinate_bits(double v)
{
    if (v == 0)
        v = 0;
    uint64_t u;
    memcpy(&u, &v, sizeof u);
    return u;
}

/* A point's hash: the grid's hash (grid_hash) of its coordinates' bits. */
static size_t point_hash(vec3 p)
{
    const int64_t k[3] = {(int64_t)coordinate_bits(p.x), (int64_t)coordinate_bits(p.y),
                          (int64_t)coordinate_bits(p.z)};
    return grid_hash(k);
}

/* STL corners 3i, 3i + 1, 3i + 2 become triangle i; equal corners (==, so
 * -0 and 0 are one) are merged into one point, the first of them, and the
 * points are numbered in (x, y, z) order. Equal corners are found through
 * a hash table, each corner looked up once, and only the distinct points
 * are sorted: an STL of n triangles has 3n corners and about n / 2 points,
 * and sorting every corner took a third of the load of a 10^5-triangle
 * file. */
static int merge_corners(mesh_file *m)
{
    uint32_t n = m->point_count;
    size_t slots = 16;
    while (slots < 2 * (size_t)n + 2)
        slots *= 2;
    uint32_t *table = malloc(slots * sizeof *table); /* a point's number, or empty */
    build_mesh_keyed *k = malloc((size_t)(n ? n : 1) * sizeof *k);
    uint32_t *map = malloc((size_t)(n ? n : 1) * sizeof *map);
    if (!table || !k || !map) {
        free(table);
        free(k);
        free(map);
        return 0;
    }
    memset(table, 0xff, slots * sizeof *table);
    uint32_t unique = 0;
    for (uint32_t i = 0; i < n; i++) {
        vec3 p = m->points[i];
        for (size_t h = point_hash(p) & (slots - 1);; h = (h + 1) & (slots - 1)) {
            uint32_t u = table[h];
            if (u == UINT32_MAX) {
                table[h] = unique;
                k[unique] = (build_mesh_keyed){p, unique};
                map[i] = unique++;
                break;
            }
            if (k[u].p.x == p.x && k[u].p.y == p.y && k[u].p.z == p.z) {
                map[i] = u;
                break;
            }
        }
    }
    /* The distinct points in (x, y, z) order; rank[u] is point u's place. */
    qsort(k, unique, sizeof *k, build_mesh_keyed_cmp);
    uint32_t *rank = table;
    for (uint32_t r = 0; r < unique; r++)
        rank[k[r].index] = r;
    int ok = 1;
    for (uint32_t t = 0; ok && t < n / 3; t++) {
        ok = start_face(m);
        for (int j = 0; ok && j < 3; j++)
            ok = add_index(m, rank[map[3 * t + (uint32_t)j]]);
    }
    ok = ok && finish_faces(m);
    for (uint32_t i = 0; ok && i < unique; i++)
        m->points[i] = k[i].p;
    m->point_count = unique;
    free(table);
    free(k);
    free(map);
    return ok;
}

sc_status build_mesh_soup(const build_ctx *c, const sc_location *loc, const char *what,
                          const vec3 *corners, uint32_t tri_count, prim *out,
                          const char **empty)
{
    mesh_file m;
    memset(&m, 0, sizeof m);
    if (tri_count > UINT32_MAX / 3 ||
        !grow_array32((void **)&m.points, &m.point_cap, 3 * tri_count, sizeof(vec3)))
        return err_nomem(c->error, loc);
    memcpy(m.points, corners, 3 * (size_t)tri_count * sizeof *corners);
    m.point_count = 3 * tri_count;
    sc_status st = merge_corners(&m) ? SC_OK : err_nomem(c->error, loc);
    build_ctx as_is = *c; /* CGAL's own closed mesh, as OpenSCAD takes it */
    as_is.drawn_as_is = 1;
    if (st == SC_OK)
        st = build_mesh_prim(&as_is, loc, what, 0, m.points, m.point_count, m.indices,
                             m.face_start, m.face_count, out, empty);
    mesh_file_free(&m);
    return st;
}

static float read_f32(const unsigned char *p)
{
    uint32_t u = (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 |
                 (uint32_t)p[3] << 24;
    float f;
    memcpy(&f, &u, sizeof f);
    return f;
}

/* The triangle count a binary STL file of size bytes announces in head,
 * where its size matches it; else -1. */
static int64_t stl_binary_count(const unsigned char *head, uint64_t size)
{
    if (size < 84)
        return -1;
    uint32_t n = (uint32_t)head[80] | (uint32_t)head[81] << 8 | (uint32_t)head[82] << 16 |
                 (uint32_t)head[83] << 24;
    return (uint64_t)n * 50 + 84 == size ? (int64_t)n : -1;
}

/* NULL when an STL file of size bytes whose first min(size, 84) bytes are
 * head is binary STL (its size matches the count it announces) or starts
 * as ASCII STL does ("solid"); else why it is neither. */
static const char *stl_unknown(const unsigned char *head, uint64_t size)
{
    if (stl_binary_count(head, size) >= 0 || (size >= 5 && memcmp(head, "solid", 5) == 0))
        return NULL;
    return "neither binary STL (its size does not match its triangle count) nor "
           "ASCII STL (it does not start with 'solid')";
}

/* How reading a mesh file went, beside what read_stl and read_off return
 * (NULL, or what is wrong): memory ran out (oom); or OpenSCAD 2021.01
 * imports nothing from such a file and renders the rest (empty), as
 * against a file it cannot render either (an index out of range, a point
 * that is not finite); a message made for the file goes in text. */
typedef struct mesh_reading {
    int oom, empty;
    int not_finite; /* empty for a corner that is nan or inf (STL) */
    int binary;     /* a binary OFF file: its points are floats */
    unsigned line;  /* the file's line where it went wrong, where known */
    char text[320];
} mesh_reading;

/* isspace in the C locale, whatever the host's locale: white space to
 * boost's STL tokens and to the C++ stream CGAL's OFF reader runs. */
static int mesh_space(char ch)
{
    return ch == ' ' || ch == '\t' || ch == '\r' || ch == '\n' || ch == '\v' ||
           ch == '\f';
}

static int has_word(const char *s, const char *e, const char *word)
{
    size_t n = strlen(word);
    for (; (size_t)(e - s) >= n; s++)
        if (memcmp(s, word, n) == 0)
            return 1;
    return 0;
}

/* [s, e) as boost::lexical_cast<double> reads it (OpenSCAD's STL reader):
 * "nan", "nan(...)", "inf" or "infinity" in any case, with a sign; else a
 * decimal number, the whole of it, that does not overflow. 0 when it is
 * not one. */
static int stl_number(const char *s, const char *e, double *out)
{
    const char *t = s + (s < e && (*s == '+' || *s == '-'));
    size_t n = (size_t)(e - t);
    if (n >= 3 && strncasecmp(t, "nan", 3) == 0 &&
        (n == 3 || (n >= 5 && t[3] == '(' && e[-1] == ')'))) {
        *out = *s == '-' ? -NAN : NAN;
        return 1;
    }
    if ((n == 3 && strncasecmp(t, "inf", 3) == 0) ||
        (n == 8 && strncasecmp(t, "infinity", 8) == 0)) {
        *out = *s == '-' ? -INFINITY : INFINITY;
        return 1;
    }
    const char *q = t;
    size_t digits = 0;
    for (; q < e && isdigit((unsigned char)*q); q++)
        digits++;
    if (q < e && *q == '.')
        for (q++; q < e && isdigit((unsigned char)*q); q++)
            digits++;
    if (!digits)
        return 0;
    if (q < e && (*q == 'e' || *q == 'E')) {
        q++;
        q += q < e && (*q == '+' || *q == '-');
        if (q == e || !isdigit((unsigned char)*q))
            return 0;
        while (q < e && isdigit((unsigned char)*q))
            q++;
    }
    if (q != e)
        return 0;
    char small[128],
        *buf = (size_t)(e - s) < sizeof small ? small : malloc((size_t)(e - s) + 1);
    if (!buf)
        return 0;
    memcpy(buf, s, (size_t)(e - s));
    buf[e - s] = 0;
    *out = strtod(buf, NULL);
    if (buf != small)
        free(buf);
    return isfinite(*out);
}

/* The three numbers after the first "vertex" in [s, e) that blanks and
 * three words follow, as OpenSCAD's pattern \s*vertex\s+(\S+)\s+(\S+)\s+(\S+)
 * finds them: 0 when no "vertex" has three words after it, -1 when one
 * has and a word is not a number (stl_number), else 1. */
static int stl_vertex(const char *s, const char *e, double c[3])
{
    for (const char *v = s; e - v >= 6; v++) {
        if (memcmp(v, "vertex", 6) != 0)
            continue;
        const char *q = v + 6, *word[3], *stop[3];
        int k = 0;
        for (; k < 3; k++) {
            const char *b = q;
            while (q < e && mesh_space(*q))
                q++;
            if (q == b || q == e)
                break;
            word[k] = q;
            while (q < e && !mesh_space(*q))
                q++;
            stop[k] = q;
        }
        if (k < 3)
            continue;
        for (k = 0; k < 3; k++)
            if (!stl_number(word[k], stop[k], &c[k]))
                return -1;
        return 1;
    }
    return 0;
}

/* Returns NULL on success, else what is wrong (r). An ASCII STL file is
 * read line by line as OpenSCAD 2021.01's import_stl reads it: the first
 * line passed over; a line with "solid", "facet" or "endloop" in it passed
 * over; "outer loop" starts a triangle; a line with "vertex" and three
 * words is a corner (a word that is not a number is OpenSCAD's "can't
 * parse vertex line"), and its third completes the triangle; any other
 * line after a triangle's third corner is its "extra vertex line" (those
 * two, OpenSCAD's errors, import nothing and render the rest); any other
 * line passed over. A triangle that "outer loop" starts again before its
 * third corner is left out, as OpenSCAD leaves it out. A corner that is
 * nan or inf (ASCII or binary) OpenSCAD reads, and then leaves the mesh out
 * of the union with the rest ("The given mesh is not closed!"): the same. */
static const char *read_stl(const char *text, size_t size, mesh_file *m, mesh_reading *r)
{
    const unsigned char *u = (const unsigned char *)text;
    const char *unknown = stl_unknown(u, size);
    if (unknown)
        return r->empty = 1, unknown;
    int64_t n = stl_binary_count(u, size);
    if (n >= 0) {
        for (int64_t t = 0; t < n; t++) {
            const unsigned char *f = u + 84 + (size_t)t * 50 + 12;
            for (int j = 0; j < 3; j++) {
                vec3 p = v3(read_f32(f + 12 * j), read_f32(f + 12 * j + 4),
                            read_f32(f + 12 * j + 8));
                if (!v3_is_finite(p)) /* OpenSCAD's mesh is not closed */
                    return r->empty = r->not_finite = 1, "a corner is not finite";
                if (!add_point(m, p))
                    return r->oom = 1, "out of memory";
            }
        }
        return merge_corners(m) ? NULL : (r->oom = 1, "out of memory");
    }
    const char *p = memchr(text, '\n', size), *end = text + size;
    p = p ? p + 1 : end;
    vec3 corner[3];
    int corners = 0;
    for (unsigned line = 2; p < end; line++) {
        const char *s = p, *e = memchr(p, '\n', (size_t)(end - p));
        e = e ? e : end;
        p = e < end ? e + 1 : end;
        while (s < e && mesh_space(*s))
            s++;
        while (e > s && mesh_space(e[-1]))
            e--;
        if (s == e || has_word(s, e, "solid") || has_word(s, e, "facet") ||
            has_word(s, e, "endloop"))
            continue;
        if (has_word(s, e, "outer loop")) {
            corners = 0;
            continue;
        }
        double c[3];
        int found = corners < 3 ? stl_vertex(s, e, c) : 0;
        if (corners < 3 && found == 0)
            continue;
        if (found < 0 || corners >= 3) {
            /* the line as printable ASCII (\xNN for any other byte), its
             * first 60 bytes */
            char shown[4 * 60 + 4];
            size_t k = 0;
            for (const char *q = s; q < e && q < s + 60; q++) {
                unsigned char ch = (unsigned char)*q;
                k += (size_t)snprintf(shown + k, sizeof shown - k,
                                      ch >= 0x20 && ch < 0x7f ? "%c" : "\\x%02x", ch);
            }
            snprintf(r->text, sizeof r->text, "line %u: %s '%s%s'", line,
                     found < 0 ? "can't parse vertex line" : "extra vertex line", shown,
                     e - s > 60 ? "..." : "");
            return r->line = line, r->empty = 1, r->text;
        }
        corner[corners] = v3(c[0], c[1], c[2]);
        if (!v3_is_finite(corner[corners])) /* OpenSCAD's CGAL leaves it out */
            return snprintf(r->text, sizeof r->text, "line %u: a corner is not finite",
                            line),
                   r->line = line, r->empty = r->not_finite = 1, r->text;
        if (++corners == 3)
            for (int j = 0; j < 3; j++)
                if (!add_point(m, corner[j]))
                    return r->oom = 1, "out of memory";
    }
    return merge_corners(m) ? NULL : (r->oom = 1, "out of memory");
}

/* Where CGAL's OFF reader is in the file: at p, on line line (1-based). */
typedef struct off_cursor {
    const char *start, *p, *end;
    unsigned line;
} off_cursor;

/* Past white space (CGAL's "in >> c" before a character). */
static void off_blank(off_cursor *c)
{
    for (; c->p < c->end && mesh_space(*c->p); c->p++)
        if (*c->p == '\n')
            c->line++;
}

/* CGAL's skip_comment_OFF: past white space and the lines it starts with
 * '#'. */
static void off_skip_comment(off_cursor *c)
{
    for (off_blank(c); c->p < c->end && *c->p == '#'; off_blank(c))
        while (c->p < c->end && *c->p != '\n')
            c->p++; /* off_blank takes the '\n', and counts it */
}

/* A number as libstdc++'s num_get<double> extracts it from [*q, e) in the
 * C locale ("is >> d", which CGAL's reader runs on a line): past white
 * space, the longest run of the form [+-] digits [. digits] [(e|E) [+-]
 * digits] (an exponent only after a digit), taken whole by strtod, or the
 * extraction fails; so "1.5.3" is 1.5 and then .3, "1-2" is 1 and then
 * -2, and "0x1", "1e", "inf" and "1e999" fail. 0 when it fails. */
static int off_double(const char **q, const char *e, double *out)
{
    const char *s = *q;
    while (s < e && mesh_space(*s))
        s++;
    const char *t = s;
    int dot = 0, digits = 0;
    if (t < e && (*t == '+' || *t == '-'))
        t++;
    for (; t < e; t++) {
        if (*t >= '0' && *t <= '9') {
            digits = 1;
        } else if (*t == '.' && !dot) {
            dot = 1;
        } else if ((*t == 'e' || *t == 'E') && digits) {
            t++;
            if (t < e && (*t == '+' || *t == '-'))
                t++;
            while (t < e && *t >= '0' && *t <= '9')
                t++;
            break;
        } else {
            break;
        }
    }
    *q = t;
    char buf[128], *big = NULL, *text = buf;
    size_t n = (size_t)(t - s);
    if (n >= sizeof buf && !(text = big = malloc(n + 1)))
        return 0;
    memcpy(text, s, n);
    text[n] = '\0';
    char *after;
    *out = strtod(text, &after);
    int ok = n > 0 && *after == '\0' && !isinf(*out);
    free(big);
    return ok;
}

/* An int as num_get<long> extracts it ("in >> n" for the header's
 * counts): past white space (counting lines), [+-] and at least one
 * digit, within int. 1 when it does; when it fails, 0 (not a number), -1
 * (past int) or -2 (the end of the file). */
static int off_int(off_cursor *c, long *out)
{
    off_blank(c);
    if (c->p >= c->end)
        return -2;
    const char *t = c->p;
    int negative = 0;
    if (t < c->end && (*t == '+' || *t == '-'))
        negative = *t++ == '-';
    const char *digits = t;
    long v = 0;
    for (; t < c->end && *t >= '0' && *t <= '9'; t++)
        if ((v = v * 10 + (*t - '0')) > (long)INT_MAX + 1)
            v = (long)INT_MAX + 2; /* past int either way */
    c->p = t;
    if (t == digits)
        return 0;
    if (v > (long)INT_MAX + negative)
        return -1;
    *out = negative ? -v : v;
    return 1;
}

/* Why off_int's result got (not 1) fails the count named what. */
static const char *off_count_why(int got, const char *what, char *buf, size_t size)
{
    snprintf(buf, size,
             got == -2   ? "the file ends before the %s count"
             : got == -1 ? "the %s count is past the largest int"
                         : "the %s count is not a number",
             what);
    return buf;
}

/* The file's last line, for c at its end: the line before the one a
 * final newline starts. */
static unsigned off_last_line(const off_cursor *c)
{
    return c->line - (c->p > c->start && c->p[-1] == '\n' && c->line > 1);
}

/* CGAL's scanner's next line of numbers (a point's or a face's): past
 * white space and comment lines, the line to its end or its '#'; *s and
 * *e bound it, *at is its number, and c moves to the next line. 0 at the
 * end of the file, with the file's last line in *at. */
static int off_next_line(off_cursor *c, const char **s, const char **e, unsigned *at)
{
    off_skip_comment(c);
    *at = c->line;
    if (c->p >= c->end) {
        *at = off_last_line(c);
        return 0;
    }
    *s = c->p;
    while (c->p < c->end && *c->p != '\n')
        c->p++;
    *e = memchr(*s, '#', (size_t)(c->p - *s));
    if (!*e)
        *e = c->p;
    if (c->p < c->end) {
        c->p++;
        c->line++;
    }
    return 1;
}

/* A binary OFF file's body as CGAL 5's reader takes it: at p (past the
 * header's line), the keyword's variants. */
typedef struct off_binary {
    const unsigned char *start, *p, *end;
    int homogeneous, dimensional, normals, colours, skel;
} off_binary;

/* The next big-endian 32-bit word; 0 at the end of the file. */
static int off_word(off_binary *b, uint32_t *out)
{
    if (b->end - b->p < 4)
        return 0;
    *out = (uint32_t)b->p[0] << 24 | (uint32_t)b->p[1] << 16 | (uint32_t)b->p[2] << 8 |
           b->p[3];
    b->p += 4;
    return 1;
}

static int off_int32(off_binary *b, int32_t *out)
{
    uint32_t w;
    if (!off_word(b, &w))
        return 0;
    *out = w > INT32_MAX ? -(int32_t)(~w) - 1 : (int32_t)w;
    return 1;
}

static int off_float(off_binary *b, double *out)
{
    uint32_t w;
    float f;
    if (!off_word(b, &w))
        return 0;
    memcpy(&f, &w, sizeof f);
    *out = f;
    return 1;
}

/* Binary OFF as CGAL's reader takes it (File_header_OFF, File_scanner_OFF,
 * Polyhedron_scan_OFF): big-endian 32-bit words, the dimension (nOFF) and
 * the point, face and edge counts (no edge count in SKEL); each point's
 * three floats (and w, 4OFF), then a normal's (NOFF) and a colour as a
 * count of 0 to 4 and as many floats (COFF); each face's point count, its
 * indices, and a colour as a count of 0 to 4 and as many floats. Texture
 * coordinates are not skipped, as CGAL does not skip them. Messages name
 * the byte where reading stopped. */
static const char *read_off_binary(off_binary *b, mesh_file *m, mesh_reading *r)
{
    /* what is wrong, at the byte reading stopped at; lenient (OpenSCAD
     * imports nothing) unless r->empty is cleared first */
    r->binary = 1;
#define BIN_FAIL(...)                                                                    \
    return snprintf(r->text, sizeof r->text, "byte %zu: ", (size_t)(b->p - b->start)),   \
           snprintf(r->text + strlen(r->text), sizeof r->text - strlen(r->text),         \
                    __VA_ARGS__),                                                        \
           r->text
    int32_t nv, nf, edges = 0;
    if ((b->dimensional && !off_int32(b, &nv)) || !off_int32(b, &nv) ||
        !off_int32(b, &nf) || (!b->skel && !off_int32(b, &edges)))
        BIN_FAIL("the file ends before its counts");
    (void)edges;
    if (nf < 0)
        BIN_FAIL("the face count is below 0");
    if (nv < 0)
        BIN_FAIL("the point count is below 0");
    for (int32_t i = 0; i < nv; i++) {
        double v[4] = {0, 0, 0, 1}, skip;
        for (int k = 0; k < 3 + b->homogeneous; k++)
            if (!off_float(b, &v[k]))
                BIN_FAIL("the file ends in point %d of %d", (int)i + 1, (int)nv);
        for (int k = 0; b->normals && k < 3 + b->homogeneous; k++)
            if (!off_float(b, &skip))
                BIN_FAIL("the file ends in point %d of %d", (int)i + 1, (int)nv);
        int32_t n = 0;
        if (b->colours && !off_int32(b, &n))
            BIN_FAIL("the file ends in point %d of %d", (int)i + 1, (int)nv);
        if (n < 0 || n > 4)
            BIN_FAIL("point %d has a colour of %d numbers (0 to 4)", (int)i + 1, (int)n);
        while (n-- > 0)
            if (!off_float(b, &skip))
                BIN_FAIL("the file ends in point %d of %d", (int)i + 1, (int)nv);
        vec3 q = b->homogeneous && v[3] != 1 ? v3(v[0] / v[3], v[1] / v[3], v[2] / v[3])
                                             : v3(v[0], v[1], v[2]);
        if (!v3_is_finite(q)) {
            r->empty = 0;
            BIN_FAIL("point %d is not finite", (int)i + 1);
        }
        if (!add_point(m, q))
            return r->oom = 1, "out of memory";
    }
    for (int32_t f = 0; f < nf; f++) {
        int32_t k;
        if (!off_int32(b, &k))
            BIN_FAIL("the file ends before face %d of %d", (int)f + 1, (int)nf);
        if (k < 0) { /* a count far past the file (CGAL's builder is left open) */
            r->empty = 0;
            BIN_FAIL("face %d has fewer indices than its point count", (int)f + 1);
        }
        if (k < 3)
            BIN_FAIL("face %d has fewer than 3 points", (int)f + 1);
        if (!start_face(m))
            return r->oom = 1, "out of memory";
        for (int32_t j = 0; j < k; j++) {
            int32_t i;
            if (!off_int32(b, &i)) {
                r->empty = 0;
                BIN_FAIL("face %d has fewer indices than its point count", (int)f + 1);
            }
            if (i < 0 || i >= nv) {
                r->empty = 0;
                BIN_FAIL("a point index of face %d is out of range", (int)f + 1);
            }
            if (!add_index(m, (uint32_t)i))
                return r->oom = 1, "out of memory";
        }
        int32_t n;
        if (!off_int32(b, &n))
            BIN_FAIL("the file ends in face %d of %d", (int)f + 1, (int)nf);
        if (n < 0 || n > 4)
            BIN_FAIL("face %d has a colour of %d numbers (0 to 4)", (int)f + 1, (int)n);
        double skip;
        while (n-- > 0)
            if (!off_float(b, &skip))
                BIN_FAIL("the file ends in face %d of %d", (int)f + 1, (int)nf);
    }
#undef BIN_FAIL
    return finish_faces(m) ? NULL : (r->oom = 1, "out of memory");
}

/* An OFF file as CGAL 5's reader (which OpenSCAD 2021.01's import()
 * runs) takes it (File_header_OFF, File_scanner_OFF, Polyhedron_scan_OFF):
 * the keyword [ST][C][N][4][n]OFF (texture coordinates, colours, normals
 * and a homogeneous coordinate after each point, all but the point
 * ignored; nOFF, the dimension first, of which the first three
 * coordinates are taken); the point count, starting with a digit, then the
 * face and edge counts (no edge count after [ST][C][N][4][n]SKEL, whose
 * faces CGAL reads as an OFF file's); then each point on a line of its own, its first
 * three numbers (over the fourth, 4OFF), and each face on a line of its
 * own, its point count and indices as numbers truncated to integers; after
 * the keyword, BINARY reads the rest as read_off_binary does. */
static const char *read_off(const char *text, size_t size, mesh_file *m, mesh_reading *r)
{
    /* OpenSCAD imports nothing from a file CGAL's reader stops in, and
     * renders the rest; it aborts where a face's index is out of range or
     * missing (CGAL's builder is left open) */
    r->empty = 1;
    off_cursor c = {text, text, text + size, 1};
    uint32_t line_cap = 0; /* of m->lines */
    unsigned at = 1;       /* the line a message names */
    /* what is wrong, at line at; lenient unless r->empty is cleared first */
#define OFF_FAIL(...)                                                                    \
    return snprintf(r->text, sizeof r->text, "line %u: ", at),                           \
           snprintf(r->text + strlen(r->text), sizeof r->text - strlen(r->text),         \
                    __VA_ARGS__),                                                        \
           r->line = at, r->text
    off_skip_comment(&c);
    at = c.line;
    const char *t = c.p;
    while (c.p < c.end && isalnum((unsigned char)*c.p) && c.p - t < 41)
        c.p++;
    size_t len = (size_t)(c.p - t), j = 0;
    if (c.p < c.end && c.p - t < 41 && *c.p != '\n') /* the character that ends it */
        c.p++;
    int homogeneous = 0, dimensional = 0;
    if (len >= 2 && t[0] == 'S' && t[1] == 'T')
        j += 2;
    int colours = 0, normals = 0;
    if (j < len && t[j] == 'C') {
        colours = 1;
        j++;
    }
    if (j < len && t[j] == 'N') {
        normals = 1;
        j++;
    }
    if (j < len && t[j] == '4') {
        homogeneous = 1;
        j++;
    }
    if (j < len && t[j] == 'n') {
        dimensional = 1;
        j++;
    }
    /* SKEL (a skeleton: no edge count) with the same prefixes */
    int skel = len == j + 4 && strncmp(t + j, "SKEL", 4) == 0;
    if (len < 2 || isdigit((unsigned char)t[1]) ||
        (isdigit((unsigned char)t[0]) && t[0] != '4') ||
        (!skel && (len != j + 3 || strncmp(t + j, "OFF", 3) != 0)))
        OFF_FAIL("it does not start with 'OFF' (or COFF, NOFF, 4OFF, nOFF, STOFF, SKEL)");
    off_skip_comment(&c);
    at = c.line;
    char count[64];
    if (c.p >= c.end) {
        at = off_last_line(&c);
        OFF_FAIL("the file ends before the point count");
    }
    if (!isdigit((unsigned char)*c.p)) {
        const char *w = c.p;
        while (c.p < c.end && isalnum((unsigned char)*c.p))
            c.p++;
        if (c.p - w == 6 && strncmp(w, "BINARY", 6) == 0) {
            /* past the character that ends the word, and its line */
            if (c.p < c.end && *c.p++ != '\n')
                while (c.p < c.end && *c.p++ != '\n')
                    ;
            off_binary b = {(const unsigned char *)c.start,
                            (const unsigned char *)c.p,
                            (const unsigned char *)c.end,
                            homogeneous,
                            dimensional,
                            normals,
                            colours,
                            skel};
            return read_off_binary(&b, m, r);
        }
        OFF_FAIL("the point count is not a number");
    }
    /* each count's line is where its read stops */
    long nv, nf, edges;
    int got = off_int(&c, &nv);
    if (got == 1 && dimensional)
        got = off_int(&c, &nv);
    at = got == -2 ? off_last_line(&c) : c.line;
    if (got != 1)
        OFF_FAIL("%s", off_count_why(got, "point", count, sizeof count));
    got = off_int(&c, &nf);
    at = got == -2 ? off_last_line(&c) : c.line;
    if (got != 1)
        OFF_FAIL("%s", off_count_why(got, "face", count, sizeof count));
    if (nf < 0)
        OFF_FAIL("the face count is below 0");
    got = skel ? 1 : off_int(&c, &edges);
    at = got == -2 ? off_last_line(&c) : c.line;
    if (got != 1)
        OFF_FAIL("%s", off_count_why(got, "edge", count, sizeof count));
    if (nv < 0)
        OFF_FAIL("the point count is below 0");
    for (long i = 0; i < nv; i++) {
        const char *s, *e;
        double v[4] = {0, 0, 0, 1};
        int got = 0;
        if (!off_next_line(&c, &s, &e, &at))
            OFF_FAIL("the file ends before point %ld of %ld", i + 1, nv);
        while (got < 3 + homogeneous && off_double(&s, e, &v[got]))
            got++;
        if (got < 3 + homogeneous)
            OFF_FAIL("point %ld has fewer than %d numbers", i + 1, 3 + homogeneous);
        vec3 q = homogeneous && v[3] != 1 ? v3(v[0] / v[3], v[1] / v[3], v[2] / v[3])
                                          : v3(v[0], v[1], v[2]);
        if (!v3_is_finite(q)) { /* 4OFF's w = 0: CGAL divides by zero and aborts */
            r->empty = 0;
            OFF_FAIL("point %ld is not finite", i + 1);
        }
        if (!add_point(m, q))
            return r->oom = 1, "out of memory";
    }
    for (long f = 0; f < nf; f++) {
        const char *s, *e;
        double k = 0; /* no number: below 3 */
        if (!off_next_line(&c, &s, &e, &at))
            OFF_FAIL("the file ends before face %ld of %ld", f + 1, nf);
        if (!grow_array32((void **)&m->lines, &line_cap, (uint32_t)f + 1,
                          sizeof *m->lines))
            return r->oom = 1, "out of memory";
        m->lines[f] = at;
        /* CGAL converts the count to size_t: one of -1 or below wraps to a
         * count far past the line's indices (its builder is left open) */
        if (off_double(&s, e, &k) && k <= -1) {
            r->empty = 0;
            OFF_FAIL("face %ld has fewer indices than its point count", f + 1);
        }
        if (!(k >= 3))
            OFF_FAIL("face %ld has fewer than 3 points", f + 1);
        if (!start_face(m))
            return r->oom = 1, "out of memory";
        /* as many as k says: a line with fewer ends the loop */
        for (double n = 0; n < floor(k); n++) {
            double i;
            if (!off_double(&s, e, &i)) {
                r->empty = 0;
                OFF_FAIL("face %ld has fewer indices than its point count", f + 1);
            }
            if (!(i > -1 && i < (double)nv)) { /* truncated: -0.5 is 0 */
                r->empty = 0;
                OFF_FAIL("a point index of face %ld is out of range", f + 1);
            }
            if (!add_index(m, (uint32_t)i))
                return r->oom = 1, "out of memory";
        }
    }
#undef OFF_FAIL
    return finish_faces(m) ? NULL : (r->oom = 1, "out of memory");
}

/* The fewest significant digits (1 to 17) that give back x, a finite
 * double. */
static int shortest_digits(double x)
{
    char buf[40];
    for (int d = 1; d < 17; d++) {
        snprintf(buf, sizeof buf, "%.*g", d, x);
        if (strtod(buf, NULL) == x)
            return d;
    }
    return 17;
}

int build_mesh_rounding(const char *path, build_mesh_rounding_info *out)
{
    memset(out, 0, sizeof *out);
    size_t size;
    const char *why;
    char *text = file_read(path, BUILD_MAX_MESH_FILE, &size, &why);
    if (!text)
        return 0;
    size_t n = strlen(path);
    int off = n >= 4 && path[n - 4] == '.' &&
              tolower((unsigned char)path[n - 3]) == 'o' &&
              tolower((unsigned char)path[n - 2]) == 'f' &&
              tolower((unsigned char)path[n - 1]) == 'f';
    int binary = !off && stl_binary_count((const unsigned char *)text, size) >= 0;
    mesh_file m;
    memset(&m, 0, sizeof m);
    mesh_reading r = {0};
    const char *bad = off ? read_off(text, size, &m, &r) : read_stl(text, size, &m, &r);
    free(text);
    binary |= r.binary;
    if (bad || m.point_count == 0) {
        mesh_file_free(&m);
        return 0;
    }
    /* the digits written: the most any coordinate needs (a sample of the
     * first 2^16 points), 9 at most for float's (binary STL and OFF) */
    int digits = 0;
    for (uint32_t i = 0; i < m.point_count && i < 65536u; i++) {
        const double *c = &m.points[i].x;
        for (int k = 0; k < 3; k++)
            if (c[k] != 0 && digits < 17) {
                int d = shortest_digits(c[k]);
                digits = d > digits ? d : digits;
            }
    }
    double offset = 0;
    if (binary) {
        for (uint32_t i = 0; i < m.point_count; i++) /* half a float's ulp */
            offset = fmax(offset, 0x1p-24 * v3_max_abs(m.points[i]));
    } else if (digits >= 6 && digits < 15) {
        for (uint32_t i = 0; i < m.point_count; i++) {
            double a = v3_max_abs(m.points[i]);
            if (a > 0) /* half a unit in the last digit written */
                offset = fmax(offset, 0.5 * pow(10, floor(log10(a)) - digits + 1));
        }
    }
    double area = 0;
    for (uint32_t f = 0; f < m.face_count; f++) {
        const uint32_t *v = &m.indices[m.face_start[f]];
        uint32_t k = m.face_start[f + 1] - m.face_start[f];
        for (uint32_t j = 1; j + 1 < k; j++)
            area += 0.5 * v3_length(v3_cross(v3_sub(m.points[v[j]], m.points[v[0]]),
                                             v3_sub(m.points[v[j + 1]], m.points[v[0]])));
    }
    mesh_file_free(&m);
    if (!(offset > 0))
        return 0;
    out->digits = binary ? 0 : digits;
    out->offset = offset * sqrt(3.0); /* each of three coordinates */
    out->volume = area * out->offset;
    return 1;
}

/* Whether CGAL's OFF reader, which OpenSCAD 2021.01's import() of an OFF
 * file runs, rolls the whole file back: its polyhedron builder, given the
 * faces by the file's point numbers, each whole and without a test first
 * (Polyhedron_scan_OFF), fails on one. Faces that run each edge one way
 * only and make one fan about each point it takes in any order; any others
 * are built by CGAL itself (nef.h: off_build), which is loaded for them.
 * 1 when it rolls back, with the face's line and CGAL's reason in why; 2
 * when one of CGAL's assertions fails, where OpenSCAD stops (why says
 * which); 0; -1 when memory runs out; -2 when the plugin does not load
 * (why says why). */
static int off_rolled_back(const mesh_file *m, char *why, size_t size)
{
    build_mesh_faces f = {.points = m->points,
                          .point_count = m->point_count,
                          .indices = m->indices,
                          .face_start = m->face_start,
                          .face_count = m->face_count,
                          .lent = 1};
    builder_run run = {0};
    uint32_t border, unused, skipped;
    uint8_t *take = malloc(m->face_count ? m->face_count : 1);
    int plain = !take || builder_take(&f, take, &run, &border, &unused, &skipped) < 0 ? -1
                : run.refusal                                                         ? 0
                              : fans_whole(&f, "", 1, why, size);
    free(take);
    if (plain)
        return plain < 0 ? -1 : 0;
    nef_plugin nef;
    char err[SC_ERROR_MESSAGE_MAX / 2];
    if (!nef_plugin_open(&nef, err, sizeof err)) {
        snprintf(why, size, "%.150s", err);
        return -2;
    }
    uint32_t refused;
    nef_status ns = nef.off_build(m->point_count, m->indices, m->face_start,
                                  m->face_count, &refused, err, sizeof err);
    nef_plugin_close(&nef);
    if (ns == NEF_NOMEM)
        return -1;
    if (ns == NEF_OK && refused == UINT32_MAX)
        return 0;
    char at[64] = "";
    if (refused < m->face_count && m->lines)
        snprintf(at, sizeof at, "line %u: face %u: ", m->lines[refused], refused + 1);
    if (ns != NEF_OK) {
        snprintf(why, size, "%s%.160s, where OpenSCAD stops", at, err);
        return 2;
    }
    if (refused < m->face_count)
        snprintf(why, size, "%sCGAL's builder says \"%.160s\"", at, err);
    else
        snprintf(why, size, "CGAL's builder cannot remove its unused points");
    return 1;
}

char *build_file_path(const build_ctx *c, const char *name)
{
    const char *slash = c->file ? strrchr(c->file, '/') : NULL;
    size_t dir = name[0] != '/' && slash ? (size_t)(slash - c->file) + 1 : 0;
    char *path = malloc(dir + strlen(name) + 1);
    if (path) {
        memcpy(path, c->file, dir);
        strcpy(path + dir, name);
    }
    return path;
}

/* An AMF file (amf.c: zipped or not, with OpenSCAD's warning when the
 * archive's only entry is read), or a 3MF file (threemf.h) read from path. */
static sc_status read_amf(const build_ctx *c, const char *text, size_t size,
                          const char *path, const model_import *import, amf_mesh *a)
{
    const sc_location *loc = &import->file_loc;
    if (import->format == MODEL_MESH_3MF)
        return threemf_read_file(path, import->file, loc, a, c->error);
    /* the file as the model: its errors at its own lines */
    sc_location file = {c->file, 0, 0};
    if (c->mesh_model)
        loc = &file;
    char *unzipped = NULL, warning[SC_ERROR_MESSAGE_MAX - 160];
    size_t unzipped_size = 0;
    sc_status st =
        amf_unzip(text, size, path, import->file, loc, BUILD_MAX_MESH_FILE, &unzipped,
                  &unzipped_size, warning, sizeof warning, c->error);
    if (st == SC_OK && warning[0])
        st = build_note(c, loc, "%s", warning);
    if (st == SC_OK)
        st = unzipped ? amf_read(unzipped, unzipped_size, import->file, loc, a, c->error)
                      : amf_read(text, size, import->file, loc, a, c->error);
    free(unzipped);
    return st;
}

static sc_status push_part(const build_ctx *c, const sc_location *loc, build_prims *out,
                           const prim *p)
{
    if (!grow_array32((void **)&out->items, &out->cap, out->count + 1,
                      sizeof *out->items))
        return err_nomem(c->error, loc);
    out->items[out->count++] = *p;
    return SC_OK;
}

/* An object of a file an import read, merged once for every mode: its
 * faces as build_mesh_merge made them in the first mode asked for (points
 * NULL), and its points as each mode places them, made from the file's
 * points by names (grid_place) when a builder of the other mode asks:
 * which points merge does not depend on the mode, only where they go. */
typedef struct merged_object {
    build_mesh_faces faces; /* face_start NULL until merged */
    vec3 *points[2];        /* exact, faithful; NULL until asked for */
} merged_object;

static void merged_free(merged_object *m)
{
    build_mesh_faces_free(&m->faces);
    free(m->points[0]);
    free(m->points[1]);
    memset(m, 0, sizeof *m);
}

/* The merged points of f in a mode (snap_float as grid_point's): each
 * from the file's point it was merged from (f->names). malloc'd; NULL
 * when memory runs out. */
static vec3 *merged_points(const vec3 *points, const build_mesh_faces *f, int snap_float)
{
    vec3 *out = malloc((size_t)(f->point_count ? f->point_count : 1) * sizeof *out);
    if (!out)
        return NULL;
    for (uint32_t u = 0; u < f->point_count; u++) {
        int64_t k[3];
        grid_place(points[f->names[u]], snap_float ? SNAP_FLOAT : SNAP_NONE, k, &out[u]);
    }
    return out;
}

/* How import_solid treats an object that is not closed, beyond what its
 * mode says (flags). */
enum {
    /* one of several that build_import makes one mesh of: left out in both
     * modes, with a warning even where the builder takes no note (hull,
     * minkowski), as in --faithful: OpenSCAD 2021.01 leaves such an object
     * out of the union of the file's objects, under hull and projection as
     * anywhere, and a part drawn by the parity rule could not keep its
     * overlaps with the others in one mesh */
    IMPORT_JOINED = 1,
    /* an object alone, the same: OpenSCAD cannot make the Nef polyhedron a
     * cut or a CGAL boolean needs of it */
    IMPORT_ALONE = 2,
    /* an object alone, for the builders that take only its corners or
     * faces: taken as it is, by the parity rule, without a warning and
     * never an error, as OpenSCAD hulls and projects the mesh it reads
     * without asking that it be closed */
    IMPORT_LOOSE = 4
};

/* One solid of a mesh file on its own points (build_mesh_merge, then
 * build_mesh_solid) appended to out; what names it in messages. With
 * several objects (note set), the warning each leaves in c->note goes to
 * c->notes at once, so that every object's is kept, in file order. how:
 * the IMPORT_ flags. merged (or NULL): where the object's faces are kept
 * merged (build_imports): taken from there when they are, with the
 * points of c's mode, put there when not, and lent from there to *faces. */
static sc_status import_solid(const build_ctx *c, const sc_location *loc,
                              const char *what, int strict, int several, unsigned how,
                              const vec3 *points, uint32_t point_count,
                              const uint32_t *indices, const uint32_t *face_start,
                              uint32_t face_count, build_prims *out,
                              const char **left_out, build_mesh_faces *faces,
                              merged_object *merged)
{
    int joined = (how & (several ? IMPORT_JOINED : IMPORT_ALONE)) != 0;
    build_ctx oc = *c;
    sc_error note = {SC_OK, "", 0, 0, ""}, unsaid = {SC_OK, "", 0, 0, ""};
    if ((several && c->note) || joined)
        oc.note = &note;
    build_mesh_faces f, kept; /* merged here; or lent from merged */
    memset(&f, 0, sizeof f);
    memset(&kept, 0, sizeof kept);
    const build_mesh_faces *use = &f;
    const char *empty = NULL;
    prim p;
    sc_status st = SC_OK;
    int mode = c->faithful && !c->drawn_as_is; /* snapped, as build_mesh_merge */
    if (c->moved)
        merged = NULL; /* kept as written */
    if (!merged || !merged->faces.face_start) {
        st = build_mesh_merge_moved(&oc, loc, 0, c->moved, points, point_count, indices,
                                    face_start, face_count, &f);
        if (st == SC_OK && c->imports)
            c->imports->merges++;
        if (st == SC_OK && merged) { /* kept for the import's next builders */
            merged->points[mode] = f.points;
            merged->faces = f;
            merged->faces.points = NULL;
            memset(&f, 0, sizeof f);
        }
    }
    if (st == SC_OK && merged) {
        if (!merged->points[mode] &&
            !(merged->points[mode] = merged_points(points, &merged->faces, mode)))
            st = err_nomem(c->error, loc);
        kept = merged->faces;
        kept.points = merged->points[mode];
        use = &kept;
    }
    build_ctx sc = oc; /* the check only: the points merge as the mode says */
    sc.faithful |= joined;
    sc.drawn_as_is &= !joined && !several; /* OpenSCAD unites objects with CGAL */
    if ((how & IMPORT_LOOSE) && !several) {
        sc.faithful = 0;
        sc.note = &unsaid;
        strict = 0;
    }
    if (st == SC_OK)
        st = build_mesh_solid(&sc, loc, what, 0, strict, use, &p, &empty);
    if (st == SC_OK && faces && !empty) {
        *faces = *use;
        faces->lent = use == &kept;
        memset(&f, 0, sizeof f);
    }
    build_mesh_faces_free(&f);
    /* an object alone left out (joined) counts as an import left out: its
     * parent does not add that it is empty (build_notes) */
    if (st == SC_OK && note.message[0])
        st = joined && !several && empty ? build_note_left_out(c, loc, "%s", note.message)
                                         : build_note(c, loc, "%s", note.message);
    if (st == SC_OK && empty && empty[0] && several)
        st = build_note(c, loc, "%s is empty: it has no volume", what);
    if (st == SC_OK && empty && !several)
        *left_out = empty;
    if (st == SC_OK && !empty)
        st = push_part(c, loc, out, &p);
    return st;
}

/* The objects of an AMF or 3MF file a, each its own solid (OpenSCAD
 * unites them with CGAL), an object without triangles left out as
 * OpenSCAD's empty PolySet. One object is built as an STL is. how:
 * import_solid's; merged (or NULL): import_solid's, for each object of
 * a (a->object_count of them, at least one). */
static sc_status import_objects(const build_ctx *c, const model_import *import,
                                int strict, unsigned how, const amf_mesh *a,
                                build_prims *out, const char **empty,
                                build_mesh_faces *faces, merged_object *merged)
{
    const sc_location *loc = &import->file_loc;
    uint32_t with_faces = 0;
    for (uint32_t o = 0; o < a->object_count; o++)
        with_faces += a->object_faces[o + 1] > a->object_faces[o];
    if (with_faces <= 1)
        return import_solid(c, loc, "imported mesh", strict, 0, how, a->points,
                            a->point_count, a->indices, a->face_start, a->face_count, out,
                            empty, faces, merged);
    sc_status st = SC_OK;
    for (uint32_t o = 0; o < a->object_count && st == SC_OK; o++) {
        uint32_t first = a->object_points[o], faces = a->object_faces[o];
        uint32_t count = a->object_faces[o + 1] - faces;
        if (!count)
            continue;
        /* the object's triangles on its own points */
        uint32_t *indices = malloc(3 * (size_t)count * sizeof *indices);
        uint32_t *start = malloc(((size_t)count + 1) * sizeof *start);
        if (!indices || !start) {
            st = err_nomem(c->error, loc);
        } else {
            for (uint32_t i = 0; i < 3 * count; i++)
                indices[i] = a->indices[a->face_start[faces] + i] - first;
            for (uint32_t f = 0; f <= count; f++)
                start[f] = 3 * f;
            char what[64];
            snprintf(what, sizeof what, "object %u of the imported file", o + 1);
            st = import_solid(c, loc, what, strict, 1, how, a->points + first,
                              a->object_points[o + 1] - first, indices, start, count, out,
                              empty, NULL, merged ? &merged[o] : NULL);
        }
        free(indices);
        free(start);
    }
    return st;
}

/* s in double quotes, as OpenSCAD 2021.01 prints a file name: '"', '\\',
 * tab, line feed and carriage return escaped, the rest as it is; cut
 * short at size. */
static const char *quoted_name(const char *s, char *out, size_t size)
{
    size_t n = 0;
    out[n++] = '"';
    for (; *s && n + 4 < size; s++) {
        const char *escape = *s == '"'    ? "\\\""
                             : *s == '\\' ? "\\\\"
                             : *s == '\t' ? "\\t"
                             : *s == '\n' ? "\\n"
                             : *s == '\r' ? "\\r"
                                          : NULL;
        if (escape) {
            out[n++] = escape[0];
            out[n++] = escape[1];
        } else {
            out[n++] = *s;
        }
    }
    out[n++] = '"';
    out[n] = '\0';
    return out;
}

sc_status build_import_unsupported(const build_ctx *c, const sc_location *loc,
                                   const char *name, int strict)
{
    static const char what[] = "Unsupported file format while trying to import file "
                               "'%s' (import() reads .stl, .off, .amf, .3mf, .dxf and "
                               ".svg files)";
    char why[SC_ERROR_MESSAGE_MAX - 160], quoted[SC_ERROR_MESSAGE_MAX / 2];
    snprintf(why, sizeof why, what, quoted_name(name, quoted, sizeof quoted));
    if (strict || c->strict)
        return err_set(c->error, SC_ERR_UNSUPPORTED, loc, "%s", why);
    return build_note_left_out(c, loc,
                               "%s; the import is empty, as OpenSCAD leaves it out "
                               "(--strict makes it an error)",
                               why);
}

/* ---- the files read, by import (build_imports) ---- */

/* A file an import read: parsed, and its objects merged. */
struct build_import_file {
    const model_import *import; /* the key (same_import); NULL in a free slot */
    int read;                   /* m or a holds the file */
    mesh_file m;                /* STL, OFF */
    amf_mesh a;                 /* AMF, 3MF */
    merged_object *merged;      /* one per object (at least one); NULL until asked for */
    uint32_t merged_count;
    /* the budget (build_ctx.triangles_left) the import's triangles were
     * charged to, or NULL: kept when the file is let go, so that a later
     * reader of the import does not charge them again */
    const size_t *charged;
};

static void import_file_free(struct build_import_file *f)
{
    mesh_file_free(&f->m);
    amf_mesh_free(&f->a);
    for (uint32_t i = 0; i < f->merged_count; i++)
        merged_free(&f->merged[i]);
    free(f->merged);
    f->merged = NULL;
    f->merged_count = 0;
    memset(&f->m, 0, sizeof f->m);
    memset(&f->a, 0, sizeof f->a);
    f->read = 0;
}

void build_imports_free(build_imports *imports)
{
    for (size_t i = 0; i < imports->cap; i++)
        if (imports->items[i].import)
            import_file_free(&imports->items[i]);
    free(imports->items);
    memset(imports, 0, sizeof *imports);
}

size_t build_imports_held(const build_imports *imports)
{
    size_t held = 0;
    for (size_t i = 0; i < imports->cap; i++)
        held += imports->items[i].import && imports->items[i].read;
    return held;
}

/* Whether a and b are one import of the model file: the same node, or the
 * copy of it the lowering makes in another context (resize's children
 * are lowered again to be measured: model.h), which keeps its position
 * and file name. */
static int same_import(const model_import *a, const model_import *b)
{
    const sc_location *p = &a->file_loc, *q = &b->file_loc;
    return a == b ||
           (p->line == q->line && p->column == q->column &&
            (p->file == q->file || (p->file && q->file && !strcmp(p->file, q->file))) &&
            !strcmp(a->file, b->file) && a->format == b->format);
}

static size_t import_slot(const struct build_import_file *items, size_t cap,
                          const model_import *import)
{
    size_t h = (size_t)import->file_loc.line * 1000003u + (size_t)import->file_loc.column;
    h ^= h >> 17;
    h *= (size_t)0x9e3779b97f4a7c15ull;
    size_t i = (h ^ (h >> 29)) & (cap - 1);
    while (items[i].import && !same_import(items[i].import, import))
        i = (i + 1) & (cap - 1);
    return i;
}

/* import's entry in imports, or NULL. */
static struct build_import_file *imports_find(const build_imports *imports,
                                              const model_import *import)
{
    if (!imports || !imports->cap)
        return NULL;
    size_t i = import_slot(imports->items, imports->cap, import);
    return imports->items[i].import ? &imports->items[i] : NULL;
}

/* import's entry in imports, made (empty) when there is none; NULL when
 * memory runs out. Entries move when the table grows. */
static struct build_import_file *imports_put(build_imports *imports,
                                             const model_import *import)
{
    struct build_import_file *found = imports_find(imports, import);
    if (found)
        return found;
    if (2 * (imports->count + 1) > imports->cap) {
        size_t cap = imports->cap ? 2 * imports->cap : 16;
        if (cap > SIZE_MAX / 2 / sizeof *imports->items)
            return NULL;
        struct build_import_file *items = calloc(cap, sizeof *items);
        if (!items)
            return NULL;
        for (size_t i = 0; i < imports->cap; i++)
            if (imports->items[i].import)
                items[import_slot(items, cap, imports->items[i].import)] =
                    imports->items[i];
        free(imports->items);
        imports->items = items;
        imports->cap = cap;
    }
    size_t i = import_slot(imports->items, imports->cap, import);
    imports->items[i].import = import;
    imports->count++;
    return &imports->items[i];
}

/* Lets go of the files of the imports among n and its siblings, and below
 * them down to the walks' depth (build_hull.h); deeper files stay until
 * the build ends. The nodes are lowered in the points context (model.h),
 * where an import holds its import; the extrusions' children are in the
 * 2D context, where an import is a drawing, not a mesh, and are passed by. */
static void imports_let_go(build_imports *imports, const model_node *n, int depth)
{
    for (; n; n = n->next) {
        if ((n->modifiers & (MODEL_MOD_DISABLE | MODEL_MOD_BACKGROUND)) ||
            n->kind == MODEL_LINEAR_EXTRUDE || n->kind == MODEL_ROTATE_EXTRUDE)
            continue;
        if (n->kind == MODEL_IMPORT && !n->pending && n->u.import) {
            struct build_import_file *file = imports_find(imports, n->u.import);
            if (file && file->read)
                import_file_free(file);
        } else if (depth < BUILD_HULL_MAX_DEPTH) {
            imports_let_go(imports, n->first_child, depth + 1);
        }
    }
}

void build_imports_done(const build_ctx *c, const model_node *n)
{
    if (c->imports && c->imports->count)
        imports_let_go(c->imports, n->first_child, 1);
}

/* Reads and parses import's file into *file (file->read set); or, as
 * import_parts says, the error, or *empty set with the warning given (a
 * file that does not open, or that OpenSCAD cannot parse), file->read
 * unset. */
static sc_status import_read(const build_ctx *c, const model_import *import, int strict,
                             struct build_import_file *file, const char **empty)
{
    const char *name = import->file;
    const sc_location loc = import->file_loc;
    int stl = import->format == MODEL_MESH_STL;
    int objects = import->format == MODEL_MESH_AMF || import->format == MODEL_MESH_3MF;
    char *path = build_file_path(c, name);
    if (!path)
        return err_nomem(c->error, (&loc));
    size_t size = 0;
    const char *why = NULL;
    /* lib3mf reads a 3MF file itself */
    char *text = import->format == MODEL_MESH_3MF
                     ? NULL
                     : file_read(path, BUILD_MAX_MESH_FILE, &size, &why);
    FILE *probe = text || import->format != MODEL_MESH_3MF ? NULL : fopen(path, "rb");
    if (probe) {
        fclose(probe);
        text = malloc(1);
    } else if (!text && import->format == MODEL_MESH_3MF) {
        why = strerror(errno);
    }
    if (!text) {
        int opened = !file_not_opened(why);
        if (!opened) /* empty, with OpenSCAD's warning, as at the top level */
            *empty = "";
        sc_status st = opened ? err_set(c->error, SC_ERR_IO, &loc,
                                        "import: cannot read '%s': %s", path, why)
                              : build_file_not_opened(c, &loc, "import", path, why);
        free(path);
        return st;
    }
    mesh_reading reading = {0};
    sc_status st = SC_OK;
    if (objects) {
        st = read_amf(c, text, size, path, import, &file->a);
        free(text);
        /* OpenSCAD 2021.01 logs a file it cannot parse ("Failed to parse
         * file", "Could not read file") and renders the rest: a warning
         * with the file's own line, and the import left out, unless
         * --strict */
        if ((st == SC_ERR_SYNTAX || st == SC_ERR_SEMANTIC) && !strict && !c->strict &&
            !c->mesh_model) {
            sc_error reason = *c->error;
            err_clear(c->error);
            st = build_note_left_out(c, &loc,
                                     "%s; the import is empty, as OpenSCAD leaves it out "
                                     "(--strict makes it an error)",
                                     reason.message);
            if (st == SC_OK)
                *empty = "";
            free(path);
            import_file_free(file);
            return st;
        }
    } else {
        why = stl ? read_stl(text, size, &file->m, &reading)
                  : read_off(text, size, &file->m, &reading);
        free(text);
    }
    if (st != SC_OK) {
        ;
    } else if (reading.oom) {
        st = err_nomem(c->error, (&loc));
    } else if (why && reading.empty && !strict && !c->strict && !c->mesh_model) {
        /* OpenSCAD 2021.01 imports nothing from an STL file that is
         * neither binary nor ASCII STL (an empty file, another format),
         * silently, nor from one with a line it cannot parse (its error),
         * nor from an OFF file CGAL's reader stops in, and renders the
         * rest: a warning, and the import left out, unless --strict */
        st =
            build_note_left_out(c, &loc,
                                "import: '%s' is not a valid %s file (%s); the import is "
                                "empty, as OpenSCAD leaves it out (--strict makes it an "
                                "error)",
                                path, stl ? "STL" : "OFF", why);
        if (st == SC_OK)
            *empty = reading.not_finite ? build_import_not_finite : "";
        free(path);
        import_file_free(file);
        return st;
    } else if (why) {
        /* the mesh as the model: its own line, where the reader knows it */
        sc_location at = {c->file, (int)reading.line, 1};
        st = err_set(
            c->error, SC_ERR_SEMANTIC, c->mesh_model && reading.line ? &at : &loc,
            "import: '%s' is not a valid %s file (%s)", path, stl ? "STL" : "OFF", why);
    }
    free(path);
    if (st == SC_OK)
        file->read = 1;
    else
        import_file_free(file);
    return st;
}

/* build_import_parts; with faces, also the merged faces of a file of one
 * object in *faces (empty when *empty is set, and for several objects);
 * how: import_solid's. The file is read once per build: taken from
 * c->imports where a builder before read it, else read and kept there;
 * last (the leaf built where the import stands, which no builder takes
 * after it), it is let go from there after use; so faces are asked for
 * only without last, as they may be lent from the file kept (import_solid).
 * Its triangles are charged to c's budget once per import statement, by
 * the first builder that takes them (build_ctx.h); the builders after it
 * take them free. */
static sc_status import_parts(const build_ctx *c, const model_import *import, int strict,
                              unsigned how, build_prims *out, const char **empty,
                              build_mesh_faces *faces, int last)
{
    memset(out, 0, sizeof *out);
    if (import->format == MODEL_MESH_UNSUPPORTED) {
        *empty = "";
        return build_import_unsupported(c, &import->file_loc, import->file, strict);
    }
    const sc_location loc = import->file_loc;
    int objects = import->format == MODEL_MESH_AMF || import->format == MODEL_MESH_3MF;
    struct build_import_file here, *file = imports_find(c->imports, import);
    memset(&here, 0, sizeof here);
    sc_status st = SC_OK;
    if (!file || !file->read) {
        file = &here;
        if ((st = import_read(c, import, strict, &here, empty)) != SC_OK || *empty)
            return st;
        struct build_import_file *kept =
            c->imports && !last ? imports_put(c->imports, import) : NULL;
        if (c->imports && !last && !kept) {
            import_file_free(&here);
            return err_nomem(c->error, (&loc));
        }
        if (kept) {
            kept->read = 1;
            kept->m = here.m;
            kept->a = here.a;
            memset(&here, 0, sizeof here);
            file = kept;
        }
    }
    merged_object *merged = NULL;
    if (file != &here && !file->merged) {
        uint32_t count = objects && file->a.object_count > 1 ? file->a.object_count : 1;
        file->merged = calloc(count, sizeof *file->merged);
        file->merged_count = file->merged ? count : 0;
        if (!file->merged)
            st = err_nomem(c->error, &loc);
    }
    if (file != &here)
        merged = file->merged;
    /* charged already: the entry stays in the table after its file is let
     * go, and the budget is the load's (a preview's parts have their own) */
    struct build_import_file *entry = imports_find(c->imports, import);
    build_ctx bc = *c;
    if (entry && c->triangles_left && entry->charged == c->triangles_left)
        bc.triangles_left = NULL;
    char why[SC_ERROR_MESSAGE_MAX - 320];
    int rolled = 0;
    if (st != SC_OK)
        ;
    else if (objects ? file->a.face_count == 0 : file->m.face_count == 0)
        *empty = "import without faces is empty";
    else if (!objects && c->faithful && import->format == MODEL_MESH_OFF &&
             (rolled = off_rolled_back(&file->m, why, sizeof why)) != 0) {
        if (rolled == -1)
            st = err_nomem(c->error, &loc);
        else if (rolled == -2)
            st = err_set(c->error, SC_ERR_IO, &loc, "import: %s", why);
        else if (rolled == 2 || strict || c->strict)
            st = err_set(c->error, SC_ERR_SEMANTIC, &loc,
                         "import: '%s' is not a mesh CGAL's OFF reader takes (%s)",
                         import->file, why);
        else if ((st = build_note_left_out(
                      c, &loc,
                      "import: '%s' is not a mesh CGAL's OFF reader takes (%s); the "
                      "import is empty, as OpenSCAD reads nothing from it (--strict "
                      "makes it an error)",
                      import->file, why)) == SC_OK)
            *empty = "";
    } else if (objects)
        st =
            import_objects(&bc, import, strict, how, &file->a, out, empty, faces, merged);
    else
        st = import_solid(&bc, &loc, "imported mesh", strict, 0, how, file->m.points,
                          file->m.point_count, file->m.indices, file->m.face_start,
                          file->m.face_count, out, empty, faces, merged);
    if (st == SC_OK && entry)
        entry->charged = c->triangles_left;
    /* several objects, every one left out or without volume: their
     * warnings were given, and the import counts as left out, so that
     * its parent does not add that it is empty (build_notes) */
    if (st == SC_OK && !*empty && out->count == 0) {
        *empty = "";
        if (c->notes)
            c->notes->left_out++;
    }
    if (st != SC_OK) {
        free(out->items);
        memset(out, 0, sizeof *out);
    }
    if (file == &here || last)
        import_file_free(file);
    return st;
}

/* The union of parts as one mesh leaf, for the builders that take an
 * import's triangles (hull's corners, projection's faces): each part
 * closed and turned outward (import_solid leaves out the others, IMPORT_JOINED),
 * so that winding numbers add up to the union. The parts' triangles were
 * charged to the budget as the parts were built; their join is the same
 * triangles, not charged again. */
static sc_status join_parts(const build_ctx *c, const sc_location *loc,
                            const build_prims *parts, prim *out)
{
    size_t tris = 0;
    for (uint32_t i = 0; i < parts->count; i++)
        tris += parts->items[i].u.mesh.mesh->tri_count;
    if (tris > UINT32_MAX / 3)
        return err_set(c->error, SC_ERR_LIMIT, loc, "imported mesh has too many faces");
    sc_status st = SC_OK;
    vec3 *v = malloc(3 * tris * sizeof *v);
    uint32_t *index = malloc(3 * tris * sizeof *index);
    if (!v || !index) {
        st = err_nomem(c->error, loc);
    } else {
        size_t k = 0;
        for (uint32_t i = 0; i < parts->count; i++) {
            const prim_mesh *m = parts->items[i].u.mesh.mesh;
            memcpy(&v[k], m->v, 3 * (size_t)m->tri_count * sizeof *v);
            k += 3 * (size_t)m->tri_count;
        }
        for (size_t i = 0; i < k; i++)
            index[i] = (uint32_t)i;
        const prim_mesh *m =
            prim_mesh_create_rule(c->csg, v, index, (uint32_t)(k / 3), 0);
        if (!m) {
            st = err_nomem(c->error, loc);
        } else {
            memset(out, 0, sizeof *out);
            out->kind = PRIM_MESH;
            out->u.mesh.mesh = m;
        }
    }
    free(v);
    free(index);
    return st;
}

sc_status build_import_parts(const build_ctx *c, const model_import *import, int strict,
                             build_prims *out, const char **empty)
{
    return import_parts(c, import, strict, 0, out, empty, NULL, 1);
}

sc_status build_import_left_out(const build_ctx *c, const model_import *import,
                                const char **empty)
{
    build_prims parts;
    sc_status st = import_parts(c, import, c->strict, IMPORT_JOINED | IMPORT_LOOSE,
                                &parts, empty, NULL, 1);
    free(parts.items);
    return st;
}

sc_status build_import_solids(const build_ctx *c, const model_import *import,
                              build_prims *out, const char **empty)
{
    return import_parts(c, import, c->strict, IMPORT_JOINED | IMPORT_ALONE, out, empty,
                        NULL, 0);
}

sc_status build_import_faces(const build_ctx *c, const model_import *import,
                             const char **empty, build_mesh_faces *faces)
{
    memset(faces, 0, sizeof *faces);
    build_prims parts;
    sc_status st = import_parts(c, import, 0, 0, &parts, empty, faces, 0);
    free(parts.items);
    return st;
}

/* build_import_solids' objects as one leaf (join_parts); how: import_solid's. */
static sc_status import_one(const build_ctx *c, const model_import *import, unsigned how,
                            prim *out, const char **empty)
{
    build_prims parts;
    sc_status st = import_parts(c, import, c->strict, how, &parts, empty, NULL, 0);
    if (st == SC_OK && !*empty)
        st = parts.count == 1 ? (*out = parts.items[0], SC_OK)
                              : join_parts(c, &import->file_loc, &parts, out);
    free(parts.items);
    return st;
}

sc_status build_import(const build_ctx *c, const model_import *import, prim *out,
                       const char **empty)
{
    return import_one(c, import, IMPORT_JOINED | IMPORT_ALONE, out, empty);
}

sc_status build_import_mesh(const build_ctx *c, const model_import *import, prim *out,
                            const char **empty)
{
    return import_one(c, import, IMPORT_JOINED | IMPORT_LOOSE, out, empty);
}
