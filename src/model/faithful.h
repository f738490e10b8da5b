/* Faithful mode: the polygons OpenSCAD 2021.01 makes of curved solids.
 *
 * With sc_load_options.faithful (`--faithful`), the builder turns each
 * sphere and cylinder into the very polyhedron OpenSCAD would mesh from its
 * $fn, $fa and $fs, as a convex plane set (PRIM_CONVEX), so an image can be
 * compared face for face with OpenSCAD's and CGAL's output. See faithful.c
 * for the rules.
 */
#ifndef SPANCAST_MODEL_FAITHFUL_H
#define SPANCAST_MODEL_FAITHFUL_H

#include "csg/csg.h"
#include "spancast/spancast.h"

/* Most fragments (points per circle) OpenSCAD's polygons are built with:
 * circles, cylinders, offsets, text, DXF arcs, extrusions, revolutions,
 * projections and hulls, whose size grows as f (MODEL_MAX_FN, the
 * largest $fn, is the same). */
#define FAITHFUL_MAX_FRAGMENTS 65536
/* Most fragments of a sphere, whose f * f / 2 faces grow as f squared
 * (8 million at 4096). */
#define FAITHFUL_MAX_SPHERE_FRAGMENTS 4096

/* OpenSCAD 2021.01's fragment count for a circle of radius r (its
 * get_fragments_from_r). Returns -1 when the count is not finite or above
 * FAITHFUL_MAX_FRAGMENTS. */
long faithful_fragments(double r, double fn, double fs, double fa);
/* The same for a sphere: -1 above FAITHFUL_MAX_SPHERE_FRAGMENTS. */
long faithful_sphere_fragments(double r, double fn, double fs, double fa);

/* The faces of a sphere of f fragments: (f + 1) / 2 rings. */
size_t faithful_sphere_face_count(long f);

/* sin and cos of an angle in degrees, exact at multiples of 30 and 45
 * degrees, as OpenSCAD's sin_degrees and cos_degrees compute them. */
double faithful_sin_deg(double degrees);
double faithful_cos_deg(double degrees);

/* Fills *out with the plane set of OpenSCAD's sphere of radius r > 0 (planes
 * in csg's arena). Fails (SC_ERR_LIMIT at loc, or SC_ERR_NOMEM) when the
 * fragment count is out of range or memory runs out. */
sc_status faithful_sphere(csg_builder *csg, double r, double fn, double fa, double fs,
                          const sc_location *loc, prim *out, sc_error *error);

/* Same for OpenSCAD's cylinder from z0 (radius r0) to z1 (radius r1), with
 * z0 < z1, r0, r1 >= 0 and not both 0. */
sc_status faithful_cylinder(csg_builder *csg, double z0, double z1, double r0, double r1,
                            double fn, double fa, double fs, const sc_location *loc,
                            prim *out, sc_error *error);

/* OpenSCAD's polyhedron as polygons, for a mesh leaf: face f is
 * points[indices[face_start[f] .. face_start[f + 1])], every face wound the
 * same way (outward, counter-clockwise seen from outside), a cone's apex
 * one point. All malloc'd: free with faithful_faces_free. */
typedef struct faithful_faces {
    vec3 *points;
    uint32_t point_count;
    uint32_t *indices;
    uint32_t *face_start; /* face_count + 1 entries */
    uint32_t face_count;
} faithful_faces;

/* The faces of the sphere and cylinder that faithful_sphere and
 * faithful_cylinder make plane sets of (the same fragments, points and
 * faces), and their errors. */
sc_status faithful_sphere_faces(double r, double fn, double fa, double fs,
                                const sc_location *loc, faithful_faces *out,
                                sc_error *error);
sc_status faithful_cylinder_faces(double z0, double z1, double r0, double r1, double fn,
                                  double fa, double fs, const sc_location *loc,
                                  faithful_faces *out, sc_error *error);
void faithful_faces_free(faithful_faces *f);

#endif
