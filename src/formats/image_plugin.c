/* Loading the OpenImageIO plugin and the tiled TIFF plugin
 * (image_backend.h) on demand.
 *
 * OpenImageIO brings some 250 shared libraries with it (OpenCV, FFmpeg,
 * DCMTK, OpenVDB, ...), whose loading alone took a quarter of a second
 * before the first ray when the tool linked it. The plugin is the only code
 * that links it, and is loaded here only for a format that PNG and EXR do
 * not cover. The tiled TIFF writer is a plugin of its own for the same
 * reason (libtiff brings eight libraries), loaded only by a streamed .tif.
 * Both are found and loaded as every plugin is (formats/plugin.h).
 */
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
