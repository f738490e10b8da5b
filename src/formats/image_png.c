/* PNG files through libpng: the writer for 8-bit images and the reader for
 * surface() height maps and the tests.
 *
 * The writer stores what OpenImageIO's PNG writer stored before it: 8-bit
 * grey or RGB, the sRGB chunk (with its gAMA and cHRM fallbacks) on sRGB
 * colour, and the metadata as tEXt chunks under OpenImageIO's names
 * ("Software", "Description" for the image description, "spancast:camera",
 * "oiio:ColorSpace"), so that any reader sees the same file. It is tuned for
 * a preview, not for the smallest file: zlib level 1 (Z_BEST_SPEED) and the
 * Up filter alone instead of libpng's default of trying all five filters on
 * every row. Up costs one subtraction a byte and suits renders, whose rows
 * repeat the row above them over the background and flat faces.
 *
 * The reader gives floats in 0..1 like OpenImageIO's: palettes become RGB,
 * grey below 8 bits becomes 8-bit, transparency becomes alpha, and 16-bit
 * samples are divided by 65535. No gamma is applied.
 *
 * libpng reports errors by longjmp; each function keeps its state in
 * volatile locals or in the struct passed to the error handler.
 */
#include <errno.h>
#include <png.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <zlib.h>

#include "formats/image_backend.h"

/* What the error handler fills before it jumps back. */
typedef struct png_failure {
    char *message;
    size_t size;
} png_failure;

static void on_error(png_structp png, png_const_charp message)
{
    png_failure *failure = png_get_error_ptr(png);
    if (failure->message[0] == '\0') /* the first cause wins */
        snprintf(failure->message, failure->size, "%s", message);
    png_longjmp(png, 1);
}

static void on_warning(png_structp png, png_const_charp message)
{
    (void)png;
    (void)message; /* warnings do not make a file unusable */
}

/* fwrite with the system's reason on failure (libpng's own says only
 * "Write Error"). */
static void write_data(png_structp png, png_bytep data, size_t length)
{
    FILE *file = png_get_io_ptr(png);
    if (fwrite(data, 1, length, file) != length)
        png_error(png, strerror(errno));
}

static void flush_data(png_structp png)
{
    FILE *file = png_get_io_ptr(png);
    if (fflush(file) != 0)
        png_error(png, strerror(errno));
}

int imgio_png_write(const imgio_image *img, const char *path, char *err, size_t err_size)
{
    err[0] = '\0';
    if (img->sample != IMGIO_UINT8 || (img->channels != 1 && img->channels != 3)) {
        snprintf(err, err_size, "PNG holds only 8-bit grey or RGB here");
        return 0;
    }
    FILE *file = fopen(path, "wb");
    if (!file) {
        snprintf(err, err_size, "%s", strerror(errno));
        return 0;
    }
    png_failure failure = {err, err_size};
    png_structp png =
        png_create_write_struct(PNG_LIBPNG_VER_STRING, &failure, on_error, on_warning);
    png_infop info = png ? png_create_info_struct(png) : NULL;
    char *volatile description = NULL;
    if (!info) {
        png_destroy_write_struct(&png, NULL);
        fclose(file);
        snprintf(err, err_size, "out of memory");
        return 0;
    }
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        free(description);
        fclose(file);
        return 0;
    }
    png_set_write_fn(png, file, write_data, flush_data);
    png_set_compression_level(png, Z_BEST_SPEED);
    png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_UP);
    png_set_IHDR(png, info, (png_uint_32)img->width, (png_uint_32)img->height, 8,
                 img->channels == 3 ? PNG_COLOR_TYPE_RGB : PNG_COLOR_TYPE_GRAY,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_BASE, PNG_FILTER_TYPE_BASE);
    if (img->color_space && strcmp(img->color_space, "sRGB") == 0)
        png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_ABSOLUTE);

    png_text text[4];
    int count = 0;
    memset(text, 0, sizeof text);
    if (img->color_space) {
        text[count].key = "oiio:ColorSpace";
        text[count++].text = (char *)img->color_space;
    }
    text[count].key = "Software";
    text[count++].text = (char *)img->software;
    if (img->camera) {
        size_t size = strlen(img->camera) + sizeof "camera: ";
        description = malloc(size);
        if (!description)
            png_error(png, "out of memory");
        snprintf(description, size, "camera: %s", img->camera);
        text[count].key = "Description";
        text[count++].text = description;
        text[count].key = "spancast:camera";
        text[count++].text = (char *)img->camera;
    }
    for (int k = 0; k < count; k++)
        text[k].compression = PNG_TEXT_COMPRESSION_NONE;
    png_set_text(png, info, text, count);

    png_write_info(png, info);
    const unsigned char *pixels = img->pixels;
    size_t row_bytes = (size_t)img->width * (size_t)img->channels;
    for (int y = 0; y < img->height; y++)
        png_write_row(png, pixels + (size_t)y * row_bytes);
    png_write_end(png, info);
    png_destroy_write_struct(&png, &info);
    free(description);
    if (fclose(file) != 0) {
        snprintf(err, err_size, "%s", strerror(errno));
        return 0;
    }
    return 1;
}

/* The part of the reader that libpng may jump out of: fills *out from the
 * open file, or returns 0 with the message in failure. The caller frees
 * *rows_out and out->pixels either way. */
static int read_body(png_structp png, png_infop info, FILE *file, image_data *out,
                     png_bytep *volatile *rows_out, png_bytep volatile *data_out)
{
    if (setjmp(png_jmpbuf(png)))
        return 0;
    png_init_io(png, file);
    png_read_info(png, info);
    int depth = png_get_bit_depth(png, info);
    png_set_expand(png); /* palette -> RGB, grey < 8 -> 8, tRNS -> alpha */
    png_set_interlace_handling(png);
    png_read_update_info(png, info);
    png_uint_32 width = png_get_image_width(png, info);
    png_uint_32 height = png_get_image_height(png, info);
    int channels = png_get_channels(png, info);
    size_t row_bytes = png_get_rowbytes(png, info);
    if ((uint64_t)width * height * (uint64_t)channels > ((uint64_t)1 << 31))
        png_error(png, "image too large");
    png_bytep data = malloc(row_bytes * height + 1);
    *data_out = data;
    png_bytep *rows = malloc(sizeof *rows * (height + 1));
    *rows_out = rows;
    float *pixels = malloc(sizeof *pixels * ((size_t)width * height * channels + 1));
    out->pixels = pixels;
    if (!data || !rows || !pixels)
        png_error(png, "out of memory");
    for (png_uint_32 y = 0; y < height; y++)
        rows[y] = data + (size_t)y * row_bytes;
    png_read_image(png, rows);
    png_read_end(png, NULL);
    size_t values = (size_t)width * height * (size_t)channels;
    if (depth == 16) {
        for (size_t k = 0; k < values; k++)
            pixels[k] = (float)(data[2 * k] << 8 | data[2 * k + 1]) / 65535.0f;
    } else {
        for (size_t k = 0; k < values; k++)
            pixels[k] = (float)data[k] / 255.0f;
    }
    out->width = (int)width;
    out->height = (int)height;
    out->channels = channels;
    return 1;
}

int imgio_png_read(const char *path, image_data *out, char *err, size_t err_size)
{
    out->width = out->height = out->channels = 0;
    out->pixels = NULL;
    FILE *file = fopen(path, "rb");
    if (!file) {
        snprintf(err, err_size, "cannot read '%s': %s", path, strerror(errno));
        return 0;
    }
    char why[256] = "";
    png_failure failure = {why, sizeof why};
    png_structp png =
        png_create_read_struct(PNG_LIBPNG_VER_STRING, &failure, on_error, on_warning);
    png_infop info = png ? png_create_info_struct(png) : NULL;
    png_bytep *volatile rows = NULL;
    png_bytep volatile data = NULL;
    int ok = info && read_body(png, info, file, out, &rows, &data);
    if (!info)
        snprintf(why, sizeof why, "out of memory");
    png_destroy_read_struct(&png, &info, NULL);
    free(rows);
    free(data);
    fclose(file);
    if (!ok) {
        free(out->pixels);
        out->pixels = NULL;
        out->width = out->height = out->channels = 0;
        snprintf(err, err_size, "cannot read '%s': %s", path, why);
    }
    return ok;
}
