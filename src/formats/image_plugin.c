/* Loading the OpenImageIO plugin and the tiled TIFF plugin
 * (image_backend.h) on demand.
 *
 * OpenImageIO brings some 250 shared libraries with it (OpenCV, FFmpeg,
 * DCMTK, OpenVDB, ...), whose loading alone took a quarter of a second
 * before the first ray when the tool linked it. The plugin is the only code
 * that links it, and is loaded here only for a format that PNG and EXR do
 * not cover. The tiled TIFF writer is a plugin of its own for the same
 * reason (libtiff brings eight libraries), loaded only by a streamed .tif.
 * EXR is a plugin too: OpenEXR's five libraries and libstdc++'s parts that
 * they start took about a millisecond of every run, PNG renders included.
 * All are found and loaded as every plugin is (formats/plugin.h).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "formats/image_backend.h"
#include "formats/plugin.h"

int imgio_plugin_open(imgio_plugin *plugin, char *err, size_t err_size)
{
    memset(plugin, 0, sizeof *plugin);
    static const char *const names[] = {"spancast_oiio_writable", "spancast_oiio_write",
                                        "spancast_oiio_read"};
    void *fns[3];
    if (!plugin_load(IMGIO_PLUGIN_FILE, "OpenImageIO", names, 3, fns, &plugin->handle,
                     err, err_size))
        return 0;
    /* Function pointers from dlsym: POSIX guarantees the conversion. */
    *(void **)&plugin->writable = fns[0];
    *(void **)&plugin->write = fns[1];
    *(void **)&plugin->read = fns[2];
    return 1;
}

void imgio_plugin_close(imgio_plugin *plugin)
{
    plugin_unload(&plugin->handle);
    memset(plugin, 0, sizeof *plugin);
}

int imgio_tiff_plugin_open(imgio_tiff_plugin *plugin, char *err, size_t err_size)
{
    memset(plugin, 0, sizeof *plugin);
    static const char *const names[] = {"spancast_tiff_tiles_open",
                                        "spancast_tiff_tiles_write",
                                        "spancast_tiff_tiles_close"};
    void *fns[3];
    if (!plugin_load(IMGIO_TIFF_PLUGIN_FILE, "TIFF", names, 3, fns, &plugin->handle, err,
                     err_size))
        return 0;
    *(void **)&plugin->open = fns[0];
    *(void **)&plugin->write = fns[1];
    *(void **)&plugin->close = fns[2];
    return 1;
}

void imgio_tiff_plugin_close(imgio_tiff_plugin *plugin)
{
    plugin_unload(&plugin->handle);
    memset(plugin, 0, sizeof *plugin);
}

/* The EXR plugin's entry points, for one use. */
typedef struct exr_plugin {
    void *handle;
    imgio_exr_write_fn *write;
    imgio_exr_read_fn *read;
    imgio_exr_tiles_open_fn *tiles_open;
    imgio_exr_tiles_write_fn *tiles_write;
    imgio_exr_tiles_close_fn *tiles_close;
} exr_plugin;

/* 1 with *p filled, or 0 with "cannot load the EXR plugin (...): ..." in
 * err. */
static int exr_plugin_open(exr_plugin *p, char *err, size_t err_size)
{
    memset(p, 0, sizeof *p);
    static const char *const names[] = {
        "spancast_exr_write", "spancast_exr_read", "spancast_exr_tiles_open",
        "spancast_exr_tiles_write", "spancast_exr_tiles_close"};
    void *fns[5];
    if (!plugin_load(IMGIO_EXR_PLUGIN_FILE, "EXR", names, 5, fns, &p->handle, err,
                     err_size))
        return 0;
    *(void **)&p->write = fns[0];
    *(void **)&p->read = fns[1];
    *(void **)&p->tiles_open = fns[2];
    *(void **)&p->tiles_write = fns[3];
    *(void **)&p->tiles_close = fns[4];
    return 1;
}

int imgio_exr_write(const imgio_image *img, const char *path, char *err, size_t err_size)
{
    exr_plugin p;
    if (!exr_plugin_open(&p, err, err_size))
        return 0;
    int ok = p.write(img, path, err, err_size);
    plugin_unload(&p.handle);
    return ok;
}

int imgio_exr_read(const char *path, image_data *out, char *err, size_t err_size)
{
    exr_plugin p;
    char why[512];
    if (!exr_plugin_open(&p, why, sizeof why)) {
        memset(out, 0, sizeof *out);
        snprintf(err, err_size, "cannot read '%s': %s", path, why);
        return 0;
    }
    int ok = p.read(path, out, err, err_size);
    plugin_unload(&p.handle);
    return ok;
}

/* A tiled EXR being written: the plugin's file and the plugin, held until
 * the file is closed. */
struct imgio_exr_tiles {
    exr_plugin plugin;
    exr_tiles *file;
};

imgio_exr_tiles *imgio_exr_tiles_open(const imgio_image *img, int tile, const char *path,
                                      char *err, size_t err_size)
{
    imgio_exr_tiles *t = malloc(sizeof *t);
    if (!t) {
        snprintf(err, err_size, "out of memory");
        return NULL;
    }
    if (!exr_plugin_open(&t->plugin, err, err_size)) {
        free(t);
        return NULL;
    }
    if (!(t->file = t->plugin.tiles_open(img, tile, path, err, err_size))) {
        plugin_unload(&t->plugin.handle);
        free(t);
        return NULL;
    }
    return t;
}

int imgio_exr_tiles_write(imgio_exr_tiles *t, int tx, int ty, const void *pixels,
                          char *err, size_t err_size)
{
    return t->plugin.tiles_write(t->file, tx, ty, pixels, err, err_size);
}

int imgio_exr_tiles_close(imgio_exr_tiles *t, char *err, size_t err_size)
{
    if (!t)
        return 1;
    int ok = t->plugin.tiles_close(t->file, err, err_size);
    plugin_unload(&t->plugin.handle);
    free(t);
    return ok;
}
