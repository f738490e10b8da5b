/* Adaptive integration over a rectangle of parallel lines: the engine of
 * the measure, overlap and compare queries (docs/measure.md).
 *
 * A quad_grid integrates a vector of functions f_k(u, v) over a rectangle
 * of the plane across a family of parallel lines: f_k is what one line
 * through (u, v) contributes (a length inside the solid, a moment along it,
 * a crossing count), computed exactly per line by the caller's sampler.
 * The rectangle is cut into cells; a cell's estimate is the midpoint rule
 * over its four quarters, and its error estimate is the difference between
 * that and the midpoint rule over the whole cell (one level coarser). For
 * a smooth integrand the finer rule's error is a third of the difference;
 * across a silhouette or an edge, where the integrand jumps, the
 * difference is still of the order of the error and refinement follows it.
 * quad_refine splits the cells holding the larger part of the estimated
 * error until every driven value's total error is within its target.
 *
 * Where neighbouring lines disagree the refinement also spreads sideways:
 * no cell stays more than one level coarser than a neighbour (edge or
 * corner), the 2:1 balance of quadtree meshes. A silhouette can cut off a
 * corner of a cell between its five lines, so that the cell sees nothing
 * there and its difference is zero; balance keeps such a cell at most twice
 * the size of the cells refined along the silhouette beside it, so the
 * part it misses shrinks with them instead of staying at the first grid's
 * size.
 *
 * A cell's five lines can all agree while the integrand jumps inside it: a
 * face seen edge-on along a grid row, between the row of quarter centres
 * and the cell's edge. The lines' signatures (which surfaces they cross)
 * catch that: where a cell's signature differs from a neighbour's, the
 * jump between them lies in the strip between their nearest lines, which
 * is a quarter of a cell on each side, so the pair's error is at most a
 * quarter of a cell's area times the difference of the two cells' means;
 * each cell carries half of that as its error (when larger than its own),
 * and the refinement follows every edge and silhouette seen in
 * projection.
 *
 * Stopping: the lines of a round are cast inside a cancel token
 * (base/cancel.h) on the caller's flag, so an interrupt stops even a slow
 * line within milliseconds (SC_ERR_CANCELLED); the token's budget of
 * implicit-surface work, RENDER_MIN_IMPLICIT_EVALS and
 * RENDER_IMPLICIT_EVALS_PER_RAY more per line done, or a line past the
 * root finder's bound, ends the integral with SC_ERR_LIMIT and the leaf in
 * limit_reason, limit_leaf and limit_prim.
 *
 * Determinism: the lines of one round are sampled in parallel (OpenMP) into
 * an array indexed by line, and everything that adds them up runs serially
 * in the cells' order, so the results do not depend on the thread count.
 * Nor on the number of processes sharing the lines (an MPI job): each casts
 * a fixed run of every round's lines, the exchange gives every process all
 * of them, and each then adds them up and chooses the next round's cells
 * exactly as one process alone would, so all take the same steps.
 */
#ifndef SPANCAST_API_QUAD_H
#define SPANCAST_API_QUAD_H

#include <signal.h>
#include <stddef.h>
#include <stdint.h>

#include "csg/csg.h"
#include "spancast/spancast.h"

/* The values of the line through (u, v) into values[0..nvalues), and the
 * line's signature: a hash of which surfaces bound its spans (leaf, part,
 * flip of each end, and their number), equal for two lines exactly when
 * they cross the same surfaces in the same order (up to hash collisions);
 * thread is the OpenMP thread number (for per-thread scratch). Returns 0
 * on failure (out of memory, an unbounded solid), which stops the
 * integration. */
typedef int (*quad_sample_fn)(void *context, int thread, double u, double v,
                              double *values, uint64_t *signature);

/* Mixes one more number into a signature (for samplers). */
static inline uint64_t quad_mix(uint64_t h, uint64_t x)
{
    h ^= x + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
    return h * 0xff51afd7ed558ccdULL;
}

typedef struct quad_cell {
    double u, v;    /* centre */
    double hu, hv;  /* half sizes */
    uint32_t i, j;  /* position among the cells of its level */
    uint32_t level; /* 0: a cell of the first grid; each split adds 1 */
} quad_cell;

#define QUAD_MAX_LEVEL 17 /* splits of a first cell; i and j stay below 2^29 */

typedef struct quad_grid {
    int nvalues;
    quad_sample_fn sample;
    void *context;
    int threads;
    double min_half;     /* cells smaller than this are not split */
    uint32_t n0, n1;     /* cells of the first grid along u and v */
    quad_cell *cells;    /* leaves of the refinement */
    double *estimate;    /* nvalues per cell: the integral over the cell */
    double *error;       /* nvalues per cell: its error estimate (>= 0) */
    double *jump;        /* nvalues per cell: the bound from neighbours that
                            cross other surfaces (see above) */
    double support[4];   /* lo0, lo1, hi0, hi1: the integrand is 0 outside
                            (infinite: no bound); see quad_integrate3 */
    uint64_t *signature; /* per cell: its five lines' signature when they
                            agree, 0 when they do not */
    size_t count, cap;   /* cells */
    double *total;       /* nvalues: the sums of estimate, then error, over the */
    double *total_error; /* cells, in cell order */
    uint64_t lines;      /* lines sampled so far */
    int failed;          /* the sampler failed (sample_status says why) */
    /* SC_ERR_LIMIT from a line's implicit work (base/cancel.h): the reason
     * and the leaf and primitive that passed it */
    int limit_reason;
    uint32_t limit_leaf;
    const void *limit_prim; /* NULL when another process passed it */
    int limit_remote;       /* another process sharing the lines passed it */
    /* the processes sharing the lines (sc_measure_options.parts), NULL when
     * this one casts them all */
    const sc_measure_options *share;
} quad_grid;

/* When one of the three grids of an integral ended on a limit of
 * implicit work (limit_reason), fills error with render_limit_error at
 * its leaf, which is one of ta's or of tb's (tb may be NULL), and returns
 * 1; otherwise returns 0 and leaves error alone. */
int quad_limit_error(const quad_grid grids[3], const csg_tree *ta, const csg_tree *tb,
                     sc_error *error);

/* Starts the integration over [lo0, hi0] x [lo1, hi1] with about base
 * cells of nearly square shape (at least 4 a side) and samples them;
 * support (lo0, lo1, hi0, hi1; NULL: none) bounds where the integrand may
 * be other than 0, and a cell reaching past it counts only its part
 * within; share
 * (may be NULL) says which processes share the lines, and must outlive g.
 * Returns SC_OK, SC_ERR_NOMEM, SC_ERR_CANCELLED (cancel set) or
 * SC_ERR_ARGUMENT when the sampler failed; free with quad_free in every
 * case. */
sc_status quad_init(quad_grid *g, const double lo[2], const double hi[2],
                    const double *support, int nvalues, size_t base,
                    quad_sample_fn sample, void *context, int threads,
                    const sc_measure_options *share, const volatile sig_atomic_t *cancel);

/* One round of refinement towards target[k] (the allowed total error of
 * value k; 0 leaves k out of the decision): the cells that together hold
 * half of the excess error are split in four. *done is set when every
 * target is met, or when nothing can be split any more (cells at min_half)
 * or max_lines would be passed; *met says whether the targets were met. */
sc_status quad_refine(quad_grid *g, const double *target, uint64_t max_lines, int *done,
                      int *met, const volatile sig_atomic_t *cancel);

void quad_free(quad_grid *g);

/* How quad_integrate3 sets the error target of a value from the first
 * estimates (tolerance times the magnitude):
 *   QUAD_FREE  not a target (the value follows the others' refinement);
 *   QUAD_EACH  each axis estimates the whole integral: its magnitude is the
 *              mean of the three axes' estimates;
 *   QUAD_SUM   the axes' estimates add up to the whole (area): a third of
 *              the sum's magnitude for each;
 *   QUAD_RELATIVE(j)  as QUAD_EACH, with the magnitude of value j (a
 *              difference of two volumes measured against their mean), or
 *              QUAD_SELF of its own magnitude when that is larger: a
 *              difference far above the tolerance needs no more than a few
 *              digits to say so. */
enum { QUAD_FREE, QUAD_EACH, QUAD_SUM };
#define QUAD_RELATIVE(j) (16 + (j))
#define QUAD_SELF 1e-2

/* Integrates along lines parallel to each axis a over the box's cross
 * section, coordinates (u, v) = (x[(a+1)%3], x[(a+2)%3]) as absolute
 * positions, with sample getting contexts[a]; rule[k] and floor[k] (the
 * smallest magnitude a target is made from) set the targets.
 *
 * widen, for an integral over two solids that must break ties alike (a
 * difference, an overlap), lays the grids on the box widened by margins
 * of 1.6 % to 2.7 % of its size on each side, a different fraction with
 * all the bits of a double on each side of each axis, with the box itself
 * as the support (quad_init). The lines of a grid on the box itself lie
 * on the planes through its corners and its edges' halves, quarters, and
 * so on: every face through opposite corners of the box holds lines of
 * every level (a chamfer at 45 degrees, two wedges that meet on the
 * diagonal). A line in a face is on the boundary of both solids, where
 * each breaks the tie its own way (an exact plane, a mesh's edge), so it
 * counted a difference or an overlap where there is none. On the widened
 * box the lines keep away from such planes: their positions are no small
 * fractions of the box, and the axes' spacings have no small ratio. The
 * cells that reach into the margins count only their part within the box,
 * where the solids are, so a face on the box costs no refinement. A
 * measure of one solid has no second way to break a tie and keeps the
 * box. Refines the
 * three grids in turn until their targets are met or options->max_lines is
 * spent, and reports progress. The grids belong to the caller (quad_free
 * each, also on failure). *converged says whether every target was met. */
sc_status quad_integrate3(const double lo[3], const double hi[3], int widen, int nvalues,
                          const int *rule, const double *floor, quad_sample_fn sample,
                          void *const contexts[3], const sc_measure_options *options,
                          quad_grid grids[3], int *converged);

/* Combines the three axes' estimates of value k (rule QUAD_EACH) into their
 * mean, with an error of the largest axis's own error estimate plus the
 * largest distance of an axis's estimate from the mean. */
sc_estimate quad_combine(const quad_grid grids[3], int k);

/* Combines the three axes' estimates of a value that lines along one axis
 * can miss where lines along another cannot (a volume of difference that
 * is a sheet parallel to one axis: it lies between that axis's lines, and
 * the other axes' lines cross it) into the largest, with an error of the
 * largest own error plus the spread of the three. */
sc_estimate quad_combine_largest(const quad_grid grids[3], int k);

#endif
