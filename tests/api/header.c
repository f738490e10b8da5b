/* Compiled, not run, by the api_header tests (tests/CMakeLists.txt): the
 * public header must compile as C (C99 and C11) and as C++ (C++11 and
 * C++17) with -Wall -Wextra -pedantic -Werror, on its own, and its init
 * macros and handles must be usable from both. Every struct's first field
 * is its size, as the header's opening comment promises. */
#include <spancast/spancast.h>

#include <stddef.h>

#ifdef __cplusplus
#define STATIC_CHECK(cond, name) static_assert(cond, #name)
#else
#define STATIC_CHECK(cond, name) typedef char name[(cond) ? 1 : -1]
#endif

STATIC_CHECK(offsetof(sc_load_options, size) == 0, load_options_size_first);
STATIC_CHECK(offsetof(sc_scene_info, size) == 0, scene_info_size_first);
STATIC_CHECK(offsetof(sc_render_options, size) == 0, render_options_size_first);
STATIC_CHECK(offsetof(sc_render_stats, size) == 0, render_stats_size_first);
STATIC_CHECK(offsetof(sc_ray_query, size) == 0, ray_query_size_first);
STATIC_CHECK(offsetof(sc_measure_options, size) == 0, measure_options_size_first);
STATIC_CHECK(offsetof(sc_measure, size) == 0, measure_size_first);
STATIC_CHECK(offsetof(sc_comparison, size) == 0, comparison_size_first);
STATIC_CHECK(SPANCAST_VERSION_NUMBER >= 100, version_number);

int header_use(const char *path);

int header_use(const char *path)
{
    sc_error error;
    sc_load_options load;
    sc_load_options_init(&load);
    sc_scene *scene = NULL;
    if (sc_scene_load(path, &load, &scene, &error) != SC_OK)
        return 1;
    sc_scene_info info;
    sc_scene_info_init(&info);
    sc_scene_get_info(scene, &info, &error);
    sc_render_options options;
    sc_render_options_init(&options);
    sc_framebuffer *fb = NULL;
    sc_status st = sc_render(scene, &options, &fb, &error);
    sc_render_stats stats;
    sc_render_stats_init(&stats);
    if (st == SC_OK)
        sc_framebuffer_get_stats(fb, &stats, &error);
    sc_framebuffer_release(fb);
    sc_ray_query query;
    sc_ray_query_init(&query);
    sc_measure_options measure_options;
    sc_measure_options_init(&measure_options);
    sc_measure measure;
    sc_measure_init(&measure);
    sc_comparison comparison;
    sc_comparison_init(&comparison);
    sc_scene_release(scene);
    return (int)info.leaf_count + (int)stats.threads;
}
