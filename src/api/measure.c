/* Mass properties of a solid (sc_scene_measure): volume, surface area,
 * centroid, inertia tensor with principal moments and axes, tight box.
 *
 * Every value is an integral over lines parallel to an axis (quad.h), each
 * line's part exact from its span list. Along the line through (u, v)
 * parallel to axis a, with s the coordinate along it (relative to the box
 * centre, like u and v), the spans [s0, s1] give exactly
 *     L  = sum (s1 - s0)               (volume:  integral of L du dv)
 *     S1 = sum (s1^2 - s0^2) / 2       (first moment along a)
 *     S2 = sum (s1^3 - s0^3) / 3       (second moment along a)
 * and u L, v L, u^2 L, v^2 L, u v L, u S1, v S1 give the other moments.
 * Every axis gives every moment, so the three axes are three independent
 * estimates; their spread enters the error (quad_combine).
 *
 * Area: a surface crossed by the lines along a, with unit normal n, has
 * integral of |n_a| dA = integral over (u, v) of the crossings counted
 * (each point of the surface projects to one crossing). With weights
 * w_a(n) that add up to 1 over the three axes, the area is the sum over the
 * axes of the integral over (u, v) of the sum over crossings of
 * w_a(n) / |n_a|. The weights w_a = n_a^2 make that |n_a| per crossing:
 * bounded, and going to 0 where the surface turns away from the lines, so
 * that the integrand has no jump at a smooth silhouette (1 / |n_a| alone
 * is unbounded there, and counting crossings with equal weights jumps).
 * The weights w_a = |n_a|^3 / |n|_3^3 give a second estimator,
 * n_a^2 / |n|_3^3 per crossing (between 0 and sqrt(3)), smoother still at
 * silhouettes; the two differ only by the integration error, and their
 * difference enters the error of the first. Only edges of the surface
 * (where faces meet) leave jumps, which the refinement follows. The
 * normals are the exact ones of the surfaces (csg_hit_normal).
 *
 * The centroid and the central inertia come from the moments about the box
 * centre, with first-order error propagation; the principal moments are the
 * tensor's eigenvalues (cyclic Jacobi), whose error is at most the
 * Frobenius norm of the tensor's error (Weyl's inequality). The tight box is
 * the extremes of every span end sampled (inside the true box) with the
 * distance to the tree's bounds (outside it) as error.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "api/lines.h"
#include "api/quad.h"
#include "base/arena.h"
#include "api/options.h"
#include "base/error.h"
#include "base/sized.h"
#include "build/scene.h"
#include "csg/csg.h"
#include "render/render.h"

void sc_measure_options_init_size(sc_measure_options *options, size_t size)
{
    if (!options || size < sizeof options->size)
        return;
    /* The defaults in full, then as much of them as the caller's struct
     * holds (base/sized.h). */
    sc_measure_options o;
    sized_clear(&o, sizeof o);
    o.tolerance = 1e-4;
    o.density = 1;
    o.max_lines = 4000000;
    memcpy(options, &o, size < sizeof o ? size : sizeof o);
    options->size = size;
}

void sc_measure_init_size(sc_measure *measure, size_t size)
{
    if (measure && size >= sizeof measure->size)
        sized_clear(measure, size);
}

enum {
    V_LENGTH,   /* L */
    V_S1,       /* S1 */
    V_U,        /* u L */
    V_V,        /* v L */
    V_S2,       /* S2 */
    V_UU,       /* u^2 L */
    V_VV,       /* v^2 L */
    V_UV,       /* u v L */
    V_US,       /* u S1 */
    V_VS,       /* v S1 */
    V_AREA,     /* sum of |n_a| */
    V_AREA2,    /* sum of n_a^2 / |n|_3^3 */
    VALUE_COUNT /* values per line */
};

/* What the threads share, and what each owns (indexed by thread). */
typedef struct measure_shared {
    const csg_tree *tree;
    double centre[3];
    lines_scratch work; /* per thread: spans, and the box of their ends */
} measure_shared;

static int sample_line(void *context, int thread, double u, double v, double *values,
                       uint64_t *signature)
{
    const lines_axis *m = context;
    const measure_shared *s = m->shared;
    int a = m->axis, ua = (a + 1) % 3, va = (a + 2) % 3;
    double du = u - s->centre[ua], dv = v - s->centre[va];
    csg_ray r = csg_axis_line(a, s->centre[a], u, v);
    arena *scratch = &s->work.arenas[thread];
    arena_reset(scratch);
    span_list spans;
    if (!csg_spans(s->tree, &r, scratch, &spans))
        return 0;
    *signature = lines_signature(0, spans);
    double length = 0, s1 = 0, s2 = 0, area = 0, area2 = 0;
    double *box = s->work.box[thread];
    for (uint32_t k = 0; k < spans.n; k++) {
        const span_end *ends[2] = {&spans.v[k].in, &spans.v[k].out};
        for (int e = 0; e < 2; e++) {
            if (ends[e]->leaf == SPAN_NO_LEAF || !isfinite(ends[e]->t))
                return 0; /* unbounded along the line */
            csg_hit hit = {ends[e]->t, ends[e]->leaf, ends[e]->part, ends[e]->flip, 0};
            vec3 n = csg_hit_normal(s->tree, &r, &hit);
            double na = fabs(a == 0 ? n.x : a == 1 ? n.y : n.z);
            double cubes =
                fabs(n.x * n.x * n.x) + fabs(n.y * n.y * n.y) + fabs(n.z * n.z * n.z);
            area += na;
            area2 += cubes > 0 ? na * na / cubes : 0;
            double p[3] = {r.o.x, r.o.y, r.o.z};
            p[a] += ends[e]->t;
            for (int i = 0; i < 3; i++) {
                box[i] = fmin(box[i], p[i]);
                box[3 + i] = fmax(box[3 + i], p[i]);
            }
        }
        double t0 = spans.v[k].in.t, t1 = spans.v[k].out.t;
        length += t1 - t0;
        s1 += (t1 * t1 - t0 * t0) / 2;
        s2 += (t1 * t1 * t1 - t0 * t0 * t0) / 3;
    }
    values[V_LENGTH] = length;
    values[V_S1] = s1;
    values[V_U] = du * length;
    values[V_V] = dv * length;
    values[V_S2] = s2;
    values[V_UU] = du * du * length;
    values[V_VV] = dv * dv * length;
    values[V_UV] = du * dv * length;
    values[V_US] = du * s1;
    values[V_VS] = dv * s1;
    values[V_AREA] = area;
    values[V_AREA2] = area2;
    return 1;
}

/* Eigen decomposition of the symmetric m by cyclic Jacobi rotations:
 * eigenvalues ascending in w, unit eigenvectors in rows of vec. */
static void eigen3(const double m[3][3], double w[3], double vec[3][3])
{
    double a[3][3], q[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    memcpy(a, m, sizeof a);
    for (int sweep = 0; sweep < 50; sweep++) {
        double off = fabs(a[0][1]) + fabs(a[0][2]) + fabs(a[1][2]);
        double diag = fabs(a[0][0]) + fabs(a[1][1]) + fabs(a[2][2]);
        if (off <= 1e-17 * diag || off == 0)
            break;
        for (int p = 0; p < 2; p++)
            for (int r = p + 1; r < 3; r++) {
                if (a[p][r] == 0)
                    continue;
                double theta = (a[r][r] - a[p][p]) / (2 * a[p][r]);
                double t =
                    (theta >= 0 ? 1 : -1) / (fabs(theta) + sqrt(theta * theta + 1));
                double c = 1 / sqrt(t * t + 1), s = t * c;
                for (int k = 0; k < 3; k++) { /* a = J^T a J */
                    double akp = a[k][p], akr = a[k][r];
                    a[k][p] = c * akp - s * akr;
                    a[k][r] = s * akp + c * akr;
                }
                for (int k = 0; k < 3; k++) {
                    double apk = a[p][k], ark = a[r][k];
                    a[p][k] = c * apk - s * ark;
                    a[r][k] = s * apk + c * ark;
                }
                for (int k = 0; k < 3; k++) { /* columns of q: eigenvectors */
                    double qkp = q[k][p], qkr = q[k][r];
                    q[k][p] = c * qkp - s * qkr;
                    q[k][r] = s * qkp + c * qkr;
                }
            }
    }
    int order[3] = {0, 1, 2};
    for (int i = 0; i < 3; i++)
        for (int j = i + 1; j < 3; j++)
            if (a[order[j]][order[j]] < a[order[i]][order[i]]) {
                int x = order[i];
                order[i] = order[j];
                order[j] = x;
            }
    for (int i = 0; i < 3; i++) {
        w[i] = a[order[i]][order[i]];
        for (int k = 0; k < 3; k++)
            vec[i][k] = q[k][order[i]] + 0.0;
    }
}

/* The mass properties from the three grids (see the file's comment). */
static void derive(const quad_grid grids[3], const measure_shared *s, double density,
                   sc_measure *out)
{
    /* Values of each axis that estimate the first and second moments:
     * first[a][i] is the value of axis a's grid for component i. */
    sc_estimate volume = quad_combine(grids, V_LENGTH);
    sc_estimate m1[3], m2[3][3];
    for (int i = 0; i < 3; i++) {
        double sum = 0, own = 0, spread = 0, est[3];
        for (int a = 0; a < 3; a++) {
            int k = i == a ? V_S1 : i == (a + 1) % 3 ? V_U : V_V;
            est[a] = grids[a].total[k];
            own = fmax(own, grids[a].total_error[k]);
            sum += est[a];
        }
        m1[i].value = sum / 3;
        for (int a = 0; a < 3; a++)
            spread = fmax(spread, fabs(est[a] - m1[i].value));
        m1[i].error = own + spread;
    }
    for (int i = 0; i < 3; i++)
        for (int j = i; j < 3; j++) {
            double sum = 0, own = 0, spread = 0, est[3];
            for (int a = 0; a < 3; a++) {
                int ua = (a + 1) % 3, va = (a + 2) % 3, k;
                if (i == j)
                    k = i == a ? V_S2 : i == ua ? V_UU : V_VV;
                else if ((i == ua && j == va) || (i == va && j == ua))
                    k = V_UV;
                else
                    k = (i == ua || j == ua) ? V_US : V_VS;
                est[a] = grids[a].total[k];
                own = fmax(own, grids[a].total_error[k]);
                sum += est[a];
            }
            m2[i][j].value = sum / 3;
            for (int a = 0; a < 3; a++)
                spread = fmax(spread, fabs(est[a] - m2[i][j].value));
            m2[i][j].error = own + spread;
            m2[j][i] = m2[i][j];
        }
    out->volume = volume;
    for (int a = 0; a < 3; a++)
        out->volume_by_axis[a] = grids[a].total[V_LENGTH];
    double area = 0, area2 = 0, area_error = 0;
    for (int a = 0; a < 3; a++) {
        area += grids[a].total[V_AREA];
        area2 += grids[a].total[V_AREA2];
        area_error += grids[a].total_error[V_AREA];
    }
    out->area.value = area;
    out->area.error = area_error + fabs(area - area2);
    out->mass.value = density * volume.value;
    out->mass.error = fabs(density) * volume.error;
    double v = volume.value, dv = volume.error;
    if (!(v > 0))
        return;
    double shrunk = v - dv > 0.5 * v ? v - dv : 0.5 * v; /* a floor for the bound */
    double c[3];
    for (int i = 0; i < 3; i++) {
        c[i] = m1[i].value / v;
        out->centroid[i].value = s->centre[i] + c[i];
        out->centroid[i].error = (m1[i].error + fabs(c[i]) * dv) / shrunk;
    }
    /* Central second moments C = M2 - M1 M1^T / V, and their errors. */
    double cm[3][3], cm_error[3][3];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            cm[i][j] = m2[i][j].value - m1[i].value * m1[j].value / v;
            cm_error[i][j] =
                m2[i][j].error +
                (fabs(m1[j].value) * m1[i].error + fabs(m1[i].value) * m1[j].error) /
                    shrunk +
                fabs(m1[i].value * m1[j].value) * dv / (shrunk * shrunk);
        }
    double trace = cm[0][0] + cm[1][1] + cm[2][2];
    double tensor[3][3], frobenius = 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            double value = density * ((i == j ? trace : 0) - cm[i][j]);
            double err = fabs(density) * (i == j ? cm_error[(i + 1) % 3][(i + 1) % 3] +
                                                       cm_error[(i + 2) % 3][(i + 2) % 3]
                                                 : cm_error[i][j]);
            tensor[i][j] = value;
            out->inertia[i][j].value = value + 0.0;
            out->inertia[i][j].error = err;
            frobenius += err * err;
        }
    frobenius = sqrt(frobenius);
    double w[3];
    eigen3(tensor, w, out->axes);
    for (int k = 0; k < 3; k++) {
        out->principal[k].value = w[k];
        out->principal[k].error = frobenius;
    }
}

/* sc_scene_measure with the library's own options and result structs. */
static sc_status measure_scene(const sc_scene *scene, const sc_measure_options *options,
                               sc_measure *out, sc_error *error)
{
    err_clear(error);
    if (!scene || !options || !out)
        return err_set(error, SC_ERR_ARGUMENT, NULL, "no scene, options or result");
    memset(out, 0, sizeof *out);
    if (!(options->tolerance > 0 && options->tolerance < 1))
        return err_set(error, SC_ERR_ARGUMENT, NULL,
                       "tolerance must lie between 0 and 1 (got %g)", options->tolerance);
    if (!isfinite(options->density))
        return err_set(error, SC_ERR_ARGUMENT, NULL, "density must be finite");
    const csg_tree *t = scene_tree(scene);
    out->threads = options_thread_count(options->threads);
    out->converged = 1;
    if (t->root == CSG_EMPTY || bbox_is_empty(&t->bounds))
        return SC_OK;
    double lo[3] = {t->bounds.lo.x, t->bounds.lo.y, t->bounds.lo.z};
    double hi[3] = {t->bounds.hi.x, t->bounds.hi.y, t->bounds.hi.z};
    for (int i = 0; i < 3; i++) {
        if (!isfinite(lo[i]) || !isfinite(hi[i]))
            return err_set(error, SC_ERR_ARGUMENT, NULL,
                           "the solid is unbounded: it has no volume to measure");
        if (!(hi[i] > lo[i]))
            return SC_OK; /* flat: no volume, and regularisation removes it anyway */
    }
    measure_shared shared;
    shared.tree = t;
    for (int i = 0; i < 3; i++)
        shared.centre[i] = (lo[i] + hi[i]) / 2;
    int threads = out->threads;
    if (!lines_scratch_init(&shared.work, threads, 1))
        return err_nomem(error, NULL);
    lines_axis axes[3];
    void *contexts[3];
    lines_axes(axes, &shared, contexts);
    int rule[VALUE_COUNT] = {0};
    double floor[VALUE_COUNT] = {0};
    rule[V_LENGTH] = QUAD_EACH;
    rule[V_AREA] = rule[V_AREA2] = QUAD_SUM;
    /* Floors: a solid too thin to be seen at the first grid still gets a
     * finite target, a millionth of its box. */
    double extent = fmax(hi[0] - lo[0], fmax(hi[1] - lo[1], hi[2] - lo[2]));
    floor[V_LENGTH] = 1e-6 * (hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2]);
    floor[V_AREA] = floor[V_AREA2] = 1e-6 * extent * extent;
    quad_grid grids[3];
    int converged = 0;
    sc_status st = quad_integrate3(lo, hi, 0, VALUE_COUNT, rule, floor, sample_line,
                                   contexts, options, grids, &converged);
    if (st == SC_OK) {
        derive(grids, &shared, options->density, out);
        out->converged = converged;
        out->lines = grids[0].lines + grids[1].lines + grids[2].lines;
        double seen[6];
        if (!lines_scratch_box(&shared.work, options, seen))
            st = SC_ERR_NOMEM;
        for (int i = 0; i < 3; i++) {
            if (!(seen[i] <= seen[3 + i])) /* nothing seen: the tree's box */
                seen[i] = lo[i], seen[3 + i] = hi[i];
            /* a hit rounded past the tree's box (a face on it, as a 2D
             * model's slab has) is on it: the error bounds stay >= 0 */
            seen[i] = fmax(seen[i], lo[i]);
            seen[3 + i] = fmin(seen[3 + i], hi[i]);
            out->box_lo[i].value = seen[i];
            out->box_lo[i].error = seen[i] - lo[i];
            out->box_hi[i].value = seen[3 + i];
            out->box_hi[i].error = hi[i] - seen[3 + i];
        }
    }
    int failed = grids[0].failed || grids[1].failed || grids[2].failed;
    int limited = st == SC_ERR_LIMIT && quad_limit_error(grids, t, NULL, error);
    for (int a = 0; a < 3; a++)
        quad_free(&grids[a]);
    lines_scratch_free(&shared.work);
    if (st == SC_ERR_CANCELLED)
        return err_set(error, SC_ERR_CANCELLED, NULL, "measure cancelled");
    if (st == SC_ERR_LIMIT && limited)
        return SC_ERR_LIMIT;
    if (st == SC_ERR_ARGUMENT && failed)
        return err_set(error, SC_ERR_ARGUMENT, NULL,
                       "a line through the solid is unbounded or ran out of memory");
    if (st)
        return err_nomem(error, NULL);
    return SC_OK;
}

sc_status sc_scene_measure(const sc_scene *scene, const sc_measure_options *options,
                           sc_measure *out, sc_error *error)
{
    err_clear(error);
    if (!scene || !options || !out)
        return err_set(error, SC_ERR_ARGUMENT, NULL, "no scene, options or result");
    sc_measure_options o;
    sc_measure m;
    sc_measure_init(&m);
    sc_status st = options_measure(options, &o, error);
    if (st == SC_OK)
        st = sized_check(out, SIZED_MIN(sc_measure, threads), "sc_measure", error);
    if (st != SC_OK)
        return st;
    st = measure_scene(scene, &o, &m, error);
    sized_write(out, &m, sizeof m, SIZED_MIN(sc_measure, threads), "sc_measure", NULL);
    return st;
}
