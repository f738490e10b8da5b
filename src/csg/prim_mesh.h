/* Triangle-mesh leaves (prim_mesh.c): closed meshes from `polyhedron` (the
 * non-convex ones) and `import`, with a hierarchy of boxes over their
 * triangles. prim.c dispatches to the operations below; they mean what
 * they mean in prim.h.
 */
#ifndef SPANCAST_CSG_PRIM_MESH_H
#define SPANCAST_CSG_PRIM_MESH_H

#include <stdint.h>

#include "csg/prim.h"

/* The most spans a mesh leaf gives one ray, and the most crossings it
 * sorts exactly; past either, the rest of the line up to the mesh's last
 * crossing is filled (see prim_mesh.c). A mesh with n triangles has at
 * most n / 2 spans, so small meshes get smaller buffers. */
#define PRIM_MESH_MAX_SPANS 32
#define PRIM_MESH_MAX_CROSSINGS 256

/* A node of the triangle hierarchy, one cache line: the boxes of its two
 * children side by side, so one fetch decides which children a ray enters
 * and in which order. Boxes are floats relative to the mesh's origin,
 * rounded outward and padded (see prim_mesh.c); an unused child has an
 * empty box (lo > hi) that no ray enters. */
typedef struct prim_mesh_node {
    float box[2][3][2]; /* [0: lo, 1: hi][axis][child] */
    uint32_t child[2];  /* inner child: its node index; leaf child: first triangle */
    uint32_t count[2];  /* leaf child: its triangle count; 0: an inner node */
} prim_mesh_node;

typedef struct prim_mesh {
    const vec3 *v;               /* 3 corners per triangle, in hierarchy order */
    const vec3 *n;               /* per triangle, (b - a) x (c - a), outward */
    const prim_mesh_node *nodes; /* nodes[0] holds the root's children */
    uint32_t tri_count, node_count;
    bbox bounds; /* of the corners, unpadded */
    vec3 origin; /* the centre of bounds: node boxes are relative to it */
    int parity;  /* inside rule: 0 winding number > 0 (closed, consistently
                    oriented meshes); 1 an odd count of crossings (any mesh) */
} prim_mesh;

struct csg_builder;

/* Builds the mesh of tri_count triangles (three indices into points each,
 * wound so that (b - a) x (c - a) points out of the solid) in b's arena;
 * triangles without area are dropped. Returns NULL when memory ran out or
 * no triangle has area. */
const prim_mesh *prim_mesh_create(struct csg_builder *b, const vec3 *points,
                                  const uint32_t *tris, uint32_t tri_count);
/* The same with the inside rule chosen: parity 1 for a mesh that is open,
 * non-manifold or inconsistently wound, where a winding number means
 * nothing (docs/meshes.md); the triangles may then face either way, and a
 * triangle listed again (the same three points) is kept once. */
const prim_mesh *prim_mesh_create_rule(struct csg_builder *b, const vec3 *points,
                                       const uint32_t *tris, uint32_t tri_count,
                                       int parity);

uint32_t prim_mesh_spans(const prim *p, uint32_t leaf, vec3 o, vec3 d, span *out,
                         uint32_t cap);

/* The spans that matter within [lo, hi] (prim_spans_range in prim.h), for
 * span lists regularised with eps; the walk visits only the part of the
 * hierarchy the answer needs. */
uint32_t prim_mesh_spans_range(const prim *p, uint32_t leaf, vec3 o, vec3 d, double lo,
                               double hi, double eps, int first, span *out, uint32_t cap);
vec3 prim_mesh_normal(const prim *p, vec3 q, uint16_t part);
int prim_mesh_inside(const prim *p, vec3 q);
uint32_t prim_mesh_max_spans(const prim *p);

#endif
