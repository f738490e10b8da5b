/* The metamorphic stability harness (stability.h).
 *
 * The depth bound, per pixel. Let X be the largest coordinate magnitude the
 * transformed case computes with: |t| + s (|c| + r + D), with c and r the
 * centre and radius of the model's box and D the camera distance (model
 * units). Every coordinate of the transformed case (eye, composite leaf
 * transform, its inverse, the primitive's solve) carries an absolute error
 * of a few ulps of X, so in model units the hit point moves by at most
 * k u X / s along the surface normal (u = 2^-53). Along a ray that meets the
 * surface at angle theta to its normal, that is a change of ray length
 * k u X / (s cos theta), so
 *   |t' - t| / t <= k u X / (s L cos theta),   L = t |d| (hit distance).
 * k = STAB_ULPS covers the chain of roundings (camera basis, two matrix
 * products, transform to local, quadratic solve: each a few ulps); the
 * tests check this bound at every pixel, the report gives the largest error.
 * Rays within STAB_GRAZE of grazing (cos theta below it) are not held to a
 * depth bound (their t is ill-conditioned by nature) but still count for the
 * mask and NaN checks.
 */
#include "bench/stability.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "build/scene.h"
#include "render/camera.h"

#define STAB_ULPS 64.0
#define STAB_GRAZE 1e-3
#define STAB_FOV 30.0

static const double UNIT_ROUNDOFF = 1.1102230246251565e-16; /* 2^-53 */

static uint64_t splitmix(uint64_t *state)
{
    uint64_t z = (*state += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

static double uniform(uint64_t *state)
{
    return (double)(splitmix(state) >> 11) * 0x1.0p-53;
}

stab_similarity stab_scaled(double sx, double sy, double sz, vec3 t)
{
    stab_similarity x;
    memset(&x, 0, sizeof x);
    x.m[0][0] = sx;
    x.m[1][1] = sy;
    x.m[2][2] = sz;
    x.t = t;
    return x;
}

stab_similarity stab_random(uint64_t seed, double log10_scale_lo, double log10_scale_hi,
                            double radius, double translation_ratio)
{
    uint64_t state = seed;
    /* A uniform rotation from a uniform unit quaternion (Shoemake). */
    double u1 = uniform(&state), u2 = uniform(&state), u3 = uniform(&state);
    const double two_pi = 6.283185307179586;
    double a = sqrt(1 - u1), b = sqrt(u1);
    double w = a * sin(two_pi * u2), x = a * cos(two_pi * u2);
    double y = b * sin(two_pi * u3), z = b * cos(two_pi * u3);
    double s =
        pow(10, log10_scale_lo + (log10_scale_hi - log10_scale_lo) * uniform(&state));
    stab_similarity r;
    r.m[0][0] = s * (1 - 2 * (y * y + z * z));
    r.m[0][1] = s * (2 * (x * y - z * w));
    r.m[0][2] = s * (2 * (x * z + y * w));
    r.m[1][0] = s * (2 * (x * y + z * w));
    r.m[1][1] = s * (1 - 2 * (x * x + z * z));
    r.m[1][2] = s * (2 * (y * z - x * w));
    r.m[2][0] = s * (2 * (x * z - y * w));
    r.m[2][1] = s * (2 * (y * z + x * w));
    r.m[2][2] = s * (1 - 2 * (x * x + y * y));
    vec3 dir = v3_normalize(
        v3(uniform(&state) - 0.5, uniform(&state) - 0.5, uniform(&state) - 0.5));
    r.t = v3_scale(dir, translation_ratio * s * radius * uniform(&state));
    return r;
}

static vec3 apply_vector(const stab_similarity *x, vec3 v)
{
    return v3(x->m[0][0] * v.x + x->m[0][1] * v.y + x->m[0][2] * v.z,
              x->m[1][0] * v.x + x->m[1][1] * v.y + x->m[1][2] * v.z,
              x->m[2][0] * v.x + x->m[2][1] * v.y + x->m[2][2] * v.z);
}

/* The harness camera: oblique (no face of an axis-aligned model is seen
 * edge-on and no pixel centre lies on an axis-aligned silhouette by
 * construction), framed on the box as OpenSCAD's viewall does. */
static int harness_camera(const bbox *bounds, int size, camera *cam)
{
    cam_view view;
    view.center = v3(0, 0, 0);
    view.forward = v3_normalize(v3(-0.5773, -0.6421, -0.5049));
    view.up = v3(0, 0, 1);
    cam_view_all(&view, bounds, 1, STAB_FOV);
    sc_error ignored;
    return cam_init(cam, &view, STAB_FOV, SC_PROJECTION_PERSPECTIVE, size, size,
                    &ignored) == SC_OK;
}

static int hit_is_finite(const csg_tree *tree, const csg_ray *ray, const csg_hit *hit)
{
    vec3 n = csg_hit_normal(tree, ray, hit);
    return isfinite(hit->t) && v3_is_finite(n);
}

uint64_t stab_nan_scan(const csg_tree *tree, int size, uint64_t *hits)
{
    *hits = 0;
    camera cam;
    if (!harness_camera(&tree->bounds, size, &cam))
        return 0;
    arena scratch;
    arena_init(&scratch, 1 << 16);
    uint64_t nan_count = 0;
    for (int j = 0; j < size; j++)
        for (int i = 0; i < size; i++) {
            csg_ray ray = {.tmin = 0, .tmax = INFINITY};
            cam_ray(&cam, i, j, 0.5, 0.5, &ray.o, &ray.d);
            csg_hit hit;
            if (csg_first_hit(tree, &ray, &scratch, &hit)) {
                ++*hits;
                nan_count += !hit_is_finite(tree, &ray, &hit);
            }
            arena_reset(&scratch);
        }
    arena_free(&scratch);
    return nan_count;
}

/* The model wrapped in multmatrix(x); NULL when out of memory. */
static char *wrap(const char *text, const stab_similarity *x)
{
    const char *format = "multmatrix([[%.17g, %.17g, %.17g, %.17g], "
                         "[%.17g, %.17g, %.17g, %.17g], [%.17g, %.17g, %.17g, %.17g], "
                         "[0, 0, 0, 1]]) {\n";
    double m[3][4];
    for (int i = 0; i < 3; i++) {
        for (int k = 0; k < 3; k++)
            m[i][k] = x->m[i][k];
        m[i][3] = v3_get(x->t, i);
    }
    size_t length = strlen(text), room = length + 512;
    char *out = malloc(room);
    if (!out)
        return NULL;
    int head = snprintf(out, room, format, m[0][0], m[0][1], m[0][2], m[0][3], m[1][0],
                        m[1][1], m[1][2], m[1][3], m[2][0], m[2][1], m[2][2], m[2][3]);
    memcpy(out + head, text, length);
    memcpy(out + head + length, "\n}\n", 4);
    return out;
}

/* Frobenius norms of m and of its inverse; 0 and 0 when m is singular. */
static void norms(const stab_similarity *x, double *norm, double *inverse_norm)
{
    affine a = affine_identity(), inverse;
    double sum = 0, inverse_sum = 0;
    for (int i = 0; i < 3; i++)
        for (int k = 0; k < 3; k++) {
            a.m[i][k] = x->m[i][k];
            sum += x->m[i][k] * x->m[i][k];
        }
    *norm = *inverse_norm = 0;
    if (!affine_invert(&a, &inverse))
        return;
    for (int i = 0; i < 3; i++)
        for (int k = 0; k < 3; k++)
            inverse_sum += inverse.m[i][k] * inverse.m[i][k];
    *norm = sqrt(sum);
    *inverse_norm = sqrt(inverse_sum);
}

sc_status stab_compare(const char *name, const char *text, const char *moved_text,
                       const stab_similarity *x, int size, stab_result *out,
                       sc_error *error)
{
    memset(out, 0, sizeof *out);
    sc_scene *base = NULL, *moved = NULL;
    sc_status st = sc_scene_load_string(name, text, strlen(text), NULL, &base, error);
    if (st != SC_OK)
        return st;
    char *wrapped = wrap(moved_text ? moved_text : text, x);
    if (!wrapped) {
        sc_scene_release(base);
        return err_nomem(error, NULL);
    }
    st = sc_scene_load_string(name, wrapped, strlen(wrapped), NULL, &moved, error);
    free(wrapped);
    if (st != SC_OK) {
        sc_scene_release(base);
        return st;
    }
    const csg_tree *a = scene_tree(base), *b = scene_tree(moved);
    out->pixels = (uint64_t)size * (uint64_t)size;
    camera cam;
    if (!bbox_is_empty(&a->bounds) && harness_camera(&a->bounds, size, &cam)) {
        double radius = v3_length(bbox_extent(&a->bounds)) / 2;
        double norm, inverse_norm;
        norms(x, &norm, &inverse_norm);
        /* In model units: the translation seen through the inverse, the
         * model and the camera, times the condition number (a rounding
         * error of u X in world moves a point by up to u X |m^-1| in model
         * units, and X itself is up to |m| times the model's coordinates). */
        double magnitude = norm * inverse_norm *
                           (inverse_norm * v3_length(x->t) +
                            v3_length(bbox_center(&a->bounds)) + radius + cam.distance);
        arena scratch;
        arena_init(&scratch, 1 << 16);
        for (int j = 0; j < size; j++)
            for (int i = 0; i < size; i++) {
                csg_ray ra = {.tmin = 0, .tmax = INFINITY}, rb;
                cam_ray(&cam, i, j, 0.5, 0.5, &ra.o, &ra.d);
                rb = ra;
                rb.o = v3_add(apply_vector(x, ra.o), x->t);
                rb.d = apply_vector(x, ra.d);
                csg_hit ha, hb;
                int hit_a = csg_first_hit(a, &ra, &scratch, &ha);
                int hit_b = csg_first_hit(b, &rb, &scratch, &hb);
                out->hits += (uint64_t)hit_a;
                out->mask_mismatches += (uint64_t)(hit_a != hit_b);
                int finite_a = !hit_a || hit_is_finite(a, &ra, &ha);
                int finite_b = !hit_b || hit_is_finite(b, &rb, &hb);
                out->nan_count += (uint64_t)!finite_a + (uint64_t)!finite_b;
                if (hit_a && hit_b && finite_a && finite_b && ha.t > 0) {
                    double rel = fabs(hb.t - ha.t) / ha.t;
                    if (rel > out->max_rel_depth_error)
                        out->max_rel_depth_error = rel;
                    vec3 n = csg_hit_normal(a, &ra, &ha);
                    double length = v3_length(ra.d);
                    double cos_theta = fabs(v3_dot(n, ra.d)) / length;
                    double bound = STAB_ULPS * UNIT_ROUNDOFF * magnitude /
                                   (ha.t * length * cos_theta);
                    if (cos_theta >= STAB_GRAZE && rel > bound)
                        out->depth_violations++;
                }
                arena_reset(&scratch);
            }
        arena_free(&scratch);
    }
    sc_scene_release(moved);
    sc_scene_release(base);
    return SC_OK;
}

/* 1 when every span of the solid along ray is no longer than eps: the far
 * camera's regularisation (its eps is 2^-40 of its distance, csg_eps)
 * removes exactly those, by the rule, so missing them is not a mismatch. */
static int below_resolution(const csg_tree *t, const csg_ray *ray, double eps,
                            arena *scratch)
{
    span_list l;
    if (!csg_spans(t, ray, scratch, &l))
        return 0;
    for (uint32_t i = 0; i < l.n; i++)
        if (l.v[i].out.t - l.v[i].in.t > eps)
            return 0;
    return 1;
}

sc_status stab_far_camera(const char *name, const char *text, double distance, int size,
                          stab_result *out, sc_error *error)
{
    memset(out, 0, sizeof *out);
    sc_scene *scene = NULL;
    sc_status st = sc_scene_load_string(name, text, strlen(text), NULL, &scene, error);
    if (st != SC_OK)
        return st;
    const csg_tree *t = scene_tree(scene);
    out->pixels = (uint64_t)size * (uint64_t)size;
    if (!bbox_is_empty(&t->bounds)) {
        vec3 center = bbox_center(&t->bounds);
        double radius = v3_length(bbox_extent(&t->bounds)) / 2;
        double near = 10 * radius;
        vec3 d = v3_normalize(v3(-0.5773, -0.6421, -0.5049));
        vec3 right = v3_normalize(v3_cross(d, v3(0, 0, 1))), up = v3_cross(right, d);
        arena scratch;
        arena_init(&scratch, 1 << 16);
        for (int j = 0; j < size; j++)
            for (int i = 0; i < size; i++) {
                double x = (2 * (i + 0.5) / size - 1) * radius;
                double y = (1 - 2 * (j + 0.5) / size) * radius;
                vec3 target = v3_add(center, v3_add(v3_scale(right, x), v3_scale(up, y)));
                csg_ray rn = {v3_madd(target, d, -near), d, 0, INFINITY};
                csg_ray rf = {v3_madd(target, d, -distance), d, 0, INFINITY};
                csg_hit hn, hf;
                int a = csg_first_hit(t, &rn, &scratch, &hn);
                int b = csg_first_hit(t, &rf, &scratch, &hf);
                out->hits += (uint64_t)a;
                if (a && !b && below_resolution(t, &rn, csg_eps(t, rf.o, rf.d), &scratch))
                    out->below_resolution++;
                else
                    out->mask_mismatches += (uint64_t)(a != b);
                int finite_a = !a || hit_is_finite(t, &rn, &hn);
                int finite_b = !b || hit_is_finite(t, &rf, &hf);
                out->nan_count += (uint64_t)!finite_a + (uint64_t)!finite_b;
                if (a && b && finite_a && finite_b && hf.t > 0) {
                    /* distance - near is exact for the distances used
                     * (both have few significant bits), so the difference
                     * is the far ray's rounding: a few ulps of distance. */
                    double rel = fabs(hf.t - (distance - near) - hn.t) / hf.t;
                    if (rel > out->max_rel_depth_error)
                        out->max_rel_depth_error = rel;
                    out->depth_violations += rel > STAB_ULPS * UNIT_ROUNDOFF;
                }
                arena_reset(&scratch);
            }
        arena_free(&scratch);
    }
    sc_scene_release(scene);
    return SC_OK;
}

char *stab_deep_differences(int levels)
{
    size_t room = (size_t)levels * 120 + 64, n = 0;
    char *text = malloc(room);
    if (!text)
        return NULL;
    for (int i = 0; i < levels; i++)
        n += (size_t)snprintf(text + n, room - n,
                              "difference() { cube(size = %.17g, center = true);\n",
                              2.0 - 1.9 * i / levels);
    n += (size_t)snprintf(text + n, room - n, "sphere(r = 0.01);");
    for (int i = 0; i < levels; i++)
        text[n++] = '}';
    text[n] = 0;
    return text;
}

char *stab_wide_union(int leaves)
{
    size_t room = (size_t)leaves * 100 + 64, n = 0;
    char *text = malloc(room);
    if (!text)
        return NULL;
    n += (size_t)snprintf(text + n, room - n, "union() {\n");
    for (int i = 0; i < leaves; i++)
        n += (size_t)snprintf(text + n, room - n,
                              "multmatrix([[1,0,0,%d],[0,1,0,%d],[0,0,1,0],[0,0,0,1]]) "
                              "{ cube(size = 0.5); }\n",
                              i % 400, i / 400);
    snprintf(text + n, room - n, "}\n");
    return text;
}
