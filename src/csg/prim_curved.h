/* The leaves that can meet a ray more than once: torus, clipped quadric
 * and implicit surface (prim_torus.c, prim_quadric.c, prim_implicit.c).
 * prim.c dispatches to them; the operations mean what they mean in
 * prim.h. */
#ifndef SPANCAST_CSG_PRIM_CURVED_H
#define SPANCAST_CSG_PRIM_CURVED_H

#include <stdint.h>

#include "csg/prim.h"

/* Parts of the clipped leaves: the surface, then the six box faces
 * (PRIM_PART_CLIP_FACE + 2k is -axis k, + 2k + 1 is +axis k). */
enum { PRIM_PART_SURFACE = 0, PRIM_PART_CLIP_FACE = 1 };

/* The stretch of the line o + t d inside the closed box b, with the faces
 * it enters and leaves through (as box parts 0..5). Returns 0 when the
 * line misses the box. d must not be zero. */
int prim_box_clip(const bbox *b, vec3 o, vec3 d, double *t0, uint16_t *face0, double *t1,
                  uint16_t *face1);

/* The outward normal of the clip face part (PRIM_PART_CLIP_FACE or
 * more) of a clipped leaf: a unit axis. */
vec3 prim_clip_face_normal(uint16_t part);

uint32_t prim_torus_spans(const prim *p, uint32_t leaf, vec3 o, vec3 d, span *out,
                          uint32_t cap);
vec3 prim_torus_normal(const prim *p, vec3 q);
int prim_torus_inside(const prim *p, vec3 q);
bbox prim_torus_bounds(const prim *p);

uint32_t prim_quadric_spans(const prim *p, uint32_t leaf, vec3 o, vec3 d, span *out,
                            uint32_t cap);
/* Q(q) for the coefficients a[10] (see prim.h). */
double prim_quadric_value(const double *a, vec3 q);
vec3 prim_quadric_normal(const prim *p, vec3 q, uint16_t part);
int prim_quadric_inside(const prim *p, vec3 q);

uint32_t prim_implicit_spans(const prim *p, uint32_t leaf, vec3 o, vec3 d, span *out,
                             uint32_t cap);
vec3 prim_implicit_normal(const prim *p, vec3 q, uint16_t part);
int prim_implicit_inside(const prim *p, vec3 q);

#endif
