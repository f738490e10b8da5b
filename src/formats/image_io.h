/* Image output: PNG and EXR directly, every other format through
 * OpenImageIO, loaded only when needed (image_backend.h).
 *
 * The public writers (sc_framebuffer_write_color, _mask, _depth, ...) live
 * in image_io.c. This header adds the check they start with, so that the
 * command line can reject an output name before it spends time rendering.
 *
 * Formats follow the file extension, as OpenImageIO knows them:
 *   colour  8 bits per channel (PNG, JPEG, BMP, ...), or 32-bit float for
 *           the float formats .exr .sxr .mxr .tif .tiff .hdr .rgbe .pfm;
 *   mask    one 8-bit channel (0 or 255) in any format (EXR stores it as
 *           half floats, 0 or 1);
 *   depth   one 32-bit float channel "Z", +inf where the ray misses, and
 *           only in .exr (.sxr .mxr) or float TIFF (.tif .tiff); any other
 *           known extension is an error, never a silently quantised file;
 *   normal  three float channels X, Y, Z, same formats as depth;
 *   id      one float channel "id" (leaf index, -1 on a miss), same formats.
 * Colour is linear in float files and sRGB-encoded in 8-bit ones (color.h).
 * Every file carries "Software" and the camera ("ImageDescription" and
 * "spancast:camera") in its metadata.
 */
#ifndef SPANCAST_FORMATS_IMAGE_IO_H
#define SPANCAST_FORMATS_IMAGE_IO_H

#include "formats/framebuffer.h"
#include "spancast/spancast.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum imgio_kind {
    IMGIO_COLOR,
    IMGIO_MASK,
    IMGIO_DEPTH, /* this one and those below need a float format */
    IMGIO_NORMAL,
    IMGIO_ID
} imgio_kind;

/* Checks, without touching the file system, that path names a format
 * spancast can write and that suits kind: .png and .exr (.sxr .mxr) are
 * known here; any other extension loads the OpenImageIO plugin to ask it,
 * so the list of formats stays OpenImageIO's own. Returns SC_OK or
 * SC_ERR_ARGUMENT with "cannot write 'x.foo': unknown image format" or
 * "cannot write depth to 'x.png': depth needs a floating-point format
 * (.exr or .tif)". */
sc_status imgio_check(const char *path, imgio_kind kind, sc_error *error);

/* 1 when path names a format OpenImageIO writes lossily whatever the
 * pixels: JPEG (.jpg .jpeg .jpe .jfif). A mask written so is no longer
 * exactly 0 and 255 where the model's edges are (seen: 1984 of 480000
 * pixels of a disc's mask at OpenImageIO's default quality). Its other
 * formats spancast writes are lossless by default (.png, .tif, .exr,
 * .jp2, ...), and .webp takes no 1-channel image. */
int imgio_lossy(const char *path);

#ifdef __cplusplus
}
#endif

#endif
