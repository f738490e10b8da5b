/* Loading the CGAL plugin (nef.h) on demand.
 *
 * As the image plugins (formats/image_plugin.c): looked for next to the
 * running executable (or in the installed helpers' folder), then in the
 * build folder (SPANCAST_PLUGIN_DIR), where the tests find it. dlopen of a
 * library already loaded only counts a reference, and RTLD_NODELETE keeps
 * CGAL's code and GMP in memory once loaded, so each build that needs the
 * plugin opens and closes its own handle and no state outlives it.
 *
 * CGAL's Nef polyhedra are not safe to use from two threads at once (the
 * top-level objects of a model are built in parallel; two projections of
 * booleans there crashed inside CGAL or never finished), so an open
 * handle holds one process-wide lock until it is closed: builds that need
 * CGAL take turns, others are not held up. The lock is recursive, as a
 * build may open the plugin again below an open one.
 */
#define _GNU_SOURCE /* RTLD_NODELETE */

#include "build/nef.h"

#include <dlfcn.h>
#include <pthread.h>
#include <stdio.h>
#include <string.h>

#include "formats/file.h"

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

static pthread_mutex_t nef_lock = PTHREAD_RECURSIVE_MUTEX_INITIALIZER_NP;

int nef_plugin_open(nef_plugin *plugin, char *err, size_t err_size)
{
    static const char *const names[] = {
        "spancast_nef_from_mesh", "spancast_nef_empty",    "spancast_nef_apply",
        "spancast_nef_is_empty",  "spancast_nef_vertices", "spancast_nef_convex_parts",
        "spancast_nef_triangles", "spancast_nef_release"};
    enum { COUNT = sizeof names / sizeof names[0] };
    memset(plugin, 0, sizeof *plugin);
    pthread_mutex_lock(&nef_lock);
    char path[4096], first[512] = "";
    void *handle = NULL;
    if (file_beside_program(NEF_PLUGIN_FILE, path, sizeof path))
        handle = open_at(path, first, sizeof first);
    if (!handle) {
        char second[512];
        snprintf(path, sizeof path, "%s/%s", SPANCAST_PLUGIN_DIR, NEF_PLUGIN_FILE);
        handle = open_at(path, second, sizeof second);
        if (!handle && !first[0])
            snprintf(first, sizeof first, "%s", second);
    }
    if (!handle) {
        snprintf(err, err_size, "cannot load the CGAL plugin (%s): %s", NEF_PLUGIN_FILE,
                 first);
        pthread_mutex_unlock(&nef_lock);
        return 0;
    }
    void *fns[COUNT];
    for (int k = 0; k < COUNT; k++) {
        if (!(fns[k] = dlsym(handle, names[k]))) {
            snprintf(err, err_size, "cannot load the CGAL plugin (%s): it lacks %s",
                     NEF_PLUGIN_FILE, names[k]);
            dlclose(handle);
            pthread_mutex_unlock(&nef_lock);
            return 0;
        }
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
    plugin->handle = handle;
    return 1;
}

void nef_plugin_close(nef_plugin *plugin)
{
    if (plugin->handle) {
        dlclose(plugin->handle);
        pthread_mutex_unlock(&nef_lock);
    }
    memset(plugin, 0, sizeof *plugin);
}
