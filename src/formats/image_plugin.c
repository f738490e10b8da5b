/* Loading the OpenImageIO plugin (image_backend.h) on demand.
 *
 * OpenImageIO brings some 250 shared libraries with it (OpenCV, FFmpeg,
 * DCMTK, OpenVDB, ...), whose loading alone took a quarter of a second
 * before the first ray when the tool linked it. The plugin is the only code
 * that links it, and is loaded here only for a format that PNG and EXR do
 * not cover. It is looked for next to the running executable, then in the
 * build folder (SPANCAST_PLUGIN_DIR), where the tests find it.
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

int imgio_plugin_open(imgio_plugin *plugin, char *err, size_t err_size)
{
    memset(plugin, 0, sizeof *plugin);
    char path[4096], first[512] = "";
    void *handle = NULL;
    if (file_beside_program(IMGIO_PLUGIN_FILE, path, sizeof path))
        handle = open_at(path, first, sizeof first);
    if (!handle) {
        char second[512];
        handle =
            open_at(SPANCAST_PLUGIN_DIR "/" IMGIO_PLUGIN_FILE, second, sizeof second);
        if (!handle && !first[0])
            snprintf(first, sizeof first, "%s", second);
    }
    if (!handle) {
        snprintf(err, err_size, "cannot load the OpenImageIO plugin: %s", first);
        return 0;
    }
    /* Function pointers from dlsym: POSIX guarantees the conversion. */
    *(void **)&plugin->writable = dlsym(handle, "spancast_oiio_writable");
    *(void **)&plugin->write = dlsym(handle, "spancast_oiio_write");
    *(void **)&plugin->read = dlsym(handle, "spancast_oiio_read");
    if (!plugin->writable || !plugin->write || !plugin->read) {
        snprintf(err, err_size,
                 "cannot load the OpenImageIO plugin: %s lacks its entry points",
                 IMGIO_PLUGIN_FILE);
        dlclose(handle);
        memset(plugin, 0, sizeof *plugin);
        return 0;
    }
    plugin->handle = handle;
    return 1;
}

void imgio_plugin_close(imgio_plugin *plugin)
{
    if (plugin->handle)
        dlclose(plugin->handle);
    memset(plugin, 0, sizeof *plugin);
}
