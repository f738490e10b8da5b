/* sc_load_options.threads: the threads a load builds a large model's
 * hierarchies on (src/csg/bvh.c, src/csg/prim_mesh.c). A program of its
 * own, so that nothing has started OpenMP's threads before it: OpenMP
 * keeps a team's threads for the next parallel region, so the threads of
 * this process tell how many a load used. A load on one thread starts
 * none; a load on two leaves one more; neither changes the calling
 * thread's own OpenMP setting; a negative count is refused.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <dirent.h>
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "spancast/spancast.h"

/* The threads of this process, from /proc/self/task. */
static int thread_count(void)
{
    DIR *d = opendir("/proc/self/task");
    assert_non_null(d);
    int n = 0;
    struct dirent *e;
    while ((e = readdir(d)))
        n += e->d_name[0] != '.';
    closedir(d);
    return n;
}

static const double PI = 3.14159265358979323846;

enum { RINGS = 150, SEGMENTS = 250 }; /* 74,500 triangles: past 65,536 */

/* A closed polyhedron of a sphere's rings, as a .csg. */
static char *sphere_csg(size_t *length)
{
    size_t cap = 8u << 20, n = 0;
    char *s = malloc(cap);
    assert_non_null(s);
    n += (size_t)snprintf(s + n, cap - n, "polyhedron(points = [[0, 0, -1]");
    for (int i = 1; i < RINGS; i++) {
        double th = PI * i / RINGS - PI / 2;
        for (int j = 0; j < SEGMENTS; j++) {
            double ph = 2 * PI * j / SEGMENTS;
            n += (size_t)snprintf(s + n, cap - n, ", [%.9f, %.9f, %.9f]",
                                  cos(th) * cos(ph), cos(th) * sin(ph), sin(th));
        }
    }
    int top = 1 + (RINGS - 1) * SEGMENTS;
    n += (size_t)snprintf(s + n, cap - n, ", [0, 0, 1]], faces = [");
#define RING(i, j) (1 + ((i)-1) * SEGMENTS + (j) % SEGMENTS)
    for (int j = 0; j < SEGMENTS; j++) {
        n += (size_t)snprintf(s + n, cap - n, "%s[0, %d, %d], [%d, %d, %d]",
                              j ? ", " : "", RING(1, j), RING(1, j + 1), top,
                              RING(RINGS - 1, j + 1), RING(RINGS - 1, j));
        for (int i = 1; i + 1 < RINGS; i++)
            n += (size_t)snprintf(s + n, cap - n, ", [%d, %d, %d], [%d, %d, %d]",
                                  RING(i, j), RING(i + 1, j + 1), RING(i, j + 1),
                                  RING(i, j), RING(i + 1, j), RING(i + 1, j + 1));
    }
#undef RING
    n += (size_t)snprintf(s + n, cap - n, "]);\n");
    assert_true(n < cap);
    *length = n;
    return s;
}

static sc_status load(const char *text, size_t length, int threads, sc_error *error)
{
    sc_load_options lo;
    sc_load_options_init(&lo);
    lo.threads = threads;
    sc_scene *scene = NULL;
    sc_status st = sc_scene_load_string("sphere.csg", text, length, &lo, &scene, error);
    if (st == SC_OK) {
        sc_scene_info info;
        sc_scene_info_init(&info);
        assert_int_equal(sc_scene_get_info(scene, &info, error), SC_OK);
        assert_int_equal(info.leaf_count, 1);
        int mesh = 0;
        for (int k = 0; k < SC_LEAF_KINDS; k++)
            if (info.leaf_kinds[k])
                mesh = k;
        assert_string_equal(sc_leaf_kind_name(mesh), "mesh");
    }
    sc_scene_release(scene);
    return st;
}

static void loads_use_the_threads_asked(void **state)
{
    (void)state;
    size_t length;
    char *text = sphere_csg(&length);
    int before = thread_count(), setting = omp_get_max_threads();
    sc_error error;
    assert_int_equal(load(text, length, 1, &error), SC_OK);
    assert_int_equal(thread_count(), before);
    assert_int_equal(omp_get_max_threads(), setting);
    assert_int_equal(load(text, length, 2, &error), SC_OK);
    assert_true(thread_count() > before);
    assert_int_equal(omp_get_max_threads(), setting);
    free(text);
}

/* A union of n^3 positioned spheres as OpenSCAD exports it, some with an
 * argument OpenSCAD warns of, in both halves of the text: 1.3 MB at 22. */
static char *union_csg(int n, size_t *length)
{
    size_t cap = (size_t)n * n * n * 200 + 64, used = 0;
    char *s = malloc(cap);
    assert_non_null(s);
    used += (size_t)snprintf(s + used, cap - used, "union() {\n");
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++)
            for (int k = 0; k < n; k++)
                used += (size_t)snprintf(
                    s + used, cap - used,
                    "\tmultmatrix([[1, 0, 0, %d], [0, 1, 0, %d], [0, 0, 1, %d], [0, 0, "
                    "0, "
                    "1]]) {\n\t\tsphere($fn = 0, $fa = 12, $fs = 2, r = 0.6%s);\n\t}\n",
                    2 * i, 2 * j, 2 * k, (i * n + j) % 7 == 3 && k == 1 ? ", q = 1" : "");
    used += (size_t)snprintf(s + used, cap - used, "}\n");
    assert_true(used < cap);
    *length = used;
    return s;
}

/* The warnings of a scene, one per line. */
static char *warnings_text(const sc_scene *scene)
{
    size_t count = sc_scene_warning_count(scene), cap = count * 600 + 1, used = 0;
    char *out = malloc(cap);
    assert_non_null(out);
    out[0] = '\0';
    for (size_t i = 0; i < count; i++) {
        char line[512];
        used += (size_t)snprintf(
            out + used, cap - used, "%s\n",
            sc_error_format(sc_scene_warning(scene, i), line, sizeof line));
    }
    return out;
}

/* A text past PARSE_SPLIT_MIN loaded on two threads is read in two parts
 * (src/syntax/parse.c): the scene, its statistics and its warnings are
 * those of the load on one thread. */
static void a_large_text_read_in_two_parts_is_the_same_model(void **state)
{
    (void)state;
    size_t length;
    char *text = union_csg(22, &length);
    assert_true(length > (1u << 20));
    sc_scene *scenes[2];
    sc_scene_info infos[2];
    char *warnings[2];
    for (int t = 0; t < 2; t++) {
        sc_load_options lo;
        sc_load_options_init(&lo);
        lo.threads = t + 1;
        sc_error error;
        assert_int_equal(
            sc_scene_load_string("union.csg", text, length, &lo, &scenes[t], &error),
            SC_OK);
        sc_scene_info_init(&infos[t]);
        assert_int_equal(sc_scene_get_info(scenes[t], &infos[t], &error), SC_OK);
        warnings[t] = warnings_text(scenes[t]);
    }
    assert_int_equal(infos[0].leaf_count, 22 * 22 * 22);
    assert_int_equal(infos[1].leaf_count, infos[0].leaf_count);
    assert_int_equal(infos[1].node_count, infos[0].node_count);
    assert_int_equal(infos[1].source_node_count, infos[0].source_node_count);
    assert_int_equal(infos[1].bvh_node_count, infos[0].bvh_node_count);
    double lo[2][3], hi[2][3];
    for (int t = 0; t < 2; t++)
        assert_int_equal(sc_scene_bounds(scenes[t], lo[t], hi[t]), 1);
    assert_memory_equal(lo[0], lo[1], sizeof lo[0]);
    assert_memory_equal(hi[0], hi[1], sizeof hi[0]);
    assert_true(sc_scene_warning_count(scenes[0]) > 20);
    assert_string_equal(warnings[1], warnings[0]);
    for (int t = 0; t < 2; t++) {
        free(warnings[t]);
        sc_scene_release(scenes[t]);
    }
    free(text);
}

static void negative_thread_count_is_refused(void **state)
{
    (void)state;
    sc_error error;
    assert_int_equal(load("cube(1);", 8, -1, &error), SC_ERR_ARGUMENT);
    assert_string_equal(error.message, "thread count must not be negative (got -1)");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(loads_use_the_threads_asked),
        cmocka_unit_test(a_large_text_read_in_two_parts_is_the_same_model),
        cmocka_unit_test(negative_thread_count_is_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
