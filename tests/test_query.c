/* Tests of the public query API (src/api/query.c): sc_scene_spans,
 * sc_scene_pixel_ray and sc_scene_inside, through models loaded from text,
 * against answers worked out by hand below.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>

#include <cmocka.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "test_util.h"

/* |a - b| <= tol * max(1, |b|) */
static void assert_near(double a, double b, double tol)
{
    double scale = fabs(b) > 1 ? fabs(b) : 1;
    if (!(fabs(a - b) <= tol * scale))
        fail_msg("%.17g is not within %g of %.17g", a, tol, b);
}

static void assert_vec_near(const double *a, double x, double y, double z, double tol)
{
    assert_near(a[0], x, tol);
    assert_near(a[1], y, tol);
    assert_near(a[2], z, tol);
}

static sc_span_list *spans_of(const sc_scene *s, double ox, double oy, double oz,
                              double dx, double dy, double dz, int both_ways)
{
    sc_ray_query q;
    sc_ray_query_init(&q);
    q.origin[0] = ox;
    q.origin[1] = oy;
    q.origin[2] = oz;
    q.direction[0] = dx;
    q.direction[1] = dy;
    q.direction[2] = dz;
    q.both_ways = both_ways;
    sc_span_list *list = NULL;
    sc_error e;
    if (sc_scene_spans(s, &q, &list, &e) != SC_OK)
        fail_msg("sc_scene_spans: %s", e.message);
    assert_non_null(list);
    return list;
}

/* The sphere of radius 3 at (3, 0, 5); the sphere node is at line 2, col 3. */
static const char sphere_text[] =
    "multmatrix([[1, 0, 0, 3], [0, 1, 0, 0], [0, 0, 1, 5], [0, 0, 0, 1]]) {\n"
    "  sphere(r = 3);\n"
    "}\n";

/* The classic worked example: o = (1, -2, -1), d = (1, 2, 4), centre
 * c = (3, 0, 5), r = 3. With o - c = (-2, -2, -6), |o + t d - c|^2 = 9 is
 *   |d|^2 t^2 + 2 d.(o - c) t + |o - c|^2 - 9 = 0
 *   21 t^2 - 60 t + 35 = 0    (d.(o - c) = -2 - 4 - 24 = -30, 44 - 9 = 35)
 *   t = (30 -+ sqrt(900 - 735)) / 21 = (30 -+ sqrt(165)) / 21,
 * about 0.8169 and 2.0402; the distance inside is
 *   (t_out - t_in) |d| = 2 sqrt(165) / 21 * sqrt(21) = 2 sqrt(55 / 7),
 * about 5.606; the normals are (p - c) / 3. */
static void test_worked_example(void **state)
{
    (void)state;
    sc_scene *s = test_load("worked.csg", sphere_text, 0);
    sc_span_list *list = spans_of(s, 1, -2, -1, 1, 2, 4, 0);
    assert_int_equal(sc_span_list_count(list), 1);
    assert_null(sc_span_list_get(list, 1));
    const sc_span *sp = sc_span_list_get(list, 0);
    double t_in = (30 - sqrt(165)) / 21, t_out = (30 + sqrt(165)) / 21;
    assert_near(sp->in.t, t_in, 1e-12);
    assert_near(sp->out.t, t_out, 1e-12);
    assert_near(sp->distance, 2 * sqrt(55.0 / 7.0), 1e-12);
    const sc_span_end *ends[2] = {&sp->in, &sp->out};
    double ts[2] = {t_in, t_out};
    for (int k = 0; k < 2; k++) {
        const sc_span_end *e = ends[k];
        double p[3] = {1 + ts[k], -2 + 2 * ts[k], -1 + 4 * ts[k]};
        assert_vec_near(e->point, p[0], p[1], p[2], 1e-12);
        assert_vec_near(e->normal, (p[0] - 3) / 3, p[1] / 3, (p[2] - 5) / 3, 1e-9);
        assert_int_equal(e->leaf, 0);
        assert_string_equal(e->leaf_kind, "sphere");
        assert_string_equal(e->location.file, "worked.csg");
        assert_int_equal(e->location.line, 2);
        assert_int_equal(e->location.column, 3);
        assert_int_equal(e->subtracted, 0);
    }
    sc_span_list_release(list);
    sc_scene_release(s);
}

/* From the centre along (0, 0, 2): the sphere is |t| <= 3 / 2. Over t >= 0
 * the span starts at the origin, on no surface; over the whole line it is
 * [-1.5, 1.5], 6 long. A ray starting above the sphere, along +z, meets it
 * only backwards: z = 20 + t in [2, 8] is t in [-18, -12]. */
static void test_both_ways(void **state)
{
    (void)state;
    sc_scene *s = test_load("worked.csg", sphere_text, 0);
    sc_span_list *list = spans_of(s, 3, 0, 5, 0, 0, 2, 0);
    assert_int_equal(sc_span_list_count(list), 1);
    const sc_span *sp = sc_span_list_get(list, 0);
    assert_true(sp->in.t == 0);
    assert_int_equal(sp->in.leaf, -1);
    assert_null(sp->in.leaf_kind);
    assert_near(sp->out.t, 1.5, 1e-12);
    assert_int_equal(sp->out.leaf, 0);
    assert_vec_near(sp->out.normal, 0, 0, 1, 1e-12);
    assert_near(sp->distance, 3, 1e-12);
    sc_span_list_release(list);

    list = spans_of(s, 3, 0, 5, 0, 0, 2, 1);
    assert_int_equal(sc_span_list_count(list), 1);
    sp = sc_span_list_get(list, 0);
    assert_near(sp->in.t, -1.5, 1e-12);
    assert_int_equal(sp->in.leaf, 0);
    assert_vec_near(sp->in.normal, 0, 0, -1, 1e-12);
    assert_vec_near(sp->in.point, 3, 0, 2, 1e-12);
    assert_near(sp->out.t, 1.5, 1e-12);
    assert_near(sp->distance, 6, 1e-12);
    sc_span_list_release(list);

    list = spans_of(s, 3, 0, 20, 0, 0, 1, 0);
    assert_int_equal(sc_span_list_count(list), 0);
    sc_span_list_release(list);
    list = spans_of(s, 3, 0, 20, 0, 0, 1, 1);
    assert_int_equal(sc_span_list_count(list), 1);
    assert_near(sc_span_list_get(list, 0)->in.t, -18, 1e-12);
    assert_near(sc_span_list_get(list, 0)->out.t, -12, 1e-12);
    sc_span_list_release(list);
    sc_scene_release(s);
}

/* A 10 mm cube with a hole of radius 2 along z through (5, 5): the box is
 * leaf 0 (line 2, col 3), the cylinder leaf 1 (line 4, col 5). */
static const char drilled_text[] =
    "difference() {\n"
    "  cube(size = [10, 10, 10], center = false);\n"
    "  multmatrix([[1, 0, 0, 5], [0, 1, 0, 5], [0, 0, 1, -1], [0, 0, 0, 1]]) {\n"
    "    cylinder(h = 12, r1 = 2, r2 = 2, center = false);\n"
    "  }\n"
    "}\n";

/* The ray x = -1 + 2 t through y = z = 5 is in the solid for x in [0, 3]
 * and [7, 10], t in [0.5, 2] and [4, 5.5], each 3 long. At x = 3 and x = 7
 * it meets the hole's wall: those ends are subtracted, and the solid's
 * outward normal there points into the hole, (1, 0, 0) at x = 3 and
 * (-1, 0, 0) at x = 7, the opposite of the cylinder's own. */
static void test_subtracted_surface(void **state)
{
    (void)state;
    sc_scene *s = test_load("drilled.csg", drilled_text, 0);
    sc_span_list *list = spans_of(s, -1, 5, 5, 2, 0, 0, 0);
    assert_int_equal(sc_span_list_count(list), 2);
    const sc_span *a = sc_span_list_get(list, 0), *b = sc_span_list_get(list, 1);
    assert_near(a->in.t, 0.5, 1e-12);
    assert_near(a->out.t, 2, 1e-12);
    assert_near(b->in.t, 4, 1e-12);
    assert_near(b->out.t, 5.5, 1e-12);
    assert_near(a->distance, 3, 1e-12);
    assert_near(b->distance, 3, 1e-12);

    const sc_span_end *box_ends[2] = {&a->in, &b->out};
    const sc_span_end *hole_ends[2] = {&a->out, &b->in};
    for (int k = 0; k < 2; k++) {
        const sc_span_end *e = box_ends[k];
        assert_int_equal(e->leaf, 0);
        assert_string_equal(e->leaf_kind, "box");
        assert_int_equal(e->location.line, 2);
        assert_int_equal(e->location.column, 3);
        assert_int_equal(e->subtracted, 0);
        assert_vec_near(e->normal, k ? 1 : -1, 0, 0, 1e-12);
        e = hole_ends[k];
        assert_int_equal(e->leaf, 1);
        assert_string_equal(e->leaf_kind, "cylinder");
        assert_string_equal(e->location.file, "drilled.csg");
        assert_int_equal(e->location.line, 4);
        assert_int_equal(e->location.column, 5);
        assert_int_equal(e->subtracted, 1);
        assert_vec_near(e->normal, k ? -1 : 1, 0, 0, 1e-12);
    }
    assert_vec_near(a->out.point, 3, 5, 5, 1e-12);
    assert_vec_near(b->in.point, 7, 5, 5, 1e-12);
    sc_span_list_release(list);
    sc_scene_release(s);
}

static int where_is(const sc_scene *s, double x, double y, double z)
{
    double p[3] = {x, y, z};
    int where = -1;
    sc_error e;
    if (sc_scene_inside(s, p, &where, &e) != SC_OK)
        fail_msg("sc_scene_inside: %s", e.message);
    return where;
}

/* Membership in the drilled cube. Its tolerance is eps = 1e-9 of its
 * extent, 1e-8 (the 2^-40 term is far smaller at this scale): a point 1e-9
 * off a face is on it, one 1e-6 off is not. */
static void test_membership(void **state)
{
    (void)state;
    sc_scene *s = test_load("drilled.csg", drilled_text, 0);
    assert_int_equal(where_is(s, 1, 1, 1), SC_INSIDE);
    assert_int_equal(where_is(s, 9, 2, 9.5), SC_INSIDE);
    assert_int_equal(where_is(s, 5, 5, 5), SC_OUTSIDE);  /* in the hole */
    assert_int_equal(where_is(s, 20, 0, 0), SC_OUTSIDE); /* beside it */
    assert_int_equal(where_is(s, -1, 5, 5), SC_OUTSIDE); /* on the axis line */
    assert_int_equal(where_is(s, 0, 5, 5), SC_ON);       /* exactly on a face */
    assert_int_equal(where_is(s, 2, 2, 10), SC_ON);      /* on the top face */
    assert_int_equal(where_is(s, 3, 5, 5), SC_ON);       /* on the hole's wall */
    assert_int_equal(where_is(s, 10, 10, 10), SC_ON);    /* a corner */
    assert_int_equal(where_is(s, -1e-9, 5, 5), SC_ON);   /* within eps */
    assert_int_equal(where_is(s, 1e-9, 5, 5), SC_ON);
    assert_int_equal(where_is(s, -1e-6, 5, 5), SC_OUTSIDE);
    assert_int_equal(where_is(s, 1e-6, 5, 5), SC_INSIDE);
    /* The wall at 45 degrees: (5 + 2 cos 45, 5 + 2 sin 45), on the circle. */
    double c = 5 + 2 * sqrt(0.5);
    assert_int_equal(where_is(s, c, c, 5), SC_ON);
    assert_int_equal(where_is(s, c + 1e-3, c + 1e-3, 5), SC_INSIDE);
    assert_int_equal(where_is(s, c - 1e-3, c - 1e-3, 5), SC_OUTSIDE);

    sc_scene *sphere = test_load("worked.csg", sphere_text, 0);
    assert_int_equal(where_is(sphere, 3, 0, 5), SC_INSIDE);
    assert_int_equal(where_is(sphere, 3, 0, 8), SC_ON);
    assert_int_equal(where_is(sphere, 3, 3, 5), SC_ON);
    assert_int_equal(where_is(sphere, 3, 3.001, 5), SC_OUTSIDE);
    sc_scene_release(sphere);
    sc_scene_release(s);
}

/* Bad arguments are errors with a message, and leave *out NULL. */
static void test_errors(void **state)
{
    (void)state;
    sc_scene *s = test_load("worked.csg", sphere_text, 0);
    sc_ray_query q;
    sc_ray_query_init(&q);
    q.origin[0] = 1;
    sc_span_list *list = (sc_span_list *)&q; /* must be reset to NULL */
    sc_error e;
    assert_int_equal(sc_scene_spans(s, &q, &list, &e), SC_ERR_ARGUMENT);
    assert_null(list);
    assert_string_equal(e.message, "ray direction must not be zero");
    q.direction[0] = 1;
    q.origin[1] = NAN;
    assert_int_equal(sc_scene_spans(s, &q, &list, &e), SC_ERR_ARGUMENT);
    assert_string_equal(e.message, "ray values must be finite");
    double p[3] = {0, INFINITY, 0};
    int where;
    assert_int_equal(sc_scene_inside(s, p, &where, &e), SC_ERR_ARGUMENT);
    assert_string_equal(e.message, "point coordinates must be finite");

    sc_render_options o;
    sc_render_options_init(&o);
    o.width = 40;
    o.height = 30;
    double origin[3], dir[3];
    assert_int_equal(sc_scene_pixel_ray(s, &o, 40, 0, origin, dir, &e), SC_ERR_ARGUMENT);
    assert_string_equal(e.message, "pixel 40,0 is outside the 40x30 image");
    sc_span_list_release(NULL);
    assert_int_equal(sc_span_list_count(NULL), 0);
    sc_scene_release(s);
}

/* A line on which an implicit leaf passes the root finder's bound of
 * evaluations (frequency 1e12 resolved to a tolerance of 1e-9: far more
 * than 2^22 cells) is SC_ERR_LIMIT at the leaf, for sc_scene_spans and
 * sc_scene_inside alike, never a list whose far part was not searched;
 * a line that misses the leaf's box still answers. */
static void test_ray_limit(void **state)
{
    (void)state;
    sc_scene *s =
        test_load("fine.csg",
                  "cube(1);\n"
                  "  implicit(f = \"sin(1e12 * x) * cos(1e11 * y) + z\",\n"
                  "    bounds = [[-1, -1, -1], [1, 1, 1]], tolerance = 1e-9);\n",
                  0);
    const char *want = "implicit surface needs more than 4194304 evaluations per ray "
                       "(limit is 4194304; the field is not resolvable at this scale)";
    sc_ray_query q;
    sc_ray_query_init(&q);
    q.origin[0] = -2;
    q.origin[1] = 0.1;
    q.direction[0] = 1;
    sc_span_list *list = (sc_span_list *)&q; /* must be reset to NULL */
    sc_error e;
    assert_int_equal(sc_scene_spans(s, &q, &list, &e), SC_ERR_LIMIT);
    assert_null(list);
    assert_string_equal(e.message, want);
    assert_int_equal(e.line, 2);
    assert_int_equal(e.column, 3);
    double p[3] = {0, 0.1, 0};
    int where = SC_ON;
    assert_int_equal(sc_scene_inside(s, p, &where, &e), SC_ERR_LIMIT);
    assert_string_equal(e.message, want);
    list = spans_of(s, -2, 5, 0.5, 1, 0, 0, 0); /* misses the implicit's box */
    assert_int_equal(sc_span_list_count(list), 0);
    sc_span_list_release(list);
    sc_scene_release(s);
}

/* A small image of depth alone, on one thread. */
static void depth_options(sc_render_options *o)
{
    sc_render_options_init(o);
    o->width = 24;
    o->height = 18;
    o->threads = 1;
    o->want_color = 0;
    o->want_depth = 1;
}

/* The pixel ray is the one render shoots: its first span's t |d| is the
 * depth render writes at that pixel, for every pixel of a small image of
 * the drilled cube, in perspective and orthographic views. */
/* Every pixel's ray (sc_scene_pixel_ray) meets the solid first at the
 * depth sc_render wrote there, so both frame the scene alike. */
static void check_pixel_rays(sc_scene *s, const sc_render_options *o)
{
    sc_framebuffer *fb = NULL;
    sc_error e;
    assert_int_equal(sc_render(s, o, &fb, &e), SC_OK);
    int hits = 0;
    for (int j = 0; j < o->height; j++) {
        for (int i = 0; i < o->width; i++) {
            double origin[3], dir[3];
            assert_int_equal(sc_scene_pixel_ray(s, o, i, j, origin, dir, &e), SC_OK);
            sc_span_list *list =
                spans_of(s, origin[0], origin[1], origin[2], dir[0], dir[1], dir[2], 0);
            float depth = sc_framebuffer_depth(fb)[j * o->width + i];
            if (sc_span_list_count(list) == 0) {
                assert_true(isinf(depth));
            } else {
                const sc_span *sp = sc_span_list_get(list, 0);
                double len = sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
                /* the depth buffer holds floats */
                assert_near(depth, sp->in.t * len, 1e-6);
                hits++;
            }
            sc_span_list_release(list);
        }
    }
    assert_true(hits > 0); /* the default view shows the whole model */
    sc_framebuffer_release(fb);
}

static void test_pixel_ray_matches_depth(void **state)
{
    (void)state;
    sc_scene *s = test_load("drilled.csg", drilled_text, 0);
    for (int proj = 0; proj < 2; proj++) {
        sc_render_options o;
        depth_options(&o);
        o.projection = proj ? SC_PROJECTION_ORTHOGRAPHIC : SC_PROJECTION_PERSPECTIVE;
        check_pixel_rays(s, &o);
    }
    sc_scene_release(s);
}

/* A sphere with its top cut off: the render frames the solid's own box
 * (csg/bounds.h), the preview the box of its CSG product, which holds the
 * top; sc_scene_frame_bounds gives each, and the pixel rays follow. */
static const char capped_text[] =
    "difference() { sphere(r = 10); multmatrix([[1, 0, 0, -20], [0, 1, 0, -20], "
    "[0, 0, 1, 5], [0, 0, 0, 1]]) cube(size = [40, 40, 40]); }\n";

static void test_frame_bounds(void **state)
{
    (void)state;
    sc_scene *s = test_load("capped.csg", capped_text, 0);
    sc_render_options o;
    depth_options(&o);
    double lo[3], hi[3];
    assert_int_equal(sc_scene_frame_bounds(s, &o, lo, hi), 1);
    for (int k = 0; k < 3; k++) {
        assert_near(lo[k], -10, 1e-6);
        assert_near(hi[k], k == 2 ? 5 : 10, 1e-6);
    }
    check_pixel_rays(s, &o);
    o.preview = 1;
    assert_int_equal(sc_scene_frame_bounds(s, &o, lo, hi), 1);
    assert_near(hi[2], 10, 1e-9);
    check_pixel_rays(s, &o);
    /* the defaults are the render's; the whole tree's box is larger */
    assert_int_equal(sc_scene_frame_bounds(s, NULL, lo, hi), 1);
    assert_near(hi[2], 5, 1e-6);
    assert_int_equal(sc_scene_bounds(s, lo, hi), 1);
    assert_near(hi[2], 10, 1e-9);
    o.size = 3; /* not a valid struct */
    assert_int_equal(sc_scene_frame_bounds(s, &o, lo, hi), 0);
    assert_true(lo[0] == 0 && hi[2] == 0);
    sc_scene_release(s);
}

/* A 2D model's render is flat at z = 0 and framed by its flat box: the
 * pixel ray is the render's, so the point at the depth render writes lies
 * on z = 0. */
static void test_pixel_ray_flat_2d(void **state)
{
    (void)state;
    static const char text[] = "square(size = [10, 4], center = false);\n";
    sc_scene *s = test_load("flat.csg", text, 0);
    sc_render_options o;
    depth_options(&o);
    sc_framebuffer *fb = NULL;
    sc_error e;
    assert_int_equal(sc_render(s, &o, &fb, &e), SC_OK);
    int hits = 0;
    for (int j = 0; j < o.height; j++)
        for (int i = 0; i < o.width; i++) {
            float depth = sc_framebuffer_depth(fb)[j * o.width + i];
            if (isinf(depth))
                continue;
            double origin[3], dir[3];
            assert_int_equal(sc_scene_pixel_ray(s, &o, i, j, origin, dir, &e), SC_OK);
            double len = sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
            assert_near(origin[2] + dir[2] * depth / len, 0, 1e-4);
            hits++;
        }
    assert_true(hits > 0);
    sc_framebuffer_release(fb);
    sc_scene_release(s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_worked_example),
        cmocka_unit_test(test_pixel_ray_flat_2d),
        cmocka_unit_test(test_both_ways),
        cmocka_unit_test(test_subtracted_surface),
        cmocka_unit_test(test_membership),
        cmocka_unit_test(test_errors),
        cmocka_unit_test(test_ray_limit),
        cmocka_unit_test(test_pixel_ray_matches_depth),
        cmocka_unit_test(test_frame_bounds),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
