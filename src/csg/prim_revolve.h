/* Solids of revolution (prim_revolve.c): rotate_extrude's exact leaf. A
 * profile in the (r, z) half-plane r >= 0, made of regions (polygons read
 * even-odd, and discs), revolved about the z axis through a full turn or a
 * wedge. prim.c dispatches to the operations below; they mean what they
 * mean in prim.h.
 */
#ifndef SPANCAST_CSG_PRIM_REVOLVE_H
#define SPANCAST_CSG_PRIM_REVOLVE_H

#include <stdint.h>

#include "csg/prim.h"

/* The size of a profile: edges plus two per disc. A ray meets each edge at
 * most twice and each disc's torus at most four times, so a ray's
 * crossings fit a fixed buffer on the stack of twice this. */
#define PRIM_REVOLVE_MAX_EDGES 2048

/* A straight edge of a polygon region, wound so that the region lies on
 * its left in the (r, z) plane (outlines counter-clockwise, holes
 * clockwise): its outward normal is (z1 - z0, r0 - r1). */
typedef struct prim_revolve_edge {
    double r0, z0, r1, z1;
    uint32_t region;
} prim_revolve_edge;

/* A disc of radius a about (rc, zc), 0 < a <= rc: a torus once revolved. */
typedef struct prim_revolve_disc {
    double rc, zc, a;
    uint32_t region;
} prim_revolve_disc;

/* Parts: the edge index, then edge_count + the disc index, then the two
 * wedge faces. */
enum { PRIM_REVOLVE_PART_START = 0xfffe, PRIM_REVOLVE_PART_END = 0xffff };

typedef struct prim_revolve {
    const prim_revolve_edge *edges; /* owned by the tree's arena */
    const prim_revolve_disc *discs;
    uint32_t edge_count, disc_count;
    uint32_t region_count;         /* the profile is the union of the regions */
    int partial;                   /* 1: only the wedge from start to end */
    double start[2];               /* unit (x, y) of the wedge's first face */
    double end[2];                 /* unit (x, y) of its last face */
    double sweep;                  /* the wedge's angle in degrees, (0, 360) */
    double r_lo, r_hi, z_lo, z_hi; /* the profile's extent */
} prim_revolve;

uint32_t prim_revolve_spans(const prim *p, uint32_t leaf, vec3 o, vec3 d, span *out,
                            uint32_t cap);
vec3 prim_revolve_normal(const prim *p, vec3 q, uint16_t part);
int prim_revolve_inside(const prim *p, vec3 q);
bbox prim_revolve_bounds(const prim *p);
uint32_t prim_revolve_max_spans(const prim *p);

#endif
