/* Faithful mode: OpenSCAD 2021.01's polyhedra for sphere and cylinder.
 *
 * Fragment count (OpenSCAD's get_fragments_from_r), for a circle of radius
 * r: 3 when r < 2^-20 (its GRID_FINE) or $fn is not finite; else
 * max($fn, 3) truncated to an integer when $fn > 0; else
 * ceil(max(min(360 / $fa, 2 pi r / $fs), 5)).
 *
 * Circle of radius r with f fragments: point k is
 * (r cos(360 k / f), r sin(360 k / f)), angles in degrees through
 * OpenSCAD's sin_degrees/cos_degrees, which reduce the angle to 0..90 and
 * return exact values at 30, 45 and 60 degrees.
 *
 * Sphere of radius r: f fragments from r, rings = (f + 1) / 2 circles of f
 * points; ring i sits at polar angle phi = 180 (i + 0.5) / rings, with
 * radius r sin(phi) at height r cos(phi). Faces: ring 0 as the top cap,
 * the last ring as the bottom cap, and between rings i and i + 1 the
 * trapezoid of points k and k + 1 of both (OpenSCAD writes it as two
 * triangles; they are coplanar, since the two chords are parallel and
 * symmetric about the plane at angle 360 (k + 0.5) / f). Every point lies
 * on the sphere, so the polyhedron is convex and equals the intersection
 * of its face planes.
 *
 * Cylinder from z0 (radius r0) to z1 (radius r1): f fragments from
 * max(r0, r1), one circle at each end (a zero radius is the apex of a
 * cone), a cap at each end with a non-zero radius, and one side face per
 * fragment through points k and k + 1 of both circles (again a planar
 * trapezoid or a triangle). Convex as the hull of two parallel convex
 * polygons with the same angular layout.
 *
 * Each face becomes a plane n . p <= d: n is Newell's normal of the face's
 * points (exact for planar polygons and robust when points repeat at an
 * apex), d the mean of n . p over the points, and the sign is chosen so that
 * a point on the axis (the centre for a sphere, mid-height for a cylinder)
 * is inside. OpenSCAD rounds its vertices to float when it exports a mesh;
 * the planes here are in double, so the two agree to float precision.
 */
#include "model/faithful.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"

#define GRID_FINE 0.00000095367431640625 /* 2^-20 */
#define PI 3.14159265358979323846
#define SQRT1_2 0.70710678118654752440
#define SQRT3_4 0.86602540378443859659  /* sqrt(3) / 2 */
#define DEG2RAD 0.017453292519943295769 /* pi / 180 */

long faithful_fragments(double r, double fn, double fs, double fa)
{
    if (r < GRID_FINE || isinf(fn) || isnan(fn))
        return 3;
    double count;
    if (fn > 0)
        count = fn >= 3 ? floor(fn) : 3;
    else
        count = ceil(fmax(fmin(360.0 / fa, r * 2 * PI / fs), 5));
    if (!(count <= FAITHFUL_MAX_FRAGMENTS))
        return -1; /* also NaN, from $fa or $fs that are 0 or NaN */
    return (long)count;
}

long faithful_sphere_fragments(double r, double fn, double fs, double fa)
{
    long f = faithful_fragments(r, fn, fs, fa);
    return f > FAITHFUL_MAX_SPHERE_FRAGMENTS ? -1 : f;
}

size_t faithful_sphere_face_count(long f)
{
    return (size_t)((f + 1) / 2 - 1) * (size_t)f + 2;
}

/* Reduces degrees to [0, 360) as OpenSCAD does (finite inputs only). */
static double reduce_degrees(double x)
{
    if (!(x < 360.0 && x >= 0.0))
        x -= 360.0 * floor(x / 360.0);
    return x;
}

double faithful_sin_deg(double x)
{
    x = reduce_degrees(x);
    int negate = x >= 180.0;
    if (negate)
        x -= 180.0;
    if (x > 90.0)
        x = 180.0 - x;
    double s;
    if (x < 45.0)
        s = x == 30.0 ? 0.5 : sin(x * DEG2RAD);
    else if (x == 45.0)
        s = SQRT1_2;
    else if (x == 60.0)
        s = SQRT3_4;
    else
        s = cos((90.0 - x) * DEG2RAD);
    return negate ? -s : s;
}

double faithful_cos_deg(double x)
{
    x = reduce_degrees(x);
    int negate = x >= 180.0;
    if (negate)
        x -= 180.0;
    if (x > 90.0) {
        x = 180.0 - x;
        negate = !negate;
    }
    double c;
    if (x > 45.0)
        c = x == 60.0 ? 0.5 : sin((90.0 - x) * DEG2RAD);
    else if (x == 45.0)
        c = SQRT1_2;
    else if (x == 30.0)
        c = SQRT3_4;
    else
        c = cos(x * DEG2RAD);
    return negate ? -c : c;
}

/* Point k of a circle of radius r with f fragments at height z. */
static vec3 circle_point(double r, long k, long f, double z)
{
    double phi = (360.0 * (double)k) / (double)f;
    return v3(r * faithful_cos_deg(phi), r * faithful_sin_deg(phi), z);
}

/* The plane of the polygon p[0..count), oriented so that inside_point is
 * inside. */
static plane face_plane(const vec3 *p, int count, vec3 inside_point)
{
    vec3 n = v3(0, 0, 0);
    for (int i = 0; i < count; i++) {
        vec3 a = p[i], b = p[(i + 1) % count];
        n = v3_add(n, v3_newell(a, b));
    }
    n = v3_scale(n, 1.0 / v3_length(n));
    double d = 0;
    for (int i = 0; i < count; i++)
        d += v3_dot(n, p[i]);
    d /= count;
    plane pl = {n, d};
    if (v3_dot(n, inside_point) > d) {
        pl.n = v3_neg(n);
        pl.d = -d;
    }
    return pl;
}

static sc_status fragment_error(double r, int limit, const sc_location *loc,
                                sc_error *error)
{
    return err_set(error, SC_ERR_LIMIT, loc,
                   "faithful mode: $fn, $fa and $fs of radius %g give too many fragments "
                   "(limit is %d)",
                   r, limit);
}

/* The rings of OpenSCAD's sphere of radius r with f fragments, top first:
 * point k of ring i in points[i * f + k]; returns their bounds. */
static bbox sphere_points(double r, long f, vec3 *points)
{
    long rings = (f + 1) / 2;
    bbox bounds = bbox_empty();
    for (long i = 0; i < rings; i++) {
        double phi = (180.0 * ((double)i + 0.5)) / (double)rings;
        double radius = r * faithful_sin_deg(phi);
        double z = r * faithful_cos_deg(phi);
        for (long k = 0; k < f; k++) {
            vec3 p = circle_point(radius, k, f, z);
            points[i * f + k] = p;
            bounds = bbox_add_point(bounds, p);
        }
    }
    return bounds;
}

/* The circles of OpenSCAD's cylinder: at z0 in points[k], at z1 in
 * points[f + k]; returns their bounds. */
static bbox cylinder_points(double z0, double z1, double r0, double r1, long f,
                            vec3 *points)
{
    bbox bounds = bbox_empty();
    for (long k = 0; k < f; k++) {
        points[k] = circle_point(r0, k, f, z0);
        points[f + k] = circle_point(r1, k, f, z1);
        bounds = bbox_add_point(bounds, points[k]);
        bounds = bbox_add_point(bounds, points[f + k]);
    }
    return bounds;
}

static void fill_convex(prim *out, plane *planes, uint32_t count, bbox bounds)
{
    memset(out, 0, sizeof *out);
    out->kind = PRIM_CONVEX;
    out->u.convex.planes = planes;
    out->u.convex.count = count;
    out->u.convex.bounds = bounds;
}

sc_status faithful_sphere(csg_builder *csg, double r, double fn, double fa, double fs,
                          const sc_location *loc, prim *out, sc_error *error)
{
    long f = faithful_sphere_fragments(r, fn, fs, fa);
    if (f < 0)
        return fragment_error(r, FAITHFUL_MAX_SPHERE_FRAGMENTS, loc, error);
    long rings = (f + 1) / 2;
    size_t count = faithful_sphere_face_count(f);
    plane *planes = csg_builder_alloc(csg, count * sizeof *planes);
    vec3 *points = malloc((size_t)rings * (size_t)f * sizeof *points);
    if (!planes || !points) {
        free(points);
        return err_nomem(error, NULL);
    }
    bbox bounds = sphere_points(r, f, points);
    vec3 centre = v3(0, 0, 0);
    size_t n = 0;
    planes[n++] = (plane){v3(0, 0, 1), points[0].z};
    planes[n++] = (plane){v3(0, 0, -1), -points[(rings - 1) * f].z};
    for (long i = 0; i + 1 < rings; i++) {
        for (long k = 0; k < f; k++) {
            long k1 = (k + 1) % f;
            vec3 quad[4] = {points[i * f + k], points[i * f + k1],
                            points[(i + 1) * f + k1], points[(i + 1) * f + k]};
            planes[n++] = face_plane(quad, 4, centre);
        }
    }
    free(points);
    fill_convex(out, planes, (uint32_t)n, bounds);
    return SC_OK;
}

sc_status faithful_cylinder(csg_builder *csg, double z0, double z1, double r0, double r1,
                            double fn, double fa, double fs, const sc_location *loc,
                            prim *out, sc_error *error)
{
    double rmax = fmax(r0, r1);
    long f = faithful_fragments(rmax, fn, fs, fa);
    if (f < 0)
        return fragment_error(rmax, FAITHFUL_MAX_FRAGMENTS, loc, error);
    size_t count = (size_t)f + 2;
    plane *planes = csg_builder_alloc(csg, count * sizeof *planes);
    vec3 *points = malloc(2 * (size_t)f * sizeof *points);
    if (!planes || !points) {
        free(points);
        return err_nomem(error, NULL);
    }
    bbox bounds = cylinder_points(z0, z1, r0, r1, f, points);
    vec3 axis = v3(0, 0, 0.5 * (z0 + z1));
    size_t n = 0;
    if (r0 > 0)
        planes[n++] = (plane){v3(0, 0, -1), -z0};
    if (r1 > 0)
        planes[n++] = (plane){v3(0, 0, 1), z1};
    for (long k = 0; k < f; k++) {
        long k1 = (k + 1) % f;
        vec3 quad[4] = {points[k], points[k1], points[f + k1], points[f + k]};
        planes[n++] = face_plane(quad, 4, axis);
    }
    free(points);
    fill_convex(out, planes, (uint32_t)n, bounds);
    return SC_OK;
}

/* ---- the same polyhedra as faces ---- */

void faithful_faces_free(faithful_faces *f)
{
    free(f->points);
    free(f->indices);
    free(f->face_start);
    memset(f, 0, sizeof *f);
}

/* Room for points, and faces of index_count indices in all. */
static int faces_alloc(faithful_faces *out, size_t points, size_t faces,
                       size_t index_count)
{
    memset(out, 0, sizeof *out);
    out->points = malloc(points * sizeof *out->points);
    out->indices = malloc(index_count * sizeof *out->indices);
    out->face_start = malloc((faces + 1) * sizeof *out->face_start);
    if (out->points && out->indices && out->face_start) {
        out->point_count = (uint32_t)points;
        out->face_start[0] = 0;
        return 1;
    }
    faithful_faces_free(out);
    return 0;
}

/* Appends the face of points a[0 .. n). */
static void add_face(faithful_faces *out, const uint32_t *a, int n)
{
    uint32_t start = out->face_start[out->face_count];
    memcpy(out->indices + start, a, (size_t)n * sizeof *a);
    out->face_start[++out->face_count] = start + (uint32_t)n;
}

/* The circle of f points from first, as a face wound counter-clockwise
 * seen from above (up) or from below. */
static void add_cap(faithful_faces *out, uint32_t first, long f, int up)
{
    uint32_t start = out->face_start[out->face_count];
    for (long k = 0; k < f; k++)
        out->indices[start + (uint32_t)k] = first + (uint32_t)(up ? k : f - 1 - k);
    out->face_start[++out->face_count] = start + (uint32_t)f;
}

sc_status faithful_sphere_faces(double r, double fn, double fa, double fs,
                                const sc_location *loc, faithful_faces *out,
                                sc_error *error)
{
    memset(out, 0, sizeof *out);
    long f = faithful_sphere_fragments(r, fn, fs, fa);
    if (f < 0)
        return fragment_error(r, FAITHFUL_MAX_SPHERE_FRAGMENTS, loc, error);
    long rings = (f + 1) / 2;
    size_t faces = faithful_sphere_face_count(f);
    if (!faces_alloc(out, (size_t)rings * (size_t)f, faces,
                     4 * (faces - 2) + 2 * (size_t)f))
        return err_nomem(error, NULL);
    sphere_points(r, f, out->points);
    add_cap(out, 0, f, 1);
    add_cap(out, (uint32_t)((rings - 1) * f), f, 0);
    for (long i = 0; i + 1 < rings; i++) {
        for (long k = 0; k < f; k++) {
            uint32_t k1 = (uint32_t)((k + 1) % f), top = (uint32_t)(i * f),
                     below = (uint32_t)((i + 1) * f);
            uint32_t quad[4] = {top + (uint32_t)k, below + (uint32_t)k, below + k1,
                                top + k1};
            add_face(out, quad, 4);
        }
    }
    return SC_OK;
}

sc_status faithful_cylinder_faces(double z0, double z1, double r0, double r1, double fn,
                                  double fa, double fs, const sc_location *loc,
                                  faithful_faces *out, sc_error *error)
{
    memset(out, 0, sizeof *out);
    double rmax = fmax(r0, r1);
    long f = faithful_fragments(rmax, fn, fs, fa);
    if (f < 0)
        return fragment_error(rmax, FAITHFUL_MAX_FRAGMENTS, loc, error);
    if (!faces_alloc(out, 2 * (size_t)f + 1, (size_t)f + 2, 6 * (size_t)f))
        return err_nomem(error, NULL);
    cylinder_points(z0, z1, r0, r1, f, out->points);
    /* a cone's apex: one point, the last, so that no edge has no length */
    uint32_t apex = (uint32_t)(2 * f), n = (uint32_t)f;
    if (r0 == 0)
        out->points[apex] = v3(0, 0, z0);
    else if (r1 == 0)
        out->points[apex] = v3(0, 0, z1);
    else
        out->point_count = apex;
    if (r0 > 0)
        add_cap(out, 0, f, 0);
    if (r1 > 0)
        add_cap(out, n, f, 1);
    for (uint32_t k = 0; k < n; k++) {
        uint32_t k1 = (k + 1) % n;
        if (r0 == 0) {
            uint32_t tri[3] = {apex, n + k1, n + k};
            add_face(out, tri, 3);
        } else if (r1 == 0) {
            uint32_t tri[3] = {k, k1, apex};
            add_face(out, tri, 3);
        } else {
            uint32_t quad[4] = {k, k1, n + k1, n + k};
            add_face(out, quad, 4);
        }
    }
    return SC_OK;
}
