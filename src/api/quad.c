/* Adaptive integration over parallel lines (quad.h).
 *
 * Each cell is sampled on five lines: its centre and the centres of its
 * four quarters. The cell's estimate is the midpoint rule on the quarters,
 * its error estimate the difference from the midpoint rule on the whole
 * cell. Splitting a cell makes its quarters cells of their own, each
 * sampled on five new lines (its centre is sampled again rather than kept:
 * a fifth more lines, a cell record half the size).
 */
#include "api/options.h"
#include "api/quad.h"

#include <float.h>
#include <math.h>
#include <omp.h>
#include <stdlib.h>
#include <string.h>

#include "base/cancel.h"
#include "base/error.h"
#include "render/render.h"

/* Room for count more cells. */
static int reserve(quad_grid *g, size_t more)
{
    if (g->count + more <= g->cap)
        return 1;
    size_t cap = g->cap ? g->cap : 1024;
    while (cap < g->count + more) {
        if (cap > SIZE_MAX / 2 / (sizeof(double) * (size_t)g->nvalues))
            return 0;
        cap *= 2;
    }
    quad_cell *cells = realloc(g->cells, cap * sizeof *cells);
    if (!cells)
        return 0;
    g->cells = cells;
    size_t values = cap * (size_t)g->nvalues;
    double *estimate = realloc(g->estimate, values * sizeof *estimate);
    if (!estimate)
        return 0;
    g->estimate = estimate;
    double *error = realloc(g->error, values * sizeof *error);
    if (!error)
        return 0;
    g->error = error;
    double *jump = realloc(g->jump, values * sizeof *jump);
    if (!jump)
        return 0;
    g->jump = jump;
    uint64_t *signature = realloc(g->signature, cap * sizeof *signature);
    if (!signature)
        return 0;
    g->signature = signature;
    g->cap = cap;
    return 1;
}

/* This process's outcome of a round, shared with the others when several
 * share the lines (sc_measure_options.share_lines); g's limit fields hold
 * the failing process's reason and leaf (the primitive only when it was
 * this process's). Returns the round's status, the same on every process. */
static sc_status round_outcome(quad_grid *g, int failed, cancel_token *token,
                               void *records, size_t size, size_t count)
{
    cancel_reason reason = cancel_check(token);
    sc_status st = SC_OK;
    if (reason == CANCEL_FLAG)
        st = SC_ERR_CANCELLED;
    else if (reason != CANCEL_NONE)
        st = SC_ERR_LIMIT;
    else if (failed)
        st = SC_ERR_ARGUMENT;
    int outcome[3] = {(int)st, (int)reason, 0};
    if (st == SC_ERR_LIMIT) {
        g->limit_leaf = atomic_load(&token->leaf);
        g->limit_prim = atomic_load(&token->prim);
        outcome[2] = (int)g->limit_leaf;
    }
    const sc_measure_options *share = g->share;
    if (share && !share->share_lines(share->share_user, records, size, count, outcome))
        return SC_ERR_NOMEM; /* the exchange failed: nothing more to be had */
    if (share && (outcome[0] != (int)st || outcome[1] != (int)reason ||
                  (st == SC_ERR_LIMIT && outcome[2] != (int)g->limit_leaf))) {
        /* another process failed first */
        st = (sc_status)outcome[0];
        g->limit_prim = NULL;
        g->limit_leaf = (uint32_t)outcome[2];
        g->limit_remote = 1;
    }
    if (st == SC_ERR_LIMIT)
        g->limit_reason = outcome[1];
    if (st == SC_ERR_ARGUMENT)
        g->failed = 1;
    return st;
}

/* The length of [c - h, c + h] within [lo, hi]. */
static double within(double c, double h, double lo, double hi)
{
    double a = fmax(c - h, lo), b = fmin(c + h, hi);
    return b > a ? b - a : 0;
}

/* The middle of [c - h, c + h] within [lo, hi]; c when they do not meet. */
static double middle_within(double c, double h, double lo, double hi)
{
    double a = fmax(c - h, lo), b = fmin(c + h, hi);
    return b > a ? (a + b) / 2 : c;
}

/* Whether the rectangle of centre (u, v) and half sizes hu, hv reaches
 * past the support (g->support). */
static int clipped(const quad_grid *g, double u, double v, double hu, double hv)
{
    return u - hu < g->support[0] || v - hv < g->support[1] || u + hu > g->support[2] ||
           v + hv > g->support[3];
}

/* The area of that rectangle within the support. */
static double support_area(const quad_grid *g, double u, double v, double hu, double hv)
{
    return within(u, hu, g->support[0], g->support[2]) *
           within(v, hv, g->support[1], g->support[3]);
}

/* The area of cell c that the integral covers: all of it, or its part
 * within the support. */
static double cell_area(const quad_grid *g, const quad_cell *c)
{
    return clipped(g, c->u, c->v, c->hu, c->hv)
               ? support_area(g, c->u, c->v, c->hu, c->hv)
               : 4 * c->hu * c->hv;
}

/* Samples the five lines of each of the n cells (which must be complete
 * but for estimate and error) and fills their estimate and error. With
 * several processes sharing the lines (g->share), this one casts its run
 * of them and the exchange brings the others'. */
static sc_status sample_cells(quad_grid *g, quad_cell *cells, double *estimate,
                              double *error, uint64_t *signature, size_t n,
                              const volatile sig_atomic_t *cancel)
{
    int k_count = g->nvalues;
    size_t lines = n * 5;
    /* One record a line: its values, then its signature (as a double's
     * bytes), so that a run of lines travels as one block. */
    size_t stride = (size_t)k_count + 1;
    double *records = malloc(lines * stride * sizeof *records);
    if (!records)
        return SC_ERR_NOMEM;
    int failed = 0;
    long long first = 0, end = (long long)lines;
    if (g->share) {
        uint64_t parts = (uint64_t)g->share->parts, part = (uint64_t)g->share->part;
        first = (long long)((uint64_t)lines * part / parts);
        end = (long long)((uint64_t)lines * (part + 1) / parts);
    }
    cancel_token token;
    cancel_init(&token, cancel, RENDER_MIN_IMPLICIT_EVALS);
#pragma omp parallel for schedule(dynamic, 64) num_threads(g->threads)
    for (long long line = first; line < end; line++) {
        int stop;
#pragma omp atomic read
        stop = failed;
        if (stop || cancel_check(&token))
            continue;
        const quad_cell *c = &cells[line / 5];
        int which = (int)(line % 5);
        double u = c->u, v = c->v, hu = c->hu, hv = c->hv;
        if (which) { /* the four quarters */
            u += (which & 1 ? 0.5 : -0.5) * c->hu;
            v += (which > 2 ? 0.5 : -0.5) * c->hv;
            hu /= 2;
            hv /= 2;
        }
        /* a rectangle past the support: the line through the middle of its
         * part within, which stands for that part alone */
        if (clipped(g, u, v, hu, hv)) {
            u = middle_within(u, hu, g->support[0], g->support[2]);
            v = middle_within(v, hv, g->support[1], g->support[3]);
        }
        cancel_scope scope;
        cancel_enter(&scope, &token);
        double *record = records + (size_t)line * stride;
        uint64_t sig = 0;
        int ok = g->sample(g->context, omp_get_thread_num(), u, v, record, &sig);
        memcpy(record + k_count, &sig, sizeof sig);
        cancel_leave(&scope);
        cancel_credit(&token, RENDER_IMPLICIT_EVALS_PER_RAY);
        if (!ok) {
#pragma omp atomic write
            failed = 1;
        }
    }
    g->lines += lines;
    sc_status st =
        round_outcome(g, failed, &token, records, stride * sizeof *records, lines);
    if (st) {
        free(records);
        return st;
    }
    for (size_t i = 0; i < n; i++) {
        const quad_cell *c = &cells[i];
        double area = 4 * c->hu * c->hv;
        /* A cell past the support (in the margins of a widened box) weighs
         * each line, drawn through the middle of its rectangle's part
         * within (above), by the area of that part: the integrand is 0
         * outside. */
        int clip = clipped(g, c->u, c->v, c->hu, c->hv);
        double quarter_area[5] = {0, area / 4, area / 4, area / 4, area / 4};
        if (clip) {
            area = support_area(g, c->u, c->v, c->hu, c->hv);
            for (int q = 1; q <= 4; q++)
                quarter_area[q] = support_area(g, c->u + (q & 1 ? 0.5 : -0.5) * c->hu,
                                               c->v + (q > 2 ? 0.5 : -0.5) * c->hv,
                                               c->hu / 2, c->hv / 2);
        }
        const double *centre = records + i * 5 * stride;
        for (int k = 0; k < k_count; k++) {
            double quarters = 0, fine = 0;
            for (int q = 1; q <= 4; q++) {
                quarters += centre[(size_t)q * stride + (size_t)k];
                fine += centre[(size_t)q * stride + (size_t)k] * quarter_area[q];
            }
            if (!clip)
                fine = quarters * area / 4;
            double coarse = centre[k] * area;
            estimate[i * (size_t)k_count + (size_t)k] = fine;
            error[i * (size_t)k_count + (size_t)k] = fabs(fine - coarse);
        }
        uint64_t s[5];
        for (int q = 0; q < 5; q++)
            memcpy(&s[q], centre + (size_t)q * stride + (size_t)k_count, sizeof s[q]);
        int same = s[0] == s[1] && s[0] == s[2] && s[0] == s[3] && s[0] == s[4];
        signature[i] = same ? s[0] | 1 : 0;
    }
    free(records);
    return SC_OK;
}

/* ---- neighbours ---- */

/* A hash table from a cell's (level, i, j) to its index among the leaves. */
typedef struct cell_map {
    uint64_t *keys; /* 0: empty (a real key has level + 1 in its top bits) */
    size_t *index;
    size_t mask;
} cell_map;

static uint64_t cell_key(uint32_t level, uint32_t i, uint32_t j)
{
    return ((uint64_t)(level + 1) << 58) | ((uint64_t)i << 29) | j;
}

static size_t cell_hash(uint64_t key)
{
    key ^= key >> 31;
    key *= 0x9e3779b97f4a7c15ULL;
    key ^= key >> 29;
    return (size_t)key;
}

static int map_build(cell_map *m, const quad_grid *g)
{
    size_t size = 16;
    while (size < g->count * 2)
        size *= 2;
    m->keys = calloc(size, sizeof *m->keys);
    m->index = malloc(size * sizeof *m->index);
    m->mask = size - 1;
    if (!m->keys || !m->index)
        return 0;
    for (size_t n = 0; n < g->count; n++) {
        const quad_cell *c = &g->cells[n];
        uint64_t key = cell_key(c->level, c->i, c->j);
        size_t h = cell_hash(key) & m->mask;
        while (m->keys[h])
            h = (h + 1) & m->mask;
        m->keys[h] = key;
        m->index[h] = n;
    }
    return 1;
}

/* The leaf holding cell (level, i, j) or a coarser cell containing it;
 * SIZE_MAX when the leaves there are finer. */
static size_t map_find(const cell_map *m, uint32_t level, uint32_t i, uint32_t j)
{
    for (uint32_t up = 0; up <= level; up++) {
        uint64_t key = cell_key(level - up, i >> up, j >> up);
        for (size_t h = cell_hash(key) & m->mask; m->keys[h]; h = (h + 1) & m->mask)
            if (m->keys[h] == key)
                return m->index[h];
    }
    return SIZE_MAX;
}

/* The cells' jump bounds (quad.h): for each pair of neighbours across an
 * edge whose signatures differ (or either is mixed), an eighth of each
 * one's area times the difference of their means. The jump lies in one of
 * the two half strips between their nearest lines, each a quarter of its
 * cell, so the pair's error is at most a quarter of a cell's area times
 * the jump; each of the two carries half of that. Neighbours finer than a
 * cell find it themselves; coarser ones are found through the map. */
static int find_jumps(quad_grid *g)
{
    int k_count = g->nvalues;
    size_t n = g->count * (size_t)k_count;
    for (size_t i = 0; i < n; i++)
        g->jump[i] = 0;
    cell_map m;
    if (!map_build(&m, g)) {
        free(m.keys);
        free(m.index);
        return 0;
    }
    static const int steps[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
    for (size_t i = 0; i < g->count; i++) {
        const quad_cell *c = &g->cells[i];
        uint64_t width = (uint64_t)g->n0 << c->level,
                 height = (uint64_t)g->n1 << c->level;
        for (int e = 0; e < 4; e++) {
            int64_t ni = (int64_t)c->i + steps[e][0], nj = (int64_t)c->j + steps[e][1];
            if (ni < 0 || nj < 0 || (uint64_t)ni >= width || (uint64_t)nj >= height)
                continue;
            size_t o = map_find(&m, c->level, (uint32_t)ni, (uint32_t)nj);
            if (o == SIZE_MAX || (g->signature[i] && g->signature[i] == g->signature[o]))
                continue;
            const quad_cell *d = &g->cells[o];
            double area_c = cell_area(g, c), area_d = cell_area(g, d);
            for (int k = 0; k < k_count; k++) {
                double mean_c =
                    area_c > 0 ? g->estimate[i * (size_t)k_count + (size_t)k] / area_c
                               : 0;
                double mean_d =
                    area_d > 0 ? g->estimate[o * (size_t)k_count + (size_t)k] / area_d
                               : 0;
                double step = fabs(mean_c - mean_d);
                double *ji = &g->jump[i * (size_t)k_count + (size_t)k];
                double *jo = &g->jump[o * (size_t)k_count + (size_t)k];
                *ji = fmax(*ji, area_c / 8 * step);
                *jo = fmax(*jo, area_d / 8 * step);
            }
        }
    }
    free(m.keys);
    free(m.index);
    return 1;
}

/* The error estimate of cell i for value k: its own, or its jump bound. */
static double cell_error(const quad_grid *g, size_t i, int k)
{
    size_t at = i * (size_t)g->nvalues + (size_t)k;
    return fmax(g->error[at], g->jump[at]);
}

/* Sums the cells' estimates and errors in cell order. The error also
 * holds the rounding of the sum and of the lines' own arithmetic: each
 * cell's estimate is off by a few units in the last place of the magnitudes
 * it was made from, and a sum of n terms by at most n units of the sum of
 * their magnitudes (Higham, recursive summation), so 8 + n units of that
 * sum bound both. Returns 0 on allocation failure. */
static int sum_cells(quad_grid *g)
{
    if (!find_jumps(g))
        return 0;
    int k_count = g->nvalues;
    for (int k = 0; k < k_count; k++) {
        double sum = 0, error = 0, magnitude = 0;
        for (size_t i = 0; i < g->count; i++) {
            double e = g->estimate[i * (size_t)k_count + (size_t)k];
            sum += e;
            magnitude += fabs(e);
            error += cell_error(g, i, k);
        }
        g->total[k] = sum;
        g->total_error[k] = error + (8.0 + (double)g->count) * DBL_EPSILON * magnitude;
    }
    return 1;
}

sc_status quad_init(quad_grid *g, const double lo[2], const double hi[2],
                    const double *support, int nvalues, size_t base,
                    quad_sample_fn sample, void *context, int threads,
                    const sc_measure_options *share, const volatile sig_atomic_t *cancel)
{
    memset(g, 0, sizeof *g);
    for (int i = 0; i < 4; i++)
        g->support[i] = support ? support[i] : i < 2 ? -INFINITY : INFINITY;
    g->share = share && share->parts > 1 && share->share_lines ? share : NULL;
    g->nvalues = nvalues;
    g->sample = sample;
    g->context = context;
    g->threads = threads > 0 ? threads : 1;
    double w0 = hi[0] - lo[0], w1 = hi[1] - lo[1];
    g->total = calloc((size_t)nvalues, sizeof *g->total);
    g->total_error = calloc((size_t)nvalues, sizeof *g->total_error);
    if (!g->total || !g->total_error)
        return SC_ERR_NOMEM;
    /* Nearly square cells, at least 4 a side. */
    double side = sqrt(w0 * w1 / (double)base);
    int n0 = side > 0 ? (int)ceil(w0 / side) : 4,
        n1 = side > 0 ? (int)ceil(w1 / side) : 4;
    n0 = n0 < 4 ? 4 : n0 > 4096 ? 4096 : n0;
    n1 = n1 < 4 ? 4 : n1 > 4096 ? 4096 : n1;
    g->min_half = 1e-9 * fmax(w0, w1);
    g->n0 = (uint32_t)n0;
    g->n1 = (uint32_t)n1;
    size_t n = (size_t)n0 * (size_t)n1;
    if (!reserve(g, n))
        return SC_ERR_NOMEM;
    for (int i = 0; i < n0; i++)
        for (int j = 0; j < n1; j++) {
            quad_cell *c = &g->cells[(size_t)i * (size_t)n1 + (size_t)j];
            c->hu = w0 / n0 / 2;
            c->hv = w1 / n1 / 2;
            c->u = lo[0] + (2 * i + 1) * c->hu;
            c->v = lo[1] + (2 * j + 1) * c->hv;
            c->i = (uint32_t)i;
            c->j = (uint32_t)j;
            c->level = 0;
        }
    sc_status st =
        sample_cells(g, g->cells, g->estimate, g->error, g->signature, n, cancel);
    if (st)
        return st;
    g->count = n;
    return sum_cells(g) ? SC_OK : SC_ERR_NOMEM;
}

/* Order of cells by descending weight, ties by position in the array. */
typedef struct ranked {
    double weight;
    size_t index;
} ranked;

static int by_weight(const void *a, const void *b)
{
    const ranked *x = a, *y = b;
    if (x->weight != y->weight)
        return x->weight > y->weight ? -1 : 1;
    return x->index < y->index ? -1 : x->index > y->index;
}

/* Adds to the marked cells (split[0..*count), mark[] set) every cell that
 * must split with them to keep the balance. Returns 0 on allocation
 * failure. */
static int balance(const quad_grid *g, size_t **split, size_t *count, unsigned char *mark)
{
    cell_map m;
    if (!map_build(&m, g)) {
        free(m.keys);
        free(m.index);
        return 0;
    }
    size_t cap = *count > 16 ? *count : 16;
    size_t *list = realloc(*split, cap * sizeof *list);
    int ok = list != NULL;
    for (size_t w = 0; ok && w < *count; w++) {
        const quad_cell *c = &g->cells[list[w]];
        uint64_t width = (uint64_t)g->n0 << c->level,
                 height = (uint64_t)g->n1 << c->level;
        for (int di = -1; ok && di <= 1; di++)
            for (int dj = -1; ok && dj <= 1; dj++) {
                int64_t ni = (int64_t)c->i + di, nj = (int64_t)c->j + dj;
                if ((!di && !dj) || ni < 0 || nj < 0 || (uint64_t)ni >= width ||
                    (uint64_t)nj >= height)
                    continue;
                size_t n = map_find(&m, c->level, (uint32_t)ni, (uint32_t)nj);
                if (n == SIZE_MAX || mark[n] || g->cells[n].level >= c->level)
                    continue;
                if (*count == cap) {
                    size_t *p = realloc(list, cap * 2 * sizeof *p);
                    if (!p) {
                        ok = 0;
                        break;
                    }
                    list = p;
                    cap *= 2;
                }
                mark[n] = 1;
                list[(*count)++] = n;
            }
    }
    if (list)
        *split = list;
    free(m.keys);
    free(m.index);
    return ok;
}

static int by_index(const void *a, const void *b)
{
    size_t x = *(const size_t *)a, y = *(const size_t *)b;
    return x < y ? -1 : x > y;
}

sc_status quad_refine(quad_grid *g, const double *target, uint64_t max_lines, int *done,
                      int *met, const volatile sig_atomic_t *cancel)
{
    int k_count = g->nvalues;
    *done = 0;
    *met = 1;
    for (int k = 0; k < k_count; k++)
        if (target[k] > 0 && g->total_error[k] > target[k])
            *met = 0;
    if (*met) {
        *done = 1;
        return SC_OK;
    }
    /* A cell's weight: its errors relative to the targets that are not met. */
    ranked *order = malloc(g->count * sizeof *order);
    unsigned char *mark = calloc(g->count, 1);
    size_t *split = NULL;
    if (!order || !mark) {
        free(order);
        free(mark);
        return SC_ERR_NOMEM;
    }
    double sum = 0;
    size_t splittable = 0;
    for (size_t i = 0; i < g->count; i++) {
        double w = 0;
        const quad_cell *c = &g->cells[i];
        if (c->hu > g->min_half && c->hv > g->min_half && c->level < QUAD_MAX_LEVEL)
            for (int k = 0; k < k_count; k++)
                if (target[k] > 0 && g->total_error[k] > target[k])
                    w += cell_error(g, i, k) / target[k];
        order[splittable].weight = w;
        order[splittable].index = i;
        splittable += w > 0;
        sum += w;
    }
    /* The cells with the most error first: the ones that hold half of it. */
    qsort(order, splittable, sizeof *order, by_weight);
    size_t count = 0;
    double taken = 0;
    while (count < splittable && (count == 0 || taken < sum / 2)) {
        taken += order[count].weight;
        count++;
    }
    if (count)
        split = malloc(count * sizeof *split);
    if (count && !split) {
        free(order);
        free(mark);
        return SC_ERR_NOMEM;
    }
    for (size_t s = 0; s < count; s++) {
        split[s] = order[s].index;
        mark[split[s]] = 1;
    }
    free(order);
    if (count && !balance(g, &split, &count, mark)) {
        free(split);
        free(mark);
        return SC_ERR_NOMEM;
    }
    free(mark);
    if (!count || g->lines + (uint64_t)count * 20 > max_lines) {
        free(split);
        *done = 1;
        return SC_OK;
    }
    /* In array order, so that the new cells' order depends on the choice only. */
    qsort(split, count, sizeof *split, by_index);
    if (!reserve(g, count * 3)) {
        free(split);
        return SC_ERR_NOMEM;
    }
    /* Each split cell becomes its first quarter in place and appends the
     * other three. */
    size_t n = count * 4;
    quad_cell *fresh = malloc(n * sizeof *fresh);
    double *estimate = malloc(n * (size_t)k_count * sizeof *estimate);
    double *error = malloc(n * (size_t)k_count * sizeof *error);
    uint64_t *signature = malloc(n * sizeof *signature);
    if (!fresh || !estimate || !error || !signature) {
        free(fresh);
        free(estimate);
        free(error);
        free(signature);
        free(split);
        return SC_ERR_NOMEM;
    }
    for (size_t s = 0; s < count; s++) {
        const quad_cell *c = &g->cells[split[s]];
        for (int q = 0; q < 4; q++) {
            quad_cell *f = &fresh[s * 4 + (size_t)q];
            f->hu = c->hu / 2;
            f->hv = c->hv / 2;
            f->u = c->u + (q & 1 ? f->hu : -f->hu);
            f->v = c->v + (q & 2 ? f->hv : -f->hv);
            f->i = c->i * 2 + (q & 1 ? 1 : 0);
            f->j = c->j * 2 + (q & 2 ? 1 : 0);
            f->level = c->level + 1;
        }
    }
    sc_status st = sample_cells(g, fresh, estimate, error, signature, n, cancel);
    if (st == SC_OK) {
        size_t values = (size_t)k_count * sizeof(double);
        for (size_t s = 0; s < count; s++)
            for (int q = 0; q < 4; q++) {
                size_t to = q == 0 ? split[s] : g->count++;
                size_t from = s * 4 + (size_t)q;
                g->cells[to] = fresh[from];
                memcpy(g->estimate + to * (size_t)k_count,
                       estimate + from * (size_t)k_count, values);
                memcpy(g->error + to * (size_t)k_count, error + from * (size_t)k_count,
                       values);
                g->signature[to] = signature[from];
            }
        if (!sum_cells(g))
            st = SC_ERR_NOMEM;
    }
    free(signature);
    free(fresh);
    free(estimate);
    free(error);
    free(split);
    return st;
}

void quad_free(quad_grid *g)
{
    free(g->cells);
    free(g->estimate);
    free(g->error);
    free(g->jump);
    free(g->signature);
    free(g->total);
    free(g->total_error);
    memset(g, 0, sizeof *g);
}

/* The magnitude a target is made from: the mean of three whole estimates
 * (QUAD_EACH) and a third of three parts (QUAD_SUM) are the same number. */
static double magnitude(const quad_grid grids[3], int k)
{
    return fabs(grids[0].total[k] + grids[1].total[k] + grids[2].total[k]) / 3;
}

/* Widens the box lo..hi in place by margins of 1.6 % to 2.7 % of its size
 * on each side, a different fraction with all the bits of a double on
 * each side of each axis (quad_integrate3's widen says why). */
static void widen_box(double lo[3], double hi[3])
{
    static const double below[3] = {0.0213599377, 0.0179442718, 0.0247108021};
    static const double above[3] = {0.0158312973, 0.0271866549, 0.0193390875};
    for (int i = 0; i < 3; i++) {
        double w = hi[i] - lo[i];
        lo[i] -= below[i] * w;
        hi[i] += above[i] * w;
    }
}

sc_status quad_integrate3(const double lo[3], const double hi[3], int widen, int nvalues,
                          const int *rule, const double *floor, quad_sample_fn sample,
                          void *const contexts[3], const sc_measure_options *options,
                          quad_grid grids[3], int *converged)
{
    for (int a = 0; a < 3; a++)
        memset(&grids[a], 0, sizeof grids[a]);
    *converged = 0;
    int threads = options_thread_count(options->threads);
    double wlo[3] = {lo[0], lo[1], lo[2]}, whi[3] = {hi[0], hi[1], hi[2]};
    if (widen)
        widen_box(wlo, whi);
    sc_status st = SC_OK;
    for (int a = 0; a < 3 && !st; a++) {
        int u = (a + 1) % 3, v = (a + 2) % 3;
        double rlo[2] = {wlo[u], wlo[v]}, rhi[2] = {whi[u], whi[v]};
        double support[4] = {lo[u], lo[v], hi[u], hi[v]};
        st = quad_init(&grids[a], rlo, rhi, widen ? support : NULL, nvalues, 4096, sample,
                       contexts[a], threads, options, options->cancel);
    }
    if (st)
        return st;
    double *target = calloc((size_t)nvalues, sizeof *target);
    if (!target)
        return SC_ERR_NOMEM;
    for (int k = 0; k < nvalues; k++)
        if (rule[k] != QUAD_FREE)
            target[k] = rule[k] >= 16
                            ? fmax(options->tolerance *
                                       fmax(magnitude(grids, rule[k] - 16), floor[k]),
                                   QUAD_SELF * magnitude(grids, k))
                            : options->tolerance * fmax(magnitude(grids, k), floor[k]);
    /* Progress: how far the worst error ratio has come down, on a log scale. */
    double first = 0;
    int done[3] = {0, 0, 0}, met[3] = {0, 0, 0};
    for (int round = 0; !st; round++) {
        double worst = 1;
        for (int a = 0; a < 3; a++)
            for (int k = 0; k < nvalues; k++)
                if (target[k] > 0 && !done[a])
                    worst = fmax(worst, grids[a].total_error[k] / target[k]);
        if (round == 0)
            first = worst;
        if (options->progress && first > 1)
            options->progress(options->progress_user,
                              fmin(0.99, log(first / worst) / log(first)));
        if (done[0] && done[1] && done[2])
            break;
        for (int a = 0; a < 3 && !st; a++)
            if (!done[a])
                st = quad_refine(&grids[a], target, options->max_lines, &done[a], &met[a],
                                 options->cancel);
    }
    free(target);
    if (st)
        return st;
    if (options->progress)
        options->progress(options->progress_user, 1);
    *converged = met[0] && met[1] && met[2];
    return SC_OK;
}

sc_estimate quad_combine(const quad_grid grids[3], int k)
{
    sc_estimate e;
    e.value = (grids[0].total[k] + grids[1].total[k] + grids[2].total[k]) / 3;
    double own = 0, spread = 0;
    for (int a = 0; a < 3; a++) {
        own = fmax(own, grids[a].total_error[k]);
        spread = fmax(spread, fabs(grids[a].total[k] - e.value));
    }
    e.error = own + spread;
    return e;
}

sc_estimate quad_combine_largest(const quad_grid grids[3], int k)
{
    sc_estimate e;
    double lo = grids[0].total[k], hi = lo, own = 0;
    for (int a = 0; a < 3; a++) {
        lo = fmin(lo, grids[a].total[k]);
        hi = fmax(hi, grids[a].total[k]);
        own = fmax(own, grids[a].total_error[k]);
    }
    e.value = hi;
    e.error = own + (hi - lo);
    return e;
}

int quad_limit_error(const quad_grid grids[3], const csg_tree *ta, const csg_tree *tb,
                     sc_error *error)
{
    for (int g = 0; g < 3; g++) {
        const quad_grid *q = &grids[g];
        if (!q->limit_reason)
            continue;
        /* Passed in another process (q->limit_remote), the leaf's primitive is
         * known only by its index: of the one tree measured, for the
         * position; of one of two compared trees, not known, so the message
         * then has no position. */
        const void *prim = q->limit_prim;
        if (q->limit_remote && !tb && q->limit_leaf < ta->leaf_count)
            prim = &ta->leaves[q->limit_leaf].prim;
        int in_b = tb && prim && q->limit_leaf < tb->leaf_count &&
                   &tb->leaves[q->limit_leaf].prim == prim;
        render_limit_error(in_b ? tb : ta, q->limit_reason, q->limit_leaf, prim, error);
        return 1;
    }
    return 0;
}
