/* Outputs written tile by tile while the render runs (image_io.c).
 *
 * An image too large to hold whole (or any image, with `render --tiled`)
 * is rendered in square tiles, and each tile goes to its files as soon as
 * it is done, so that memory holds the tiles in flight, not the image.
 * Tiled EXR (.exr .sxr .mxr; image_exr_tiled.cpp) and tiled TIFF (.tif
 * .tiff, BigTIFF when large; image_tiff_tiled.c) are written this way:
 * their tiles are compressed and stored one by one. The output is atomic as
 * for the other writers (image_io.c): the tiles go to a temporary file
 * beside the target, renamed over it only when the last tile is in.
 */
#ifndef SPANCAST_FORMATS_IMAGE_STREAM_H
#define SPANCAST_FORMATS_IMAGE_STREAM_H

#include "formats/image_io.h"
#include "spancast/spancast.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct imgio_stream imgio_stream;

/* 1 when path's format is written tile by tile (.exr, .sxr, .mxr, .tif,
 * .tiff). */
int imgio_stream_supported(const char *path);

/* Starts the kind output of a width x height image in tiles of side tile
 * at path (a temporary beside it until imgio_stream_finish); camera is
 * the metadata's camera text, or NULL. On success *out belongs to the
 * caller (imgio_stream_finish or imgio_stream_abandon); on failure it is
 * NULL and error says why (SC_ERR_ARGUMENT when path is not a tiled
 * format, SC_ERR_IO, SC_ERR_NOMEM). */
sc_status imgio_stream_open(const char *path, imgio_kind kind, int width, int height,
                            int tile, const char *camera, imgio_stream **out,
                            sc_error *error);

/* Writes tile (tx, ty) from tile, the render of that tile's region (its
 * buffer for the stream's kind). Tiles come row by row, left to right,
 * each once. */
sc_status imgio_stream_write(imgio_stream *s, int tx, int ty, const sc_framebuffer *tile,
                             sc_error *error);

/* Completes the file and renames it over the target; frees s. When
 * *cancel is set (cancel may be NULL) the temporary is removed instead and
 * the result is SC_ERR_CANCELLED; on a failure it is removed too. */
sc_status imgio_stream_finish(imgio_stream *s, const volatile sig_atomic_t *cancel,
                              sc_error *error);

/* Removes the temporary and frees s; NULL is ignored. */
void imgio_stream_abandon(imgio_stream *s);

#ifdef __cplusplus
}
#endif

#endif
