/* Loading plugins on demand (plugin.h). */
#define _GNU_SOURCE /* RTLD_NODELETE */

#include "formats/plugin.h"

#include <dlfcn.h>
#include <stdio.h>

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

int plugin_load(const char *file, const char *what, const char *const names[], int count,
                void **fns, void **handle_out, char *err, size_t err_size)
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
        snprintf(err, err_size, "cannot load the %s plugin (%s): %s", what, file, first);
        return 0;
    }
    for (int k = 0; k < count; k++)
        if (!(fns[k] = dlsym(handle, names[k]))) {
            snprintf(err, err_size, "cannot load the %s plugin (%s): it lacks %s", what,
                     file, names[k]);
            dlclose(handle);
            return 0;
        }
    *handle_out = handle;
    return 1;
}

void plugin_unload(void **handle)
{
    if (*handle)
        dlclose(*handle);
    *handle = NULL;
}
