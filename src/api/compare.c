/* Comparing two solids (sc_scene_compare), and loading a mesh file as a
 * solid to compare against (sc_scene_load_mesh).
 *
 * The volumes of A, B, A minus B and B minus A are integrated over the box
 * holding both, like the measures (quad.h): along each line both span
 * lists come from their own trees and the differences from the boolean
 * sweep with its regularisation (span.h), so each line's part is exact and
 * slivers thinner than the scene tolerance (coincident faces) count as
 * nothing. The differences are refined until their errors are within the
 * tolerance times the mean of the two volumes (at most the larger one),
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
    /* the leading space puts every position in the model at column 2 or
     * later, and leaves column 1 of line 1 to the mesh file's own first
     * line (mesh_model_unplace) */
    size_t k = (size_t)sprintf(t, " import(file = \"");
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
    if (e->line == 1 && e->column != 1 && strcmp(e->file, path) == 0)
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

enum { C_A, C_B, C_ONLY_A, C_ONLY_B, C_MEAN, C_VALUES };

typedef struct compare_shared {
    const csg_tree *a, *b;
    lines_scratch work; /* per thread: the span lists */
} compare_shared;

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
    values[C_ONLY_A] = length_of(only_a);
    values[C_ONLY_B] = length_of(only_b);
    values[C_MEAN] = (values[C_A] + values[C_B]) / 2;
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
    compare_shared shared = {ta, tb, {0}};
    if (!lines_scratch_init(&shared.work, threads, 0))
        return err_nomem(error, NULL);
    lines_axis axes[3];
    void *contexts[3];
    lines_axes(axes, &shared, contexts);
    /* The differences are refined against the mean of the two volumes,
     * which is at most the larger one (and is it when they agree); the
     * volumes themselves are only reported. */
    int rule[C_VALUES] = {QUAD_FREE, QUAD_FREE, QUAD_RELATIVE(C_MEAN),
                          QUAD_RELATIVE(C_MEAN), QUAD_FREE};
    double floor[C_VALUES] = {0, 0, 0, 0, 0};
    quad_grid grids[3];
    int converged = 0;
    sc_measure_options o = *options;
    o.threads = threads;
    sc_status st = quad_integrate3(lo, hi, 1, C_VALUES, rule, floor, sample_compare,
                                   contexts, &o, grids, &converged);
    if (st == SC_OK) {
        out->volume_a = quad_combine(grids, C_A);
        out->volume_b = quad_combine(grids, C_B);
        /* a difference that is a sheet parallel to two axes lies between
         * their lines; the third axis's lines cross it */
        out->only_a = quad_combine_largest(grids, C_ONLY_A);
        out->only_b = quad_combine_largest(grids, C_ONLY_B);
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
