/* Reading AMF meshes as OpenSCAD 2021.01's import("file.amf") reads them
 * (amf.c has the rules). */
#ifndef SPANCAST_FORMATS_AMF_H
#define SPANCAST_FORMATS_AMF_H

#include <stddef.h>
#include <stdint.h>

#include "math/vec.h"
#include "spancast/spancast.h"

/* The triangles of an AMF file: every object's, their indices into the
 * points of all objects together. */
typedef struct amf_mesh {
    vec3 *points;
    uint32_t point_count;
    uint32_t *indices;    /* 3 per triangle */
    uint32_t *face_start; /* face f: indices[face_start[f] .. [f + 1]); count + 1 */
    uint32_t face_count;
    uint32_t object_count; /* <object> elements read */
} amf_mesh;

/* Most points, and most triangles, of one file. */
#define AMF_MAX_POINTS 50000000u

/* Reads the AMF text (size bytes; an uncompressed AMF, not a zip) into
 * out (zeroed here; free with amf_mesh_free, also after an error). name
 * is the file as the model names it; errors are set at *at as
 * "import: NAME:LINE: why". */
sc_status amf_read(const char *text, size_t size, const char *name, const sc_location *at,
                   amf_mesh *out, sc_error *error);
void amf_mesh_free(amf_mesh *m);

#endif
