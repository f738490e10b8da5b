/* Readers of spancast's curved leaves for the lowering pass
 * (lower_curved.c): each reads and checks a node's arguments, or fills
 * c->error. */
#ifndef SPANCAST_MODEL_LOWER_CURVED_H
#define SPANCAST_MODEL_LOWER_CURVED_H

#include "model/args.h"
#include "model/model.h"

sc_status model_read_torus(const model_reader *c, const parse_node *n, model_torus *out);
sc_status model_read_quadric(const model_reader *c, const parse_node *n,
                             model_quadric *out);
/* The expression compiled into out->program. */
sc_status model_read_implicit(const model_reader *c, const parse_node *n,
                              model_implicit *out);

#endif
