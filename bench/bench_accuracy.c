/* `spancast bench accuracy`: error against run time of the implicit
 * surface root finders.
 *
 * Seven scenes with analytic ground truth, each an implicit leaf clipped to
 * the box [-1.5, 1.5]^3:
 *   sphere        x^2 + y^2 + z^2 - 1                       (the unit sphere)
 *   torus         (|p|^2 + R^2 - r^2)^2 - 4 R^2 (x^2 + y^2), R = 1, r = 0.35
 *                 (truth: the torus leaf, whose quartic roots are isolated
 *                 and polished to full precision, see prim_torus.c)
 *   triple_root   (x^2 + y^2 + z^2 - 1)^3                   (the unit sphere)
 *   high_freq     sin(30 n.p), n = (1, 2, 2) / 3: layers 0.105 apart
 *                 (truth: the first layer entered, in closed form)
 *   steep_exp     exp(10 (|p|^2 - 1)) - 1                   (the unit sphere;
 *                 |grad f| spans 25 orders of magnitude over the box)
 *   minmax_kink   min(max(|x|, |y|, |z|) - 0.6, |p - c| - 0.5), c = (.5, .5, .5)
 *                 (truth: the nearer of a box and a sphere)
 *   thin_shell    ||p| - 1| - 0.002                  (the sphere of radius 1.002)
 * Rays: an N x N orthographic grid (N = --rays, default 16) of unit
 * directions from an oblique view, covering the box and some empty space
 * around it. For every scene, method and tolerance it writes one CSV row:
 *   scene,method,tolerance,rays,mean_abs_error,max_abs_error,wrong_hits,seconds
 * errors are |t - t_true| over the rays that hit in both (in scene units),
 * wrong_hits counts rays whose hit or miss disagrees with the truth,
 * seconds is the wall time of the rays, cast on all cores (OMP_NUM_THREADS
 * sets how many; root finding only, floored at 1e-6 in the plot; the Lipschitz
 * estimate is made once per scene, as the builder does). --plot draws mean
 * error against seconds, log-log, one panel per scene, through gnuplot.
 */
#include "bench/bench.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "csg/prim.h"
#include "implicit/expr.h"
#include "implicit/solve.h"

enum { SCENE_COUNT = 7 };

static const double PI = 3.14159265358979323846;

typedef struct scene {
    const char *name;
    const char *f;
} scene;

static const scene scenes[SCENE_COUNT] = {
    {"sphere", "x*x + y*y + z*z - 1"},
    {"torus", "(x*x + y*y + z*z + 1 - 0.35*0.35)^2 - 4*(x*x + y*y)"},
    {"triple_root", "(x*x + y*y + z*z - 1)^3"},
    {"high_freq", "sin(30 * (x + 2*y + 2*z) / 3)"},
    {"steep_exp", "exp(10 * (x*x + y*y + z*z - 1)) - 1"},
    {"minmax_kink", "min(max(abs(x), abs(y), abs(z)) - 0.6, "
                    "sqrt((x-0.5)^2 + (y-0.5)^2 + (z-0.5)^2) - 0.5)"},
    {"thin_shell", "abs(sqrt(x*x + y*y + z*z) - 1) - 0.002"},
};

static const double tolerances[] = {1e-2, 1e-3, 1e-4, 1e-5};
enum { TOLERANCE_COUNT = sizeof tolerances / sizeof tolerances[0] };

static const bbox box = {{-1.5, -1.5, -1.5}, {1.5, 1.5, 1.5}};

/* First t >= 0 where the ray enters the sphere |p - c| <= r; -1 if none. */
static double sphere_hit(vec3 o, vec3 d, vec3 c, double r)
{
    vec3 oc = v3_sub(o, c);
    double b = v3_dot(oc, d), k = v3_dot(oc, oc) - r * r;
    double disc = b * b - k; /* |d| = 1 */
    if (disc < 0)
        return -1;
    double q = -(b + copysign(sqrt(disc), b));
    double t0 = fmin(q, k / q), t1 = fmax(q, k / q);
    return t0 >= 0 ? t0 : t1 >= 0 ? 0 : -1;
}

/* Entry of the ray into a closed box; -1 if it misses. */
static double box_hit(vec3 o, vec3 d, bbox b, double *t_exit)
{
    double t0 = 0, t1 = INFINITY;
    const double *po = &o.x, *pd = &d.x, *lo = &b.lo.x, *hi = &b.hi.x;
    for (int k = 0; k < 3; k++) {
        if (pd[k] == 0) {
            if (po[k] < lo[k] || po[k] > hi[k])
                return -1;
            continue;
        }
        double ta = (lo[k] - po[k]) / pd[k], tb = (hi[k] - po[k]) / pd[k];
        t0 = fmax(t0, fmin(ta, tb));
        t1 = fmin(t1, fmax(ta, tb));
    }
    if (t_exit)
        *t_exit = t1;
    return t0 <= t1 ? t0 : -1;
}

/* The true first hit of scene s (clipped to the box, as the leaf is). */
static double truth(int s, vec3 o, vec3 d)
{
    double t_exit;
    double t_box = box_hit(o, d, box, &t_exit);
    if (t_box < 0)
        return -1;
    double t = -1;
    switch (s) {
    case 0:
    case 2:
    case 4:
        t = sphere_hit(o, d, v3(0, 0, 0), 1);
        break;
    case 1: {
        prim p;
        memset(&p, 0, sizeof p);
        p.kind = PRIM_TORUS;
        p.u.torus.major = 1;
        p.u.torus.minor = 0.35;
        span sp[2];
        uint32_t n = prim_spans(&p, 0, o, d, sp, 2);
        t = n ? sp[0].in.t : -1;
        break;
    }
    case 3: {
        /* sin(K s) < 0 with s = n.p linear in t: s0 + c t */
        const double k = 30;
        vec3 nrm = v3(1.0 / 3, 2.0 / 3, 2.0 / 3);
        double s0 = v3_dot(nrm, v3_madd(o, d, t_box)), c = v3_dot(nrm, d);
        if (sin(k * s0) < 0)
            return t_box;
        double s_star;
        if (c > 0)
            s_star = (PI + 2 * PI * ceil((k * s0 - PI) / (2 * PI))) / k;
        else if (c < 0)
            s_star = 2 * PI * floor(k * s0 / (2 * PI)) / k;
        else
            return -1;
        t = t_box + (s_star - s0) / c;
        return t <= t_exit ? t : -1;
    }
    case 5: {
        double a = box_hit(o, d, (bbox){v3(-0.6, -0.6, -0.6), v3(0.6, 0.6, 0.6)}, NULL);
        double b = sphere_hit(o, d, v3(0.5, 0.5, 0.5), 0.5);
        t = a < 0 ? b : b < 0 ? a : fmin(a, b);
        break;
    }
    default:
        t = sphere_hit(o, d, v3(0, 0, 0), 1.002);
        break;
    }
    return t >= 0 && t <= t_exit ? fmax(t, t_box) : -1;
}

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

typedef struct row {
    int scene, method;
    double tolerance;
    long rays;
    double mean_error, max_error;
    long wrong;
    double seconds;
} row;

/* The grid ray (i, j) of n x n: origins on a plane 5 units before the
 * box's centre, unit direction. */
static void grid_ray(int i, int j, int n, vec3 *o, vec3 *d)
{
    vec3 dir = v3_normalize(v3(-0.52, -0.71, -0.47));
    vec3 a = v3_normalize(v3_cross(dir, v3(0, 0, 1)));
    vec3 b = v3_cross(a, dir);
    double u = -2.1 + 4.2 * (i + 0.5) / n, v = -2.1 + 4.2 * (j + 0.5) / n;
    *o = v3_madd(v3_madd(v3_scale(dir, -5), a, u), b, v);
    *d = dir;
}

static void run_one(const expr_program *f, double lipschitz, int s, int m, double tol,
                    int n, row *out)
{
    prim p;
    memset(&p, 0, sizeof p);
    p.kind = PRIM_IMPLICIT;
    p.u.implicit.program = f;
    p.u.implicit.box = box;
    p.u.implicit.tolerance = tol;
    p.u.implicit.lipschitz = lipschitz;
    p.u.implicit.method = m;
    double *hits = malloc((size_t)n * n * sizeof *hits);
    if (!hits)
        return;
    double start = now();
    /* The grid's rows on all cores: a ray's cost varies tenfold along the
     * grid (misses are cheap), hence rows handed out one at a time. */
#pragma omp parallel for schedule(dynamic, 1)
    for (int j = 0; j < n; j++) {
        for (int i = 0; i < n; i++) {
            vec3 o, d;
            grid_ray(i, j, n, &o, &d);
            span sp[PRIM_IMPLICIT_MAX_SPANS];
            uint32_t k = prim_spans(&p, 0, o, d, sp, PRIM_IMPLICIT_MAX_SPANS);
            double t = -1;
            for (uint32_t q = 0; q < k && t < 0; q++) {
                if (sp[q].out.t >= 0)
                    t = fmax(sp[q].in.t, 0);
            }
            hits[j * n + i] = t;
        }
    }
    double seconds = now() - start;
    double sum = 0, max = 0;
    long both = 0, wrong = 0;
    for (int j = 0; j < n; j++) {
        for (int i = 0; i < n; i++) {
            vec3 o, d;
            grid_ray(i, j, n, &o, &d);
            double want = truth(s, o, d), got = hits[j * n + i];
            if ((want >= 0) != (got >= 0)) {
                wrong++;
            } else if (want >= 0) {
                double e = fabs(got - want);
                sum += e;
                max = fmax(max, e);
                both++;
            }
        }
    }
    free(hits);
    *out = (row){s, m, tol, (long)n * n, both ? sum / both : 0, max, wrong, seconds};
}

/* Writes the file through a temporary name and renames it into place. */
static int write_csv(const char *path, const row *rows, int count)
{
    size_t len = strlen(path) + 16;
    char *tmp = malloc(len);
    if (!tmp)
        return 0;
    snprintf(tmp, len, "%s.tmp%ld", path, (long)getpid());
    FILE *fp = fopen(tmp, "w");
    int ok = fp != NULL;
    if (ok) {
        fprintf(fp, "scene,method,tolerance,rays,mean_abs_error,max_abs_error,wrong_hits,"
                    "seconds\n");
        for (int i = 0; i < count; i++) {
            const row *r = &rows[i];
            fprintf(fp, "%s,%s,%g,%ld,%.3e,%.3e,%ld,%.3e\n", scenes[r->scene].name,
                    solve_method_name((solve_method)r->method), r->tolerance, r->rays,
                    r->mean_error, r->max_error, r->wrong, r->seconds);
        }
        ok = fclose(fp) == 0;
    }
    if (ok)
        ok = rename(tmp, path) == 0;
    if (!ok) {
        fprintf(stderr, "spancast: error: cannot write '%s': %s\n", path,
                strerror(errno));
        remove(tmp);
    }
    free(tmp);
    return ok;
}

/* Draws the plot with gnuplot from the CSV: one panel per scene, mean
 * error (floored at 1e-17 so that exact answers show) against seconds,
 * log-log, a line per method; rays with a wrong hit or miss are written
 * beside their point. */
static int plot(const char *csv, const char *png)
{
    size_t len = strlen(png) + 32;
    char *tmp = malloc(len), *script = malloc(len + 8);
    if (!tmp || !script) {
        free(tmp);
        free(script);
        return 0;
    }
    snprintf(tmp, len, "%s.tmp%ld.png", png, (long)getpid());
    snprintf(script, len + 8, "%s.tmp%ld.gp", png, (long)getpid());
    FILE *fp = fopen(script, "w");
    int ok = fp != NULL;
    if (ok) {
        fprintf(fp, "set terminal pngcairo size 1500,1100 font ',10'\n");
        fprintf(fp, "set output '%s'\n", tmp);
        fprintf(fp, "set datafile separator ','\n");
        fprintf(fp,
                "set logscale xy\nset format y '10^{%%L}'\nset format x '10^{%%L}'\n");
        fprintf(fp, "set xlabel 'seconds'\nset ylabel 'mean |t - t_{true}|'\n");
        fprintf(fp, "set key top right\nset grid\n");
        fprintf(fp, "set multiplot layout 3,3 title 'spancast bench accuracy: error "
                    "against run time (labels: wrong hits)'\n");
        static const char *const colors[3] = {"#1f77b4", "#d62728", "#2ca02c"};
        for (int s = 0; s < SCENE_COUNT; s++) {
            fprintf(fp, "set title '%s' noenhanced\n", scenes[s].name);
            fprintf(fp, "plot ");
            for (int m = 0; m < SOLVE_METHOD_COUNT; m++) {
                const char *name = solve_method_name((solve_method)m);
                fprintf(fp,
                        "'%s' using ((strcol(1) eq '%s' && strcol(2) eq '%s') ? ($8 < "
                        "1e-6 ? 1e-6 : $8) : "
                        "1/0):($5 < 1e-17 ? 1e-17 : $5) with linespoints lw 2 pt 7 lc "
                        "rgb '%s' title '%s', ",
                        csv, scenes[s].name, name, colors[m], name);
                fprintf(fp,
                        "'%s' using ((strcol(1) eq '%s' && strcol(2) eq '%s' && $7 > 0) "
                        "? ($8 < 1e-6 ? 1e-6 : $8) : 1/0):($5 < 1e-17 ? 1e-17 : "
                        "$5):(sprintf('%%d', $7)) "
                        "with labels offset 0,0.8 tc rgb '%s' notitle%s",
                        csv, scenes[s].name, name, colors[m],
                        m + 1 < SOLVE_METHOD_COUNT ? ", " : "\n");
            }
        }
        fprintf(fp, "unset multiplot\n");
        ok = fclose(fp) == 0;
    }
    if (ok) {
        size_t clen = strlen(script) + 64;
        char *cmd = malloc(clen);
        ok = cmd != NULL;
        if (ok) {
            snprintf(cmd, clen, "gnuplot '%s'", script);
            int st = system(cmd);
            ok = st == 0;
            if (!ok)
                fprintf(stderr,
                        "spancast: error: gnuplot failed (status %d); --plot needs "
                        "gnuplot (Debian: gnuplot-nox)\n",
                        st);
            free(cmd);
        }
    }
    if (ok && rename(tmp, png) != 0) {
        fprintf(stderr, "spancast: error: cannot write '%s': %s\n", png, strerror(errno));
        ok = 0;
    }
    remove(tmp);
    remove(script);
    free(tmp);
    free(script);
    return ok;
}

int bench_main(int argc, char **argv)
{
    if (argc < 1 || strcmp(argv[0], "accuracy") != 0) {
        fprintf(stderr,
                "spancast: error: %s (expected 'bench accuracy' or 'bench stability')\n",
                argc < 1 ? "missing benchmark" : "unknown benchmark");
        return 2;
    }
    const char *csv = NULL, *png = NULL;
    long n = 16;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        const char *value = i + 1 < argc ? argv[i + 1] : NULL;
        if (!strcmp(a, "--csv") || !strcmp(a, "--plot") || !strcmp(a, "--rays")) {
            if (!value) {
                fprintf(stderr, "spancast: error: option '%s' expects a value\n", a);
                return 2;
            }
            i++;
            if (!strcmp(a, "--csv")) {
                csv = value;
            } else if (!strcmp(a, "--plot")) {
                png = value;
            } else {
                char *end;
                n = strtol(value, &end, 10);
                if (*end || n < 1 || n > 1000) {
                    fprintf(stderr, "spancast: error: --rays expects an integer from 1 "
                                    "to 1000 (rays per side of the grid)\n");
                    return 2;
                }
            }
        } else {
            fprintf(stderr, "spancast: error: unknown option '%s'\n", a);
            return 2;
        }
    }
    if (!csv) {
        fprintf(stderr, "spancast: error: missing --csv FILE\n");
        return 2;
    }
    row rows[SCENE_COUNT * SOLVE_METHOD_COUNT * TOLERANCE_COUNT];
    int count = 0;
    for (int s = 0; s < SCENE_COUNT; s++) {
        expr_program f;
        expr_error e;
        if (!expr_compile(scenes[s].f, strlen(scenes[s].f), NULL, 0, &f, &e)) {
            fprintf(stderr, "spancast: error: scene %s: %s\n", scenes[s].name, e.message);
            return 1;
        }
        double lipschitz = solve_estimate_lipschitz(&f, box);
        for (int m = 0; m < SOLVE_METHOD_COUNT; m++) {
            for (int k = 0; k < TOLERANCE_COUNT; k++) {
                row *r = &rows[count++];
                run_one(&f, lipschitz, s, m, tolerances[k], (int)n, r);
                fprintf(stderr, "%-12s %-9s %-6g mean %.2e max %.2e wrong %ld  %.3f s\n",
                        scenes[s].name, solve_method_name((solve_method)m), r->tolerance,
                        r->mean_error, r->max_error, r->wrong, r->seconds);
            }
        }
    }
    if (!write_csv(csv, rows, count))
        return 1;
    if (png && !plot(csv, png))
        return 1;
    return 0;
}
