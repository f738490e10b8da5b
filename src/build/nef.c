/* Loading the CGAL plugin (nef.h) on demand, found and loaded as every
 * plugin is (formats/plugin.h): RTLD_NODELETE keeps CGAL's code and GMP in
 * memory once loaded, so each build that needs the plugin opens and closes
 * its own handle and no state outlives it.
 */
#include "build/nef.h"

#include <string.h>

#include "formats/plugin.h"

int nef_plugin_open(nef_plugin *plugin, char *err, size_t err_size)
{
    static const char *const names[] = {
        "spancast_nef_from_mesh", "spancast_nef_empty",    "spancast_nef_apply",
        "spancast_nef_is_empty",  "spancast_nef_vertices", "spancast_nef_convex_parts",
        "spancast_nef_release"};
    enum { COUNT = sizeof names / sizeof names[0] };
    memset(plugin, 0, sizeof *plugin);
    void *fns[COUNT], *handle = NULL;
    if (!plugin_load(NEF_PLUGIN_FILE, "CGAL", names, COUNT, fns, &handle, err, err_size))
        return 0;
    /* Function pointers from dlsym: POSIX guarantees the conversion. */
    *(void **)&plugin->from_mesh = fns[0];
    *(void **)&plugin->empty = fns[1];
    *(void **)&plugin->apply = fns[2];
    *(void **)&plugin->is_empty = fns[3];
    *(void **)&plugin->vertices = fns[4];
    *(void **)&plugin->convex_parts = fns[5];
    *(void **)&plugin->release = fns[6];
    plugin->handle = handle;
    return 1;
}

void nef_plugin_close(nef_plugin *plugin)
{
    plugin_unload(&plugin->handle);
    memset(plugin, 0, sizeof *plugin);
}
