/* Readers of spancast's shading nodes for the lowering pass
 * (lower_shading.c): each reads and checks a node's arguments into the
 * record the builder places, or fills at->error. */
#ifndef SPANCAST_MODEL_LOWER_SHADING_H
#define SPANCAST_MODEL_LOWER_SHADING_H

#include "model/args.h"
#include "model/model.h"
#include "model/shading.h"

/* light(): its kind, colour, intensity, radius, and its position or
 * direction in the node's own coordinates. */
sc_status model_read_light(const model_reader *at, const parse_node *n,
                           shading_light *out);
/* camera(): in world coordinates. */
sc_status model_read_camera(const model_reader *at, const parse_node *n,
                            shading_camera *out);
/* background(): its colour. */
sc_status model_read_background(const model_reader *at, const parse_node *n, float c[3]);
/* material(). */
sc_status model_read_material(const model_reader *at, const parse_node *n,
                              model_material *out);

#endif
