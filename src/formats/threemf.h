/* Reading 3MF meshes as OpenSCAD 2021.01's import("file.3mf") reads them:
 * through lib3mf 1.8 (Debian's lib3mf1, the library OpenSCAD uses), in the
 * plugin spancast-3mf.so (threemf/threemf_lib3mf.cpp), which the library
 * loads on the first 3MF import (plugin.h), since lib3mf brings libzip.
 *
 * As OpenSCAD: every mesh object's triangles, at the positions the file
 * gives (single precision, as lib3mf stores them), each object once;
 * build items, their transforms and components are not read (seen on
 * OpenSCAD 2021.01: an object placed by two items, one of them moved,
 * and by a component, imports as the object alone). OpenSCAD unites
 * several objects with CGAL; here their triangles are returned together
 * with where each object starts (amf_mesh), and the caller builds each
 * object and unites them.
 */
#ifndef SPANCAST_FORMATS_THREEMF_H
#define SPANCAST_FORMATS_THREEMF_H

#include <stddef.h>
#include <stdint.h>

#include "formats/amf.h"
#include "spancast/spancast.h"

#define THREEMF_PLUGIN_FILE "spancast-3mf.so"
/* Most points, and most triangles, of one file. */
#define THREEMF_MAX_POINTS AMF_MAX_POINTS

/* The plugin's entry point: the file's mesh objects into malloc'd arrays
 * (xyz 3 per point, indices 3 per triangle into the points of all
 * objects, objects 2 per object and 2 more: where each object's points
 * and triangles start, then the totals), or 0 with lib3mf's reason in err. */
typedef int (*threemf_read_fn)(const char *path, uint32_t max_points, double **xyz,
                               uint32_t *point_count, uint32_t **indices,
                               uint32_t *face_count, uint32_t **objects,
                               uint32_t *object_count, char *err, size_t err_size);

/* Reads the 3MF file at path into out (zeroed here; free with
 * amf_mesh_free, also after an error). name is the file as the model
 * names it; errors are set at *at as "import: NAME: why". */
sc_status threemf_read_file(const char *path, const char *name, const sc_location *at,
                            amf_mesh *out, sc_error *error);

#endif
