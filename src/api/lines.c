/* The shared pieces of the line integrals: see lines.h. */
#include "api/lines.h"

#include <math.h>
#include <stdlib.h>

#include "api/quad.h"

int lines_pair_spans(int a, double u, double v, const csg_tree *ta, const csg_tree *tb,
                     arena *scratch, csg_ray *r, span_list *sa, span_list *sb,
                     double *eps)
{
    *r = csg_axis_line(a, 0, u, v);
    arena_reset(scratch);
    if (!csg_spans(ta, r, scratch, sa) || !csg_spans(tb, r, scratch, sb))
        return 0;
    *eps = fmax(csg_eps(ta, r->o, r->d), csg_eps(tb, r->o, r->d));
    return 1;
}

uint64_t lines_signature(uint64_t h, span_list s)
{
    h = quad_mix(h, s.n);
    for (uint32_t k = 0; k < s.n; k++) {
        const span_end *ends[2] = {&s.v[k].in, &s.v[k].out};
        for (int e = 0; e < 2; e++)
            h = quad_mix(h, ((uint64_t)ends[e]->leaf << 24) |
                                ((uint64_t)ends[e]->part << 8) | ends[e]->flip);
    }
    return h;
}

void lines_axes(lines_axis axes[3], void *shared, void *contexts[3])
{
    for (int a = 0; a < 3; a++) {
        axes[a].shared = shared;
        axes[a].axis = a;
        contexts[a] = &axes[a];
    }
}

int lines_scratch_init(lines_scratch *s, int threads, int with_box)
{
    s->threads = threads;
    s->arenas = calloc((size_t)threads, sizeof *s->arenas);
    s->box = with_box ? malloc((size_t)threads * sizeof *s->box) : NULL;
    if (!s->arenas || (with_box && !s->box)) {
        free(s->arenas);
        free(s->box);
        return 0;
    }
    for (int k = 0; k < threads; k++) {
        arena_init(&s->arenas[k], 16 * 1024);
        for (int i = 0; with_box && i < 3; i++) {
            s->box[k][i] = INFINITY;
            s->box[k][3 + i] = -INFINITY;
        }
    }
    return 1;
}

void lines_scratch_free(lines_scratch *s)
{
    for (int k = 0; k < s->threads; k++)
        arena_free(&s->arenas[k]);
    free(s->arenas);
    free(s->box);
}

int lines_scratch_box(const lines_scratch *s, const sc_measure_options *options,
                      double seen[6])
{
    for (int i = 0; i < 3; i++) {
        seen[i] = INFINITY;
        seen[3 + i] = -INFINITY;
    }
    for (int k = 0; k < s->threads; k++)
        for (int i = 0; i < 3; i++) {
            seen[i] = fmin(seen[i], s->box[k][i]);
            seen[3 + i] = fmax(seen[3 + i], s->box[k][3 + i]);
        }
    if (options->parts > 1 && options->share_box)
        return options->share_box(options->share_user, seen);
    return 1;
}
