/* The renderer's internal entry point and shading constants.
 *
 * sc_render (public) renders a loaded scene; render_tree does the same for a
 * bare compiled tree, so tests can render trees they build directly. The
 * default light rig is fixed to the camera, so every view is lit the same
 * way; it is written here so that tests and documentation can name it.
 */
#ifndef SPANCAST_RENDER_RENDER_H
#define SPANCAST_RENDER_RENDER_H

#include "csg/csg.h"
#include "spancast/spancast.h"

#define RENDER_TILE_SIZE 16   /* tiles of 16 x 16 pixels are scheduled over threads */
#define RENDER_MAX_SIDE 32768 /* largest image width or height */

/* OpenSCAD's Cornfield background, #ffffe5, as display values. */
#define RENDER_BACKGROUND_R 1.0f
#define RENDER_BACKGROUND_G 1.0f
#define RENDER_BACKGROUND_B (229.0f / 255.0f)

/* Renders tree as options ask (options NULL: the defaults). On success
 * *framebuffer belongs to the caller (sc_framebuffer_release); on failure it
 * is NULL and error is filled. */
sc_status render_tree(const csg_tree *tree, const sc_render_options *options,
                      sc_framebuffer **framebuffer, sc_error *error);

/* Largest total size of a render's image buffers, in GiB. */
#define RENDER_MAX_MEMORY_GIB 16

/* SC_ERR_LIMIT when the buffers options ask for exceed RENDER_MAX_MEMORY_GIB
 * or the machine's physical memory; SC_OK otherwise. (budget.c) */
sc_status render_check_memory(const sc_render_options *options, sc_error *error);

#endif
