/* Reading images as float pixels (image_read.h): PNG and EXR directly, any
 * other format through the OpenImageIO plugin. The format is told by the
 * file's first bytes, not its name, as OpenImageIO did. */
#define _POSIX_C_SOURCE 200809L

#include "formats/image_read.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "formats/image_backend.h"

int image_read(const char *path, image_data *out, char *err, int err_size)
{
    out->width = out->height = out->channels = 0;
    out->pixels = NULL;
    size_t size = err_size > 0 ? (size_t)err_size : 0;
    unsigned char magic[8] = {0};
    FILE *file = fopen(path, "rb");
    if (!file) {
        snprintf(err, size, "cannot read '%s': %s", path, strerror(errno));
        return 0;
    }
    size_t got = fread(magic, 1, sizeof magic, file);
    int failed = ferror(file), why_not = errno;
    fclose(file);
    if (failed) { /* a folder, for one */
        snprintf(err, size, "cannot read '%s': %s", path, strerror(why_not));
        return 0;
    }
    static const unsigned char png[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    static const unsigned char exr[4] = {0x76, 0x2f, 0x31, 0x01};
    if (got == sizeof magic && memcmp(magic, png, sizeof png) == 0)
        return imgio_png_read(path, out, err, size);
    if (got >= sizeof exr && memcmp(magic, exr, sizeof exr) == 0)
        return imgio_exr_read(path, out, err, size);
    imgio_plugin plugin;
    char why[512];
    if (!imgio_plugin_open(&plugin, why, sizeof why)) {
        snprintf(err, size, "cannot read '%s': %s", path, why);
        return 0;
    }
    int ok = plugin.read(path, out, err, size);
    imgio_plugin_close(&plugin);
    return ok;
}

void image_data_free(image_data *img)
{
    free(img->pixels);
    img->pixels = NULL;
}
