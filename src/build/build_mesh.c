/* Building mesh leaves: the polyhedra that are not convex, and
 * import("file.stl" | "file.off").
 *
 * A mesh must bound a solid: closed (every undirected edge in exactly two
 * faces) and consistently oriented (those two faces run along the edge in
 * opposite directions). Anything else is an error naming an offending
 * edge; OpenSCAD's own CGAL render rejects such meshes too, and a ray
 * caster cannot tell inside from outside without it. Which way the faces
 * wind does not matter: OpenSCAD lists them clockwise seen from outside,
 * STL and OFF files usually the other way, so the sign of the enclosed
 * volume (divergence theorem, sum of a . (b x c) / 6 over the triangles,
 * about the centre of the bounds for accuracy) decides, and a mesh whose
 * volume is negative is turned inside out. A mesh without volume is empty,
 * with a warning. Faces with more than three points are split into fans
 * about their first point; where a fan of a non-convex face overlaps
 * itself, the winding number of prim_mesh.c cancels the overlap.
 *
 * Files: binary STL is recognised by its size (84 + 50 n bytes for the n
 * triangles its header announces), anything else starting with "solid" is
 * read as ASCII STL (every "vertex x y z"), and .off files as OFF (header,
 * counts, points, then faces as "k i1 .. ik" with any colour after them).
 * STL repeats each corner per triangle; corners with equal coordinates are
 * merged, so the edge checks above apply. Paths are relative to the
 * directory of the file being read, as OpenSCAD resolves them.
 */
#include "build/build_mesh.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "base/grow.h"
#include "csg/prim_mesh.h"
#include "formats/file.h"

static int compare_u64(const void *a, const void *b)
{
    uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
    return x < y ? -1 : x > y;
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

/* Closed and consistently oriented, else an error naming an edge. */
static sc_status check_edges(const build_ctx *c, const sc_location *loc, const char *what,
                             int numbered, const vec3 *points, const uint32_t *indices,
                             const uint32_t *face_start, uint32_t face_count)
{
    int by_coordinates = !numbered;
    char name[256];
    uint32_t total = face_start[face_count];
    uint64_t *directed = malloc((size_t)(total ? total : 1) * sizeof *directed);
    uint64_t *undirected = malloc((size_t)(total ? total : 1) * sizeof *undirected);
    if (!directed || !undirected) {
        free(directed);
        free(undirected);
        return err_nomem(c->error, loc);
    }
    size_t count = 0;
    for (uint32_t f = 0; f < face_count; f++) {
        uint32_t s = face_start[f], e = face_start[f + 1];
        for (uint32_t i = s; i < e; i++) {
            uint32_t p = indices[i], q = indices[i + 1 < e ? i + 1 : s];
            if (p == q)
                continue;
            directed[count] = (uint64_t)p << 32 | q;
            undirected[count++] = p < q ? (uint64_t)p << 32 | q : (uint64_t)q << 32 | p;
        }
    }
    qsort(directed, count, sizeof *directed, compare_u64);
    qsort(undirected, count, sizeof *undirected, compare_u64);
    sc_status st = SC_OK;
    for (size_t i = 0; i < count && st == SC_OK;) {
        size_t j = i;
        while (j < count && undirected[j] == undirected[i])
            j++;
        if (j - i != 2)
            st = err_set(
                c->error, SC_ERR_SEMANTIC, loc,
                "%s is not closed (edge %s is used by %zu face%s)", what,
                edge_name(name, sizeof name, points, by_coordinates, undirected[i]),
                j - i, j - i == 1 ? "" : "s");
        i = j;
    }
    for (size_t i = 0; i + 1 < count && st == SC_OK; i++) {
        if (directed[i] == directed[i + 1])
            st = err_set(
                c->error, SC_ERR_SEMANTIC, loc,
                "%s is not consistently oriented (edge %s runs the same way in "
                "two faces)",
                what, edge_name(name, sizeof name, points, by_coordinates, directed[i]));
    }
    free(directed);
    free(undirected);
    return st;
}

sc_status build_mesh_prim(const build_ctx *c, const sc_location *loc, const char *what,
                          int numbered, const vec3 *points, uint32_t point_count,
                          const uint32_t *indices, const uint32_t *face_start,
                          uint32_t face_count, prim *out, const char **empty)
{
    sc_status st =
        check_edges(c, loc, what, numbered, points, indices, face_start, face_count);
    if (st != SC_OK)
        return st;
    size_t tri_count = 0;
    for (uint32_t f = 0; f < face_count; f++)
        tri_count += face_start[f + 1] - face_start[f] - 2;
    if (tri_count > UINT32_MAX / 3)
        return err_set(c->error, SC_ERR_LIMIT, loc, "%s has too many faces", what);
    uint32_t *tris = malloc((tri_count ? tri_count : 1) * 3 * sizeof *tris);
    if (!tris)
        return err_nomem(c->error, loc);
    bbox box = bbox_empty();
    for (uint32_t i = 0; i < point_count; i++)
        box = bbox_add_point(box, points[i]);
    vec3 centre = v3_scale(v3_add(box.lo, box.hi), 0.5);
    size_t k = 0;
    double volume = 0;
    for (uint32_t f = 0; f < face_count; f++) {
        uint32_t s = face_start[f], e = face_start[f + 1];
        for (uint32_t i = s + 1; i + 1 < e; i++) {
            tris[3 * k] = indices[s];
            tris[3 * k + 1] = indices[i];
            tris[3 * k + 2] = indices[i + 1];
            vec3 a = v3_sub(points[indices[s]], centre);
            vec3 b = v3_sub(points[indices[i]], centre);
            vec3 d = v3_sub(points[indices[i + 1]], centre);
            volume += v3_dot(a, v3_cross(b, d)) / 6;
            k++;
        }
    }
    vec3 ext = v3_sub(box.hi, box.lo);
    double size = fmax(ext.x, fmax(ext.y, ext.z));
    if (!(fabs(volume) > 1e-12 * size * size * size)) {
        free(tris);
        *empty = numbered ? "polyhedron without volume is empty"
                          : "imported mesh without volume is empty";
        return SC_OK;
    }
    if (volume < 0) {
        for (size_t i = 0; i < k; i++) {
            uint32_t t = tris[3 * i + 1];
            tris[3 * i + 1] = tris[3 * i + 2];
            tris[3 * i + 2] = t;
        }
    }
    const prim_mesh *m = prim_mesh_create(c->csg, points, tris, (uint32_t)k);
    free(tris);
    if (!m)
        return err_nomem(c->error, loc);
    memset(out, 0, sizeof *out);
    out->kind = PRIM_MESH;
    out->u.mesh.mesh = m;
    return SC_OK;
}

/* ---- files ---- */

typedef struct mesh_file {
    vec3 *points;
    uint32_t point_count, point_cap;
    uint32_t *indices, *face_start;
    uint32_t index_count, index_cap, face_count, face_cap;
} mesh_file;

static void mesh_file_free(mesh_file *m)
{
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

typedef struct keyed_point {
    vec3 p;
    uint32_t index;
} keyed_point;

static int compare_points(const void *a, const void *b)
{
    const keyed_point *x = a, *y = b;
    if (x->p.x != y->p.x)
        return x->p.x < y->p.x ? -1 : 1;
    if (x->p.y != y->p.y)
        return x->p.y < y->p.y ? -1 : 1;
    if (x->p.z != y->p.z)
        return x->p.z < y->p.z ? -1 : 1;
    return x->index < y->index ? -1 : x->index > y->index;
}

/* STL corners 3i, 3i + 1, 3i + 2 become triangle i; equal corners are
 * merged into one point. */
static int merge_corners(mesh_file *m)
{
    uint32_t n = m->point_count;
    keyed_point *k = malloc((size_t)(n ? n : 1) * sizeof *k);
    uint32_t *map = malloc((size_t)(n ? n : 1) * sizeof *map);
    if (!k || !map) {
        free(k);
        free(map);
        return 0;
    }
    for (uint32_t i = 0; i < n; i++)
        k[i] = (keyed_point){m->points[i], i};
    qsort(k, n, sizeof *k, compare_points);
    uint32_t unique = 0;
    for (uint32_t i = 0; i < n; i++) {
        if (i == 0 || compare_points(&(keyed_point){k[i].p, 0},
                                     &(keyed_point){k[unique - 1].p, 0}) != 0)
            k[unique++].p = k[i].p;
        map[k[i].index] = unique - 1;
    }
    int ok = 1;
    for (uint32_t t = 0; ok && t < n / 3; t++) {
        ok = start_face(m);
        for (int j = 0; ok && j < 3; j++)
            ok = add_index(m, map[3 * t + (uint32_t)j]);
    }
    ok = ok && finish_faces(m);
    for (uint32_t i = 0; ok && i < unique; i++)
        m->points[i] = k[i].p;
    m->point_count = unique;
    free(k);
    free(map);
    return ok;
}

static float read_f32(const unsigned char *p)
{
    uint32_t u = (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 |
                 (uint32_t)p[3] << 24;
    float f;
    memcpy(&f, &u, sizeof f);
    return f;
}

/* Returns NULL on success, else what is wrong. */
static const char *read_stl(const char *text, size_t size, mesh_file *m, int *oom)
{
    const unsigned char *u = (const unsigned char *)text;
    if (size >= 84) {
        uint32_t n = (uint32_t)u[80] | (uint32_t)u[81] << 8 | (uint32_t)u[82] << 16 |
                     (uint32_t)u[83] << 24;
        if ((uint64_t)n * 50 + 84 == size) {
            for (uint32_t t = 0; t < n; t++) {
                const unsigned char *f = u + 84 + (size_t)t * 50 + 12;
                for (int j = 0; j < 3; j++) {
                    vec3 p = v3(read_f32(f + 12 * j), read_f32(f + 12 * j + 4),
                                read_f32(f + 12 * j + 8));
                    if (!v3_is_finite(p))
                        return "a corner is not finite";
                    if (!add_point(m, p))
                        return *oom = 1, "out of memory";
                }
            }
            return merge_corners(m) ? NULL : (*oom = 1, "out of memory");
        }
    }
    if (size < 5 || strncmp(text, "solid", 5) != 0)
        return "neither binary STL (its size does not match its triangle count) nor "
               "ASCII STL (it does not start with 'solid')";
    const char *p = text, *end = text + size;
    while (p < end) {
        while (p < end && (*p == ' ' || *p == '\t' || *p == '\r' || *p == '\n'))
            p++;
        const char *word = p;
        while (p < end && !(*p == ' ' || *p == '\t' || *p == '\r' || *p == '\n'))
            p++;
        if (p - word == 6 && strncmp(word, "vertex", 6) == 0) {
            double c[3];
            for (int j = 0; j < 3; j++) {
                char *next;
                c[j] = strtod(p, &next);
                if (next == p || next > end)
                    return "a 'vertex' without three numbers";
                p = next;
            }
            vec3 q = v3(c[0], c[1], c[2]);
            if (!v3_is_finite(q))
                return "a corner is not finite";
            if (!add_point(m, q))
                return *oom = 1, "out of memory";
        }
    }
    if (m->point_count % 3 != 0)
        return "its vertex count is not a multiple of 3";
    return merge_corners(m) ? NULL : (*oom = 1, "out of memory");
}

/* The next whitespace-separated token of an OFF file, skipping '#'
 * comments; *newline is set when a line break came before it. */
static const char *off_token(const char **p, const char *end, int *newline)
{
    *newline = 0;
    for (;;) {
        while (*p < end && (**p == ' ' || **p == '\t' || **p == '\r' || **p == '\n')) {
            if (**p == '\n')
                *newline = 1;
            (*p)++;
        }
        if (*p < end && **p == '#') {
            while (*p < end && **p != '\n')
                (*p)++;
            continue;
        }
        break;
    }
    if (*p >= end)
        return NULL;
    const char *t = *p;
    while (*p < end &&
           !(**p == ' ' || **p == '\t' || **p == '\r' || **p == '\n' || **p == '#'))
        (*p)++;
    return t;
}

static int off_number(const char **p, const char *end, double *out)
{
    int nl;
    const char *t = off_token(p, end, &nl);
    if (!t)
        return 0;
    char buf[64];
    size_t len = (size_t)(*p - t);
    if (len >= sizeof buf)
        return 0;
    memcpy(buf, t, len);
    buf[len] = 0;
    char *next;
    *out = strtod(buf, &next);
    return *next == 0;
}

static const char *read_off(const char *text, size_t size, mesh_file *m, int *oom)
{
    const char *p = text, *end = text + size;
    int nl;
    const char *t = off_token(&p, end, &nl);
    if (!t || p - t != 3 || strncmp(t, "OFF", 3) != 0)
        return "it does not start with 'OFF'";
    double counts[3];
    for (int j = 0; j < 3; j++)
        if (!off_number(&p, end, &counts[j]) || !(counts[j] >= 0) ||
            counts[j] != floor(counts[j]) || counts[j] > UINT32_MAX / 4)
            return "bad point, face and edge counts";
    uint32_t nv = (uint32_t)counts[0], nf = (uint32_t)counts[1];
    for (uint32_t i = 0; i < nv; i++) {
        double c[3];
        for (int j = 0; j < 3; j++)
            if (!off_number(&p, end, &c[j]))
                return "fewer points than its header says, or a bad coordinate";
        vec3 q = v3(c[0], c[1], c[2]);
        if (!v3_is_finite(q))
            return "a point is not finite";
        if (!add_point(m, q))
            return *oom = 1, "out of memory";
    }
    for (uint32_t f = 0; f < nf; f++) {
        double k;
        if (!off_number(&p, end, &k) || k != floor(k) || k < 3 || k > nv)
            return "fewer faces than its header says, or a face with a bad point count";
        if (!start_face(m))
            return *oom = 1, "out of memory";
        for (uint32_t j = 0; j < (uint32_t)k; j++) {
            double i;
            if (!off_number(&p, end, &i) || i != floor(i) || i < 0 || i >= nv)
                return "a face's point index is bad or out of range";
            if (!add_index(m, (uint32_t)i))
                return *oom = 1, "out of memory";
        }
        /* anything after the indices on the line is a colour */
        while (p < end && *p != '\n')
            p++;
    }
    return finish_faces(m) ? NULL : (*oom = 1, "out of memory");
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

sc_status build_import(const build_ctx *c, const model_import *import, prim *out,
                       const char **empty)
{
    const char *name = import->file;
    const sc_location loc = import->file_loc;
    int stl = import->format == MODEL_MESH_STL;
    char *path = build_file_path(c, name);
    if (!path)
        return err_nomem(c->error, (&loc));
    size_t size = 0;
    const char *why = NULL;
    char *text = file_read(path, BUILD_MAX_MESH_FILE, &size, &why);
    if (!text) {
        sc_status st =
            err_set(c->error, SC_ERR_IO, &loc, "import: cannot read '%s': %s", path, why);
        free(path);
        return st;
    }
    mesh_file m;
    memset(&m, 0, sizeof m);
    int oom = 0;
    why = stl ? read_stl(text, size, &m, &oom) : read_off(text, size, &m, &oom);
    free(text);
    sc_status st = SC_OK;
    if (oom)
        st = err_nomem(c->error, (&loc));
    else if (why)
        st = err_set(c->error, SC_ERR_SEMANTIC, &loc,
                     "import: '%s' is not a valid %s file (%s)", path,
                     stl ? "STL" : "OFF", why);
    else if (m.face_count == 0)
        *empty = "import without faces is empty";
    else
        st = build_mesh_prim(c, &loc, "imported mesh", 0, m.points, m.point_count,
                             m.indices, m.face_start, m.face_count, out, empty);
    free(path);
    mesh_file_free(&m);
    return st;
}
