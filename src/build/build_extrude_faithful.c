/* linear_extrude(height, center, twist, slices, scale) built exactly as
 * OpenSCAD 2021.01 builds it (its extrudePolygon and add_slice), as a
 * closed mesh leaf (build_mesh_prim).
 *
 * The profile is the union of the 2D children through the 2D engine
 * (build_twod_children). From z = h1 to h2 (0 and height, or -height/2 and
 * height/2 centred) it is cut into `slices` layers. Ring j (0 .. slices)
 * is every profile point p moved by diag(s_j) R(-a_j) at height
 * h1 + (h2 - h1) j / slices, where a_j = twist j / slices degrees and
 * s_j = 1 - (1 - scale) j / slices per axis (OpenSCAD's expressions in
 * its order, with its degree sine and cosine). Between rings j and j + 1
 * each profile edge (prev, curr) gives a quad, split into two triangles
 * along the shorter diagonal: |prev_j - curr_j+1| against
 * |curr_j - prev_j+1|, equal when they differ by at most 1e-5 of their
 * sum, in which case the split follows the twist's direction and whether
 * the contour is a hole. When the top ring has a zero scale the split is
 * the other one, and the second triangle is left out where the quad's top
 * edge has collapsed. The bottom cap is the profile at h1, the top cap the
 * last ring (left out when a scale is 0: the top is a point or a segment).
 *
 * Slices: `slices` when given (> 0); else with twist OpenSCAD's helix rule
 * (conical when the scale is uniform and not 1): at least one slice per
 * 120 degrees, $fn per 360 degrees when $fn > 0, else the fewer of
 * twist / $fa and the length of the path of the farthest point over $fs;
 * without twist but with different x and y scales, $fn, else the longest
 * diagonal path over $fs; otherwise 1.
 *
 * Making the mesh closed: points of neighbouring rings are computed once
 * and shared. A top ring scaled to a point merges into one apex; one
 * scaled onto a segment has its points merged where they coincide, and
 * a triangle whose top edge passes over other top points is split at
 * them, so each piece of the segment is used by two triangles.
 */
#include "build/build_extrude_faithful.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "base/grow.h"
#include "build/build_mesh.h"
#include "build/build_twod.h"
#include "model/faithful.h"

/* Most slices of one extrusion. */
#define MAX_SLICES MODEL_MAX_SLICES
/* OpenSCAD's GRID_FINE: radii below it get the minimum slice count. */
#define GRID_FINE 0.00000095367431640625
#define DEG2RAD (3.14159265358979323846 / 180.0)

typedef struct params {
    double height, twist, sx, sy, fn, fa, fs;
    double slices; /* given slices, 0 when not given */
    int center;
} params;

typedef struct mesh {
    vec3 *points;
    uint32_t ring; /* points per ring */
    uint32_t *indices, *face_start;
    size_t index_count, index_cap, face_count, face_cap;
    uint32_t *top_map; /* top ring point -> merged point, or NULL */
    uint32_t *line;    /* merged top points sorted along the segment */
    uint32_t line_count;
    int line_axis; /* 0: the top is on the x axis, 1: on the y axis */
    uint32_t top;  /* first point of the top ring */
    /* with a segment-shaped top (line): OpenSCAD's own faces, its triangles
     * not split over the segment's points (what faithful mode checks is
     * closed), or NULL */
    struct mesh *raw;
} mesh;

/* The model's arguments (model.h), their error reported first. */
static sc_status read_params(const build_ctx *c, const model_node *n, params *p)
{
    if (n->pending)
        return build_pending(c, n);
    const model_linear_extrude *e = n->u.linear_extrude;
    *p = (params){e->height, e->twist,  e->sx,     e->sy,    e->res.fn,
                  e->res.fa, e->res.fs, e->slices, e->center};
    return SC_OK;
}

/* OpenSCAD's Calc::get_helix_slices, in doubles (no conversion of an
 * unbounded count to int). */
static double helix_slices(double r_sqr, double height, double twist, double fn,
                           double fs, double fa)
{
    twist = fabs(twist);
    double min_slices = fmax(ceil(twist / 120.0), 1);
    if (sqrt(r_sqr) < GRID_FINE || isinf(fn) || isnan(fn))
        return min_slices;
    if (fn > 0.0)
        return fmax(ceil(twist / 360.0 * fn), min_slices);
    double fa_slices = ceil(twist / fa);
    double t = twist * DEG2RAD, cc = height / t;
    double fs_slices = ceil(t * sqrt(r_sqr + cc * cc) / fs);
    return fmax(fmin(fa_slices, fs_slices), min_slices);
}

static double archimedes_length(double a, double theta)
{
    return 0.5 * a * (theta * sqrt(1 + theta * theta) + asinh(theta));
}

/* Calc::get_conical_helix_slices: twist with a uniform scale other than 1. */
static double conical_slices(double r_sqr, double height, double twist, double scale,
                             double fn, double fs, double fa)
{
    twist = fabs(twist);
    double r = sqrt(r_sqr);
    double min_slices = fmax(ceil(twist / 120.0), 1);
    if (r < GRID_FINE || isinf(fn) || isnan(fn))
        return min_slices;
    if (fn > 0.0)
        return fmax(ceil(twist * fn / 360), min_slices);
    double rads = twist * DEG2RAD;
    double angle_end = scale > 1 ? rads * scale / (scale - 1) : rads / (1 - scale);
    double angle_start = angle_end - rads;
    double a = r / angle_end;
    double spiral = archimedes_length(a, angle_end) - archimedes_length(a, angle_start);
    double total = sqrt(spiral * spiral + height * height);
    double fs_slices = ceil(total / fs);
    double fa_slices = ceil(twist / fa);
    return fmax(fmin(fa_slices, fs_slices), min_slices);
}

/* Calc::get_diagonal_slices: different x and y scales, no twist. */
static double diagonal_slices(double delta_sqr, double height, double fn, double fs)
{
    if (sqrt(delta_sqr) < GRID_FINE || isinf(fn) || isnan(fn))
        return 1;
    if (fn > 0.0)
        return fmax(trunc(fn), 1);
    return fmax(ceil(sqrt(delta_sqr + height * height) / fs), 1);
}

static double slice_count(const params *p, const twod_region *r)
{
    if (p->slices > 0)
        return p->slices;
    if (p->twist != 0) {
        double max_r_sqr = 0;
        for (uint32_t i = 0; i < r->point_count; i++) {
            double x = r->xy[2 * i], y = r->xy[2 * i + 1];
            max_r_sqr = fmax(max_r_sqr, x * x + y * y);
        }
        if ((p->sx == 1.0 && p->sy == 1.0) || p->sx != p->sy)
            return helix_slices(max_r_sqr, p->height, p->twist, p->fn, p->fs, p->fa);
        return conical_slices(max_r_sqr, p->height, p->twist, p->sx, p->fn, p->fs, p->fa);
    }
    if (p->sx != p->sy) {
        double max_delta_sqr = 0;
        for (uint32_t i = 0; i < r->point_count; i++) {
            double x = r->xy[2 * i], y = r->xy[2 * i + 1];
            double dx = x - x * p->sx, dy = y - y * p->sy;
            max_delta_sqr = fmax(max_delta_sqr, dx * dx + dy * dy);
        }
        return diagonal_slices(max_delta_sqr, p->height, p->fn, p->fs);
    }
    return 1;
}

/* OpenSCAD's sgn_vdiff: -1, 0 or 1 as |a| is shorter, about equal (within
 * 10 ppm of the sum) or longer than |b|. */
static int sgn_vdiff(double ax, double ay, double bx, double by)
{
    double l1 = sqrt(ax * ax + ay * ay), l2 = sqrt(bx * bx + by * by);
    double diff = 2 * fabs(l1 - l2) * 1e5;
    return diff > l1 + l2 ? (l1 < l2 ? -1 : 1) : 0;
}

static int add_face(mesh *m, const uint32_t *v, uint32_t count)
{
    if (!grow_array((void **)&m->face_start, &m->face_cap, m->face_count + 2,
                    sizeof *m->face_start) ||
        !grow_array((void **)&m->indices, &m->index_cap, m->index_count + count,
                    sizeof *m->indices) ||
        m->index_count + count > UINT32_MAX)
        return 0;
    m->face_start[m->face_count++] = (uint32_t)m->index_count;
    memcpy(m->indices + m->index_count, v, count * sizeof *v);
    m->index_count += count;
    m->face_start[m->face_count] = (uint32_t)m->index_count;
    return 1;
}

static uint32_t vertex(const mesh *m, uint32_t ring, uint32_t i)
{
    uint32_t v = ring * m->ring + i;
    return v >= m->top && m->top_map ? m->top_map[v - m->top] : v;
}

static double along(const mesh *m, uint32_t v)
{
    return m->line_axis == 0 ? m->points[v].x : m->points[v].y;
}

/* First index in the sorted segment points whose position is > t. */
static uint32_t line_after(const mesh *m, double t)
{
    uint32_t lo = 0, hi = m->line_count;
    while (lo < hi) {
        uint32_t mid = lo + (hi - lo) / 2;
        if (along(m, m->line[mid]) > t)
            hi = mid;
        else
            lo = mid + 1;
    }
    return lo;
}

/* Adds triangle (a, b, c); degenerate ones (a repeated point) are left
 * out, and on a segment-shaped top an edge over other top points is split
 * at them. */
static int add_triangle(mesh *m, uint32_t a, uint32_t b, uint32_t c)
{
    if (a == b || b == c || c == a)
        return 1;
    uint32_t t[3] = {a, b, c};
    if (m->raw && !add_face(m->raw, t, 3))
        return 0;
    if (m->line) {
        for (int e = 0; e < 3; e++) {
            uint32_t u = t[e], v = t[(e + 1) % 3], w = t[(e + 2) % 3];
            if (u < m->top || v < m->top)
                continue;
            double tu = along(m, u), tv = along(m, v);
            int up = tu < tv;
            uint32_t from = line_after(m, up ? tu : tv), to = line_after(m, up ? tv : tu);
            /* points strictly between: [from, to) minus the end itself */
            uint32_t prev = u;
            for (uint32_t k = 0; k < to - from; k++) {
                uint32_t q = m->line[up ? from + k : to - 1 - k];
                if (q == v || along(m, q) == (up ? tv : tu))
                    continue;
                uint32_t f[3] = {w, prev, q};
                if (!add_face(m, f, 3))
                    return 0;
                prev = q;
            }
            uint32_t f[3] = {w, prev, v};
            return add_face(m, f, 3);
        }
    }
    return add_face(m, t, 3);
}

static int compare_points(const void *pa, const void *pb, const vec3 *points)
{
    uint32_t a = *(const uint32_t *)pa, b = *(const uint32_t *)pb;
    const vec3 *p = &points[a], *q = &points[b];
    if (p->x != q->x)
        return p->x < q->x ? -1 : 1;
    if (p->y != q->y)
        return p->y < q->y ? -1 : 1;
    return (a > b) - (a < b);
}

/* qsort takes no context (the points): a merge sort of point indices. */
static void sort_points(uint32_t *v, uint32_t *tmp, uint32_t count, const vec3 *points)
{
    if (count < 2)
        return;
    uint32_t half = count / 2;
    sort_points(v, tmp, half, points);
    sort_points(v + half, tmp, count - half, points);
    uint32_t i = 0, j = half, k = 0;
    while (i < half && j < count)
        tmp[k++] = compare_points(&v[i], &v[j], points) <= 0 ? v[i++] : v[j++];
    while (i < half)
        tmp[k++] = v[i++];
    while (j < count)
        tmp[k++] = v[j++];
    memcpy(v, tmp, count * sizeof *v);
}

/* Merges coinciding points of the top ring; on a segment-shaped top also
 * lists the merged points along it. */
static int merge_top(mesh *m, int segment_axis)
{
    uint32_t n = m->ring;
    uint32_t *order = malloc((size_t)n * sizeof *order);
    uint32_t *tmp = malloc((size_t)n * sizeof *tmp);
    m->top_map = malloc((size_t)n * sizeof *m->top_map);
    m->line = malloc((size_t)n * sizeof *m->line);
    if (!order || !tmp || !m->top_map || !m->line) {
        free(order);
        free(tmp);
        return 0;
    }
    for (uint32_t i = 0; i < n; i++)
        order[i] = m->top + i;
    sort_points(order, tmp, n, m->points);
    m->line_count = 0;
    for (uint32_t i = 0; i < n; i++) {
        uint32_t v = order[i];
        if (i > 0 && m->points[v].x == m->points[m->line[m->line_count - 1]].x &&
            m->points[v].y == m->points[m->line[m->line_count - 1]].y) {
            m->top_map[v - m->top] = m->line[m->line_count - 1];
        } else {
            m->top_map[v - m->top] = v;
            m->line[m->line_count++] = v;
        }
    }
    /* sorted by x then y: along the y axis when x is 0 throughout */
    m->line_axis = segment_axis;
    if (segment_axis < 0) {
        free(m->line);
        m->line = NULL;
    }
    free(order);
    free(tmp);
    return 1;
}

static void mesh_free(mesh *m)
{
    free(m->points);
    free(m->indices);
    free(m->face_start);
    free(m->top_map);
    free(m->line);
    if (m->raw) {
        free(m->raw->indices);
        free(m->raw->face_start);
    }
}

/* Hands the mesh of m to faces: its side faces one loop each, then the
 * caps, each one face of all its loops (the cap faces of m alternate
 * bottom and top per contour, the top left out when top_zero). Takes the
 * points and indices of m. 0 when memory runs out. */
static int take_faces(mesh *m, uint32_t point_count, uint32_t cap_first, int top_zero,
                      build_mesh_faces *faces)
{
    uint32_t loops = (uint32_t)m->face_count;
    uint32_t *loop_start = malloc(((size_t)loops + 1) * sizeof *loop_start);
    uint32_t *face_loops = malloc(((size_t)cap_first + 3) * sizeof *face_loops);
    uint32_t *indices = malloc((m->index_count ? m->index_count : 1) * sizeof *indices);
    if (!loop_start || !face_loops || !indices) {
        free(loop_start);
        free(face_loops);
        free(indices);
        return 0;
    }
    /* sides as they are, then the bottom loops, then the top ones */
    uint32_t l = 0, k = 0, f = 0;
    for (uint32_t pass = 0; pass < 3; pass++) {
        if (pass > 0)
            face_loops[f++] = l;
        for (uint32_t i = 0; i < loops; i++) {
            int cap = i >= cap_first;
            int top = cap && !top_zero && (i - cap_first) % 2 == 1;
            if (pass != (!cap ? 0u : top ? 2u : 1u))
                continue;
            if (pass == 0)
                face_loops[f++] = l;
            loop_start[l++] = k;
            for (uint32_t j = m->face_start[i]; j < m->face_start[i + 1]; j++)
                indices[k++] = m->indices[j];
        }
    }
    loop_start[l] = k;
    face_loops[f] = l;
    faces->points = m->points;
    faces->point_count = point_count;
    faces->indices = indices;
    faces->face_start = loop_start;
    faces->face_loops = face_loops;
    faces->face_count = f;
    m->points = NULL;
    return 1;
}

/* The matrix OpenSCAD 2021.01 moves the profile by at a ring, by rows:
 * Scaling(sx, sy) times rotate_degrees(-deg) (extrudePolygon, add_slice). */
static void slice_matrix(double sx, double sy, double deg, double m[4])
{
    double cs = faithful_cos_deg(-deg), sn = faithful_sin_deg(-deg);
    m[0] = sx * cs;
    m[1] = sx * -sn;
    m[2] = sy * sn;
    m[3] = sy * cs;
}

/* The profile's point (x, y) moved by m, at height z. */
static vec3 slice_point(const double m[4], double x, double y, double z)
{
    return v3(m[0] * x + m[1] * y, m[2] * x + m[3] * y, z);
}

/* Hands the mesh of m to faces as OpenSCAD 2021.01's PolySet reaches
 * CGAL's builder (CGAL_Build_PolySet): the bottom cap's triangles, the top
 * cap's, then the sides, each face as the builder turns it (m's sides
 * already are: wound inward) and with corners of its own, in the order the
 * builder meets them, so that the grid merges them as OpenSCAD's does. The
 * caps are OpenSCAD's Polygon2d::tessellate of the profile (cdt), the top
 * one of the profile moved by the whole twist and scale. 0 where CGAL
 * refuses the profile (OpenSCAD's tessellation fails there too); -1 when
 * memory runs out. */
static int openscad_faces(mesh *m, uint32_t cap_first, const twod_region *r,
                          const params *p, double h1, double h2, int top_zero,
                          const nef_plugin *cdt, build_mesh_faces *faces)
{
    uint32_t *cap[2] = {NULL, NULL}, cap_count[2] = {0, 0};
    double *top = malloc(((size_t)r->point_count * 2 + 1) * sizeof *top);
    if (!top)
        return -1;
    double mt[4];
    slice_matrix(p->sx, p->sy, p->twist, mt);
    for (uint32_t i = 0; i < r->point_count; i++) {
        vec3 q = slice_point(mt, r->xy[2 * i], r->xy[2 * i + 1], 0);
        top[2 * i] = q.x;
        top[2 * i + 1] = q.y;
    }
    char why[512];
    int ok = 1;
    for (int k = 0; ok && k < 2 - top_zero; k++) {
        nef_status ns = cdt->tessellate(k ? top : r->xy, r->start, r->contour_count,
                                        &cap[k], &cap_count[k], why, sizeof why);
        ok = ns == NEF_OK ? 1 : ns == NEF_NOMEM ? -1 : 0;
    }
    size_t corners = 3 * ((size_t)cap_count[0] + cap_count[1]);
    corners += m->face_start[cap_first];
    size_t face_count = (size_t)cap_count[0] + cap_count[1] + cap_first;
    vec3 *points = NULL;
    uint32_t *start = NULL, *indices = NULL;
    if (ok == 1 && (corners > UINT32_MAX || face_count >= UINT32_MAX))
        ok = -1;
    if (ok == 1) {
        points = malloc((corners + 1) * sizeof *points);
        indices = malloc((corners + 1) * sizeof *indices);
        start = malloc((face_count + 1) * sizeof *start);
        if (!points || !indices || !start)
            ok = -1;
    }
    if (ok == 1) {
        uint32_t k = 0, f = 0;
        /* the bottom cap's triangles reversed in its PolySet, so as the
         * triangulation gives them here; the top's the other way */
        for (int c = 0; c < 2; c++)
            for (uint32_t t = 0; t < cap_count[c]; t++) {
                start[f++] = k;
                for (int j = 0; j < 3; j++) {
                    uint32_t i = cap[c][3 * t + (c ? 2 - j : j)];
                    points[k] = c ? v3(top[2 * i], top[2 * i + 1], h2)
                                  : v3(r->xy[2 * i], r->xy[2 * i + 1], h1);
                    indices[k] = k;
                    k++;
                }
            }
        for (uint32_t s = 0; s < cap_first; s++) {
            start[f++] = k;
            for (uint32_t j = m->face_start[s]; j < m->face_start[s + 1]; j++) {
                points[k] = m->points[m->indices[j]];
                indices[k] = k;
                k++;
            }
        }
        start[f] = k;
        memset(faces, 0, sizeof *faces);
        faces->points = points;
        faces->point_count = k;
        faces->indices = indices;
        faces->face_start = start;
        faces->face_count = f;
    } else {
        free(points);
        free(indices);
        free(start);
    }
    free(cap[0]);
    free(cap[1]);
    free(top);
    return ok;
}

/* The extrusion of r as a mesh leaf in *out, or, when faces is not NULL,
 * as faces for CGAL in *faces (out unused): with cdt, as OpenSCAD's
 * PolySet (openscad_faces), else each cap one face of all its loops. */
static sc_status extrude(const build_ctx *c, const sc_location *loc, const params *p,
                         const twod_region *r, uint32_t slices, prim *out,
                         const char **empty, build_mesh_faces *faces,
                         const nef_plugin *cdt)
{
    double h1 = p->center ? -p->height / 2.0 : 0,
           h2 = p->center ? p->height / 2.0 : p->height;
    mesh m;
    memset(&m, 0, sizeof m);
    m.ring = r->point_count;
    m.top = slices * m.ring;
    size_t total = ((size_t)slices + 1) * m.ring;
    m.points = malloc(total * sizeof *m.points);
    if (!m.points)
        return err_nomem(c->error, loc);
    for (uint32_t j = 0; j <= slices; j++) {
        double rot = p->twist * j / slices;
        double scx = 1 - (1 - p->sx) * j / slices, scy = 1 - (1 - p->sy) * j / slices;
        double h = h1 + (h2 - h1) * j / slices;
        double mj[4];
        slice_matrix(scx, scy, rot, mj);
        for (uint32_t i = 0; i < m.ring; i++)
            m.points[(size_t)j * m.ring + i] =
                slice_point(mj, r->xy[2 * i], r->xy[2 * i + 1], h);
    }
    double top_sx = 1 - (1 - p->sx) * slices / slices;
    double top_sy = 1 - (1 - p->sy) * slices / slices;
    int top_zero = top_sx == 0 || top_sy == 0;
    int ok = 1;
    mesh raw;
    memset(&raw, 0, sizeof raw);
    if (top_zero)
        ok = merge_top(&m, top_sx == 0 && top_sy == 0 ? -1 : top_sy == 0 ? 0 : 1);
    if (ok && m.line && !faces)
        m.raw = &raw;
    for (uint32_t j = 0; ok && j < slices; j++) {
        double rot1 = p->twist * j / slices, rot2 = p->twist * (j + 1) / slices;
        double s2x = 1 - (1 - p->sx) * (j + 1) / slices;
        double s2y = 1 - (1 - p->sy) * (j + 1) / slices;
        int any_zero = s2x == 0 || s2y == 0, any_non_zero = s2x != 0 || s2y != 0;
        int back_twist = rot2 <= rot1;
        for (uint32_t k = 0; ok && k < r->contour_count; k++) {
            uint32_t s = r->start[k], len = r->start[k + 1] - s;
            if (len == 0)
                continue;
            int positive = twod_contour_area(r, k) >= 0;
            int flip = !positive ^ back_twist;
            for (uint32_t i = 1; ok && i <= len; i++) {
                uint32_t pi = s + i - 1, ci = s + i % len;
                uint32_t p1 = vertex(&m, j, pi), c1 = vertex(&m, j, ci);
                uint32_t p2 = vertex(&m, j + 1, pi), c2 = vertex(&m, j + 1, ci);
                const vec3 *P1 = &m.points[(size_t)j * m.ring + pi];
                const vec3 *C1 = &m.points[(size_t)j * m.ring + ci];
                const vec3 *P2 = &m.points[(size_t)(j + 1) * m.ring + pi];
                const vec3 *C2 = &m.points[(size_t)(j + 1) * m.ring + ci];
                int diff =
                    sgn_vdiff(P1->x - C2->x, P1->y - C2->y, C1->x - P2->x, C1->y - P2->y);
                int split_first = diff == -1 || (diff == 0 && !flip);
                int second =
                    !any_zero || (any_non_zero && (P2->x != C2->x || P2->y != C2->y));
                if (split_first ^ any_zero) {
                    ok = add_triangle(&m, p1, c2, c1) &&
                         (!second || add_triangle(&m, c2, p1, p2));
                } else {
                    ok = add_triangle(&m, p1, p2, c1) &&
                         (!second || add_triangle(&m, p2, c2, c1));
                }
            }
        }
    }
    /* caps, wound against the sides: the bottom as the contour runs, the
     * top the other way */
    uint32_t cap_first = (uint32_t)m.face_count;
    uint32_t raw_cap_first = m.raw ? (uint32_t)m.raw->face_count : 0;
    uint32_t *face = malloc(((size_t)m.ring + 1) * sizeof *face);
    ok = ok && face;
    for (uint32_t k = 0; ok && k < r->contour_count; k++) {
        uint32_t s = r->start[k], len = r->start[k + 1] - s;
        if (len < 3)
            continue;
        for (uint32_t i = 0; i < len; i++)
            face[i] = vertex(&m, 0, s + i);
        ok = add_face(&m, face, len) && (!m.raw || add_face(m.raw, face, len));
        if (ok && !top_zero) {
            for (uint32_t i = 0; i < len; i++)
                face[i] = vertex(&m, slices, s + len - 1 - i);
            ok = add_face(&m, face, len);
        }
    }
    free(face);
    sc_status st;
    if (!ok)
        st = err_nomem(c->error, loc);
    else if (faces) {
        /* OpenSCAD's own tessellation, or where CGAL refuses the profile
         * (which OpenSCAD 2021.01 does not survive), each cap whole */
        int made =
            cdt ? openscad_faces(&m, cap_first, r, p, h1, h2, top_zero, cdt, faces) : 0;
        if (made == 0)
            made = take_faces(&m, (uint32_t)total, cap_first, top_zero, faces) ? 1 : -1;
        st = made == 1 ? SC_OK : err_nomem(c->error, loc);
    } else {
        /* the caps: each contour's bottom (1), then its top (2) where the
         * top has area; only the bottoms where OpenSCAD's own mesh differs */
        const mesh *own = m.raw ? m.raw : &m;
        uint8_t *cap_of = calloc(own->face_count ? own->face_count : 1, 1);
        uint32_t first = m.raw ? raw_cap_first : cap_first;
        for (size_t k = first; cap_of && k < own->face_count; k++)
            cap_of[k] = (uint8_t)(m.raw || top_zero ? 1 : 1 + (k - first) % 2);
        build_mesh_checks openscad = {own->indices, own->face_start,
                                      (uint32_t)own->face_count, cap_of};
        st = cap_of
                 ? build_mesh_prim_checked(c, loc, "linear_extrude", 0, m.points,
                                           (uint32_t)total, m.indices, m.face_start,
                                           (uint32_t)m.face_count, &openscad, out, empty)
                 : err_nomem(c->error, loc);
        free(cap_of);
    }
    if (st == SC_OK && *empty && (*empty)[0]) /* "": left out, with its warning */
        *empty = "linear_extrude without height or area is empty";
    mesh_free(&m);
    return st;
}

static sc_status linear_extrude(const build_ctx *c, const model_node *n, int emit,
                                prim *out, const char **empty, build_mesh_faces *faces,
                                const nef_plugin *cdt)
{
    params p = {0};
    sc_status st = read_params(c, n, &p);
    if (st != SC_OK)
        return st;
    twod_region r;
    twod_init(&r);
    st = build_twod_children(c, n, &r);
    if (st == SC_OK && emit) {
        if (!(p.height > 0 && isfinite(p.height)) || !(fabs(twod_area(&r)) > 0)) {
            *empty = "linear_extrude without height or area is empty";
        } else {
            double slices = slice_count(&p, &r);
            if (!(slices <= MAX_SLICES) ||
                slices * r.point_count > (double)BUILD_EXTRUDE_MAX_QUADS)
                st = err_set(c->error, SC_ERR_LIMIT, &n->loc,
                             "linear_extrude: %g slices of %u points are too many (limit "
                             "is %u side faces)",
                             slices, r.point_count, BUILD_EXTRUDE_MAX_QUADS);
            else if (!faces) /* a mesh: each side face is a triangle or two */
                st = build_check_triangles(c, &n->loc, "linear_extrude",
                                           (size_t)slices * r.point_count);
            if (st == SC_OK)
                st =
                    extrude(c, &n->loc, &p, &r, (uint32_t)slices, out, empty, faces, cdt);
        }
    }
    twod_free(&r);
    return st;
}

sc_status build_linear_extrude_faithful(const build_ctx *c, const model_node *n, int emit,
                                        prim *out, const char **empty)
{
    return linear_extrude(c, n, emit, out, empty, NULL, NULL);
}

sc_status build_linear_extrude_faces(const build_ctx *c, const model_node *n,
                                     build_mesh_faces *faces, const char **empty,
                                     const nef_plugin *cdt)
{
    memset(faces, 0, sizeof *faces);
    return linear_extrude(c, n, 1, NULL, empty, faces, cdt);
}

sc_status build_flat_slab(const build_ctx *c, const sc_location *loc,
                          const twod_region *r, double height, prim *out,
                          const char **empty)
{
    /* height centred, one slice, no twist or scale; past 1e6 across,
     * height 1e-6 of the larger of its width and height, far above the
     * rays' tolerance (1e-9 of the extent: csg.h) */
    params p = {1, 0, 1, 1, 0, 12, 2, 1, 1};
    p.height = height;
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (uint32_t i = 0; i < r->point_count; i++)
        for (int a = 0; a < 2; a++) {
            lo[a] = fmin(lo[a], r->xy[2 * i + a]);
            hi[a] = fmax(hi[a], r->xy[2 * i + a]);
        }
    double across = fmax(hi[0] - lo[0], hi[1] - lo[1]);
    if (across > 1e6)
        p.height = height * 1e-6 * across;
    if (!(fabs(twod_area(r)) > 0)) {
        *empty = "the 2D model has no area";
        return SC_OK;
    }
    /* OpenSCAD draws a 2D result as it is, never through CGAL */
    build_ctx drawn = *c;
    drawn.drawn_as_is = 1;
    sc_status st = extrude(&drawn, loc, &p, r, 1, out, empty, NULL, NULL);
    if (st == SC_OK && *empty)
        *empty = "the 2D model has no area";
    return st;
}
