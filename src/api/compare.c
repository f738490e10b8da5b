/* Comparing two solids (sc_scene_compare), and loading a mesh file as a
 * solid to compare against (sc_scene_load_mesh).
 *
 * The volumes of A, B, A minus B and B minus A are integrated over the box
 * holding both, like the measures (quad.h): along each line both span
 * lists come from their own trees and the differences from the boolean
 * sweep with its regularisation (span.h), so each line's part is exact and
 * slivers thinner than the scene tolerance (coincident faces) count as
 * nothing. Each axis counts its share of each part of a difference
 * (part_weighted), which lets a sheet thinner than the lines' spacing count
 * once, on the axes whose lines cross it, and the three shares add up to
 * the difference. The differences are refined until their errors are within
 * the tolerance times the mean of the two volumes (at most the larger one),
 * which is what a regression check asks: "is the change smaller than this
 * part of the model". Identical solids give zero on every line, and stop
 * at the first grid.
 *
 * A mesh is loaded as the one-line model import(file = "PATH"), so it is
 * read, checked and cast exactly as an import in a model is (meshes.md);
 * the model is named by the path as given, and its errors and warnings
 * are put on that file (a position in the one-line model would point
 * into the mesh at a place that says nothing).
 */
#define _XOPEN_SOURCE 700

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "api/lines.h"
#include "build/build_mesh.h"
#include "api/mesh_model.h"
#include "api/quad.h"
#include "base/arena.h"
#include "api/options.h"
#include "base/error.h"
#include "base/sized.h"
#include "build/scene.h"
#include "csg/csg.h"
#include "csg/span.h"
#include "render/render.h"

int mesh_model_is_mesh(const char *path)
{
    size_t n = strlen(path);
    if (n < 5 || path[n - 4] != '.')
        return 0;
    char ext[4];
    for (int i = 0; i < 3; i++)
        ext[i] = (char)(path[n - 3 + i] | 32);
    ext[3] = '\0';
    return strcmp(ext, "stl") == 0 || strcmp(ext, "off") == 0 ||
           strcmp(ext, "amf") == 0 || strcmp(ext, "3mf") == 0;
}

sc_status mesh_model_text(const char *path, char **text, size_t *length, sc_error *error)
{
    *text = NULL;
    *length = 0;
    char *full = realpath(path, NULL);
    if (!full)
        return err_set(error, SC_ERR_IO, NULL, "cannot open '%s': %s", path,
                       strerror(errno));
    size_t n = strlen(full);
    char *t = n < SIZE_MAX / 2 - 32 ? malloc(n * 2 + 32) : NULL;
    if (!t) {
        free(full);
        return err_nomem(error, NULL);
    }
    size_t k = (size_t)sprintf(t, "import(file = \"");
    for (size_t i = 0; i < n; i++) {
        if (full[i] == '"' || full[i] == '\\')
            t[k++] = '\\';
        t[k++] = full[i];
    }
    k += (size_t)sprintf(t + k, "\");\n");
    free(full);
    *text = t;
    *length = k;
    return SC_OK;
}

void mesh_model_unplace(sc_error *e, const char *path)
{
    if (e->line == 1 && strcmp(e->file, path) == 0)
        e->line = e->column = 0;
}

sc_status sc_scene_load_mesh(const char *path, const sc_load_options *options,
                             sc_scene **scene, sc_error *error)
{
    err_clear(error);
    *scene = NULL;
    if (!path)
        return err_set(error, SC_ERR_ARGUMENT, NULL, "no file name");
    char *text;
    size_t k;
    sc_status st = mesh_model_text(path, &text, &k, error);
    if (st != SC_OK)
        return st;
    st = mesh_model_load(path, text, k, options, scene, error);
    free(text);
    if (st != SC_OK)
        mesh_model_unplace(error, path);
    for (size_t i = 0; *scene && i < (*scene)->warning_count; i++)
        mesh_model_unplace(&(*scene)->warnings[i], path);
    return st;
}

/* The values of a line: the lengths of A and B, the weighted lengths of
 * A - B and B - A (part_weighted), and the mean of A and B and a third of it,
 * which the differences' targets are made from (the three axes' weighted
 * parts add up to each difference). */
enum { C_A, C_B, C_ONLY_A, C_ONLY_B, C_MEAN, C_THIRD, C_VALUES };

typedef struct compare_shared {
    const csg_tree *a, *b;
    lines_scratch work; /* per thread: the span lists */
    double width;       /* part_weighted's scale: a 128th of the box's largest side */
} compare_shared;

/* The chord through p along axis b of the part of a difference (A - B
 * when a_first, else B - A) that holds p, up to 4 width (4 width for a
 * longer one: it is cast over 4 width on each side of p, which holds every
 * shorter chord through p); 0 when p is in no part (a tie broken the other
 * way on this line). Memory from scratch, given back. */
static double part_chord(const compare_shared *s, int b, vec3 p, int a_first,
                         arena *scratch, int *oom)
{
    csg_ray r = csg_axis_line(b, 0, 0, 0);
    r.o = p;
    r.tmin = -4 * s->width;
    r.tmax = 4 * s->width;
    arena_mark mark = arena_save(scratch);
    span_list sa, sb;
    double chord = 0;
    if (!csg_spans(s->a, &r, scratch, &sa) || !csg_spans(s->b, &r, scratch, &sb)) {
        *oom = 1;
    } else {
        double eps = fmax(csg_eps(s->a, r.o, r.d), csg_eps(s->b, r.o, r.d));
        span_list d = a_first ? span_combine(SPAN_DIFFERENCE, sa, sb, eps, scratch, oom)
                              : span_combine(SPAN_DIFFERENCE, sb, sa, eps, scratch, oom);
        for (uint32_t k = 0; k < d.n; k++)
            if (d.v[k].in.t <= 0 && d.v[k].out.t >= 0)
                chord = d.v[k].in.t <= r.tmin || d.v[k].out.t >= r.tmax
                            ? r.tmax
                            : fmin(d.v[k].out.t - d.v[k].in.t, r.tmax);
    }
    arena_restore(scratch, mark);
    return chord;
}

/* Axis a's share at p of the part of a difference (a_first: A - B) that
 * holds p, whose chord along a through p is la (part_weighted). */
static double part_share(const compare_shared *s, int a, vec3 p, double la, int a_first,
                         arena *scratch, int *oom)
{
    double inverse[3], total = 0;
    for (int c = 0; c < 3; c++) {
        double l = c == a ? la : part_chord(s, c, p, a_first, scratch, oom);
        /* none: p is in no part along c (a tie broken the other way),
         * which says nothing of its shape */
        l = l > 0 ? fmin(l, 4 * s->width) : 4 * s->width;
        inverse[c] = 1 / (l * l) + 1 / (s->width * s->width);
        total += inverse[c];
    }
    return inverse[a] / total;
}

/* The length of the difference d (a_first: A - B) on the line r along
 * axis a, each point weighted by the share of it that lines along a count.
 *
 * Every axis's lines estimate the whole volume of a part that is wide
 * every way; but a part thinner than the lines' spacing, most often a
 * sheet (a face moved by less than it), is crossed by the lines of an axis
 * only as far as the sheet faces that axis, and a sheet parallel to an
 * axis lies between its lines. A sheet of thickness t with unit normal n
 * is crossed by the lines along c over a length t / |n_c|, and lines along
 * c counting a share n_c^2 of it count it once in all (the shares add up
 * to |n|^2 = 1). So each point p of a part is shared among the axes by
 * the part's chords l_c through p along each axis c (the span itself along
 * a, part_chord along the other two): axis c's share is w_c / sum w_k,
 * with w_c = 1 / l_c^2 + 1 / width^2. A sheet much thinner than width gets
 * n_c^2; a part much wider than width, a third on each axis (the mean of
 * the three estimates); a rod, half on each axis across it; a speck, a
 * third each. The shares add up to 1 at every point, so the three axes'
 * estimates add up to the difference whatever the shape.
 *
 * Each axis's lines must still integrate their own share well. It varies
 * along a span where the part's other chords do (a lump, a wedge: they are
 * longest through its middle), so each span is integrated at the three
 * Gauss-Legendre points; the share taken at the middle and applied to the
 * whole span counts a sphere 23 % high. The width term keeps the share
 * smooth where a chord reaches the probes' cap (a hard cap at 2/64 of the
 * box put a kink there, and a sphere 2 % high). A span shorter than
 * width / 32 is a sheet crossed, with the same chords all along it, and
 * its middle is enough: that is most spans where a model is compared with
 * its own export. */
static double part_weighted(const compare_shared *s, int a, const csg_ray *r, span_list d,
                            int a_first, arena *scratch, int *oom)
{
    static const double node = 0.7745966692414834; /* sqrt(3 / 5) */
    double length = 0;
    for (uint32_t k = 0; k < d.n && !*oom; k++) {
        double in = d.v[k].in.t, out = d.v[k].out.t, mid = 0.5 * (in + out);
        double half = 0.5 * (out - in);
        double share =
            part_share(s, a, v3_madd(r->o, r->d, mid), out - in, a_first, scratch, oom);
        if (out - in <= s->width / 32) {
            length += (out - in) * share;
            continue;
        }
        double sum = 8.0 / 9.0 * share;
        for (int side = -1; side <= 1; side += 2)
            sum += 5.0 / 9.0 *
                   part_share(s, a, v3_madd(r->o, r->d, mid + side * node * half),
                              out - in, a_first, scratch, oom);
        length += half * sum;
    }
    return length;
}

static double length_of(span_list s)
{
    double length = 0;
    for (uint32_t k = 0; k < s.n; k++)
        length += s.v[k].out.t - s.v[k].in.t;
    return length;
}

static int sample_compare(void *context, int thread, double u, double v, double *values,
                          uint64_t *signature)
{
    const lines_axis *m = context;
    const compare_shared *s = m->shared;
    arena *scratch = &s->work.arenas[thread];
    csg_ray r;
    span_list sa, sb;
    double eps;
    if (!lines_pair_spans(m->axis, u, v, s->a, s->b, scratch, &r, &sa, &sb, &eps))
        return 0;
    int oom = 0;
    span_list only_a = span_combine(SPAN_DIFFERENCE, sa, sb, eps, scratch, &oom);
    span_list only_b = span_combine(SPAN_DIFFERENCE, sb, sa, eps, scratch, &oom);
    if (oom)
        return 0;
    *signature = lines_signature(lines_signature(0, sa), sb);
    values[C_A] = length_of(sa);
    values[C_B] = length_of(sb);
    values[C_ONLY_A] = part_weighted(s, m->axis, &r, only_a, 1, scratch, &oom);
    values[C_ONLY_B] = part_weighted(s, m->axis, &r, only_b, 0, scratch, &oom);
    if (oom)
        return 0;
    values[C_MEAN] = (values[C_A] + values[C_B]) / 2;
    values[C_THIRD] = values[C_MEAN] / 3;
    for (int k = 0; k < C_VALUES; k++)
        if (!isfinite(values[k]))
            return 0; /* unbounded */
    return 1;
}

/* sc_scene_compare with the library's own options and result structs. */
static sc_status compare_scenes(const sc_scene *a, const sc_scene *b,
                                const sc_measure_options *options, sc_comparison *out,
                                sc_error *error)
{
    err_clear(error);
    if (!a || !b || !options || !out)
        return err_set(error, SC_ERR_ARGUMENT, NULL, "no scenes, options or result");
    memset(out, 0, sizeof *out);
    out->converged = 1; /* nothing to integrate: nothing falls short */
    if (!(options->tolerance > 0 && options->tolerance < 1))
        return err_set(error, SC_ERR_ARGUMENT, NULL,
                       "tolerance must lie between 0 and 1 (got %g)", options->tolerance);
    const csg_tree *ta = scene_tree(a), *tb = scene_tree(b);
    bbox box = bbox_empty();
    if (ta->root != CSG_EMPTY)
        box = bbox_union(box, ta->bounds);
    if (tb->root != CSG_EMPTY)
        box = bbox_union(box, tb->bounds);
    if (bbox_is_empty(&box))
        return SC_OK;
    double lo[3] = {box.lo.x, box.lo.y, box.lo.z}, hi[3] = {box.hi.x, box.hi.y, box.hi.z};
    for (int i = 0; i < 3; i++) {
        if (!isfinite(lo[i]) || !isfinite(hi[i]))
            return err_set(error, SC_ERR_ARGUMENT, NULL,
                           "a solid is unbounded: it has no volume to compare");
        if (!(hi[i] > lo[i]))
            return SC_OK;
    }
    int threads = options_thread_count(options->threads);
    compare_shared shared = {ta, tb, {0}, 0};
    shared.width = fmax(hi[0] - lo[0], fmax(hi[1] - lo[1], hi[2] - lo[2])) / 128;
    if (!lines_scratch_init(&shared.work, threads, 0))
        return err_nomem(error, NULL);
    lines_axis axes[3];
    void *contexts[3];
    lines_axes(axes, &shared, contexts);
    /* The differences are refined against the mean of the two volumes,
     * which is at most the larger one (and is it when they agree); the
     * volumes themselves are only reported. */
    int rule[C_VALUES] = {
        QUAD_FREE, QUAD_FREE, QUAD_RELATIVE(C_THIRD), QUAD_RELATIVE(C_THIRD),
        QUAD_FREE, QUAD_FREE};
    double floor[C_VALUES] = {0, 0, 0, 0, 0, 0};
    quad_grid grids[3];
    int converged = 0;
    sc_measure_options o = *options;
    o.threads = threads;
    sc_status st = quad_integrate3(lo, hi, 1, C_VALUES, rule, floor, sample_compare,
                                   contexts, &o, grids, &converged);
    if (st == SC_OK) {
        out->volume_a = quad_combine(grids, C_A);
        out->volume_b = quad_combine(grids, C_B);
        /* each axis's share of the differences (part_weighted) */
        out->only_a = quad_combine_sum(grids, C_ONLY_A);
        out->only_b = quad_combine_sum(grids, C_ONLY_B);
        out->difference.value = out->only_a.value + out->only_b.value;
        out->difference.error = out->only_a.error + out->only_b.error;
        out->lines = grids[0].lines + grids[1].lines + grids[2].lines;
        out->converged = converged;
    }
    int failed = grids[0].failed || grids[1].failed || grids[2].failed;
    int limited = st == SC_ERR_LIMIT && quad_limit_error(grids, ta, tb, error);
    for (int g = 0; g < 3; g++)
        quad_free(&grids[g]);
    lines_scratch_free(&shared.work);
    if (st == SC_ERR_CANCELLED)
        return err_set(error, SC_ERR_CANCELLED, NULL, "comparison cancelled");
    if (limited)
        return SC_ERR_LIMIT;
    if (st == SC_ERR_ARGUMENT && failed)
        return err_set(error, SC_ERR_ARGUMENT, NULL,
                       "a line through the solids is unbounded or ran out of memory");
    if (st)
        return err_nomem(error, NULL);
    return SC_OK;
}

void sc_comparison_init_size(sc_comparison *comparison, size_t size)
{
    if (comparison && size >= sizeof comparison->size)
        sized_clear(comparison, size);
}

sc_status sc_scene_compare(const sc_scene *a, const sc_scene *b,
                           const sc_measure_options *options, sc_comparison *out,
                           sc_error *error)
{
    err_clear(error);
    if (!a || !b || !options || !out)
        return err_set(error, SC_ERR_ARGUMENT, NULL, "no scenes, options or result");
    sc_measure_options o;
    sc_comparison c;
    sc_comparison_init(&c);
    sc_status st = options_measure(options, &o, error);
    if (st == SC_OK)
        st = sized_check(out, SIZED_MIN(sc_comparison, lines), "sc_comparison", error);
    if (st != SC_OK)
        return st;
    st = compare_scenes(a, b, &o, &c, error);
    sized_write(out, &c, sizeof c, SIZED_MIN(sc_comparison, lines), "sc_comparison",
                NULL);
    return st;
}
