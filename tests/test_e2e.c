/* End to end: a .scad model goes through OpenSCAD (`openscad -o x.csg`), the
 * resulting .csg through the spancast command-line tool, and the mask and
 * depth images it writes are read back and compared with an independent
 * expectation computed here from the README's camera contract and the
 * analytic shape: the silhouette of a sphere (perspective) and of a plate
 * with a drilled hole (orthographic).
 *
 * Pixels whose centre ray passes within a relative 1e-9 of the analytic
 * silhouette are left out of the comparison: there the answer depends on the
 * last bits of the numbers OpenSCAD wrote, not on spancast.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>

#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "render/image_read.h"

#ifndef SPANCAST_BINARY
#error "SPANCAST_BINARY must name the spancast executable"
#endif
#ifndef SPANCAST_TEST_WORK
#error "SPANCAST_TEST_WORK must name a scratch folder"
#endif

typedef struct v3d {
    double x, y, z;
} v3d;

static v3d sub(v3d a, v3d b)
{
    return (v3d){a.x - b.x, a.y - b.y, a.z - b.z};
}
static v3d add(v3d a, v3d b)
{
    return (v3d){a.x + b.x, a.y + b.y, a.z + b.z};
}
static v3d mul(v3d a, double s)
{
    return (v3d){a.x * s, a.y * s, a.z * s};
}
static double dot(v3d a, v3d b)
{
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
static v3d cross(v3d a, v3d b)
{
    return (v3d){a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
static v3d unit(v3d a)
{
    return mul(a, 1.0 / sqrt(dot(a, a)));
}

/* The README's camera contract, written out again independently of
 * src/render/. */
typedef struct contract {
    v3d e, f, r, u;
    double a, dist;
    int w, h, ortho;
} contract;

static contract make_contract(v3d eye, v3d center, double fov_deg, int w, int h,
                              int ortho)
{
    contract c;
    c.e = eye;
    c.f = unit(sub(center, eye));
    v3d z = {0, 0, 1}, y = {0, 1, 0};
    v3d fz = cross(c.f, z);
    c.r = unit(dot(fz, fz) > 0 ? fz : cross(c.f, y));
    c.u = cross(c.r, c.f);
    c.a = tan(fov_deg * 3.14159265358979323846 / 360.0);
    c.dist = sqrt(dot(sub(center, eye), sub(center, eye)));
    c.w = w;
    c.h = h;
    c.ortho = ortho;
    return c;
}

static void pixel_ray(const contract *c, int i, int j, v3d *o, v3d *d)
{
    double x = (2.0 * (i + 0.5) / c->w - 1.0) * c->a * c->w / c->h;
    double y = (1.0 - 2.0 * (j + 0.5) / c->h) * c->a;
    v3d offset = add(mul(c->r, x), mul(c->u, y));
    if (c->ortho) {
        *o = add(c->e, mul(offset, c->dist));
        *d = c->f;
    } else {
        *o = c->e;
        *d = add(c->f, offset);
    }
}

static void write_file(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs(text, f);
    fclose(f);
}

static void run(const char *command)
{
    int rc = system(command);
    if (rc != 0)
        fail_msg("command failed (%d): %s", rc, command);
}

static image_data read_image(const char *path)
{
    image_data img;
    char err[512];
    if (!image_read(path, &img, err, sizeof err))
        fail_msg("%s", err);
    return img;
}

/* Converts model.scad in the work folder through OpenSCAD and spancast. */
static void render_model(const char *name, const char *scad, const char *camera, int w,
                         int h, const char *extra)
{
    char path[1024], cmd[4096];
    mkdir(SPANCAST_TEST_WORK, 0777);
    snprintf(path, sizeof path, "%s/%s.scad", SPANCAST_TEST_WORK, name);
    write_file(path, scad);
    snprintf(cmd, sizeof cmd, "openscad -o '%s/%s.csg' '%s' 2>/dev/null",
             SPANCAST_TEST_WORK, name, path);
    run(cmd);
    snprintf(cmd, sizeof cmd,
             "'%s' render '%s/%s.csg' -o '%s/%s.png' --mask='%s/%s-mask.png' "
             "--depth='%s/%s-depth.exr' --camera=%s --imgsize=%d,%d %s --quiet",
             SPANCAST_BINARY, SPANCAST_TEST_WORK, name, SPANCAST_TEST_WORK, name,
             SPANCAST_TEST_WORK, name, SPANCAST_TEST_WORK, name, camera, w, h, extra);
    run(cmd);
}

static void load_outputs(const char *name, image_data *mask, image_data *depth, int w,
                         int h)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/%s-mask.png", SPANCAST_TEST_WORK, name);
    *mask = read_image(path);
    snprintf(path, sizeof path, "%s/%s-depth.exr", SPANCAST_TEST_WORK, name);
    *depth = read_image(path);
    assert_int_equal(mask->width, w);
    assert_int_equal(mask->height, h);
    assert_int_equal(mask->channels, 1);
    assert_int_equal(depth->width, w);
    assert_int_equal(depth->height, h);
    assert_int_equal(depth->channels, 1);
}

static void sphere_silhouette(void **state)
{
    (void)state;
    const int w = 160, h = 120;
    render_model("sphere", "translate([1, 2, 3]) sphere(r = 5, $fn = 12);\n",
                 "30,-40,25,1,2,3", w, h, "");
    image_data mask, depth;
    load_outputs("sphere", &mask, &depth, w, h);

    contract c = make_contract((v3d){30, -40, 25}, (v3d){1, 2, 3}, 22.5, w, h, 0);
    v3d center = {1, 2, 3};
    double radius = 5;
    int compared = 0, hits = 0, mismatches = 0, depth_bad = 0;
    for (int j = 0; j < h; j++) {
        for (int i = 0; i < w; i++) {
            v3d o, d;
            pixel_ray(&c, i, j, &o, &d);
            v3d oc = sub(o, center);
            double dd = dot(d, d), b = dot(d, oc);
            double disc = b * b - dd * (dot(oc, oc) - radius * radius);
            if (fabs(disc) <= 1e-9 * dd * radius * radius)
                continue;
            compared++;
            int expect = disc > 0;
            float m = mask.pixels[j * w + i];
            int got = m > 0.5f;
            if (got != expect) {
                mismatches++;
                continue;
            }
            float z = depth.pixels[j * w + i];
            if (!expect) {
                depth_bad += !isinf(z);
                continue;
            }
            hits++;
            double t = (-b - sqrt(disc)) / dd;
            double want = t * sqrt(dd);
            depth_bad += !(fabs(z - want) <= 1e-6 * want);
        }
    }
    printf("sphere: %d pixels compared, %d hits, %d mask mismatches, %d depth errors\n",
           compared, hits, mismatches, depth_bad);
    assert_true(hits > 1000);
    assert_int_equal(mismatches, 0);
    assert_int_equal(depth_bad, 0);
    image_data_free(&mask);
    image_data_free(&depth);
}

/* A 20 x 10 x 5 plate with a hole of radius 3, seen straight down with the
 * orthographic camera: the mask is the rectangle minus the disc. */
static void drilled_plate_orthographic(void **state)
{
    (void)state;
    const int w = 200, h = 150;
    render_model("plate",
                 "difference() {\n"
                 "  cube([20, 10, 5], center = true);\n"
                 "  cylinder(r = 3, h = 20, center = true, $fn = 8);\n"
                 "}\n",
                 "0,0,100,0,0,0", w, h, "--projection=o");
    image_data mask, depth;
    load_outputs("plate", &mask, &depth, w, h);

    contract c = make_contract((v3d){0, 0, 100}, (v3d){0, 0, 0}, 22.5, w, h, 1);
    int compared = 0, hits = 0, mismatches = 0, depth_bad = 0;
    for (int j = 0; j < h; j++) {
        for (int i = 0; i < w; i++) {
            v3d o, d;
            pixel_ray(&c, i, j, &o, &d);
            double px = o.x, py = o.y, r2 = px * px + py * py;
            if (fabs(fabs(px) - 10) < 1e-9 * 10 || fabs(fabs(py) - 5) < 1e-9 * 10 ||
                fabs(r2 - 9) < 1e-9 * 9)
                continue;
            compared++;
            int expect = fabs(px) < 10 && fabs(py) < 5 && r2 > 9;
            int got = mask.pixels[j * w + i] > 0.5f;
            if (got != expect) {
                mismatches++;
                continue;
            }
            float z = depth.pixels[j * w + i];
            if (!expect) {
                depth_bad += !isinf(z);
                continue;
            }
            hits++;
            depth_bad += !(fabs(z - 97.5) <= 1e-6 * 97.5);
        }
    }
    printf("plate: %d pixels compared, %d hits, %d mask mismatches, %d depth errors\n",
           compared, hits, mismatches, depth_bad);
    assert_true(hits > 1000);
    assert_int_equal(mismatches, 0);
    assert_int_equal(depth_bad, 0);
    image_data_free(&mask);
    image_data_free(&depth);
}

/* The default model renders through the quick-start path and covers a
 * sensible part of the frame. */
static void default_model_renders(void **state)
{
    (void)state;
    char cmd[4096], path[1024];
    mkdir(SPANCAST_TEST_WORK, 0777);
    snprintf(cmd, sizeof cmd,
             "'%s' render '%s/models/bracket.csg' -o '%s/bracket.png' "
             "--mask='%s/bracket-mask.png' --imgsize=320,240 --quiet",
             SPANCAST_BINARY, SPANCAST_SOURCE_DIR, SPANCAST_TEST_WORK,
             SPANCAST_TEST_WORK);
    run(cmd);
    snprintf(path, sizeof path, "%s/bracket-mask.png", SPANCAST_TEST_WORK);
    image_data mask = read_image(path);
    long covered = 0;
    for (int k = 0; k < mask.width * mask.height; k++)
        covered += mask.pixels[k] > 0.5f;
    double fraction = (double)covered / (mask.width * mask.height);
    printf("bracket: %.1f%% of the frame covered\n", 100 * fraction);
    /* The default view frames the whole model: it neither misses it nor
     * fills the frame edge to edge. */
    assert_true(fraction > 0.10 && fraction < 0.90);
    image_data_free(&mask);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(sphere_silhouette),
        cmocka_unit_test(drilled_plate_orthographic),
        cmocka_unit_test(default_model_renders),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
