/* What the line integrals of the measures, overlaps and comparison share
 * (measure.c, overlap.c, compare.c): the line of a grid point along an
 * axis, and the signature of a span list that tells the integrator
 * (quad.h) whether two neighbouring lines cross the same surfaces. */
#ifndef SPANCAST_API_LINES_H
#define SPANCAST_API_LINES_H

#include <stdint.h>

#include "base/arena.h"
#include "csg/csg.h"
#include "csg/span.h"
#include "spancast/spancast.h"

/* The whole line *r along axis a through (u, v) (csg_axis_line at 0) and
 * the spans of the trees ta and tb along it (none for an empty tree), in
 * scratch, which is reset first; *eps is the larger of the two trees'
 * tolerances on the line. Returns 0 when out of memory. */
int lines_pair_spans(int a, double u, double v, const csg_tree *ta, const csg_tree *tb,
                     arena *scratch, csg_ray *r, span_list *sa, span_list *sb,
                     double *eps);

/* The context of one axis's line sampler (quad_integrate3): what the three
 * axes share, which is the query's own struct (measure_shared,
 * pair_shared, compare_shared), and the axis. */
typedef struct lines_axis {
    void *shared;
    int axis; /* 0, 1, 2: the lines run along x, y, z */
} lines_axis;

/* Points axes[a] at shared with axis a, and contexts[a] at axes[a]: the
 * three contexts quad_integrate3 hands the sampler. */
void lines_axes(lines_axis axes[3], void *shared, void *contexts[3]);

/* What each thread of a line integration owns, indexed by thread: a
 * scratch arena for its span lists and, when asked for, the box of the
 * span ends it has seen (lo xyz, hi xyz; empty at first). */
typedef struct lines_scratch {
    arena *arenas;
    double (*box)[6]; /* NULL unless asked for */
    int threads;
} lines_scratch;

/* Sets up s for threads threads, with boxes when with_box is set. Returns
 * 0 when memory ran out (s then holds nothing to free). */
int lines_scratch_init(lines_scratch *s, int threads, int with_box);

/* Frees what lines_scratch_init made. */
void lines_scratch_free(lines_scratch *s);

/* The union of the threads' boxes into seen (lo xyz, hi xyz), and of the
 * other processes' when several share the lines (options->parts); empty
 * (lo > hi) when none saw a span end. Returns 0 when the exchange with
 * the other processes failed. */
int lines_scratch_box(const lines_scratch *s, const sc_measure_options *options,
                      double seen[6]);

/* h mixed with the surfaces of the list's ends, in order. */
uint64_t lines_signature(uint64_t h, span_list s);

#endif
