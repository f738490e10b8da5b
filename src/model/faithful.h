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

/* Most fragments (points per circle) faithful mode builds; a sphere of f
 * fragments has about f * f / 2 faces. */
#define FAITHFUL_MAX_FRAGMENTS 4096

/* OpenSCAD 2021.01's fragment count for a circle of radius r (its
 * get_fragments_from_r). Returns -1 when the count is not finite or above
 * FAITHFUL_MAX_FRAGMENTS. */
long faithful_fragments(double r, double fn, double fs, double fa);

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

#endif
