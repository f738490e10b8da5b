/* Loading the CGAL plugin (nef.h) on demand, found and loaded as every
 * plugin is (formats/plugin.h): RTLD_NODELETE keeps CGAL's code and GMP in
 * memory once loaded, so each build that needs the plugin opens and closes
 * its own handle and no state outlives it.
 *
 * CGAL's Nef polyhedra are not safe to use from two threads at once (the
 * top-level objects of a model are built in parallel; two projections of
 * booleans there crashed inside CGAL or never finished), so an open
 * handle holds one process-wide lock until it is closed: builds that need
 * CGAL take turns, others are not held up. The lock is recursive, as a
 * build may open the plugin again below an open one.
 */
#define _GNU_SOURCE /* PTHREAD_RECURSIVE_MUTEX_INITIALIZER_NP */

#include "build/nef.h"

#include <pthread.h>
#include <string.h>

#include "formats/plugin.h"

static pthread_mutex_t nef_lock = PTHREAD_RECURSIVE_MUTEX_INITIALIZER_NP;

int nef_plugin_open(nef_plugin *plugin, char *err, size_t err_size)
{
    static const char *const names[] = {
        "spancast_nef_from_mesh",   "spancast_nef_empty",
        "spancast_nef_apply",       "spancast_nef_is_empty",
        "spancast_nef_vertices",    "spancast_nef_convex_parts",
        "spancast_nef_triangles",   "spancast_nef_release",
        "spancast_nef_copy",        "spancast_nef_transform",
        "spancast_nef_plane_check", "spancast_nef_off_build",
        "spancast_nef_section",     "spancast_nef_self_crossing",
        "spancast_nef_tessellate",  "spancast_nef_hull"};
    enum { COUNT = sizeof names / sizeof names[0] };
    memset(plugin, 0, sizeof *plugin);
    pthread_mutex_lock(&nef_lock);
    void *fns[COUNT], *handle = NULL;
    if (!plugin_load(NEF_PLUGIN_FILE, "CGAL", names, COUNT, fns, &handle, err,
                     err_size)) {
        pthread_mutex_unlock(&nef_lock);
        return 0;
    }
    /* Function pointers from dlsym: POSIX guarantees the conversion. */
    *(void **)&plugin->from_mesh = fns[0];
    *(void **)&plugin->empty = fns[1];
    *(void **)&plugin->apply = fns[2];
    *(void **)&plugin->is_empty = fns[3];
    *(void **)&plugin->vertices = fns[4];
    *(void **)&plugin->convex_parts = fns[5];
    *(void **)&plugin->triangles = fns[6];
    *(void **)&plugin->release = fns[7];
    *(void **)&plugin->copy = fns[8];
    *(void **)&plugin->transform = fns[9];
    *(void **)&plugin->plane_check = fns[10];
    *(void **)&plugin->off_build = fns[11];
    *(void **)&plugin->section = fns[12];
    *(void **)&plugin->self_crossing = fns[13];
    *(void **)&plugin->tessellate = fns[14];
    *(void **)&plugin->hull = fns[15];
    plugin->handle = handle;
    return 1;
}

void nef_plugin_close(nef_plugin *plugin)
{
    if (plugin->handle) {
        plugin_unload(&plugin->handle);
        pthread_mutex_unlock(&nef_lock);
    }
    memset(plugin, 0, sizeof *plugin);
}
