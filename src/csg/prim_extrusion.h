/* Extrusion leaves (prim_extrusion.c): a 2D region, given as a small CSG
 * tree of ellipses and even-odd polygon sets, extruded straight along z
 * between z0 and z1. prim.c dispatches to the operations below; they mean
 * what they mean in prim.h.
 *
 * The builder describes the region in postfix order through a
 * prim_region (plain malloc'd arrays, freed with prim_region_free), then
 * prim_extrusion_create copies it into the tree's memory.
 */
#ifndef SPANCAST_CSG_PRIM_EXTRUSION_H
#define SPANCAST_CSG_PRIM_EXTRUSION_H

#include <stdint.h>

#include "csg/prim.h"

/* Operations of the region's postfix program. */
typedef enum prim_region_op {
    PRIM_REGION_ELLIPSE,      /* push the ellipse `index` */
    PRIM_REGION_POLYGON,      /* push the polygon set of edges index .. index+count-1 */
    PRIM_REGION_UNION,        /* pop b, pop a, push a or b */
    PRIM_REGION_INTERSECTION, /* pop b, pop a, push a and b */
    PRIM_REGION_DIFFERENCE    /* pop b, pop a, push a and not b */
} prim_region_op;

/* An ellipse as the unit disc of u = m (p - c): the image of a circle of
 * radius r under an invertible 2D affine map A p + c is m = (r A)^-1. */
typedef struct prim_region_ellipse {
    double m[2][2];
    double c[2];
} prim_region_ellipse;

typedef struct prim_region_node {
    uint8_t op;     /* prim_region_op */
    uint32_t index; /* ellipse: its index; polygon: its first edge */
    uint32_t count; /* polygon: its edges */
    double box[4];  /* leaves: 2D bounds, x0 y0 x1 y1 */
} prim_region_node;

/* The region being described (builder side). Edges are 4 doubles each,
 * a -> b: ax ay bx by. */
typedef struct prim_region {
    prim_region_node *nodes;
    uint32_t node_count, node_cap;
    double *edges;
    uint32_t edge_count, edge_cap;
    prim_region_ellipse *ellipses;
    uint32_t ellipse_count, ellipse_cap;
} prim_region;

/* The most nested operands the postfix program may keep waiting (the
 * builder's nesting limit keeps well below it). */
#define PRIM_REGION_MAX_STACK 2048

/* Edges per box of the one-level hierarchy over a polygon set's edges. */
#define PRIM_EXTRUSION_CHUNK 16

/* The most polygon edges one region may have. */
#define PRIM_EXTRUSION_MAX_EDGES (1 << 26)

/* The builder's steps; each returns 0 when memory ran out. A polygon set
 * is its closed paths (path k is the points xy[2 start[k]] .. before
 * xy[2 start[k + 1]]), inside where a point is inside an odd number of
 * them; paths of fewer than 3 points and zero-length edges are dropped, and
 * a set with no edge left pushes nothing (*pushed = 0). An ellipse with a
 * singular map pushes nothing too. */
int prim_region_add_polygon(prim_region *r, const double *xy, const uint32_t *start,
                            uint32_t paths, int *pushed);
int prim_region_add_ellipse(prim_region *r, const double map[2][3], double radius,
                            int *pushed);
int prim_region_add_op(prim_region *r, prim_region_op op);
void prim_region_free(prim_region *r);

/* The leaf's data, in the tree's memory. */
typedef struct prim_extrusion {
    const prim_region_node *nodes; /* postfix */
    uint32_t node_count;
    const double *edges; /* surface g < edge_count is edge g */
    uint32_t edge_count;
    const double *chunk_boxes;           /* 2D box of edges 16 c .. 16 c + 15, padded */
    const prim_region_ellipse *ellipses; /* surface edge_count + k is ellipse k */
    uint32_t ellipse_count;
    uint32_t max_stack;  /* operands waiting at once */
    uint32_t work_spans; /* room the span sweep needs (prim_max_spans) */
    double z0, z1;       /* the slab, z0 < z1 */
    bbox bounds;
} prim_extrusion;

/* Builds the leaf of the region r (a complete postfix program of one
 * operand) between z0 < z1 in b's memory. Returns NULL when memory ran
 * out, the program is malformed or needs more than PRIM_REGION_MAX_STACK
 * operands at once, or it has more than PRIM_EXTRUSION_MAX_EDGES edges. */
struct csg_builder;
const prim_extrusion *prim_extrusion_create(struct csg_builder *b, const prim_region *r,
                                            double z0, double z1);

/* 2D point membership of the region (closed: the boundary is inside). */
int prim_extrusion_inside_2d(const prim_extrusion *e, double x, double y);

uint32_t prim_extrusion_spans(const prim *p, uint32_t leaf, vec3 o, vec3 d, span *out,
                              uint32_t cap);
vec3 prim_extrusion_normal(const prim *p, vec3 q, uint16_t part);
int prim_extrusion_inside(const prim *p, vec3 q);
uint32_t prim_extrusion_max_spans(const prim *p);

#endif
