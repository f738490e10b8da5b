/* Reading AMF meshes as OpenSCAD 2021.01's import("file.amf") reads them
 * (amf.c has the rules). */
#ifndef SPANCAST_FORMATS_AMF_H
#define SPANCAST_FORMATS_AMF_H

#include <stddef.h>
#include <stdint.h>

#include "math/vec.h"
#include "spancast/spancast.h"

/* The triangles of an AMF file: every object's, their indices into the
 * points of all objects together, and where each object's points and
 * triangles start (an object is one solid, which OpenSCAD unites with the
 * others). */
typedef struct amf_mesh {
    vec3 *points;
    uint32_t point_count;
    uint32_t *indices;    /* 3 per triangle */
    uint32_t *face_start; /* face f: indices[face_start[f] .. [f + 1]); count + 1 */
    uint32_t face_count;
    uint32_t object_count; /* <object> elements read */
    /* object o: points [object_points[o], [o + 1]), triangles (faces)
     * [object_faces[o], [o + 1]); object_count + 1 entries each (NULL when
     * there is no object) */
    uint32_t *object_points, *object_faces;
} amf_mesh;

/* Most points, and most triangles, of one file. */
#define AMF_MAX_POINTS 50000000u

/* Reads the AMF text (size bytes; an uncompressed AMF, not a zip: see
 * amf_unzip) into
 * out (zeroed here; free with amf_mesh_free, also after an error). name
 * is the file as the model names it; errors are set at *at as
 * "import: NAME:LINE: why", or where *at has no line (the file is the
 * model) at that line of at->file. */
sc_status amf_read(const char *text, size_t size, const char *name, const sc_location *at,
                   amf_mesh *out, sc_error *error);
void amf_mesh_free(amf_mesh *m);

/* A zipped AMF file, as OpenSCAD 2021.01 reads one (import_amf.cc, with
 * libzip, xml.h): when data (size bytes) is a zip archive, its entry
 * named as the file (path's last component) in any folder, else its only
 * entry, with OpenSCAD's warning in warning ("" otherwise). Returns SC_OK
 * with *text NULL when data is not a zip archive (it is the AMF text
 * itself), or with the entry in *text (malloc'd, *text_size bytes and a
 * NUL); an archive without that entry and with more than one is an error
 * (OpenSCAD: a warning and an empty import), as is an entry larger than
 * max_size. name is the file as the model names it; errors are set at
 * *at as "import: NAME: why". */
sc_status amf_unzip(const char *data, size_t size, const char *path, const char *name,
                    const sc_location *at, size_t max_size, char **text,
                    size_t *text_size, char *warning, size_t warning_size,
                    sc_error *error);

#endif
