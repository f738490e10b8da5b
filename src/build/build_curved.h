/* Builder of spancast's own curved leaves (build_implicit.c):
 *   torus(r1, r2)                         major radius r1 in the xy plane,
 *                                         minor radius r2
 *   quadric(a, bounds)                    A x^2 + B y^2 + C z^2 + D xy
 *                                         + E yz + F xz + G x + H y + I z + J
 *                                         <= 0 inside the box bounds
 *   implicit(f, bounds, method, tolerance, params, lipschitz)
 *                                         f(x, y, z) < 0 inside the box
 * build.c dispatches to these; each reads and checks its node's arguments
 * and, when emit is set, fills the primitive (the implicit's bytecode is
 * allocated from the tree's memory). A shape that makes no geometry sets
 * *empty to a warning message instead.
 */
#ifndef SPANCAST_BUILD_BUILD_CURVED_H
#define SPANCAST_BUILD_BUILD_CURVED_H

#include "csg/csg.h"
#include "spancast/spancast.h"
#include "syntax/parse.h"

typedef struct build_ctx {
    const char *file; /* for positions */
    csg_builder *csg; /* owner of the bytecode */
    sc_error *error;
    int faithful; /* --faithful: OpenSCAD's polygons and polyhedra */
    /* where a builder may leave one warning (a font fallback), or NULL */
    sc_error *note;
} build_ctx;

/* Argument helpers shared by the builders of spancast's own leaves and of
 * extrusions (build_args.c). build_arg: the value of the named or positional
 * argument, NULL when absent or undef; build_loc: a value's position;
 * build_wrong_type: the error for an argument of the wrong type. */
const parse_value *build_arg(const parse_node *n, const char *name, int position);
sc_location build_loc(const build_ctx *c, const parse_value *v);
sc_status build_wrong_type(const build_ctx *c, const parse_node *n, const char *param,
                           const parse_value *v, const char *expected);
/* A number argument into *out (left alone when absent). */
sc_status build_number(const build_ctx *c, const parse_node *n, const char *name,
                       int position, double *out);
/* A true/false argument into *out (left alone when absent). */
sc_status build_bool(const build_ctx *c, const parse_node *n, const char *name,
                     int position, int *out);
/* multmatrix(m): a row-major 4x4 affine matrix of finite numbers with the
 * bottom row [0, 0, 0, 1]; no argument is the identity. */
sc_status build_matrix(const build_ctx *c, const parse_node *n, double m[4][4]);
/* A 2D node's multmatrix(m): m checked as a 4x4 affine matrix of finite
 * numbers, and inner = outer after its xy part (x' = m00 x + m01 y + m03,
 * y' = m10 x + m11 y + m13; z is dropped, as OpenSCAD flattens 2D
 * children). Maps are rows [a b tx; c d ty]; inner may be outer. */
sc_status build_matrix_xy(const build_ctx *c, const parse_node *n,
                          const double outer[2][3], double inner[2][3]);
/* polygon(points, paths)'s arguments: points (NULL when absent) a vector
 * of finite [x, y], paths (NULL when absent) a vector of vectors; the
 * indices in the paths are the caller's to check. */
#define BUILD_POLYGON_PATHS "a vector of paths, each a vector of point indices"
sc_status build_polygon(const build_ctx *c, const parse_node *n,
                        const parse_value **points, const parse_value **paths);
/* Entry of path number path of a polygon with count points: an integer
 * index below count into *index, else the error at the entry. */
sc_status build_polygon_index(const build_ctx *c, const parse_value *v, uint32_t path,
                              uint32_t count, uint32_t *index);
/* cube(size = s | [x, y, z], center = false)'s arguments. */
sc_status build_cube_args(const build_ctx *c, const parse_node *n, double size[3],
                          int *center);
/* square(size = s | [x, y], center = false)'s arguments. */
sc_status build_square(const build_ctx *c, const parse_node *n, double *sx, double *sy,
                       int *center);

sc_status build_torus(const build_ctx *c, const parse_node *n, int emit, prim *out,
                      const char **empty);
sc_status build_quadric(const build_ctx *c, const parse_node *n, int emit, prim *out,
                        const char **empty);
sc_status build_implicit(const build_ctx *c, const parse_node *n, int emit, prim *out,
                         const char **empty);

#endif
