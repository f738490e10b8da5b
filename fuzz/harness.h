/* The whole load path on one input, for the fuzzer and its regression replay.
 *
 * fuzz_one runs what `spancast render` runs on a model: lexer, parser,
 * builder and compile (sc_scene_load_string), then a tiny 8 x 8 render on
 * one thread with every buffer on, so camera set-up, bounds, ray queries and
 * shading all see the scene. Its only job is to reach code with hostile
 * input; the sanitizers the caller is built with judge the outcome. It also
 * checks the library's own promises: a failed load returns no scene and a
 * non-empty message, a successful render a framebuffer of the asked size.
 * Implicit leaves are rendered too, so the root finders and the interval
 * evaluators see hostile fields: the render's budget of implicit work
 * (docs/limits.md) ends a field that is unresolvable at this scale with an
 * SC_ERR_LIMIT error after about 2^18 evaluations, well within the
 * fuzzer's time limit per input. The load's meshes get a budget of 65536
 * triangles (sc_load_options.max_triangles), as a program that loads
 * untrusted models would set: a few bytes of linear_extrude(twist = ...,
 * slices = ...) ask for millions of triangles, valid work that takes
 * seconds per hundred thousand under the sanitizers and coverage.
 * Returns 0 when those hold, -1 otherwise. It lives in a header so that the
 * libFuzzer target (fuzz/fuzz_load.c) and the replay test
 * (tests/test_fuzz_regressions.c) share it without a library of its own.
 */
#ifndef SPANCAST_FUZZ_HARNESS_H
#define SPANCAST_FUZZ_HARNESS_H

#include <stddef.h>
#include <stdint.h>

#include "spancast/spancast.h"

/* The library's promises after a load that returned st (scene, error):
 * a failed load gives no scene and a message; a scene's warnings have
 * messages; its tiny render (8 x 8, one thread, every buffer) is of that
 * size, or fails with a message and no framebuffer. Releases the scene.
 * 0 when they hold, -1 otherwise. */
static inline int fuzz_loaded(sc_status st, sc_scene *scene, sc_error *error)
{
    if (st != SC_OK)
        return scene == NULL && error->status == st && error->message[0] ? 0 : -1;
    int result = 0;
    size_t warnings = sc_scene_warning_count(scene);
    for (size_t k = 0; k < warnings; k++) {
        if (!sc_scene_warning(scene, k)->message[0])
            result = -1;
    }
    sc_render_options ro;
    sc_render_options_init(&ro);
    ro.width = ro.height = 8;
    ro.threads = 1;
    ro.want_color = ro.want_depth = ro.want_mask = ro.want_normal = 1;
    sc_framebuffer *fb = NULL;
    st = sc_render(scene, &ro, &fb, error);
    if (st == SC_OK &&
        (!fb || sc_framebuffer_width(fb) != 8 || sc_framebuffer_height(fb) != 8))
        result = -1;
    if (st != SC_OK && (fb || !error->message[0] || st == SC_ERR_CANCELLED))
        result = -1;
    sc_framebuffer_release(fb);
    sc_scene_release(scene);
    return result;
}

/* The whole load path on one input (above). */
static inline int fuzz_one(const uint8_t *data, size_t size)
{
    sc_load_options lo;
    sc_load_options_init(&lo);
    lo.max_triangles = (size_t)1 << 16;
    sc_scene *scene = NULL;
    sc_error error;
    sc_status st =
        sc_scene_load_string("fuzz.csg", (const char *)data, size, &lo, &scene, &error);
    return fuzz_loaded(st, scene, &error);
}

#endif
