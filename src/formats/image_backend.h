/* The image back ends behind image_io.c and image_read.c.
 *
 * A write is described once, as an imgio_image, and handed to the back end
 * that the file's extension selects: PNG (libpng, image_png.c) is written
 * directly, EXR through OpenEXR in a plugin of its own
 * (exr/image_exr.cpp, built as spancast-exr.so); every other format goes
 * through OpenImageIO in a plugin (oiio/image_oiio.cpp, built as
 * spancast-oiio.so) that is loaded only when such a file is written or read,
 * so that a run which writes PNG or EXR never loads OpenImageIO and the
 * hundreds of libraries it depends on. The back ends write exactly the file
 * they are given (the temporary of image_io.c) and report failures as text;
 * the temporary, the rename and the sc_error belong to image_io.c.
 */
#ifndef SPANCAST_FORMATS_IMAGE_BACKEND_H
#define SPANCAST_FORMATS_IMAGE_BACKEND_H

#include <stddef.h>

#include "formats/image_read.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum imgio_sample {
    IMGIO_UINT8, /* one byte a value, 0..255 (EXR stores these as half 0..1) */
    IMGIO_FLOAT  /* 32-bit float, stored as such */
} imgio_sample;

typedef struct imgio_image {
    int width, height, channels;
    const char *const *channel_names; /* channels names, in memory order */
    imgio_sample sample;
    const void *pixels;      /* rows from the top, channels interleaved */
    const char *color_space; /* "sRGB" or "Linear" tag, or NULL for none */
    const char *software;    /* "spancast 0.1.0" */
    const char *camera;      /* the camera in words, or NULL */
} imgio_image;

/* Each writer creates or truncates path and writes img to it. Returns 1 on
 * success; on failure 0, with a message (no path, no trailing newline) in
 * err. A failed write may leave a partial file at path. The EXR writer
 * loads the EXR plugin (below) for the write; without it the write fails
 * with "cannot load the EXR plugin (spancast-exr.so): why". */
int imgio_png_write(const imgio_image *img, const char *path, char *err, size_t err_size);
int imgio_exr_write(const imgio_image *img, const char *path, char *err, size_t err_size);

/* Tiled EXR, tile by tile (exr/image_exr_tiled.cpp). open starts a file of
 * img's size, channels, sample type and metadata (img->pixels is not
 * read) in square tiles of side tile; write stores tile (tx, ty) from
 * pixels, its rows from the top, channels interleaved, as wide and high as
 * the tile is inside the image; tiles come row by row, left to right, each
 * once. close finishes the file and frees t (also after a failure). Each
 * returns NULL or 0 on failure with a message in err. open holds the EXR
 * plugin until close. */
typedef struct imgio_exr_tiles imgio_exr_tiles;
imgio_exr_tiles *imgio_exr_tiles_open(const imgio_image *img, int tile, const char *path,
                                      char *err, size_t err_size);
int imgio_exr_tiles_write(imgio_exr_tiles *t, int tx, int ty, const void *pixels,
                          char *err, size_t err_size);
int imgio_exr_tiles_close(imgio_exr_tiles *t, char *err, size_t err_size);

/* The EXR plugin (exr/image_exr.h), the only code that links OpenEXR: its
 * entry points, looked up by the names spancast_exr_write, _read,
 * _tiles_open, _tiles_write and _tiles_close, do what the imgio_exr_
 * functions of the same names say; the plugin's tiled file is exr_tiles. */
#define IMGIO_EXR_PLUGIN_FILE "spancast-exr.so"
typedef struct exr_tiles exr_tiles;
typedef int imgio_exr_write_fn(const imgio_image *img, const char *path, char *err,
                               size_t err_size);
typedef int imgio_exr_read_fn(const char *path, image_data *out, char *err,
                              size_t err_size);
typedef exr_tiles *imgio_exr_tiles_open_fn(const imgio_image *img, int tile,
                                           const char *path, char *err, size_t err_size);
typedef int imgio_exr_tiles_write_fn(exr_tiles *t, int tx, int ty, const void *pixels,
                                     char *err, size_t err_size);
typedef int imgio_exr_tiles_close_fn(exr_tiles *t, char *err, size_t err_size);
imgio_exr_write_fn spancast_exr_write;
imgio_exr_read_fn spancast_exr_read;
imgio_exr_tiles_open_fn spancast_exr_tiles_open;
imgio_exr_tiles_write_fn spancast_exr_tiles_write;
imgio_exr_tiles_close_fn spancast_exr_tiles_close;

/* Tiled TIFF (BigTIFF when large), tile by tile: as the tiled EXR calls
 * above; tile must be a multiple of 16. They are the entry points of a
 * plugin of their own, spancast-tiff.so (tiff/image_tiff_tiled.c), the only
 * code that links libtiff, which with the eight libraries it brings would
 * otherwise load in every run; imgio_tiff_plugin_open loads it, found as
 * the OpenImageIO plugin is. */
typedef struct imgio_tiff_tiles imgio_tiff_tiles;
typedef imgio_tiff_tiles *imgio_tiff_open_fn(const imgio_image *img, int tile,
                                             const char *path, char *err,
                                             size_t err_size);
typedef int imgio_tiff_write_fn(imgio_tiff_tiles *t, int tx, int ty, const void *pixels,
                                char *err, size_t err_size);
typedef int imgio_tiff_close_fn(imgio_tiff_tiles *t, char *err, size_t err_size);

#define IMGIO_TIFF_PLUGIN_FILE "spancast-tiff.so"
typedef struct imgio_tiff_plugin {
    void *handle;
    imgio_tiff_open_fn *open;
    imgio_tiff_write_fn *write;
    imgio_tiff_close_fn *close;
} imgio_tiff_plugin;

/* 1 with *plugin filled, or 0 with "cannot load the TIFF plugin (...): ..." in
 * err; imgio_tiff_plugin_close drops the reference (a zeroed plugin is
 * fine). */
int imgio_tiff_plugin_open(imgio_tiff_plugin *plugin, char *err, size_t err_size);
void imgio_tiff_plugin_close(imgio_tiff_plugin *plugin);

/* Readers, as image_read(): 1 on success, else 0 with the whole message
 * ("cannot read 'x': ...") in err. */
int imgio_png_read(const char *path, image_data *out, char *err, size_t err_size);
int imgio_exr_read(const char *path, image_data *out, char *err, size_t err_size);

/* The OpenImageIO plugin's entry points, looked up by these names. */
#define IMGIO_PLUGIN_FILE "spancast-oiio.so"
typedef int imgio_plugin_writable_fn(const char *path);
typedef int imgio_plugin_write_fn(const imgio_image *img, const char *path, char *err,
                                  size_t err_size);
typedef int imgio_plugin_read_fn(const char *path, image_data *out, char *err,
                                 size_t err_size);

/* A loaded plugin. imgio_plugin_open looks for IMGIO_PLUGIN_FILE next to the
 * executable (/proc/self/exe), then in the build folder it was built in.
 * Returns 1 with *plugin filled, or 0 with "cannot load the OpenImageIO
 * plugin (...): ..." in err. The library stays loaded for the rest of the process
 * (OpenImageIO does not support being unloaded); imgio_plugin_close only
 * drops this reference. */
typedef struct imgio_plugin {
    void *handle;
    imgio_plugin_writable_fn *writable; /* 1 if OpenImageIO writes path's format */
    imgio_plugin_write_fn *write;
    imgio_plugin_read_fn *read;
} imgio_plugin;

int imgio_plugin_open(imgio_plugin *plugin, char *err, size_t err_size);
void imgio_plugin_close(imgio_plugin *plugin);

#ifdef __cplusplus
}
#endif

#endif
