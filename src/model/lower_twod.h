/* The 2D context of the lowering pass (lower_twod.c, model.h): a node
 * below an extrusion, or a 2D shape, read with its error kept in the node
 * for the builder that reads it.
 */
#ifndef SPANCAST_MODEL_LOWER_TWOD_H
#define SPANCAST_MODEL_LOWER_TWOD_H

#include "base/arena.h"
#include "model/model.h"

/* Lowers the arguments of n, already given its kind in out, in the 2D
 * context: square, circle, polygon, offset, text, import (a drawing) and
 * multmatrix have some; other kinds none. An argument error goes into
 * out->pending (allocated from mem); the status is SC_ERR_NOMEM in *error
 * when memory runs out, else SC_OK. */
sc_status model_twod_args(arena *mem, const char *file, const parse_node *n,
                          model_node *out, sc_error *error);

/* import(file = "x.dxf" | "x.svg") outside the 2D context (in the main
 * model or the points context; model_import_is_drawing(n)): out->u.import
 * names the file and holds the drawing, whose arguments are read as in
 * the 2D context, an error going into out->pending. The status is
 * SC_ERR_NOMEM in *error when memory runs out, else SC_OK. */
sc_status model_import_drawing(arena *mem, const char *file, const parse_node *n,
                               model_node *out, sc_error *error);

#endif
