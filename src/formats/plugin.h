/* Plugins: shared objects that the library loads with dlopen on first use,
 * so that a run pays for a heavy dependency (OpenImageIO, libtiff, CGAL and
 * GMP) only when it needs it.
 *
 * A plugin file is looked for next to the running executable (or in the
 * installed helpers' folder, file_beside_program), then in the build folder
 * (SPANCAST_PLUGIN_DIR), where the tests find it. Nothing is cached: dlopen
 * of a library already loaded only counts a reference, and RTLD_NODELETE
 * keeps the plugin's code in memory once loaded (OpenImageIO and CGAL do
 * not support unloading), so every use opens and closes its own handle and
 * no state outlives it.
 */
#ifndef SPANCAST_FORMATS_PLUGIN_H
#define SPANCAST_FORMATS_PLUGIN_H

#include <stddef.h>

/* Loads the plugin file (a file name, such as "spancast-cgal.so") and
 * looks up its count entry points names[] into fns[]. Returns 1 with
 * *handle set, or 0 with "cannot load the WHAT plugin (FILE): why" in err
 * (dlopen's reason, or "it lacks NAME"). */
int plugin_load(const char *file, const char *what, const char *const names[], int count,
                void **fns, void **handle, char *err, size_t err_size);

/* Drops the reference *handle holds (NULL: nothing) and clears it. */
void plugin_unload(void **handle);

#endif
