/* Primitives: the leaves of a CSG tree, in their local frame.
 *
 * A closed set of kinds dispatched by switch, each with the same small set
 * of operations:
 *   prim_bounds  local axis-aligned bounds;
 *   prim_spans   the span list of a local ray o + t d (all crossings, with
 *                surface parts; d is not normalised, t means the same point
 *                as in the world frame);
 *   prim_normal  outward normal (not normalised) at a local point on the
 *                given part; called only for the hit that survives the
 *                booleans;
 *   prim_inside  point membership, the oracle the tests compare spans with.
 * Sphere, box, frustum and convex polyhedron are convex: one span at most.
 * Torus, clipped quadric and implicit surface (prim_curved.h) and triangle
 * mesh (prim_mesh.h) can give several; prim_max_spans bounds every kind.
 */
#ifndef SPANCAST_CSG_PRIM_H
#define SPANCAST_CSG_PRIM_H

#include <stdint.h>

#include "csg/span.h"
#include "math/vec.h"

typedef enum prim_kind {
    PRIM_SPHERE,   /* |p| <= r */
    PRIM_BOX,      /* lo <= p <= hi */
    PRIM_CYLINDER, /* frustum along z: z0 <= z <= z1, radius r0 at z0 to r1 at z1 */
    PRIM_CONVEX,   /* intersection of halfspaces n . p <= d */
    PRIM_TORUS,    /* (|(x, y)| - R)^2 + z^2 <= r^2, 0 < r < R (prim_torus.c) */
    PRIM_QUADRIC,  /* Q(p) <= 0 within a box (prim_quadric.c) */
    PRIM_IMPLICIT, /* f(p) < 0 within a box (prim_implicit.c) */
    PRIM_MESH,     /* closed triangle mesh (prim_mesh.c) */
    PRIM_REVOLVE,  /* profile revolved about z (prim_revolve.c) */
    /* a 2D region extruded along z (prim_extrusion.c) */
    PRIM_EXTRUSION,
    PRIM_OUTLINE, /* prism of a curved outline, z0 <= z <= z1 (prim_outline.c) */
    PRIM_KIND_COUNT
} prim_kind;

/* A plane n . p = d; inside is n . p <= d. n need not be unit length. */
typedef struct plane {
    vec3 n;
    double d;
} plane;

/* A clipped quadric's coefficients and box, out of line: 128 bytes in
 * every leaf of every kind made a leaf 48 bytes larger than any other kind
 * needs. */
typedef struct prim_quadric {
    double a[10]; /* A..J: A x^2 + B y^2 + C z^2 + D xy + E yz + F xz
                     + G x + H y + I z + J */
    bbox box;     /* the clipping box */
} prim_quadric;

struct expr_program;
struct prim_mesh;
struct prim_revolve;
struct prim_extrusion;
struct prim_outline;

/* The most planes a builder makes a convex leaf (PRIM_CONVEX) of: a ray
 * tests them one by one, so a larger convex solid (a hull, a faithful
 * sphere or cylinder) is a mesh leaf, whose box hierarchy a ray descends.
 * Measured on one faithful sphere at 1600x1200: 114 planes 0.38 s against
 * 0.47 s as a mesh, 422 planes 1.0 s against 0.53 s; a cylinder of 258
 * planes 0.59 s against 0.77 s. (A leaf's part numbers are 16-bit, so
 * 65,536 planes is a hard limit.) */
#define PRIM_CONVEX_MAX_PLANES 256

/* Spans an implicit leaf gives one ray at most; see prim_implicit.c for
 * what happens to a ray that crosses its surface more often. */
#define PRIM_IMPLICIT_MAX_SPANS 16

typedef struct prim {
    prim_kind kind;
    union {
        struct {
            double r;
        } sphere;
        struct {
            vec3 lo, hi;
        } box;
        struct {
            double z0, z1; /* z0 < z1 */
            double r0, r1; /* radii at z0 and z1, >= 0, not both 0 */
        } cylinder;
        struct {
            const plane *planes; /* owned by the scene arena */
            uint32_t count;
            bbox bounds; /* of the polyhedron's vertices */
        } convex;
        struct {
            double major, minor; /* R, r */
        } torus;
        struct {
            const prim_quadric *q; /* owned by the tree's arena */
        } quadric;
        struct {
            const struct expr_program *program; /* owned by the tree's arena */
            bbox box;                           /* the clipping box */
            double tolerance;                   /* root-finding tolerance, length */
            double lipschitz;                   /* bound on |grad f| for sphere tracing */
            int method;                         /* solve_method */
        } implicit;
        struct {
            const struct prim_mesh *mesh; /* owned by the tree's arena */
        } mesh;
        struct {
            const struct prim_revolve *rev; /* owned by the tree's arena */
        } revolve;
        struct {
            const struct prim_extrusion *ext; /* owned by the tree's arena */
        } extrusion;
        struct {
            const struct prim_outline *outline; /* owned by the tree's arena */
        } outline;
    } u;
} prim;

/* Surface parts. */
enum {
    PRIM_PART_SPHERE = 0,
    /* box: 0 -x, 1 +x, 2 -y, 3 +y, 4 -z, 5 +z */
    PRIM_PART_CYL_SIDE = 0,
    PRIM_PART_CYL_BOTTOM = 1,
    PRIM_PART_CYL_TOP = 2
    /* convex: the plane index */
};

bbox prim_bounds(const prim *p);

/* Writes at most cap spans of the local ray to out (sorted, disjoint), with
 * leaf set in every span end; returns the count. The spans cover the whole
 * line, not only t >= 0: callers clip. Never NaN or Inf. */
uint32_t prim_spans(const prim *p, uint32_t leaf, vec3 o, vec3 d, span *out,
                    uint32_t cap);

/* The spans that matter to a query within [lo, hi] whose lists are
 * regularised with eps (span.h): after span_regularize, the result agrees
 * with prim_spans' on [lo, hi], and a span that meets [lo, hi] keeps both
 * its ends. With first set, only up to the first crossing after lo: the
 * list ends with the first span that reaches past lo, whose in end is exact
 * when it lies at or after lo and whose out end is exact when its in end
 * lies before lo. Meshes walk only the part of their hierarchy this needs;
 * every other kind returns prim_spans' whole list. */
uint32_t prim_spans_range(const prim *p, uint32_t leaf, vec3 o, vec3 d, double lo,
                          double hi, double eps, int first, span *out, uint32_t cap);

vec3 prim_normal(const prim *p, vec3 local_point, uint16_t part);

int prim_inside(const prim *p, vec3 local_point);

/* The kind's name as `spancast info` prints it. */
const char *prim_kind_name(prim_kind kind);

/* Upper bound on the spans one ray can produce, for sizing buffers. */
uint32_t prim_max_spans(const prim *p);

#endif
