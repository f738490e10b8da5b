/* The mesh readers on one input, for the fuzzer and its regression replay.
 *
 * fuzz_mesh_one writes the input, less its first byte, to a file and loads
 * it as `spancast render FILE` does (sc_scene_load_mesh): an OFF file
 * (ASCII or binary, as its keyword says) or an STL file (ASCII or binary,
 * as its size and first word say), by bit 0 of the first byte; bit 1
 * loads it faithfully, where an OFF file that is not a plain closed mesh
 * goes to CGAL's own polyhedron builder in the CGAL plugin (which
 * scripts/fuzz does not build: CGAL is not ours to fuzz, and the load
 * fails with the plugin's error there). Then the checks and the tiny
 * render of fuzz_loaded (harness.h). The file lives in a folder of the
 * process's own under $TMPDIR (or /tmp), made on the first call and
 * removed at exit. Returns fuzz_loaded's verdict, or -1 when the file
 * cannot be written.
 */
#ifndef SPANCAST_FUZZ_MESH_HARNESS_H
#define SPANCAST_FUZZ_MESH_HARNESS_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "harness.h"
#include "spancast/spancast.h"

/* mkdtemp and rmdir are POSIX; the harness is built as C11 */
char *mkdtemp(char *template_name);
int rmdir(const char *path);

static char fuzz_mesh_dir[4096], fuzz_mesh_off[4200], fuzz_mesh_stl[4200];

/* The folder and its two files, at exit. */
static void fuzz_mesh_clean(void)
{
    remove(fuzz_mesh_off);
    remove(fuzz_mesh_stl);
    rmdir(fuzz_mesh_dir);
}

static int fuzz_mesh_one(const uint8_t *data, size_t size)
{
    char *dir = fuzz_mesh_dir, *off = fuzz_mesh_off, *stl = fuzz_mesh_stl;
    if (!dir[0]) {
        const char *tmp = getenv("TMPDIR");
        snprintf(dir, sizeof fuzz_mesh_dir, "%s/spancast-fuzz-mesh-XXXXXX",
                 tmp && *tmp ? tmp : "/tmp");
        if (!mkdtemp(dir))
            return -1;
        snprintf(off, sizeof fuzz_mesh_off, "%s/m.off", dir);
        snprintf(stl, sizeof fuzz_mesh_stl, "%s/m.stl", dir);
        atexit(fuzz_mesh_clean);
    }
    if (size < 1)
        return 0;
    const char *path = data[0] & 1 ? stl : off;
    FILE *f = fopen(path, "wb");
    if (!f)
        return -1;
    size_t wrote = fwrite(data + 1, 1, size - 1, f);
    if (fclose(f) != 0 || wrote != size - 1)
        return -1;
    sc_load_options lo;
    sc_load_options_init(&lo);
    lo.max_triangles = (size_t)1 << 16;
    lo.faithful = (data[0] & 2) != 0;
    sc_scene *scene = NULL;
    sc_error error;
    sc_status st = sc_scene_load_mesh(path, &lo, &scene, &error);
    return fuzz_loaded(st, scene, &error);
}

#endif
