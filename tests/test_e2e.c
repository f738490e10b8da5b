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

#include "formats/image_read.h"

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

/* ---- the default model's silhouette ----
 *
 * models/bracket.csg seen by the default camera is the union of a few
 * convex parts; its holes never show through at this view (below), so a
 * pixel is covered exactly when its centre ray meets one of these parts:
 *   plate    cube([80, 50, 8]) minus its 8 chamfer prisms (4 vertical
 *            corner edges, 4 top edges), each a cube turned by 45 degrees
 *   block    cube([36, 10, 42]) at (22, 36, 0)
 *   boss     cylinder(r = 12, h = 12) along -y from (40, 36.01, 30)
 *   gussets  cube([5, 12.01, 30]) at (22, 24, 0) and (53, 24, 0), each cut
 *            by a cube turned about x
 *   posts    cylinder(r = 6, h = 12) at (10, 40, 0) and (70, 40, 0)
 * with the numbers exactly as the file writes them.
 *
 * No hole shows through. The default forward direction (docs/camera.md) is
 * F = (-sin 55 sin 25, sin 55 cos 25, -cos 55) = (-0.346189, 0.742404,
 * -0.573576). A ray that sees through a straight hole of length L and
 * diameter D across its axis moves sideways by L tan(angle to the axis),
 * which must stay below D:
 *   vertical holes: tan = |F_xy| / |F_z| = 0.819152 / 0.573576 = 1.428;
 *     the r = 3 holes at (10, 12), (70, 12) are narrow for z in [0, 5]
 *     below their counterbores: 7.14 > 6; the r = 2.5 holes through the
 *     posts for z in [0, 9.5]: 13.6 > 5; the slot (x 27..53, y 9..15)
 *     for z in [0, 8]: the shift's y part is 8 * 0.742404 / 0.573576 = 10.4
 *     > 6;
 *   the r = 6 hole along y through boss and block, narrow for y in
 *     [25.99, 46] behind its countersink: tan = |F_xz| / |F_y| =
 *     0.669918 / 0.742404 = 0.902, 20.01 * 0.902 = 18.1 > 12.
 * The holes lie inside the parts' outlines, so they cut no notch in them.
 *
 * The camera: no --camera gives the gimbal 0,0,0,55,0,25,140 with viewall
 * and autocenter. The tree's bounds are the union's: the plate's box
 * [0, 80] x [0, 50] x [0, 8] and the block's top at z = 42, so c = (40, 25,
 * 21), radius = |(80, 50, 42)| / 2 and dist = radius / sin(11.25 deg).
 *
 * Each part is cast once grown and once shrunk by EPS (subtracted chamfers
 * the other way): a pixel hit by the shrunk parts must be covered, one
 * missed by the grown parts must not be. The pixels where the two differ
 * are those the silhouette passes within EPS of, the only ones whose answer
 * depends on rounding; the covered count must lie between the two counts.
 */

typedef struct part {
    double m[3][4]; /* local to world */
    double lo[3], hi[3];
    double radius; /* a cylinder of this radius about local z when > 0 */
} part;

typedef struct interval {
    double a, b;
} interval;

static void compose(double out[3][4], const double a[3][4], const double b[3][4])
{
    double r[3][4];
    for (int i = 0; i < 3; i++)
        for (int k = 0; k < 4; k++) {
            r[i][k] = k == 3 ? a[i][3] : 0;
            for (int j = 0; j < 3; j++)
                r[i][k] += a[i][j] * b[j][k];
        }
    memcpy(out, r, sizeof r);
}

/* A cube of the given size at the origin (centred or not), placed by the
 * matrices outer * inner. */
static part cube_part(const double outer[3][4], const double inner[3][4], double sx,
                      double sy, double sz, int centre)
{
    part p;
    memset(&p, 0, sizeof p);
    compose(p.m, outer, inner);
    double size[3] = {sx, sy, sz};
    for (int i = 0; i < 3; i++) {
        p.lo[i] = centre ? -size[i] / 2 : 0;
        p.hi[i] = centre ? size[i] / 2 : size[i];
    }
    return p;
}

static part cylinder_part(const double outer[3][4], const double inner[3][4], double r,
                          double h)
{
    part p = cube_part(outer, inner, 2 * r, 2 * r, h, 0);
    p.radius = r;
    return p;
}

/* The stretch of o + t d (t >= 0) inside p grown by g; 0 when empty. */
static int part_interval(const part *p, v3d o, v3d d, double g, interval *out)
{
    /* local = m^-1 (world - translation), by the adjugate */
    const double(*m)[4] = p->m;
    double inv[3][3];
    double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                 m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                 m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    for (int i = 0; i < 3; i++)
        for (int k = 0; k < 3; k++) {
            int r0 = (k + 1) % 3, r1 = (k + 2) % 3, c0 = (i + 1) % 3, c1 = (i + 2) % 3;
            inv[i][k] = (m[r0][c0] * m[r1][c1] - m[r0][c1] * m[r1][c0]) / det;
        }
    double w[3] = {o.x - m[0][3], o.y - m[1][3], o.z - m[2][3]}, dw[3] = {d.x, d.y, d.z};
    double lo_[3], ld[3];
    for (int i = 0; i < 3; i++) {
        lo_[i] = inv[i][0] * w[0] + inv[i][1] * w[1] + inv[i][2] * w[2];
        ld[i] = inv[i][0] * dw[0] + inv[i][1] * dw[1] + inv[i][2] * dw[2];
    }
    double a = 0, b = INFINITY;
    for (int i = p->radius > 0 ? 2 : 0; i < 3; i++) {
        double lo = p->lo[i] - g, hi = p->hi[i] + g;
        if (ld[i] == 0) {
            if (lo_[i] < lo || lo_[i] > hi)
                return 0;
            continue;
        }
        double t0 = (lo - lo_[i]) / ld[i], t1 = (hi - lo_[i]) / ld[i];
        if (t0 > t1) {
            double s = t0;
            t0 = t1;
            t1 = s;
        }
        a = fmax(a, t0);
        b = fmin(b, t1);
    }
    if (p->radius > 0) {
        double r = p->radius + g;
        double qa = ld[0] * ld[0] + ld[1] * ld[1];
        double qb = lo_[0] * ld[0] + lo_[1] * ld[1];
        double qc = lo_[0] * lo_[0] + lo_[1] * lo_[1] - r * r;
        double disc = qb * qb - qa * qc;
        if (qa == 0 || disc <= 0)
            return 0;
        a = fmax(a, (-qb - sqrt(disc)) / qa);
        b = fmin(b, (-qb + sqrt(disc)) / qa);
    }
    out->a = a;
    out->b = b;
    return a < b;
}

typedef struct bracket {
    part plate, chamfers[8], block, boss, gusset[2][2], posts[2];
} bracket;

static bracket bracket_parts(void)
{
    const double s = 0.707107, gc = 0.92837, gs = 0.371657;
    const double id[3][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}};
    const double turn_z[3][4] = {{s, -s, 0, 0}, {s, s, 0, 0}, {0, 0, 1, 0}};
    const double turn_x[3][4] = {{1, 0, 0, 0}, {0, s, -s, 0}, {0, s, s, 0}};
    const double turn_y[3][4] = {{s, 0, s, 0}, {0, 1, 0, 0}, {-s, 0, s, 0}};
    const double y_down[3][4] = {{1, 0, 0, 0}, {0, 0, -1, 0}, {0, 1, 0, 0}};
    const double gusset_cut[3][4] = {{1, 0, 0, -1}, {0, gc, gs, 0}, {0, -gs, gc, 0}};
    const double side = 2.82843;
    bracket b;
    b.plate = cube_part(id, id, 80, 50, 8, 0);
    for (int k = 0; k < 4; k++) {
        double at[3][4] = {
            {1, 0, 0, 80 * (k / 2)}, {0, 1, 0, 50 * (k % 2)}, {0, 0, 1, 4}};
        b.chamfers[k] = cube_part(at, turn_z, side, side, 10, 1);
    }
    for (int k = 0; k < 2; k++) {
        double along_x[3][4] = {{1, 0, 0, 40}, {0, 1, 0, 50 * k}, {0, 0, 1, 8}};
        double along_y[3][4] = {{1, 0, 0, 80 * k}, {0, 1, 0, 25}, {0, 0, 1, 8}};
        b.chamfers[4 + k] = cube_part(along_x, turn_x, 82, side, side, 1);
        b.chamfers[6 + k] = cube_part(along_y, turn_y, side, 52, side, 1);
    }
    const double block_at[3][4] = {{1, 0, 0, 22}, {0, 1, 0, 36}, {0, 0, 1, 0}};
    b.block = cube_part(block_at, id, 36, 10, 42, 0);
    const double boss_at[3][4] = {{1, 0, 0, 40}, {0, 1, 0, 36.01}, {0, 0, 1, 30}};
    b.boss = cylinder_part(boss_at, y_down, 12, 12);
    for (int k = 0; k < 2; k++) {
        double at[3][4] = {{1, 0, 0, k ? 53 : 22}, {0, 1, 0, 24}, {0, 0, 1, 0}};
        b.gusset[k][0] = cube_part(at, id, 5, 12.01, 30, 0);
        double cut[3][4];
        compose(cut, at, gusset_cut);
        b.gusset[k][1] = cube_part(cut, id, 7, 24.02, 60, 0);
        double post_at[3][4] = {{1, 0, 0, k ? 70 : 10}, {0, 1, 0, 40}, {0, 0, 1, 0}};
        b.posts[k] = cylinder_part(post_at, id, 6, 12);
    }
    return b;
}

/* 1 when some stretch of [i.a, i.b] is not inside any of cuts[0..n). */
static int survives(interval i, const interval *cuts, int n)
{
    /* the lowest start not yet covered moves up past every cut that
     * contains it; n passes are enough for n cuts */
    double a = i.a;
    for (int pass = 0; pass < n; pass++)
        for (int k = 0; k < n; k++)
            if (cuts[k].a <= a && a < cuts[k].b)
                a = cuts[k].b;
    return a < i.b;
}

/* 1 when the ray meets the bracket's parts grown by g. */
static int bracket_hit(const bracket *b, v3d o, v3d d, double g)
{
    interval i, j;
    if (part_interval(&b->plate, o, d, g, &i)) {
        interval cuts[8];
        int n = 0;
        for (int k = 0; k < 8; k++)
            n += part_interval(&b->chamfers[k], o, d, -g, &cuts[n]);
        if (survives(i, cuts, n))
            return 1;
    }
    if (part_interval(&b->block, o, d, g, &i) || part_interval(&b->boss, o, d, g, &i))
        return 1;
    for (int k = 0; k < 2; k++) {
        if (part_interval(&b->posts[k], o, d, g, &i))
            return 1;
        if (part_interval(&b->gusset[k][0], o, d, g, &i) &&
            part_interval(&b->gusset[k][1], o, d, g, &j) &&
            fmax(i.a, j.a) < fmin(i.b, j.b))
            return 1;
    }
    return 0;
}

/* The default model through the quick-start path (no --camera): its mask
 * is the silhouette above. */
static void default_model_renders(void **state)
{
    (void)state;
    const int w = 320, h = 240;
    char cmd[4096], path[1024];
    mkdir(SPANCAST_TEST_WORK, 0777);
    snprintf(cmd, sizeof cmd,
             "'%s' render '%s/models/bracket.csg' -o '%s/bracket.png' "
             "--mask='%s/bracket-mask.png' --imgsize=%d,%d --quiet",
             SPANCAST_BINARY, SPANCAST_SOURCE_DIR, SPANCAST_TEST_WORK, SPANCAST_TEST_WORK,
             w, h);
    run(cmd);
    snprintf(path, sizeof path, "%s/bracket-mask.png", SPANCAST_TEST_WORK);
    image_data mask = read_image(path);
    assert_int_equal(mask.width, w);
    assert_int_equal(mask.height, h);

    const double deg = 3.14159265358979323846 / 180;
    v3d f = {-sin(55 * deg) * sin(25 * deg), sin(55 * deg) * cos(25 * deg),
             -cos(55 * deg)};
    v3d centre = {40, 25, 21};
    double radius = sqrt(80.0 * 80 + 50 * 50 + 42 * 42) / 2;
    double dist = radius / sin(11.25 * deg);
    contract c = make_contract(sub(centre, mul(f, dist)), centre, 22.5, w, h, 0);
    const double eps = 1e-9 * 2 * radius;
    bracket b = bracket_parts();
    long covered = 0, sure = 0, maybe = 0, mismatches = 0;
    for (int j = 0; j < h; j++) {
        for (int i = 0; i < w; i++) {
            v3d o, d;
            pixel_ray(&c, i, j, &o, &d);
            int in = bracket_hit(&b, o, d, -eps), out = bracket_hit(&b, o, d, eps);
            int got = mask.pixels[j * w + i] > 0.5f;
            covered += got;
            sure += in;
            maybe += out;
            mismatches += (in && !got) || (!out && got);
        }
    }
    printf("bracket: %ld pixels covered (%.1f%% of the frame), silhouette gives %ld to "
           "%ld, %ld mismatches\n",
           covered, 100.0 * covered / (w * h), sure, maybe, mismatches);
    assert_int_equal(mismatches, 0);
    assert_true(sure <= covered && covered <= maybe);
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
