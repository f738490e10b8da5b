/* `spancast bench meshes`: primary-ray throughput on triangle meshes, the
 * tree's own first-hit query against Embree's rtcIntersect1 on the same
 * triangles and the same rays; and `spancast bench torus-stl`, which writes
 * the benchmark's imported mesh.
 *
 *   spancast-bench meshes FILE.csg [--size W,H] [--reps N]
 *   spancast-bench torus-stl --triangles N FILE.stl
 *
 * meshes loads FILE (as `spancast render` does, exact mode) and casts a
 * W x H grid (default 400 x 300) of pinhole rays from OpenSCAD's default
 * view direction, the bounding sphere filling the view. It times, on one
 * thread, in CPU time (what the process got, whatever else the machine
 * runs), the best of N repetitions (default 3):
 *   spancast  csg_first_hit, the query the renderer's camera rays make;
 *   embree    rtcIntersect1 on every mesh leaf of the tree, its vertices
 *             carried to world coordinates in single precision (Embree's
 *             own), default scene flags;
 *   robust    the same with RTC_SCENE_FLAG_ROBUST, Embree's watertight mode.
 * It prints one line per engine: Mrays/s, hits, and for Embree the rays
 * whose hit or miss differs from spancast's and the largest relative
 * difference of t where both hit. Without Embree at build time only the
 * spancast line is printed. Leaves other than meshes are in spancast's
 * rays but not in Embree's: the anchor is meant for mesh-only models.
 *
 * torus-stl writes a binary STL of a closed, outward-wound torus with a
 * rippled surface (R = 30, r = 10 + 1.5 sin 12u sin 7v), about N
 * triangles: the stand-in for an imported scan or CAD export.
 */
#include "bench/bench.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "build/build.h"
#include "model/model.h"
#include "csg/csg.h"
#include "csg/prim_mesh.h"
#include "formats/file.h"
#include "syntax/parse.h"

#ifdef SPANCAST_HAVE_EMBREE
#include <embree3/rtcore.h>
#endif

static const double PI = 3.14159265358979323846;

static double cpu_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

typedef struct ray_grid {
    vec3 eye;
    vec3 *dir; /* w * h directions */
    uint32_t count;
} ray_grid;

/* Pinhole rays from OpenSCAD's default view (rotate 55, 0, 25), the
 * bounding sphere filling a 30 degree field of view. */
static int make_rays(const csg_tree *t, int w, int h, ray_grid *g)
{
    vec3 centre = bbox_center(&t->bounds);
    double radius = 0.5 * v3_length(bbox_extent(&t->bounds));
    double ax = 55 * PI / 180, az = 25 * PI / 180;
    vec3 back = v3(sin(az) * sin(ax), -cos(az) * sin(ax), cos(ax));
    double fov = 30 * PI / 180;
    g->eye = v3_add(centre, v3_scale(back, radius / sin(fov / 2)));
    vec3 fwd = v3_neg(back);
    vec3 right = v3_normalize(v3_cross(fwd, v3(0, 0, 1)));
    vec3 up = v3_cross(right, fwd);
    double half = tan(fov / 2);
    g->count = (uint32_t)w * (uint32_t)h;
    g->dir = malloc(g->count * sizeof *g->dir);
    if (!g->dir)
        return 0;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            double sx = (2 * (x + 0.5) / w - 1) * half * w / h;
            double sy = (1 - 2 * (y + 0.5) / h) * half;
            g->dir[(size_t)y * w + x] =
                v3_normalize(v3_add(fwd, v3_add(v3_scale(right, sx), v3_scale(up, sy))));
        }
    return 1;
}

typedef struct result {
    double seconds;
    uint32_t hits;
    double *t; /* per ray, INFINITY for a miss */
} result;

static void run_spancast(const csg_tree *t, const ray_grid *g, int reps, result *r)
{
    arena scratch;
    arena_init(&scratch, 64 * 1024);
    r->seconds = INFINITY;
    for (int rep = 0; rep < reps; rep++) {
        uint32_t hits = 0;
        double start = cpu_seconds();
        for (uint32_t i = 0; i < g->count; i++) {
            csg_ray ray = {g->eye, g->dir[i], 0, INFINITY};
            csg_hit hit;
            int found = csg_first_hit(t, &ray, &scratch, &hit);
            arena_reset(&scratch);
            hits += (uint32_t)found;
            r->t[i] = found ? hit.t : INFINITY;
        }
        double s = cpu_seconds() - start;
        if (s < r->seconds)
            r->seconds = s;
        r->hits = hits;
    }
    arena_free(&scratch);
}

#ifdef SPANCAST_HAVE_EMBREE
/* Embree's scene of the tree's mesh leaves; NULL when it has none. */
static RTCScene embree_scene(RTCDevice dev, const csg_tree *t, int robust,
                             double *seconds)
{
    double start = cpu_seconds();
    RTCScene scene = rtcNewScene(dev);
    if (robust)
        rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST);
    int meshes = 0;
    for (uint32_t i = 0; i < t->leaf_count; i++) {
        const csg_leaf *l = &t->leaves[i];
        if (l->prim.kind != PRIM_MESH || !l->prim.u.mesh.mesh)
            continue;
        const prim_mesh *m = l->prim.u.mesh.mesh;
        affine to_world; /* the leaf keeps only its inverse */
        if (!affine_invert(&l->to_local, &to_world))
            continue;
        RTCGeometry geom = rtcNewGeometry(dev, RTC_GEOMETRY_TYPE_TRIANGLE);
        float *v =
            rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                    3 * sizeof(float), 3 * (size_t)m->tri_count);
        unsigned *idx =
            rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                    3 * sizeof(unsigned), m->tri_count);
        for (uint32_t k = 0; k < 3 * m->tri_count; k++) {
            vec3 p = affine_point(&to_world, m->v[k]);
            v[3 * k] = (float)p.x;
            v[3 * k + 1] = (float)p.y;
            v[3 * k + 2] = (float)p.z;
            idx[k] = k;
        }
        rtcCommitGeometry(geom);
        rtcAttachGeometry(scene, geom);
        rtcReleaseGeometry(geom);
        meshes++;
    }
    rtcCommitScene(scene);
    *seconds = cpu_seconds() - start;
    if (!meshes) {
        rtcReleaseScene(scene);
        return NULL;
    }
    return scene;
}

static void run_embree(RTCScene scene, const ray_grid *g, int reps, result *r)
{
    struct RTCIntersectContext ctx;
    r->seconds = INFINITY;
    for (int rep = 0; rep < reps; rep++) {
        uint32_t hits = 0;
        double start = cpu_seconds();
        for (uint32_t i = 0; i < g->count; i++) {
            rtcInitIntersectContext(&ctx);
            struct RTCRayHit rh;
            rh.ray.org_x = (float)g->eye.x;
            rh.ray.org_y = (float)g->eye.y;
            rh.ray.org_z = (float)g->eye.z;
            rh.ray.dir_x = (float)g->dir[i].x;
            rh.ray.dir_y = (float)g->dir[i].y;
            rh.ray.dir_z = (float)g->dir[i].z;
            rh.ray.tnear = 0;
            rh.ray.tfar = INFINITY;
            rh.ray.time = 0;
            rh.ray.mask = 0xffffffffu;
            rh.ray.id = 0;
            rh.ray.flags = 0;
            rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
            rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
            rtcIntersect1(scene, &ctx, &rh);
            int found = rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
            hits += (uint32_t)found;
            r->t[i] = found ? rh.ray.tfar : INFINITY;
        }
        double s = cpu_seconds() - start;
        if (s < r->seconds)
            r->seconds = s;
        r->hits = hits;
    }
}

/* Prints an Embree line against spancast's result. */
static void print_embree(const char *name, const ray_grid *g, const result *e,
                         const result *sc, double build)
{
    uint32_t differ = 0;
    double worst = 0;
    for (uint32_t i = 0; i < g->count; i++) {
        int a = isfinite(e->t[i]), b = isfinite(sc->t[i]);
        if (a != b) {
            differ++;
        } else if (a) {
            double rel = fabs(e->t[i] - sc->t[i]) / fabs(sc->t[i]);
            if (rel > worst)
                worst = rel;
        }
    }
    printf("%-9s %10.3f %10u %10u %12.2e %10.3f\n", name, g->count / e->seconds / 1e6,
           e->hits, differ, worst, build);
}
#endif

static int meshes_main(int argc, char **argv)
{
    const char *file = NULL;
    int w = 400, h = 300, reps = 3;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--size") && i + 1 < argc) {
            if (sscanf(argv[++i], "%d,%d", &w, &h) != 2 || w < 1 || h < 1 || w > 10000 ||
                h > 10000) {
                fprintf(stderr, "spancast bench meshes: bad --size '%s'\n", argv[i]);
                return 2;
            }
        } else if (!strcmp(argv[i], "--reps") && i + 1 < argc) {
            reps = atoi(argv[++i]);
            if (reps < 1 || reps > 1000) {
                fprintf(stderr, "spancast bench meshes: bad --reps '%s'\n", argv[i]);
                return 2;
            }
        } else if (!file && argv[i][0] != '-') {
            file = argv[i];
        } else {
            fprintf(stderr,
                    "usage: spancast bench meshes FILE.csg [--size W,H] [--reps N]\n");
            return 2;
        }
    }
    if (!file) {
        fprintf(stderr,
                "usage: spancast bench meshes FILE.csg [--size W,H] [--reps N]\n");
        return 2;
    }
    const char *why = NULL;
    size_t size = 0;
    char *text = file_read(file, (size_t)1 << 31, &size, &why);
    if (!text) {
        fprintf(stderr, "%s: error: %s\n", file, why);
        return 1;
    }
    double load_start = cpu_seconds();
    parse_tree *syntax = NULL;
    csg_tree *tree = NULL;
    sc_error err;
    sc_error *warnings = NULL;
    size_t warning_count = 0;
    model *typed = NULL;
    sc_status st = parse_text(file, text, size, &syntax, &err);
    if (st == SC_OK)
        st = model_lower(syntax, &typed, &err);
    if (st == SC_OK)
        st = build_scene(typed, 0, 0, &tree, NULL, &warnings, &warning_count, &err);
    double load = cpu_seconds() - load_start;
    free(warnings);
    model_free(typed);
    parse_tree_free(syntax);
    free(text);
    if (st != SC_OK) {
        char buf[1024];
        fprintf(stderr, "%s\n", sc_error_format(&err, buf, sizeof buf));
        return 1;
    }
    uint64_t triangles = 0;
    for (uint32_t i = 0; i < tree->leaf_count; i++)
        if (tree->leaves[i].prim.kind == PRIM_MESH && tree->leaves[i].prim.u.mesh.mesh)
            triangles += tree->leaves[i].prim.u.mesh.mesh->tri_count;
    ray_grid g;
    result sc = {0, 0, NULL};
    if (tree->root == CSG_EMPTY || !make_rays(tree, w, h, &g) ||
        !(sc.t = malloc(g.count * sizeof *sc.t))) {
        fprintf(stderr, "%s: error: empty model or out of memory\n", file);
        csg_tree_free(tree);
        return 1;
    }
    printf("model: %s, %llu mesh triangles in %u leaves, %dx%d rays, best of %d, "
           "1 thread, CPU time\n",
           file, (unsigned long long)triangles, tree->leaf_count, w, h, reps);
    printf("%-9s %10s %10s %10s %12s %10s\n", "engine", "Mrays/s", "hits", "differ",
           "max rel dt", "build s");
    run_spancast(tree, &g, reps, &sc);
    printf("%-9s %10.3f %10u %10s %12s %10.3f\n", "spancast", g.count / sc.seconds / 1e6,
           sc.hits, "-", "-", load);
#ifdef SPANCAST_HAVE_EMBREE
    RTCDevice dev = rtcNewDevice("threads=1");
    result e = {0, 0, malloc(g.count * sizeof(double))};
    for (int robust = 0; dev && e.t && robust < 2; robust++) {
        double build = 0;
        RTCScene scene = embree_scene(dev, tree, robust, &build);
        if (!scene)
            break;
        run_embree(scene, &g, reps, &e);
        print_embree(robust ? "robust" : "embree", &g, &e, &sc, build);
        rtcReleaseScene(scene);
    }
    free(e.t);
    if (dev)
        rtcReleaseDevice(dev);
#endif
    free(sc.t);
    free(g.dir);
    csg_tree_free(tree);
    return 0;
}

static void put_u32(unsigned char *p, uint32_t v)
{
    for (int k = 0; k < 4; k++)
        p[k] = (unsigned char)(v >> (8 * k));
}

static void put_f32(unsigned char *p, float f)
{
    uint32_t v;
    memcpy(&v, &f, sizeof v);
    put_u32(p, v);
}

/* The point at grid position (i, j), wrapped, so the seams share their
 * corners exactly. */
static vec3 torus_point(int i, int j, int nu, int nv)
{
    i %= nu;
    j %= nv;
    double u = 2 * PI * i / nu, v = 2 * PI * j / nv;
    double r = 10 + 1.5 * sin(12 * u) * sin(7 * v);
    return v3((30 + r * cos(v)) * cos(u), (30 + r * cos(v)) * sin(u), r * sin(v));
}

static int torus_main(int argc, char **argv)
{
    long want = 0;
    const char *file = NULL;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--triangles") && i + 1 < argc)
            want = atol(argv[++i]);
        else if (!file)
            file = argv[i];
    }
    if (want < 8 || want > 100000000L || !file) {
        fprintf(stderr, "usage: spancast bench torus-stl --triangles N FILE.stl\n");
        return 2;
    }
    /* nu * nv quads of two triangles, nu = 3 nv (the long way round) */
    int nv = (int)ceil(sqrt(want / 6.0));
    if (nv < 3)
        nv = 3;
    int nu = 3 * nv;
    uint32_t count = 2u * (uint32_t)nu * (uint32_t)nv;
    FILE *f = fopen(file, "wb");
    if (!f) {
        perror(file);
        return 1;
    }
    unsigned char header[84] = {0};
    memcpy(header, "spancast bench torus", 20);
    put_u32(header + 80, count);
    int ok = fwrite(header, 1, sizeof header, f) == sizeof header;
    for (int i = 0; ok && i < nu; i++)
        for (int j = 0; ok && j < nv; j++) {
            vec3 a = torus_point(i, j, nu, nv), b = torus_point(i + 1, j, nu, nv),
                 c = torus_point(i + 1, j + 1, nu, nv), d = torus_point(i, j + 1, nu, nv);
            const vec3 tri[2][3] = {{a, b, c}, {a, c, d}};
            for (int k = 0; ok && k < 2; k++) {
                unsigned char rec[50] = {0};
                for (int q = 0; q < 3; q++) {
                    put_f32(rec + 12 + 12 * q, (float)tri[k][q].x);
                    put_f32(rec + 16 + 12 * q, (float)tri[k][q].y);
                    put_f32(rec + 20 + 12 * q, (float)tri[k][q].z);
                }
                ok = fwrite(rec, 1, sizeof rec, f) == sizeof rec;
            }
        }
    if (fclose(f) != 0 || !ok) {
        fprintf(stderr, "%s: write error\n", file);
        return 1;
    }
    return 0;
}

int bench_meshes_main(int argc, char **argv)
{
    if (argc > 0 && !strcmp(argv[0], "torus-stl"))
        return torus_main(argc, argv);
    return meshes_main(argc, argv);
}
