/* The metamorphic stability harness: a model against itself under a
 * similarity transform.
 *
 * A similarity x -> s R x + t (R a rotation, s > 0) maps the ray o + t d to
 * the ray s R o + t' + t (s R d): the same parameter t reaches the image of
 * the same point. So a model wrapped in multmatrix(s R | t), seen by the
 * camera moved the same way, must give the same mask and the same ray
 * parameter at every pixel. stab_compare loads both, casts the pixel-centre
 * rays of an oblique perspective camera framed on the model (the same
 * formulas as the renderer's, camera.h) through both trees with
 * csg_first_hit, and counts where they differ. docs/stability.md states the
 * bounds the tests hold it to.
 */
#ifndef SPANCAST_BENCH_STABILITY_H
#define SPANCAST_BENCH_STABILITY_H

#include <stdint.h>

#include "csg/csg.h"
#include "math/vec.h"
#include "spancast/spancast.h"

/* x -> m x + t. A similarity (m = s R) for the metamorphic checks; any
 * invertible m for the ill-conditioned cases (an affine map takes rays to
 * rays with the same parameter just as well). */
typedef struct stab_similarity {
    double m[3][3];
    vec3 t;
} stab_similarity;

typedef struct stab_result {
    uint64_t pixels;
    uint64_t hits;              /* pixels whose ray hits the untransformed model */
    uint64_t mask_mismatches;   /* hit in one, miss in the other */
    uint64_t nan_count;         /* hits whose t or normal is not finite (either model) */
    double max_rel_depth_error; /* max |t' - t| / t over pixels hit in both */
    uint64_t depth_violations;  /* pixels whose error exceeds their bound (see docs) */
    uint64_t below_resolution;  /* far camera: near hits whose every span is shorter
                                   than the far ray's eps (removed by the rule) */
} stab_result;

/* A random similarity from seed: a uniform rotation, scale 10^u with u
 * uniform in [log10_scale_lo, log10_scale_hi], and a translation of length
 * up to translation_ratio times the scaled model radius radius. */
stab_similarity stab_random(uint64_t seed, double log10_scale_lo, double log10_scale_hi,
                            double radius, double translation_ratio);

/* diag(sx, sy, sz) with translation t. */
stab_similarity stab_scaled(double sx, double sy, double sz, vec3 t);

/* Compares the model in text (named name in messages) with the model in
 * moved_text (text itself when NULL) wrapped in multmatrix(x), on a
 * size x size image. Returns SC_OK and fills *out, or the loading error.
 * An empty model gives pixels == size * size and no hits. */
sc_status stab_compare(const char *name, const char *text, const char *moved_text,
                       const stab_similarity *x, int size, stab_result *out,
                       sc_error *error);

/* Counts the NaN results of the same camera's rays through one tree: hits
 * whose t or normal is not finite. *hits gets the number of hits. */
uint64_t stab_nan_scan(const csg_tree *tree, int size, uint64_t *hits);

/* The far-camera case: the model seen from distance along the harness
 * camera's direction, with the field of view shrunk to frame it, against the
 * same rays started 10 radii from the model. Both are orthographic in effect
 * (parallel rays, origins on a grid across the view); out's depth error is
 * |t_far - (distance - near) - t_near| / t_far. A near hit whose spans are
 * all shorter than the far ray's eps counts as below_resolution, not as a
 * mismatch. */
sc_status stab_far_camera(const char *name, const char *text, double distance, int size,
                          stab_result *out, sc_error *error);

/* Generated models (malloc'd text, NULL when out of memory): levels nested
 * differences of shrinking centred cubes around a small sphere, and a union
 * of leaves cubes on a grid. */
char *stab_deep_differences(int levels);
char *stab_wide_union(int leaves);

#endif
