/* Loading the OpenImageIO plugin and the tiled TIFF plugin
 * (image_backend.h) on demand.
 *
 * OpenImageIO brings some 250 shared libraries with it (OpenCV, FFmpeg,
 * DCMTK, OpenVDB, ...), whose loading alone took a quarter of a second
 * before the first ray when the tool linked it. The plugin is the only code
 * that links it, and is loaded here only for a format that PNG and EXR do
 * not cover. The tiled TIFF writer is a plugin of its own for the same
 * reason (libtiff brings eight libraries), loaded only by a streamed .tif.
 * Each is looked for next to the running executable, then in the build
 * folder (SPANCAST_PLUGIN_DIR), where the tests find it.
 *
 * Nothing is cached: dlopen of a library already loaded only counts a
 * reference, and RTLD_NODELETE keeps OpenImageIO in memory once loaded
 * (unloading it is not supported), so every use opens and closes its own
 * handle and no state outlives a call.
 */
#define _GNU_SOURCE /* RTLD_NODELETE */

#include <dlfcn.h>
#include <stdio.h>
#include <string.h>

#include "formats/file.h"
#include "formats/image_backend.h"

#ifndef SPANCAST_PLUGIN_DIR
#define SPANCAST_PLUGIN_DIR "."
#endif

/* dlopen of path; NULL with dlerror's text in err. */
static void *open_at(const char *path, char *err, size_t err_size)
{
    void *handle = dlopen(path, RTLD_NOW | RTLD_LOCAL | RTLD_NODELETE);
    if (!handle) {
        const char *why = dlerror();
        snprintf(err, err_size, "%.400s", why ? why : path);
    }
    return handle;
}

/* dlopen of the plugin file (beside the executable, then in the build
 * folder) and dlsym of its count entry points into fns; 1 with *handle set,
 * or 0 with "cannot load the WHAT plugin: ..." in err. */
static int plugin_load(const char *file, const char *what, const char *const names[],
                       void **fns, int count, void **handle_out, char *err,
                       size_t err_size)
{
    char path[4096], first[512] = "";
    void *handle = NULL;
    if (file_beside_program(file, path, sizeof path))
        handle = open_at(path, first, sizeof first);
    if (!handle) {
        char second[512];
        snprintf(path, sizeof path, "%s/%s", SPANCAST_PLUGIN_DIR, file);
        handle = open_at(path, second, sizeof second);
        if (!handle && !first[0])
            snprintf(first, sizeof first, "%s", second);
    }
    if (!handle) {
        snprintf(err, err_size, "cannot load the %s plugin: %s", what, first);
        return 0;
    }
    for (int k = 0; k < count; k++)
        if (!(fns[k] = dlsym(handle, names[k]))) {
            snprintf(err, err_size,
                     "cannot load the %s plugin: %s lacks its entry points", what, file);
            dlclose(handle);
            return 0;
        }
    *handle_out = handle;
    return 1;
}

int imgio_plugin_open(imgio_plugin *plugin, char *err, size_t err_size)
{
    memset(plugin, 0, sizeof *plugin);
    static const char *const names[] = {"spancast_oiio_writable", "spancast_oiio_write",
                                        "spancast_oiio_read"};
    void *fns[3];
    if (!plugin_load(IMGIO_PLUGIN_FILE, "OpenImageIO", names, fns, 3, &plugin->handle,
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
    if (plugin->handle)
        dlclose(plugin->handle);
    memset(plugin, 0, sizeof *plugin);
}

int imgio_tiff_plugin_open(imgio_tiff_plugin *plugin, char *err, size_t err_size)
{
    memset(plugin, 0, sizeof *plugin);
    static const char *const names[] = {"spancast_tiff_tiles_open",
                                        "spancast_tiff_tiles_write",
                                        "spancast_tiff_tiles_close"};
    void *fns[3];
    if (!plugin_load(IMGIO_TIFF_PLUGIN_FILE, "TIFF", names, fns, 3, &plugin->handle, err,
                     err_size))
        return 0;
    *(void **)&plugin->open = fns[0];
    *(void **)&plugin->write = fns[1];
    *(void **)&plugin->close = fns[2];
    return 1;
}

void imgio_tiff_plugin_close(imgio_tiff_plugin *plugin)
{
    if (plugin->handle)
        dlclose(plugin->handle);
    memset(plugin, 0, sizeof *plugin);
}
