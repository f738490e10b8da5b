/* The points context of the lowering pass (lower_points.c, model.h): the
 * nodes below hull, minkowski and resize, read as their builders read
 * them, each node's error kept in it.
 */
#ifndef SPANCAST_MODEL_LOWER_POINTS_H
#define SPANCAST_MODEL_LOWER_POINTS_H

#include "base/arena.h"
#include "model/model.h"

/* Lowers the arguments of n, already given its kind in out, in the points
 * context: cube, sphere, cylinder, polyhedron, import, surface, torus,
 * quadric, implicit, multmatrix, resize and the extrusions have some;
 * other kinds none. An argument error goes into out->pending (allocated
 * from mem); the status is SC_ERR_NOMEM in *error when memory runs out,
 * else SC_OK. */
sc_status model_points_args(arena *mem, const char *file, const parse_node *n,
                            model_node *out, sc_error *error);

#endif
