/* What every builder of src/build/ shares: the build context (the file
 * for positions, the CSG builder that owns what leaves allocate, where
 * errors and a warning go, faithful mode), and, for the builders that
 * still read their own syntax node (the extrusions, hull, minkowski,
 * resize and the 2D shapes), the argument readers of the model layer
 * (model/args.h) through a build_ctx (BUILD_READER).
 */
#ifndef SPANCAST_BUILD_BUILD_CTX_H
#define SPANCAST_BUILD_BUILD_CTX_H

#include "csg/csg.h"
#include "model/args.h"
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

/* The argument readers of model/args.h for a builder: the reader of c,
 * e.g. model_number(BUILD_READER(c), n, "h", 0, &h). */
#define BUILD_READER(c) (&(model_reader){(c)->file, (c)->error})

/* A 2D node's multmatrix(m): m checked as a 4x4 affine matrix of finite
 * numbers, and inner = outer after its xy part (x' = m00 x + m01 y + m03,
 * y' = m10 x + m11 y + m13; z is dropped, as OpenSCAD flattens 2D
 * children). Maps are rows [a b tx; c d ty]; inner may be outer.
 * (build_args.c) */
sc_status build_matrix_xy(const build_ctx *c, const parse_node *n,
                          const double outer[2][3], double inner[2][3]);

#endif
