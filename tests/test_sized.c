/* Tests of the sized structs of the public API (src/base/sized.c and the
 * calls that use it): a caller's struct from an older header (shorter)
 * keeps the defaults of the fields it lacks, a result is never written
 * past the caller's size, and a struct never set up or from a newer
 * header is SC_ERR_ARGUMENT with a message that says which.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>

#include <cmocka.h>
#include <stdio.h>
#include <string.h>

#include "base/sized.h"
#include "test_util.h"

/* A struct as two releases of a header declare it: v2 appends b. */
typedef struct options_v1 {
    size_t size;
    int a;
} options_v1;

typedef struct options_v2 {
    size_t size;
    int a;
    double b;
} options_v2;

static void defaults_v2(options_v2 *o)
{
    sized_clear(o, sizeof *o);
    o->a = 1;
    o->b = 2.5;
}

static void test_read_older(void **state)
{
    (void)state;
    options_v1 old;
    sized_clear(&old, sizeof old);
    old.a = 7;
    options_v2 own;
    defaults_v2(&own);
    sc_error e;
    assert_int_equal(
        sized_read(&own, sizeof own, &old, SIZED_MIN(options_v2, a), "options", &e),
        SC_OK);
    assert_int_equal(own.a, 7);             /* the caller's */
    assert_true(own.b == 2.5);              /* the default of the field it lacks */
    assert_int_equal(own.size, sizeof own); /* the library's own size */
}

static void test_read_same(void **state)
{
    (void)state;
    options_v2 caller;
    defaults_v2(&caller);
    caller.a = 3;
    caller.b = -1;
    options_v2 own;
    defaults_v2(&own);
    assert_int_equal(
        sized_read(&own, sizeof own, &caller, SIZED_MIN(options_v2, a), "options", NULL),
        SC_OK);
    assert_int_equal(own.a, 3);
    assert_true(own.b == -1);
}

static void test_read_errors(void **state)
{
    (void)state;
    options_v2 own;
    defaults_v2(&own);
    unsigned char zeros[64] = {0};
    sc_error e;
    assert_int_equal(
        sized_read(&own, sizeof own, zeros, SIZED_MIN(options_v2, a), "sc_thing", &e),
        SC_ERR_ARGUMENT);
    char want[256];
    snprintf(want, sizeof want,
             "sc_thing has size 0, less than the %zu of any release: it was not set "
             "up by sc_thing_init",
             SIZED_MIN(options_v2, a));
    assert_string_equal(e.message, want);
    assert_int_equal(own.a, 1); /* untouched */

    struct {
        options_v2 v2;
        int c; /* a field of a newer header */
    } newer;
    sized_clear(&newer, sizeof newer);
    assert_int_equal(
        sized_read(&own, sizeof own, &newer, SIZED_MIN(options_v2, a), "sc_thing", &e),
        SC_ERR_ARGUMENT);
    snprintf(want, sizeof want,
             "sc_thing has size %zu: it comes from a newer spancast than this library "
             "%s, which knows %zu bytes of it",
             sizeof newer, SPANCAST_VERSION_STRING, sizeof own);
    assert_string_equal(e.message, want);
}

static void test_write_shorter(void **state)
{
    (void)state;
    options_v2 result;
    defaults_v2(&result);
    result.a = 42;
    result.b = 9;
    /* The caller's struct is a v1, followed by bytes that are not its own. */
    struct {
        options_v1 v1;
        unsigned char after[16];
    } caller;
    memset(&caller, 0xab, sizeof caller);
    caller.v1.size = sizeof caller.v1;
    assert_int_equal(sized_write(&caller.v1, &result, sizeof result,
                                 SIZED_MIN(options_v1, a), "result", NULL),
                     SC_OK);
    assert_int_equal(caller.v1.a, 42);
    assert_int_equal(caller.v1.size, sizeof caller.v1);
    /* Nothing past the caller's size: the padding of v1 and what follows. */
    const unsigned char *p = (const unsigned char *)&caller;
    for (size_t k = sizeof caller.v1; k < sizeof caller; k++)
        assert_int_equal(p[k], 0xab);
}

static const char *cube = "cube(size = 2, center = true);\n";

/* The public calls check their structs. */
static void test_public_uninitialised(void **state)
{
    (void)state;
    sc_scene *s = test_load("cube.csg", cube, 0);
    sc_error e;
    char want[256];

    sc_render_options o;
    memset(&o, 0, sizeof o);
    sc_framebuffer *fb = NULL;
    assert_int_equal(sc_render(s, &o, &fb, &e), SC_ERR_ARGUMENT);
    assert_null(fb);
    snprintf(want, sizeof want,
             "sc_render_options has size 0, less than the %zu of any release: it was "
             "not set up by sc_render_options_init",
             SIZED_MIN(sc_render_options, sheet));
    assert_string_equal(e.message, want);

    sc_measure_options mo;
    sc_measure_options_init(&mo);
    sc_measure m;
    memset(&m, 0, sizeof m);
    assert_int_equal(sc_scene_measure(s, &mo, &m, &e), SC_ERR_ARGUMENT);
    snprintf(want, sizeof want,
             "sc_measure has size 0, less than the %zu of any release: it was not set "
             "up by sc_measure_init",
             SIZED_MIN(sc_measure, threads));
    assert_string_equal(e.message, want);

    sc_scene_info info;
    memset(&info, 0, sizeof info);
    assert_int_equal(sc_scene_get_info(s, &info, &e), SC_ERR_ARGUMENT);
    sc_scene_info_init(&info);
    assert_int_equal(sc_scene_get_info(s, &info, &e), SC_OK);
    assert_int_equal(info.size, sizeof info);
    assert_int_equal(info.leaf_count, 1);

    sc_ray_query q;
    memset(&q, 0, sizeof q);
    q.direction[0] = 1;
    sc_span_list *spans = NULL;
    assert_int_equal(sc_scene_spans(s, &q, &spans, &e), SC_ERR_ARGUMENT);
    assert_null(spans);
    sc_scene_release(s);
}

/* A render through options as an older header declares them (the size of
 * the first recorded ABI): the fields after it take their defaults. */
static void test_public_oldest_options(void **state)
{
    (void)state;
    sc_scene *s = test_load("cube.csg", cube, 0);
    sc_render_options o;
    memset(&o, 0x5a, sizeof o); /* what lies past the older struct */
    sc_render_options_init_size(&o, SIZED_MIN(sc_render_options, sheet));
    o.width = 9;
    o.height = 7;
    o.want_mask = 1;
    sc_framebuffer *fb = NULL;
    sc_error e;
    assert_int_equal(sc_render(s, &o, &fb, &e), SC_OK);
    assert_int_equal(sc_framebuffer_width(fb), 9);
    assert_int_equal(sc_framebuffer_height(fb), 7);
    assert_non_null(sc_framebuffer_mask(fb));
    assert_int_equal(sc_framebuffer_mask(fb)[4 * 9 + 4],
                     255); /* the cube in the middle */
    sc_render_stats stats;
    sc_render_stats_init(&stats);
    assert_int_equal(sc_framebuffer_get_stats(fb, &stats, &e), SC_OK);
    assert_int_equal(stats.camera_rays, 63);
    sc_framebuffer_release(fb);
    sc_scene_release(s);
}

/* The handles' getters take NULL and indices past the end. */
static void test_handles_null(void **state)
{
    (void)state;
    assert_int_equal(sc_overlap_list_count(NULL), 0);
    assert_null(sc_overlap_list_get(NULL, 0));
    sc_overlap_list_release(NULL);
    assert_int_equal(sc_framebuffer_width(NULL), 0);
    assert_null(sc_framebuffer_color(NULL));
    sc_framebuffer_release(NULL);
    assert_int_equal(sc_span_list_count(NULL), 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_read_older),
        cmocka_unit_test(test_read_same),
        cmocka_unit_test(test_read_errors),
        cmocka_unit_test(test_write_shorter),
        cmocka_unit_test(test_public_uninitialised),
        cmocka_unit_test(test_public_oldest_options),
        cmocka_unit_test(test_handles_null),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
