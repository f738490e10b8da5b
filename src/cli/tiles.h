/* `spancast render` in tiles: across MPI ranks, and streamed to tiled
 * files for images larger than memory (tiles.c). */
#ifndef SPANCAST_CLI_TILES_H
#define SPANCAST_CLI_TILES_H

#include "spancast/spancast.h"

/* The files of one render: colour, and the AOVs asked for (NULL: none). */
typedef struct tiles_outputs {
    const char *color, *mask, *depth, *normal, *id;
    int tiled; /* --tiled: stream every output tile by tile */
} tiles_outputs;

/* Renders scene as options say. Whole, as sc_render, when one process
 * renders and the image's buffers fit in memory (*written is 0 and the
 * caller writes *fb); else in tiles (across the ranks of an MPI job),
 * either assembled into *fb on rank 0 (*written 0) or, with out->tiled or
 * when the image's buffers do not fit, each tile written to every output
 * as it is done (*written 1; *fb then has the size, camera and counters
 * of the render but no buffers). On ranks other than 0, *fb is NULL.
 * On failure *fb is NULL and error says why. */
sc_status tiles_render(const sc_scene *scene, const sc_render_options *options,
                       const tiles_outputs *out, sc_framebuffer **fb, int *written,
                       sc_error *error);

/* The side of the square tiles of an image of width x height: the largest
 * of 256, 128, 64 and 32 that cuts it into at least 64 tiles (32 when
 * none does). A function of the image alone, so that a tiled file does not
 * depend on how many ranks rendered it. */
int tiles_side(int width, int height);

#endif
