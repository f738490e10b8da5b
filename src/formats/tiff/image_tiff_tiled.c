/* Tiled TIFF files written tile by tile, for images too large to hold
 * whole (libtiff): the plugin spancast-tiff.so, the only code that links
 * libtiff, which the library loads when a render streams a .tif
 * (image_plugin.c), so that libtiff and the eight libraries it brings are
 * not loaded by every run.
 *
 * The TIFF counterpart of image_exr_tiled.cpp: a render that streams its
 * outputs (image_stream.h) hands each finished tile to
 * spancast_tiff_tiles_write as soon as it has it, and the tile is compressed
 * (Deflate, each tile on its own) and written to the file at once. The
 * samples are those of the untiled TIFF the OpenImageIO plugin writes for
 * the same output (8-bit mask, 32-bit float colour, depth, normals and
 * ids), interleaved, with the same metadata (Software, and the camera in
 * ImageDescription), so that only the layout differs. TIFF keeps a table
 * of where each tile lies, so the tiles could come in any order; they come
 * row by row. Memory is one full tile (edge tiles are padded to the tile
 * size, as TIFF stores them) and libtiff's tile table, 8 bytes a tile (16
 * in BigTIFF). An image whose samples could pass 4 GiB is written as
 * BigTIFF (64-bit offsets), which the 32-bit offsets of a classic TIFF
 * cannot address; smaller ones stay classic TIFF, which every reader
 * knows.
 *
 * libtiff's messages go to a handler of this file's (per file, through
 * TIFFOpenExt), never to stderr; the first error is the message returned.
 */
#include "formats/image_backend.h"

#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <tiffio.h>

/* The entry points, looked up by these names (image_backend.h). */
imgio_tiff_open_fn spancast_tiff_tiles_open;
imgio_tiff_write_fn spancast_tiff_tiles_write;
imgio_tiff_close_fn spancast_tiff_tiles_close;

struct imgio_tiff_tiles {
    TIFF *file;
    int width, height, tile, channels;
    size_t sample_size;    /* bytes of one sample: 1 or 4 */
    unsigned char *buffer; /* one full tile */
    char message[256];     /* libtiff's first error, or empty */
};

static int on_error(TIFF *tif, void *user, const char *module, const char *format,
                    va_list args)
{
    (void)tif;
    (void)module;
    imgio_tiff_tiles *t = user;
    if (!t->message[0])
        vsnprintf(t->message, sizeof t->message, format, args);
    return 1; /* handled: nothing on stderr */
}

static int on_warning(TIFF *tif, void *user, const char *module, const char *format,
                      va_list args)
{
    (void)tif;
    (void)user;
    (void)module;
    (void)format;
    (void)args;
    return 1; /* warnings about what we write are not the user's concern */
}

/* The message of a failure into err: libtiff's, or what. */
static void failed(const imgio_tiff_tiles *t, const char *what, char *err,
                   size_t err_size)
{
    snprintf(err, err_size, "%s", t && t->message[0] ? t->message : what);
}

imgio_tiff_tiles *spancast_tiff_tiles_open(const imgio_image *img, int tile,
                                           const char *path, char *err, size_t err_size)
{
    if (tile <= 0 || tile % 16 != 0) { /* TIFF's rule for tile sizes */
        snprintf(err, err_size, "tiles of %d pixels (TIFF needs a multiple of 16)", tile);
        return NULL;
    }
    imgio_tiff_tiles *t = calloc(1, sizeof *t);
    if (!t) {
        snprintf(err, err_size, "out of memory");
        return NULL;
    }
    t->width = img->width;
    t->height = img->height;
    t->tile = tile;
    t->channels = img->channels;
    t->sample_size = img->sample == IMGIO_UINT8 ? 1 : 4;
    size_t tile_bytes =
        (size_t)tile * (size_t)tile * (size_t)t->channels * t->sample_size;
    t->buffer = calloc(1, tile_bytes);
    TIFFOpenOptions *options = TIFFOpenOptionsAlloc();
    if (!t->buffer || !options) {
        TIFFOpenOptionsFree(options);
        spancast_tiff_tiles_close(t, err, err_size);
        snprintf(err, err_size, "out of memory");
        return NULL;
    }
    TIFFOpenOptionsSetErrorHandlerExtR(options, on_error, t);
    TIFFOpenOptionsSetWarningHandlerExtR(options, on_warning, t);
    /* Every sample uncompressed, whole tiles, and the tables: past 4 GiB
     * less a margin for the directory, BigTIFF. */
    uint64_t across = ((uint64_t)t->width + (uint64_t)tile - 1) / (uint64_t)tile;
    uint64_t down = ((uint64_t)t->height + (uint64_t)tile - 1) / (uint64_t)tile;
    uint64_t raw = across * down * (uint64_t)tile_bytes + across * down * 8;
    int big = raw > ((uint64_t)1 << 32) - ((uint64_t)1 << 24);
    t->file = TIFFOpenExt(path, big ? "w8" : "w", options);
    TIFFOpenOptionsFree(options);
    if (!t->file) {
        failed(t, "cannot create the file", err, err_size);
        spancast_tiff_tiles_close(t, NULL, 0);
        return NULL;
    }
    TIFF *f = t->file;
    int ok = TIFFSetField(f, TIFFTAG_IMAGEWIDTH, (uint32_t)t->width) &&
             TIFFSetField(f, TIFFTAG_IMAGELENGTH, (uint32_t)t->height) &&
             TIFFSetField(f, TIFFTAG_TILEWIDTH, (uint32_t)tile) &&
             TIFFSetField(f, TIFFTAG_TILELENGTH, (uint32_t)tile) &&
             TIFFSetField(f, TIFFTAG_SAMPLESPERPIXEL, (uint16_t)t->channels) &&
             TIFFSetField(f, TIFFTAG_BITSPERSAMPLE, (uint16_t)(8 * t->sample_size)) &&
             TIFFSetField(f, TIFFTAG_SAMPLEFORMAT,
                          img->sample == IMGIO_UINT8 ? SAMPLEFORMAT_UINT
                                                     : SAMPLEFORMAT_IEEEFP) &&
             TIFFSetField(f, TIFFTAG_PHOTOMETRIC,
                          t->channels == 3 ? PHOTOMETRIC_RGB : PHOTOMETRIC_MINISBLACK) &&
             TIFFSetField(f, TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG) &&
             TIFFSetField(f, TIFFTAG_COMPRESSION, COMPRESSION_ADOBE_DEFLATE) &&
             TIFFSetField(f, TIFFTAG_SOFTWARE, img->software);
    if (ok && img->camera) {
        char description[1024];
        snprintf(description, sizeof description, "camera: %s", img->camera);
        ok = TIFFSetField(f, TIFFTAG_IMAGEDESCRIPTION, description);
    }
    if (!ok) {
        failed(t, "cannot set up the file", err, err_size);
        spancast_tiff_tiles_close(t, NULL, 0);
        return NULL;
    }
    return t;
}

int spancast_tiff_tiles_write(imgio_tiff_tiles *t, int tx, int ty, const void *pixels,
                              char *err, size_t err_size)
{
    int x = tx * t->tile, y = ty * t->tile;
    int w = t->width - x < t->tile ? t->width - x : t->tile;
    int h = t->height - y < t->tile ? t->height - y : t->tile;
    size_t pixel_size = (size_t)t->channels * t->sample_size;
    size_t row = (size_t)w * pixel_size, full_row = (size_t)t->tile * pixel_size;
    size_t tile_bytes = full_row * (size_t)t->tile;
    if (w < t->tile || h < t->tile) /* an edge tile: the rest stays 0 */
        memset(t->buffer, 0, tile_bytes);
    for (int j = 0; j < h; j++)
        memcpy(t->buffer + (size_t)j * full_row, (const char *)pixels + (size_t)j * row,
               row);
    uint32_t index = TIFFComputeTile(t->file, (uint32_t)x, (uint32_t)y, 0, 0);
    if (TIFFWriteEncodedTile(t->file, index, t->buffer, (tmsize_t)tile_bytes) < 0) {
        failed(t, "cannot write a tile", err, err_size);
        return 0;
    }
    return 1;
}

int spancast_tiff_tiles_close(imgio_tiff_tiles *t, char *err, size_t err_size)
{
    if (!t)
        return 1;
    int ok = 1;
    if (t->file) {
        /* Writes the directory (with the tile tables) and closes. */
        ok = TIFFWriteDirectory(t->file) && !t->message[0];
        TIFFClose(t->file);
        ok = ok && !t->message[0];
        if (!ok && err)
            failed(t, "cannot complete the file", err, err_size);
    }
    free(t->buffer);
    free(t);
    return ok;
}
