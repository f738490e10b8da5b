/* The documented resource limits (docs/limits.md), each at its boundary:
 * the largest allowed input loads, one more is SC_ERR_LIMIT with the exact
 * "file:line:col: error: ... (limit is N)" message. Nodes in a file, items
 * in a vector, bytes in a string and $fn are checked through the public
 * loader; the size of a render's buffers through sc_render, which must fail
 * before it allocates anything (a 32768 x 32768 render with every buffer
 * would need 29 GiB), the size of a polyhedron the convex path takes, and
 * the size of a file read whole (file_read: the jobs, DXF, SVG, mesh and
 * height-map files).
 * Nesting depth has its own tests in test_parse.c and
 * test_build.c. */
#define _DEFAULT_SOURCE /* mkstemp */

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "build/build.h"
#include "formats/file.h"
#include "render/render.h"
#include "syntax/lex.h"
#include "syntax/parse.h"

/* Loads text; returns its status and the formatted error in buf. */
static sc_status load(const char *text, size_t length, char *buf, size_t size)
{
    sc_scene *scene = NULL;
    sc_error e;
    sc_status st = sc_scene_load_string("m.csg", text, length, NULL, &scene, &e);
    buf[0] = '\0';
    if (st == SC_OK) {
        assert_non_null(scene);
        sc_scene_release(scene);
    } else {
        assert_null(scene);
        sc_error_format(&e, buf, size);
    }
    return st;
}

/* text of `count` copies of item, joined by sep, between open and close. */
static char *repeat(const char *open, const char *item, const char *sep, size_t count,
                    const char *close)
{
    size_t n = strlen(open) + count * (strlen(item) + strlen(sep)) + strlen(close) + 1;
    char *s = malloc(n), *p = s;
    assert_non_null(s);
    p += sprintf(p, "%s", open);
    for (size_t i = 0; i < count; i++)
        p += sprintf(p, "%s%s", i ? sep : "", item);
    sprintf(p, "%s", close);
    return s;
}

static void test_node_count(void **state)
{
    (void)state;
    char buf[1024];
    /* cube(); is 7 bytes: node k starts at column 7 (k - 1) + 1. */
    char *text = repeat("", "cube();", "", PARSE_MAX_NODES, "");
    assert_int_equal(load(text, strlen(text), buf, sizeof buf), SC_OK);
    free(text);
    text = repeat("", "cube();", "", PARSE_MAX_NODES + 1, "");
    assert_int_equal(load(text, strlen(text), buf, sizeof buf), SC_ERR_LIMIT);
    assert_string_equal(buf,
                        "m.csg:1:28000001: error: too many nodes (limit is 4000000)");
    free(text);
}

static void test_vector_length(void **state)
{
    (void)state;
    char buf[1024];
    /* "c = [" is 5 bytes after "group(", items "0, " 3 bytes each. */
    char *text = repeat("group(c = [", "0", ", ", PARSE_MAX_VECTOR, "]);");
    assert_int_equal(load(text, strlen(text), buf, sizeof buf), SC_OK);
    free(text);
    text = repeat("group(c = [", "0", ", ", PARSE_MAX_VECTOR + 1, "]);");
    assert_int_equal(load(text, strlen(text), buf, sizeof buf), SC_ERR_LIMIT);
    assert_string_equal(buf, "m.csg:1:3000012: error: too many items in a vector (limit "
                             "is 1000000)");
    free(text);
    /* The limit is per vector: many full vectors are fine. */
    char *inner = repeat("[", "0", ",", 1000, "]");
    text = repeat("group(c = [", inner, ",", 1001, "]);");
    assert_int_equal(load(text, strlen(text), buf, sizeof buf), SC_OK);
    free(text);
    free(inner);
}

static void test_string_length(void **state)
{
    (void)state;
    char buf[1024];
    char *text = repeat("color(\"", "a", "", LEX_MAX_STRING, "\") { cube(); }");
    assert_int_equal(load(text, strlen(text), buf, sizeof buf), SC_OK);
    free(text);
    text = repeat("\n  color(\"", "a", "", LEX_MAX_STRING + 1, "\") { cube(); }");
    assert_int_equal(load(text, strlen(text), buf, sizeof buf), SC_ERR_LIMIT);
    assert_string_equal(buf,
                        "m.csg:2:9: error: string too long (limit is 1000000 bytes)");
    free(text);
}

static void test_fn(void **state)
{
    (void)state;
    char buf[1024];
    const char *ok = "sphere(r = 1, $fn = 65536); cylinder(h = 1, $fn = -1e300);";
    assert_int_equal(load(ok, strlen(ok), buf, sizeof buf), SC_OK);
    const char *big = "group() {\n  sphere(r = 1, $fn = 65537);\n}";
    assert_int_equal(load(big, strlen(big), buf, sizeof buf), SC_ERR_LIMIT);
    assert_string_equal(buf,
                        "m.csg:2:23: error: $fn 65537 is too large (limit is 65536)");
    /* OpenSCAD 2021.01's 3 fragments (test_faithful.c) */
    const char *inf = "cylinder(h = 1, $fn = inf); sphere($fn = nan);";
    assert_int_equal(load(inf, strlen(inf), buf, sizeof buf), SC_OK);
    /* Checked in subtrees that are not built too, like every error. */
    const char *background = "%sphere(r = 1, $fn = 1e6);";
    assert_int_equal(load(background, strlen(background), buf, sizeof buf), SC_ERR_LIMIT);
    assert_string_equal(buf,
                        "m.csg:1:22: error: $fn 1e+06 is too large (limit is 65536)");
}

/* The deepest tree the nesting limit allows, rendered on worker threads:
 * the levels alternate between a union of a sphere and the level below and
 * an intersection of a large cube and the level below, so compiling can
 * neither flatten a level into its parent nor drop it, and the recursive
 * ray queries go 9999 levels deep on each thread's own stack. */
static void test_deep_render(void **state)
{
    (void)state;
    const int pairs = (PARSE_MAX_DEPTH - 1) / 2, levels = 2 * pairs;
    char *text = malloc((size_t)pairs * 80 + 16), *p = text;
    assert_non_null(text);
    for (int i = 0; i < pairs; i++)
        p += sprintf(
            p, "union() { sphere(r = 1); intersection() { cube(100, center = true); ");
    p += sprintf(p, "cube(1);");
    for (int i = 0; i < levels; i++)
        *p++ = '}';
    *p = '\0';
    sc_scene *scene = NULL;
    sc_error e;
    assert_int_equal(sc_scene_load_string("m.csg", text, strlen(text), NULL, &scene, &e),
                     SC_OK);
    sc_scene_info info;
    sc_scene_info_init(&info);
    assert_int_equal(sc_scene_get_info(scene, &info, NULL), SC_OK);
    assert_int_equal(info.depth, (size_t)levels + 1);
    sc_render_options o;
    sc_render_options_init(&o);
    o.width = o.height = 16;
    o.threads = 2;
    o.want_mask = 1;
    sc_framebuffer *fb = NULL;
    assert_int_equal(sc_render(scene, &o, &fb, &e), SC_OK);
    assert_int_equal(fb->mask[8 * 16 + 8], 255); /* the default view is centred */
    sc_framebuffer_release(fb);
    sc_scene_release(scene);
    free(text);
}

/* A convex bipyramid over an n-gon: n + 2 points, 2 n faces, closed. */
static char *bipyramid(int n)
{
    size_t size = (size_t)n * 120 + 256;
    char *s = malloc(size), *p = s;
    assert_non_null(s);
    p += sprintf(p, "polyhedron(points = [[0, 0, -1], [0, 0, 1]");
    for (int i = 0; i < n; i++)
        p += sprintf(p, ", [%.17g, %.17g, 0]", cos(6.283185307179586 * i / n),
                     sin(6.283185307179586 * i / n));
    p += sprintf(p, "], faces = [");
    for (int i = 0; i < n; i++) {
        int a = 2 + i, b = 2 + (i + 1) % n;
        p += sprintf(p, "%s[0, %d, %d], [1, %d, %d]", i ? ", " : "", b, a, a, b);
    }
    sprintf(p, "]);");
    return s;
}

static void test_polyhedron_work(void **state)
{
    (void)state;
    char buf[1024];
    /* 2 n (n + 2) face-point pairs: n = 7070 is 99 998 080, n = 7071 is
     * 100 026 366. */
    char *text = bipyramid(7070);
    assert_int_equal(load(text, strlen(text), buf, sizeof buf), SC_OK);
    free(text);
    /* Past the limit the plane path is not tried: the polyhedron becomes a
     * triangle mesh (build_mesh.c), whose cost grows as n log n. */
    text = bipyramid(7071);
    assert_int_equal(load(text, strlen(text), buf, sizeof buf), SC_OK);
    free(text);
}

static void test_render_memory(void **state)
{
    (void)state;
    sc_scene *scene = NULL;
    sc_error e;
    const char *text = "sphere(r = 1);";
    assert_int_equal(sc_scene_load_string("m.csg", text, strlen(text), NULL, &scene, &e),
                     SC_OK);
    sc_render_options o;
    sc_render_options_init(&o);
    o.width = o.height = 32768;
    o.want_color = o.want_depth = o.want_mask = o.want_normal = 1;
    sc_framebuffer *fb = (sc_framebuffer *)1;
    /* 29 bytes a pixel: 29 GiB, refused before any allocation. */
    assert_int_equal(sc_render(scene, &o, &fb, &e), SC_ERR_LIMIT);
    assert_null(fb);
    char buf[1024];
    assert_string_equal(sc_error_format(&e, buf, sizeof buf),
                        "error: a 32768x32768 render needs 29.0 GiB of image buffers "
                        "(limit is 16 GiB)");
    /* The estimate counts only the buffers asked for. */
    assert_int_equal(render_check_memory(&o, &e), SC_ERR_LIMIT);
    o.want_depth = o.want_mask = o.want_normal = 0;
    o.height = 8;
    assert_int_equal(render_check_memory(&o, &e), SC_OK);
    /* 16 GiB exactly is allowed: colour (12) + depth (4) at 32768 x 32768. */
    o.height = 32768;
    o.want_depth = 1;
    sc_status st = render_check_memory(&o, &e);
    if (st != SC_OK) /* a machine with less than 16 GiB says so */
        assert_non_null(strstr(e.message, "more than this machine's"));
    o.want_mask = 1;
    assert_int_equal(render_check_memory(&o, &e), SC_ERR_LIMIT);
    assert_string_equal(e.message, "a 32768x32768 render needs 17.0 GiB of image buffers "
                                   "(limit is 16 GiB)");
    /* A crop is budgeted by its own buffers: a 100 x 100 corner of an
     * image whose whole buffers would not fit renders. */
    o.width = o.height = 200000;
    o.region[0] = o.region[1] = 0;
    o.region[2] = o.region[3] = 100;
    o.want_color = 1;
    o.want_depth = o.want_mask = o.want_normal = 0;
    assert_int_equal(sc_render(scene, &o, &fb, &e), SC_OK);
    assert_int_equal(fb->width, 100);
    assert_int_equal(fb->height, 100);
    sc_framebuffer_release(fb);
    o.region[2] = o.region[3] = 0;
    /* The side limit comes first. */
    o.width = RENDER_MAX_SIDE + 1;
    o.height = 32768;
    assert_int_equal(sc_render(scene, &o, &fb, &e), SC_ERR_ARGUMENT);
    assert_string_equal(
        e.message, "image size 262145x32768 is out of range (1 to 262144 pixels a side)");
    sc_scene_release(scene);
}

/* The model's extent: a model within 1e30 of the origin loads, in both
 * modes, and is drawn as the same model at scale 1 (a sphere's mask is
 * the same image), and one that reaches past it is the error, wherever
 * the shape lies below transforms; past about 1e77 products of a few
 * coordinates leave double's range, and OpenSCAD's triangulation works in
 * float. */
static void test_extent(void **state)
{
    (void)state;
    char buf[512], text[512];
    for (int faithful = 0; faithful <= 1; faithful++) {
        sc_load_options o;
        sc_load_options_init(&o);
        o.faithful = faithful;
        uint8_t *masks[2] = {NULL, NULL};
        for (int k = 0; k < 2; k++) {
            /* the same sphere of 8 fragments, at scale 1 and at 1e29 */
            const char *f = k ? "1e29" : "1";
            snprintf(text, sizeof text,
                     "multmatrix([[%s, 0, 0, 0], [0, %s, 0, 0], [0, 0, %s, 0], [0, 0, 0, "
                     "1]]) sphere(r = 10, $fn = 8);",
                     f, f, f);
            sc_scene *s = NULL;
            sc_error e;
            sc_status st = sc_scene_load_string("m.csg", text, strlen(text), &o, &s, &e);
            if (st != SC_OK)
                fail_msg("%s", sc_error_format(&e, buf, sizeof buf));
            sc_render_options r;
            sc_render_options_init(&r);
            r.width = 64;
            r.height = 48;
            r.want_color = 0;
            r.want_mask = 1;
            sc_framebuffer *fb = NULL;
            assert_int_equal(sc_render(s, &r, &fb, &e), SC_OK);
            masks[k] = malloc(64 * 48);
            assert_non_null(masks[k]);
            memcpy(masks[k], sc_framebuffer_mask(fb), 64 * 48);
            sc_framebuffer_release(fb);
            sc_scene_release(s);
        }
        size_t hits = 0;
        for (int i = 0; i < 64 * 48; i++)
            hits += masks[0][i] != 0;
        assert_true(hits > 64 * 48 / 20);
        assert_memory_equal(masks[0], masks[1], 64 * 48);
        free(masks[0]);
        free(masks[1]);
    }
    const char *within = "cube(1e30);";
    assert_int_equal(load(within, strlen(within), buf, sizeof buf), SC_OK);
    const char *past = "group() {\n  multmatrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, "
                       "-2e30], [0, 0, 0, 1]]) cube(1);\n  cube(1);\n}";
    assert_int_equal(load(past, strlen(past), buf, sizeof buf), SC_ERR_LIMIT);
    assert_string_equal(buf, "m.csg: error: the model reaches 2e+30 from the origin "
                             "(limit is 1e+30)");
}

/* Writes a file of size bytes (a repeated digit) at path. */
static void write_bytes(const char *path, size_t size)
{
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    for (size_t i = 0; i < size; i++)
        assert_int_equal(fputc('0' + (int)(i % 10), f), '0' + (int)(i % 10));
    assert_int_equal(fclose(f), 0);
}

/* file_read takes a file of exactly its limit whole, and refuses one byte
 * more, whether or not the limit is a power of two times its first
 * buffer (64 KiB). */
static void test_file_limit(void **state)
{
    (void)state;
    char path[] = "/tmp/spancast-limit-XXXXXX";
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    close(fd);
    static const size_t limits[] = {1, 65535, 65536, 100000, 131072, 300001};
    for (size_t k = 0; k < sizeof limits / sizeof limits[0]; k++) {
        size_t limit = limits[k], size = 0;
        const char *why = NULL;
        write_bytes(path, limit);
        char *text = file_read(path, limit, &size, &why);
        if (!text)
            fail_msg("a file of %zu bytes, limit %zu: %s", limit, limit, why);
        assert_int_equal(size, limit);
        assert_int_equal(text[limit - 1], '0' + (int)((limit - 1) % 10));
        assert_int_equal(text[limit], 0);
        free(text);
        write_bytes(path, limit + 1);
        assert_null(file_read(path, limit, &size, &why));
        assert_ptr_equal(why, file_too_large);
    }
    unlink(path);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_node_count),    cmocka_unit_test(test_vector_length),
        cmocka_unit_test(test_string_length), cmocka_unit_test(test_fn),
        cmocka_unit_test(test_deep_render),   cmocka_unit_test(test_polyhedron_work),
        cmocka_unit_test(test_render_memory), cmocka_unit_test(test_file_limit),
        cmocka_unit_test(test_extent),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
