/* Reading motion(from = M0, to = M1) for the lowering pass
 * (lower_motion.c). */
#ifndef SPANCAST_MODEL_LOWER_MOTION_H
#define SPANCAST_MODEL_LOWER_MOTION_H

#include "model/args.h"
#include "model/model.h"

/* Reads and checks n's from and to into *out, or fills r->error. */
sc_status model_read_motion(const model_reader *r, const parse_node *n,
                            model_motion *out);

#endif
