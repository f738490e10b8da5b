/* The renderer's internal entry points and constants.
 *
 * sc_render (public) renders a loaded scene; render_scene does the same for
 * a compiled tree and its shading record, render_tree for a bare tree (the
 * default light rig and materials), so tests can render trees they build
 * directly. Shading itself is in shade.h.
 */
#ifndef SPANCAST_RENDER_RENDER_H
#define SPANCAST_RENDER_RENDER_H

#include "csg/csg.h"
#include "model/shading.h"
#include "formats/framebuffer.h"
#include "spancast/spancast.h"

#define RENDER_TILE_SIZE 16      /* tiles of 16 x 16 pixels are scheduled over threads */
#define RENDER_MAX_SIDE 262144   /* largest image width or height (2^28 tiles) */
#define RENDER_MAX_SPP 65536     /* most samples per pixel */
#define RENDER_MAX_EDGE_WIDTH 16 /* widest edge line, pixels */
#define RENDER_DEFAULT_EDGE_ANGLE 30.0 /* creases: degrees between normals */
#define RENDER_MAX_AO 1024             /* most ambient occlusion rays per hit */
#define RENDER_DEFAULT_AO_RADIUS 0.1   /* of the model's diagonal */

/* OpenSCAD's Cornfield background, #ffffe5, as display values (the
 * framebuffer holds their linear equivalent: color.h). */
#define RENDER_BACKGROUND_R 1.0f
#define RENDER_BACKGROUND_G 1.0f
#define RENDER_BACKGROUND_B (229.0f / 255.0f)

/* Fills *options, all of it, with the defaults sc_render_options_init
 * gives (its size field the library's own sizeof). */
void render_options_defaults(sc_render_options *options);

/* A framebuffer of width x height with the buffers options ask for (its
 * origin at 0, 0; the caller sets x0, y0 for a crop); NULL when out of
 * memory. Release with sc_framebuffer_release. */
sc_framebuffer *render_framebuffer_new(const sc_render_options *o, int width, int height);

/* Renders tree as options ask (options NULL: the defaults). On success
 * *framebuffer belongs to the caller (sc_framebuffer_release); on failure it
 * is NULL and error is filled. */
sc_status render_tree(const csg_tree *tree, const sc_render_options *options,
                      sc_framebuffer **framebuffer, sc_error *error);

/* The box that frames the render of tree under look (may be NULL) with
 * options (--viewall, the default camera): for the render, the solid's
 * own box (csg/bounds.h) as OpenSCAD frames its mesh, or a 2D model's
 * flat box as it frames its polygons (shading.h), else the tree's; for
 * the preview, the boxes OpenSCAD gives its CSG products, with the
 * modifier parts. Fails only on memory. */
sc_status render_frame_bounds(const csg_tree *tree, const shading *look,
                              const sc_render_options *options, bbox *out,
                              sc_error *error);

/* The same with a shading record (NULL: as render_tree). */
sc_status render_scene(const csg_tree *tree, const shading *look,
                       const sc_render_options *options, sc_framebuffer **framebuffer,
                       sc_error *error);
/* Largest total size of a render's image buffers, in GiB. */
#define RENDER_MAX_MEMORY_GIB 16

/* SC_ERR_LIMIT when the buffers options ask for exceed RENDER_MAX_MEMORY_GIB
 * or the machine's physical memory; SC_OK otherwise. (budget.c) */
sc_status render_check_memory(const sc_render_options *options, sc_error *error);

/* Evaluations of implicit surfaces a render may spend on average per
 * pixel sample and camera-like ray (the sample's own ray, its edge
 * neighbours, its ambient occlusion rays); see docs/limits.md. */
#define RENDER_IMPLICIT_EVALS_PER_RAY (1u << 12)

/* The least budget of a render: a small image may still meet a few hard
 * rays. */
#define RENDER_MIN_IMPLICIT_EVALS (1u << 18)

struct cancel_token;

/* The implicit-surface evaluations a render may spend beyond
 * RENDER_MIN_IMPLICIT_EVALS for each pixel it has done: the rays each
 * sample casts times RENDER_IMPLICIT_EVALS_PER_RAY, times the samples.
 * (budget.c) */
uint64_t render_work_credit(const sc_render_options *options);

/* The error of a work limit (cancel_reason reason: CANCEL_RAY_LIMIT or
 * CANCEL_BUDGET) passed at leaf (primitive prim), at the leaf's position
 * when it is one of tree's (tree may be NULL). (budget.c) */
sc_status render_limit_error(const csg_tree *tree, int reason, uint32_t leaf,
                             const void *prim, sc_error *error);

sc_status render_stop_error(const csg_tree *tree, struct cancel_token *token,
                            sc_error *error);

#endif
