/* Small helpers the cmocka test programs share. Include after <cmocka.h>. */
#ifndef SPANCAST_TESTS_TEST_UTIL_H
#define SPANCAST_TESTS_TEST_UTIL_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "build/scene.h"
#include "csg/csg.h"
#include "spancast/spancast.h"

/* A leaf's world transform (the leaf keeps only its inverse); fails the
 * test when it cannot be inverted back. */
static inline affine test_leaf_to_world(const csg_leaf *l)
{
    affine to_world;
    assert_true(affine_invert(&l->to_local, &to_world));
    return to_world;
}

/* The whole file at path, NUL-terminated (the terminator is not counted in
 * *length, which may be NULL); fails the test when it cannot be read. */
static inline char *test_read_file(const char *path, size_t *length)
{
    FILE *f = fopen(path, "rb");
    assert_non_null(f);
    assert_int_equal(fseek(f, 0, SEEK_END), 0);
    long n = ftell(f);
    assert_true(n >= 0);
    assert_int_equal(fseek(f, 0, SEEK_SET), 0);
    char *text = malloc((size_t)n + 1);
    assert_non_null(text);
    assert_int_equal(fread(text, 1, (size_t)n, f), (size_t)n);
    text[n] = 0;
    fclose(f);
    if (length)
        *length = (size_t)n;
    return text;
}

/* Loads text as the file name; fails the test with the message when the
 * load fails. */
static inline sc_scene *test_load(const char *name, const char *text, int faithful)
{
    sc_scene *s = NULL;
    sc_error e;
    sc_load_options o;
    sc_load_options_init(&o);
    o.faithful = faithful;
    if (sc_scene_load_string(name, text, strlen(text), &o, &s, &e) != SC_OK) {
        char buf[1024];
        fail_msg("unexpected error: %s", sc_error_format(&e, buf, sizeof buf));
    }
    assert_non_null(s);
    return s;
}

/* Loading text as the file name fails with status and exactly the message
 * expected, and gives no scene. */
static inline void test_check_error(const char *name, const char *text, sc_status status,
                                    const char *expected)
{
    sc_scene *s = (sc_scene *)1;
    sc_error e;
    assert_int_equal(sc_scene_load_string(name, text, strlen(text), NULL, &s, &e),
                     status);
    assert_null(s);
    char buf[1024];
    assert_string_equal(sc_error_format(&e, buf, sizeof buf), expected);
}

/* Loading text as the file name with --strict (sc_load_options.strict),
 * faithful or not, fails with status and exactly the message expected,
 * and gives no scene. */
static inline void test_check_strict_error(const char *name, const char *text,
                                           int faithful, sc_status status,
                                           const char *expected)
{
    sc_scene *s = (sc_scene *)1;
    sc_error e;
    sc_load_options o;
    sc_load_options_init(&o);
    o.faithful = faithful;
    o.strict = 1;
    assert_int_equal(sc_scene_load_string(name, text, strlen(text), &o, &s, &e), status);
    assert_null(s);
    char buf[1024];
    assert_string_equal(sc_error_format(&e, buf, sizeof buf), expected);
}

/* Loading text as the file name succeeds with exactly the warnings
 * expected, in order, each written "file:line:col: message"; returns the
 * scene for more checks. */
static inline sc_scene *test_check_warnings(const char *name, const char *text,
                                            int faithful, const char *const *expected,
                                            size_t count)
{
    sc_scene *s = test_load(name, text, faithful);
    for (size_t i = 0; i < sc_scene_warning_count(s) || i < count; i++) {
        char got[SC_ERROR_FILE_MAX + SC_ERROR_MESSAGE_MAX + 64] = "(none)";
        if (i < sc_scene_warning_count(s)) {
            const sc_error *w = sc_scene_warning(s, i);
            snprintf(got, sizeof got, "%s:%d:%d: %s", w->file, w->line, w->column,
                     w->message);
        }
        assert_string_equal(got, i < count ? expected[i] : "(no more warnings)");
    }
    return s;
}

/* A point, and whether it lies in a scene's solid (csg_inside). */
typedef struct test_point {
    double x, y, z;
    int in;
} test_point;

/* test_check_warnings in exact and then in faithful mode: in both, exactly
 * the count warnings expected, and each of the point_count points in the
 * solid or not as it says. */
static inline void test_check_warnings_both(const char *name, const char *text,
                                            const char *const *expected, size_t count,
                                            const test_point *points, size_t point_count)
{
    for (int faithful = 0; faithful <= 1; faithful++) {
        sc_scene *s = test_check_warnings(name, text, faithful, expected, count);
        for (size_t i = 0; i < point_count; i++) {
            const test_point *p = &points[i];
            if (!csg_inside(scene_tree(s), v3(p->x, p->y, p->z)) != !p->in)
                fail_msg("faithful %d: (%g, %g, %g) should be %s", faithful, p->x, p->y,
                         p->z, p->in ? "inside" : "outside");
        }
        sc_scene_release(s);
    }
}

#endif
