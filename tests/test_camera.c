/* Tests of the camera contract (src/render/camera.c, docs/camera.md).
 *
 * The expected values are worked out by hand from the contract and from
 * OpenSCAD 2021.01's definitions (Camera::setup, Camera::setVpr,
 * Camera::viewAll, GLView::setupCamera): pixel rays of a known camera at the
 * centre and the corners, orthographic origins, the gimbal's named views
 * (top, bottom, front, right, a rolled view), the default view, --viewall
 * with and without --autocenter, and the errors.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>

#include <cmocka.h>
#include <string.h>

#include "render/camera.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

#define TOL 1e-12

static void assert_near(double got, double want, double tol)
{
    if (!(fabs(got - want) <= tol * fmax(1.0, fabs(want))))
        fail_msg("got %.17g, want %.17g", got, want);
}

static void assert_vec(vec3 got, vec3 want, double tol)
{
    assert_near(got.x, want.x, tol);
    assert_near(got.y, want.y, tol);
    assert_near(got.z, want.z, tol);
}

static void make_camera(camera *cam, const cam_view *view, double fov,
                        sc_projection projection, int w, int h)
{
    sc_error e;
    assert_int_equal(cam_init(cam, view, fov, projection, w, h, &e), SC_OK);
}

static void lookat(cam_view *view, double ex, double ey, double ez, double cx, double cy,
                   double cz)
{
    const double p[6] = {ex, ey, ez, cx, cy, cz};
    sc_error e;
    assert_int_equal(cam_view_lookat(p, view, &e), SC_OK);
}

static void gimbal(cam_view *view, double tx, double ty, double tz, double rx, double ry,
                   double rz, double d)
{
    const double p[7] = {tx, ty, tz, rx, ry, rz, d};
    sc_error e;
    assert_int_equal(cam_view_gimbal(p, view, &e), SC_OK);
}

static void test_degree_trig(void **state)
{
    (void)state;
    assert_true(cam_sin_deg(0) == 0.0);
    assert_true(cam_sin_deg(90) == 1.0);
    assert_true(cam_sin_deg(180) == 0.0);
    assert_true(cam_sin_deg(270) == -1.0);
    assert_true(cam_sin_deg(-90) == -1.0);
    assert_true(cam_sin_deg(450) == 1.0);
    assert_true(cam_sin_deg(30) == 0.5);
    assert_true(cam_sin_deg(150) == 0.5);
    assert_true(cam_cos_deg(90) == 0.0);
    assert_true(cam_cos_deg(-90) == 0.0);
    assert_true(cam_cos_deg(180) == -1.0);
    assert_true(cam_cos_deg(60) == 0.5);
    assert_true(cam_cos_deg(360) == 1.0);
    assert_true(cam_sin_deg(45) == cam_cos_deg(45));
    assert_true(cam_sin_deg(10) == cam_cos_deg(80));
    assert_near(cam_sin_deg(55), sin(55 * M_PI / 180), 1e-15);
    assert_near(cam_cos_deg(-25), cos(25 * M_PI / 180), 1e-15);
}

/* Eye on +x looking at the origin, fov 90 (a = 1), 101 x 51 pixels: forward
 * -x, right f x z = +y, up +z. */
static void test_pixel_rays(void **state)
{
    (void)state;
    cam_view view;
    camera cam;
    lookat(&view, 10, 0, 0, 0, 0, 0);
    make_camera(&cam, &view, 90, SC_PROJECTION_PERSPECTIVE, 101, 51);
    assert_vec(cam.f, v3(-1, 0, 0), TOL);
    assert_vec(cam.r, v3(0, 1, 0), TOL);
    assert_vec(cam.u, v3(0, 0, 1), TOL);
    assert_near(cam.a, 1.0, TOL);
    assert_near(cam.aspect, 101.0 / 51.0, TOL);

    vec3 o, d;
    /* the centre pixel looks straight at the centre */
    cam_ray(&cam, 50, 25, 0.5, 0.5, &o, &d);
    assert_vec(o, v3(10, 0, 0), 0);
    assert_vec(d, v3(-1, 0, 0), TOL);
    /* the top-left corner of the image: x = -a W/H, y = +a */
    cam_ray(&cam, 0, 0, 0, 0, &o, &d);
    assert_vec(d, v3(-1, -101.0 / 51.0, 1), TOL);
    /* the bottom-right corner */
    cam_ray(&cam, 100, 50, 1, 1, &o, &d);
    assert_vec(d, v3(-1, 101.0 / 51.0, -1), TOL);
    /* pixel (0, 0) at its centre: x = (1/101 - 1) W/H, y = 1 - 1/51 */
    cam_ray(&cam, 0, 0, 0.5, 0.5, &o, &d);
    assert_vec(d, v3(-1, (1.0 / 101 - 1) * 101.0 / 51.0, 1 - 1.0 / 51), TOL);
}

/* The same camera, orthographic: origins on the plane through the eye,
 * half-height |c - e| a = 10, all directions f. */
static void test_orthographic_rays(void **state)
{
    (void)state;
    cam_view view;
    camera cam;
    lookat(&view, 10, 0, 0, 0, 0, 0);
    make_camera(&cam, &view, 90, SC_PROJECTION_ORTHOGRAPHIC, 101, 51);
    vec3 o, d;
    cam_ray(&cam, 50, 25, 0.5, 0.5, &o, &d);
    assert_vec(o, v3(10, 0, 0), TOL);
    assert_vec(d, v3(-1, 0, 0), TOL);
    cam_ray(&cam, 0, 0, 0, 0, &o, &d);
    assert_vec(o, v3(10, -10 * 101.0 / 51.0, 10), TOL);
    assert_vec(d, v3(-1, 0, 0), TOL);
    cam_ray(&cam, 100, 50, 1, 1, &o, &d);
    assert_vec(o, v3(10, 10 * 101.0 / 51.0, -10), TOL);

    /* fov 22.5 at distance 20: half-height 20 tan(11.25 degrees) */
    lookat(&view, 0, -20, 0, 0, 0, 0);
    make_camera(&cam, &view, 22.5, SC_PROJECTION_ORTHOGRAPHIC, 64, 64);
    cam_ray(&cam, 0, 0, 0, 0, &o, &d);
    double h = 20 * tan(11.25 * M_PI / 180);
    assert_vec(o, v3(-h, -20, h), TOL);
    assert_vec(d, v3(0, 1, 0), TOL);
}

/* Vertical views of the vector form use right = f x y: looking down gives
 * right +x, up +y (OpenSCAD picks rz = 0); looking up gives right -x, up
 * +y (OpenSCAD picks rz = 180). */
static void test_vertical_lookat(void **state)
{
    (void)state;
    cam_view view;
    camera cam;
    lookat(&view, 1, 2, 30, 1, 2, 0);
    make_camera(&cam, &view, 30, SC_PROJECTION_PERSPECTIVE, 10, 10);
    assert_vec(cam.f, v3(0, 0, -1), 0);
    assert_vec(cam.r, v3(1, 0, 0), 0);
    assert_vec(cam.u, v3(0, 1, 0), 0);
    lookat(&view, 0, 0, -5, 0, 0, 0);
    make_camera(&cam, &view, 30, SC_PROJECTION_PERSPECTIVE, 10, 10);
    assert_vec(cam.f, v3(0, 0, 1), 0);
    assert_vec(cam.r, v3(-1, 0, 0), 0);
    assert_vec(cam.u, v3(0, 1, 0), 0);
}

/* The eye and centre of the vector form are kept as given. */
static void test_lookat_keeps_points(void **state)
{
    (void)state;
    cam_view view;
    camera cam;
    lookat(&view, 3, -4, 5, 0.5, 1, -2);
    make_camera(&cam, &view, 22.5, SC_PROJECTION_PERSPECTIVE, 640, 480);
    assert_vec(cam.eye, v3(3, -4, 5), 1e-14);
    assert_vec(cam.center, v3(0.5, 1, -2), 0);
    vec3 dir = v3(-2.5, 5, -7);
    assert_vec(cam.f, v3_scale(dir, 1 / v3_length(dir)), TOL);
    assert_near(cam.distance, v3_length(dir), TOL);
    /* right is horizontal, up has a positive z */
    assert_near(cam.r.z, 0, TOL);
    assert_true(cam.u.z > 0);
}

/* Gimbal views, by hand from R = Rz(rz) Ry(ry) Rx(rx - 90): forward
 * R (0,1,0), up R (0,0,1), eye = vpt - d forward. */
static void test_gimbal_views(void **state)
{
    (void)state;
    cam_view view;
    camera cam;

    /* top: rotate 0,0,0 looks down -z with x right and y up */
    gimbal(&view, 1, 2, 3, 0, 0, 0, 10);
    make_camera(&cam, &view, 22.5, SC_PROJECTION_PERSPECTIVE, 10, 10);
    assert_vec(cam.eye, v3(1, 2, 13), 0);
    assert_vec(cam.center, v3(1, 2, 3), 0);
    assert_vec(cam.f, v3(0, 0, -1), 0);
    assert_vec(cam.r, v3(1, 0, 0), 0);
    assert_vec(cam.u, v3(0, 1, 0), 0);

    /* bottom: 180,0,0 looks up +z with x right and y down */
    gimbal(&view, 0, 0, 0, 180, 0, 0, 10);
    make_camera(&cam, &view, 22.5, SC_PROJECTION_PERSPECTIVE, 10, 10);
    assert_vec(cam.eye, v3(0, 0, -10), 0);
    assert_vec(cam.r, v3(1, 0, 0), 0);
    assert_vec(cam.u, v3(0, -1, 0), 0);

    /* front: 90,0,0 from -y, x right, z up */
    gimbal(&view, 0, 0, 0, 90, 0, 0, 10);
    make_camera(&cam, &view, 22.5, SC_PROJECTION_PERSPECTIVE, 10, 10);
    assert_vec(cam.eye, v3(0, -10, 0), 0);
    assert_vec(cam.r, v3(1, 0, 0), 0);
    assert_vec(cam.u, v3(0, 0, 1), 0);

    /* right: 90,0,90 from +x, y right */
    gimbal(&view, 0, 0, 0, 90, 0, 90, 10);
    make_camera(&cam, &view, 22.5, SC_PROJECTION_PERSPECTIVE, 10, 10);
    assert_vec(cam.eye, v3(10, 0, 0), 0);
    assert_vec(cam.r, v3(0, 1, 0), 0);
    assert_vec(cam.u, v3(0, 0, 1), 0);

    /* top turned by rz = 90: screen right is +y, screen up is -x */
    gimbal(&view, 0, 0, 0, 0, 0, 90, 10);
    make_camera(&cam, &view, 22.5, SC_PROJECTION_PERSPECTIVE, 10, 10);
    assert_vec(cam.r, v3(0, 1, 0), 0);
    assert_vec(cam.u, v3(-1, 0, 0), 0);

    /* rolled: 90,90,0 still looks along +y, but world +x is screen up */
    gimbal(&view, 0, 0, 0, 90, 90, 0, 10);
    make_camera(&cam, &view, 22.5, SC_PROJECTION_PERSPECTIVE, 10, 10);
    assert_vec(cam.f, v3(0, 1, 0), 0);
    assert_vec(cam.u, v3(1, 0, 0), 0);
    assert_vec(cam.r, v3(0, 0, -1), 0);

    /* OpenSCAD's default rotation 55,0,25 */
    gimbal(&view, 0, 0, 0, 55, 0, 25, 140);
    make_camera(&cam, &view, 22.5, SC_PROJECTION_PERSPECTIVE, 10, 10);
    double s55 = sin(55 * M_PI / 180), c55 = cos(55 * M_PI / 180);
    double s25 = sin(25 * M_PI / 180), c25 = cos(25 * M_PI / 180);
    vec3 f = v3(-s55 * s25, s55 * c25, -c55);
    assert_vec(cam.f, f, TOL);
    assert_vec(cam.eye, v3_scale(f, -140), TOL);
    assert_vec(cam.r, v3(c25, s25, 0), TOL);
    assert_vec(cam.u, v3(-c55 * s25, c55 * c25, s55), TOL);
}

/* Random gimbals always give a right-handed orthonormal basis with the
 * camera at distance |d| from the centre. */
static void test_gimbal_basis(void **state)
{
    (void)state;
    unsigned seed = 12345;
    for (int k = 0; k < 500; k++) {
        double p[7];
        for (int m = 0; m < 7; m++) {
            seed = seed * 1103515245u + 12345u;
            p[m] = ((seed >> 8) % 100000) / 100000.0 * 720 - 360;
        }
        p[6] = fabs(p[6]) + 1;
        cam_view view;
        camera cam;
        sc_error e;
        assert_int_equal(cam_view_gimbal(p, &view, &e), SC_OK);
        make_camera(&cam, &view, 40, SC_PROJECTION_PERSPECTIVE, 7, 5);
        assert_near(v3_length(cam.f), 1, 1e-14);
        assert_near(v3_length(cam.r), 1, 1e-14);
        assert_near(v3_length(cam.u), 1, 1e-14);
        assert_near(v3_dot(cam.f, cam.r), 0, 1e-14);
        assert_near(v3_dot(cam.f, cam.u), 0, 1e-14);
        assert_vec(v3_cross(cam.r, cam.u), v3_neg(cam.f), 1e-14);
        assert_near(v3_length(v3_sub(cam.eye, v3(p[0], p[1], p[2]))), p[6], 1e-12);
        /* the gimbal's up, made orthogonal to f, is the camera's up */
        assert_vec(cam.u, view.up, 1e-12);
    }
}

/* viewAll: radius = |centre of box - centre| + half diagonal, distance =
 * radius / sin(fov / 2); autocenter moves the centre to the box's. */
static void test_viewall(void **state)
{
    (void)state;
    bbox box = {{0, 0, 0}, {2, 2, 2}};
    double s = sin(11.25 * M_PI / 180);
    cam_view view;

    gimbal(&view, 0, 0, 0, 55, 0, 25, 140);
    vec3 f = view.forward;
    cam_view_all(&view, &box, 0, 22.5);
    assert_vec(view.center, v3(0, 0, 0), 0);
    assert_near(view.distance, 2 * sqrt(3.0) / s, TOL);
    assert_vec(view.forward, f, 0);

    gimbal(&view, 0, 0, 0, 55, 0, 25, 140);
    cam_view_all(&view, &box, 1, 22.5);
    assert_vec(view.center, v3(1, 1, 1), 0);
    assert_near(view.distance, sqrt(3.0) / s, TOL);

    /* an empty solid: centre at the origin, distance 140 */
    bbox empty = bbox_empty();
    gimbal(&view, 5, 5, 5, 55, 0, 25, 10);
    cam_view_all(&view, &empty, 1, 22.5);
    assert_vec(view.center, v3(0, 0, 0), 0);
    assert_near(view.distance, 140, 0);

    /* the vector form keeps its direction and moves its eye */
    bbox cube = {{-1, -1, -1}, {1, 1, 1}};
    lookat(&view, 10, 0, 0, 0, 0, 0);
    cam_view_all(&view, &cube, 1, 30);
    camera cam;
    make_camera(&cam, &view, 30, SC_PROJECTION_PERSPECTIVE, 10, 10);
    assert_vec(cam.eye, v3(sqrt(3.0) / sin(15 * M_PI / 180), 0, 0), TOL);
    assert_vec(cam.f, v3(-1, 0, 0), TOL);

    /* viewall replaces a gimbal distance that is not positive */
    gimbal(&view, 0, 0, 0, 90, 0, 0, -10);
    cam_view_all(&view, &cube, 1, 22.5);
    make_camera(&cam, &view, 22.5, SC_PROJECTION_PERSPECTIVE, 10, 10);
    assert_true(cam.eye.y < 0);
}

static void test_options(void **state)
{
    (void)state;
    sc_render_options o;
    memset(&o, 0, sizeof o);
    o.width = 800;
    o.height = 600;
    o.fov_deg = 22.5;
    bbox box = {{-1, -2, 0}, {3, 2, 4}};
    cam_view view, want;
    sc_error e;

    /* automatic: OpenSCAD's default rotation, viewall and autocenter */
    o.camera_mode = SC_CAMERA_AUTO;
    assert_int_equal(cam_view_from_options(&o, &box, &view, &e), SC_OK);
    gimbal(&want, 0, 0, 0, 55, 0, 25, 140);
    cam_view_all(&want, &box, 1, 22.5);
    assert_vec(view.center, v3(1, 0, 2), 0);
    assert_vec(view.forward, want.forward, 0);
    assert_near(view.distance, 2 * sqrt(3.0) / sin(11.25 * M_PI / 180), TOL);

    /* autocenter alone does nothing (OpenSCAD 2021.01 applies it inside
     * viewAll only) */
    o.camera_mode = SC_CAMERA_GIMBAL;
    const double g[7] = {1, 2, 3, 60, 0, 30, 50};
    memcpy(o.camera, g, sizeof g);
    o.autocenter = 1;
    assert_int_equal(cam_view_from_options(&o, &box, &view, &e), SC_OK);
    assert_vec(view.center, v3(1, 2, 3), 0);
    assert_near(view.distance, 50, 0);

    /* viewall without autocenter: radius counts the offset to the box */
    o.autocenter = 0;
    o.viewall = 1;
    assert_int_equal(cam_view_from_options(&o, &box, &view, &e), SC_OK);
    assert_vec(view.center, v3(1, 2, 3), 0);
    assert_near(view.distance, (sqrt(5.0) + 2 * sqrt(3.0)) / sin(11.25 * M_PI / 180),
                TOL);
}

static void test_errors(void **state)
{
    (void)state;
    cam_view view;
    camera cam;
    sc_error e;
    const double same[6] = {1, 2, 3, 1, 2, 3};
    assert_int_equal(cam_view_lookat(same, &view, &e), SC_ERR_ARGUMENT);
    assert_string_equal(e.message, "camera eye and centre are the same point");
    const double bad[7] = {0, 0, 0, NAN, 0, 0, 10};
    assert_int_equal(cam_view_gimbal(bad, &view, &e), SC_ERR_ARGUMENT);
    assert_string_equal(e.message, "camera values must be finite");

    gimbal(&view, 0, 0, 0, 55, 0, 25, 0);
    assert_int_equal(cam_init(&cam, &view, 22.5, SC_PROJECTION_PERSPECTIVE, 10, 10, &e),
                     SC_ERR_ARGUMENT);
    assert_string_equal(e.message, "camera distance must be positive (got 0)");
    gimbal(&view, 0, 0, 0, 55, 0, 25, -10);
    assert_int_equal(cam_init(&cam, &view, 22.5, SC_PROJECTION_PERSPECTIVE, 10, 10, &e),
                     SC_ERR_ARGUMENT);
    assert_string_equal(e.message, "camera distance must be positive (got -10)");

    gimbal(&view, 0, 0, 0, 55, 0, 25, 10);
    assert_int_equal(cam_init(&cam, &view, 180, SC_PROJECTION_PERSPECTIVE, 10, 10, &e),
                     SC_ERR_ARGUMENT);
    assert_string_equal(e.message,
                        "field of view must be between 0 and 180 degrees (got 180)");
    assert_int_equal(cam_init(&cam, &view, 30, SC_PROJECTION_PERSPECTIVE, 0, 10, &e),
                     SC_ERR_ARGUMENT);
    assert_string_equal(e.message, "image size must be positive (got 0x10)");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_degree_trig),
        cmocka_unit_test(test_pixel_rays),
        cmocka_unit_test(test_orthographic_rays),
        cmocka_unit_test(test_vertical_lookat),
        cmocka_unit_test(test_lookat_keeps_points),
        cmocka_unit_test(test_gimbal_views),
        cmocka_unit_test(test_gimbal_basis),
        cmocka_unit_test(test_viewall),
        cmocka_unit_test(test_options),
        cmocka_unit_test(test_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
