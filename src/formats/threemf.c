/* The library's side of the 3MF plugin (threemf.h). */
#include "formats/threemf.h"

#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "formats/plugin.h"

sc_status threemf_read_file(const char *path, const char *name, const sc_location *at,
                            amf_mesh *out, sc_error *error)
{
    memset(out, 0, sizeof *out);
    static const char *const names[] = {"spancast_3mf_read"};
    void *fns[1], *handle = NULL;
    char why[512];
    if (!plugin_load(THREEMF_PLUGIN_FILE, "3MF", names, 1, fns, &handle, why, sizeof why))
        return err_set(error, SC_ERR_IO, at, "import: %s: %s", name, why);
    threemf_read_fn read;
    /* Function pointers from dlsym: POSIX guarantees the conversion. */
    *(void **)&read = fns[0];
    double *xyz = NULL;
    uint32_t *indices = NULL, *starts = NULL;
    uint32_t points = 0, faces = 0, objects = 0;
    int ok = read(path, THREEMF_MAX_POINTS, &xyz, &points, &indices, &faces, &starts,
                  &objects, why, sizeof why);
    plugin_unload(&handle);
    if (!ok) {
        free(xyz);
        free(indices);
        free(starts);
        return err_set(error, SC_ERR_SYNTAX, at, "import: %s: %s", name, why);
    }
    size_t ends = (size_t)objects + 1;
    out->points = points ? malloc((size_t)points * sizeof *out->points) : NULL;
    out->face_start = malloc(((size_t)faces + 1) * sizeof *out->face_start);
    out->object_points = objects ? malloc(ends * sizeof *out->object_points) : NULL;
    out->object_faces = objects ? malloc(ends * sizeof *out->object_faces) : NULL;
    if ((points && !out->points) || !out->face_start ||
        (objects && (!out->object_points || !out->object_faces))) {
        free(xyz);
        free(indices);
        free(starts);
        amf_mesh_free(out);
        return err_nomem(error, at);
    }
    for (uint32_t i = 0; i < points; i++)
        out->points[i] = v3(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
    for (uint32_t f = 0; f <= faces; f++)
        out->face_start[f] = 3 * f;
    for (size_t o = 0; objects && o < ends; o++) {
        out->object_points[o] = starts[2 * o];
        out->object_faces[o] = starts[2 * o + 1];
    }
    free(xyz);
    free(starts);
    out->indices = indices;
    out->point_count = points;
    out->face_count = faces;
    out->object_count = objects;
    return SC_OK;
}
