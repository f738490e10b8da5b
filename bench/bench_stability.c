/* `spancast bench stability`: the numerical stability suite as a report.
 *
 * Runs the stiff and extreme cases of tests/test_stability.c (the models in
 * tests/stability/ under the project folder given by --dir, default ".")
 * through the metamorphic harness (src/render/stability.c) and writes one
 * CSV row per case:
 *   case,pixels,mask_mismatches,max_rel_depth_error,nan_count,seconds
 * pixels is the image size squared (--size, default 64); mask_mismatches
 * counts pixels hit in one of the two renders and not the other (for the
 * far camera, chords below its resolution are left out, see
 * docs/stability.md); max_rel_depth_error is the largest |t' - t| / t;
 * nan_count counts hits whose depth or normal is not finite; seconds is the
 * wall time of the case (loading both models included). The cases:
 *   scale_S          part.csg scaled by S (1e-6 .. 1e6) about the origin
 *   translate_T      part.csg moved to (T, -0.6 T, 0.3 T)
 *   random_similarity part.csg under 8 random rotations, scales over 12
 *                    decades and translations up to 1000 radii (summed)
 *   coincident_OP    coincident faces against the solid they must equal,
 *                    in place and moved to 1e8 (_at_1e8)
 *   thin_wall, edge_hole   under a random similarity
 *   ill_scale_z_1e-9, ill_shear, mirror   part.csg under affine maps of
 *                    condition number 1.4e9, 1e6 and 1
 *   singular         part.csg under a singular matrix: the empty solid with
 *                    one warning, so every hit would be a mismatch
 *   deep_differences_D, wide_union_100000   generated trees, moved by a
 *                    random similarity (the deep one D = --depth levels,
 *                    default 10000, on an 8 x 8 image)
 *   far_camera_1e9   part.csg from 1e9 away against 10 radii away
 *   model:FILE       every model in DIR/models under 3 random similarities
 * The exit status is 1 when a case has a mismatch, a NaN or a depth error
 * over its bound, so the report doubles as a check.
 */
#include <dirent.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

#include "build/scene.h"
#include "bench/bench.h"
#include "bench/stability.h"

typedef struct row {
    char name[96];
    stab_result r;
    double seconds;
} row;

typedef struct bench {
    const char *dir;
    int size;
    int depth; /* levels of the deep case (--depth), the multmatrix included */
    row *rows;
    int count, room;
    int failed; /* a load failed or a case broke its bound */
} bench;

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* The text of a file, malloc'd; NULL (with a message) when unreadable. */
static char *read_text(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f) {
        fprintf(stderr, "spancast: error: cannot read '%s': %s\n", path, strerror(errno));
        return NULL;
    }
    char *text = NULL;
    size_t n = 0, room = 0;
    for (;;) {
        if (n + 4096 + 1 > room) {
            room = 2 * room + 4096 + 1;
            char *bigger = realloc(text, room);
            if (!bigger) {
                free(text);
                fclose(f);
                fprintf(stderr, "spancast: error: out of memory\n");
                return NULL;
            }
            text = bigger;
        }
        size_t got = fread(text + n, 1, 4096, f);
        n += got;
        if (got < 4096)
            break;
    }
    fclose(f);
    text[n] = 0;
    return text;
}

static char *read_case(bench *b, const char *file)
{
    char path[4096];
    snprintf(path, sizeof path, "%s/tests/stability/%s", b->dir, file);
    return read_text(path);
}

static row *new_row(bench *b, const char *name)
{
    if (b->count == b->room) {
        int room = b->room ? 2 * b->room : 64;
        row *bigger = realloc(b->rows, (size_t)room * sizeof *bigger);
        if (!bigger)
            return NULL;
        b->rows = bigger;
        b->room = room;
    }
    row *r = &b->rows[b->count++];
    memset(r, 0, sizeof *r);
    snprintf(r->name, sizeof r->name, "%.*s", (int)sizeof r->name - 1, name);
    return r;
}

static void add(stab_result *sum, const stab_result *r)
{
    sum->pixels += r->pixels;
    sum->hits += r->hits;
    sum->mask_mismatches += r->mask_mismatches;
    sum->nan_count += r->nan_count;
    sum->depth_violations += r->depth_violations;
    sum->below_resolution += r->below_resolution;
    if (r->max_rel_depth_error > sum->max_rel_depth_error)
        sum->max_rel_depth_error = r->max_rel_depth_error;
}

/* Runs a compare case and records its row; text and moved are the model
 * and the solid compared with it (NULL: the model); source names the file
 * the text came from (positions, and imports relative to it), NULL: name. */
static void compare_case(bench *b, const char *name, const char *source, const char *text,
                         const char *moved, const stab_similarity *x, int times)
{
    row *r = new_row(b, name);
    if (!r || !text) {
        b->failed = 1;
        return;
    }
    double start = now();
    for (int k = 0; k < times; k++) {
        stab_result one;
        sc_error e;
        stab_similarity xk = x ? *x : stab_random((uint64_t)k + 1, -6, 6, 2.0, 1e3);
        if (stab_compare(source ? source : name, text, moved, &xk, b->size, &one, &e) !=
            SC_OK) {
            fprintf(stderr, "spancast: error: %s: %s\n", name, e.message);
            b->failed = 1;
            return;
        }
        add(&r->r, &one);
    }
    r->seconds = now() - start;
}

static void file_case(bench *b, const char *name, const char *file,
                      const char *moved_file, const stab_similarity *x)
{
    char *text = read_case(b, file),
         *moved = moved_file ? read_case(b, moved_file) : NULL;
    if (moved_file && !moved)
        b->failed = 1;
    else
        compare_case(b, name, NULL, text, moved, x, 1);
    free(text);
    free(moved);
}

static void model_cases(bench *b)
{
    char folder[4096];
    snprintf(folder, sizeof folder, "%s/models", b->dir);
    DIR *d = opendir(folder);
    if (!d) {
        fprintf(stderr, "spancast: error: cannot read '%s': %s\n", folder,
                strerror(errno));
        b->failed = 1;
        return;
    }
    char names[64][256];
    int n = 0;
    struct dirent *e;
    while ((e = readdir(d)) && n < 64) {
        size_t len = strlen(e->d_name);
        if (len > 4 && len < 256 && !strcmp(e->d_name + len - 4, ".csg"))
            memcpy(names[n++], e->d_name, len + 1);
    }
    closedir(d);
    qsort(names, (size_t)n, sizeof names[0], (int (*)(const void *, const void *))strcmp);
    for (int i = 0; i < n; i++) {
        char path[4096 + 256], name[300];
        const char *file = names[i];
        snprintf(path, sizeof path, "%s/%.255s", folder, file);
        snprintf(name, sizeof name, "model:%.255s", file);
        char *text = read_text(path);
        compare_case(b, name, path, text, NULL, NULL, 3);
        free(text);
    }
}

/* The part under an exactly singular matrix must load as the empty solid
 * (with a warning): every pixel hit is a mismatch. */
static void singular_case(bench *b, const char *part)
{
    row *r = new_row(b, "singular");
    if (!r || !part) {
        b->failed = 1;
        return;
    }
    double start = now();
    const char *head =
        "multmatrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 0, 0], [0, 0, 0, 1]]) {\n";
    size_t n = strlen(head) + strlen(part) + 4;
    char *text = malloc(n);
    sc_scene *scene = NULL;
    sc_error e;
    if (!text) {
        b->failed = 1;
        return;
    }
    snprintf(text, n, "%s%s\n}\n", head, part);
    if (sc_scene_load_string("singular.csg", text, strlen(text), NULL, &scene, &e) !=
        SC_OK) {
        fprintf(stderr, "spancast: error: singular: %s\n", e.message);
        b->failed = 1;
    } else {
        r->r.pixels = (uint64_t)b->size * (uint64_t)b->size;
        r->r.nan_count = stab_nan_scan(scene_tree(scene), b->size, &r->r.mask_mismatches);
        if (sc_scene_warning_count(scene) != 1)
            b->failed = 1;
        sc_scene_release(scene);
    }
    free(text);
    r->seconds = now() - start;
}

static void run_cases(bench *b)
{
    static const char *scale_names[] = {"scale_1e-6", "scale_1e-3", "scale_1",
                                        "scale_1e3", "scale_1e6"};
    static const double scales[] = {1e-6, 1e-3, 1, 1e3, 1e6};
    for (int i = 0; i < 5; i++) {
        stab_similarity x = stab_scaled(scales[i], scales[i], scales[i], v3(0, 0, 0));
        file_case(b, scale_names[i], "part.csg", NULL, &x);
    }
    stab_similarity t6 = stab_scaled(1, 1, 1, v3(1e6, -0.6e6, 0.3e6));
    stab_similarity t8 = stab_scaled(1, 1, 1, v3(1e8, -0.6e8, 0.3e8));
    file_case(b, "translate_1e6", "part.csg", NULL, &t6);
    file_case(b, "translate_1e8", "part.csg", NULL, &t8);
    char *part = read_case(b, "part.csg");
    compare_case(b, "random_similarity", NULL, part, NULL, NULL, 8);

    stab_similarity identity = stab_scaled(1, 1, 1, v3(0, 0, 0));
    static const char *ops[] = {"union", "intersection", "difference"};
    for (int i = 0; i < 3; i++) {
        char name[64], model[64], expected[64];
        snprintf(name, sizeof name, "coincident_%s", ops[i]);
        snprintf(model, sizeof model, "coincident_%s.csg", ops[i]);
        snprintf(expected, sizeof expected, "coincident_%s_expected.csg", ops[i]);
        file_case(b, name, expected, model, &identity);
        snprintf(name, sizeof name, "coincident_%s_at_1e8", ops[i]);
        file_case(b, name, expected, model, &t8);
    }
    stab_similarity thin = stab_random(7, -3, 3, 1.0, 10);
    file_case(b, "thin_wall", "thin_wall.csg", NULL, &thin);
    stab_similarity edge = stab_random(9, -3, 3, 1.0, 10);
    file_case(b, "edge_hole", "edge_hole.csg", NULL, &edge);

    stab_similarity flat = stab_scaled(1, 1, 1e-9, v3(0, 0, 0));
    compare_case(b, "ill_scale_z_1e-9", NULL, part, NULL, &flat, 1);
    stab_similarity shear = identity;
    shear.m[0][1] = 1e3;
    shear.m[1][2] = -200;
    compare_case(b, "ill_shear", NULL, part, NULL, &shear, 1);
    stab_similarity mirror = stab_scaled(-1, 1, 1, v3(3, 0, 0));
    compare_case(b, "mirror", NULL, part, NULL, &mirror, 1);
    singular_case(b, part);

    /* depth - 2 differences around a leaf, inside the harness's multmatrix:
     * the moved model is depth levels deep (default 10000, the limit). */
    char *deep = stab_deep_differences(b->depth - 2);
    char deep_name[64];
    snprintf(deep_name, sizeof deep_name, "deep_differences_%d", b->depth);
    stab_similarity move = stab_random(3, -6, 6, 2.0, 1e3);
    /* A ray through all 5000 shells costs quadratic time in the depth (each
     * level merges the list below it), so this case uses an 8 x 8 image. */
    int size = b->size;
    b->size = size < 8 ? size : 8;
    compare_case(b, deep_name, NULL, deep, NULL, &move, 1);
    b->size = size;
    free(deep);
    char *wide = stab_wide_union(100000);
    compare_case(b, "wide_union_100000", NULL, wide, NULL, &move, 1);
    free(wide);

    row *far = new_row(b, "far_camera_1e9");
    if (far && part) {
        sc_error e;
        double start = now();
        if (stab_far_camera("part.csg", part, 1e9, b->size, &far->r, &e) != SC_OK) {
            fprintf(stderr, "spancast: error: far camera: %s\n", e.message);
            b->failed = 1;
        }
        far->seconds = now() - start;
    } else {
        b->failed = 1;
    }
    free(part);
    model_cases(b);
}

static int write_csv(const char *path, const bench *b)
{
    FILE *f = fopen(path, "w");
    if (!f) {
        fprintf(stderr, "spancast: error: cannot write '%s': %s\n", path,
                strerror(errno));
        return 0;
    }
    fprintf(f, "case,pixels,mask_mismatches,max_rel_depth_error,nan_count,seconds\n");
    for (int i = 0; i < b->count; i++) {
        const row *r = &b->rows[i];
        fprintf(f, "%s,%llu,%llu,%.3g,%llu,%.3f\n", r->name,
                (unsigned long long)r->r.pixels, (unsigned long long)r->r.mask_mismatches,
                r->r.max_rel_depth_error, (unsigned long long)r->r.nan_count, r->seconds);
    }
    if (fclose(f) != 0) {
        fprintf(stderr, "spancast: error: cannot write '%s': %s\n", path,
                strerror(errno));
        remove(path);
        return 0;
    }
    return 1;
}

int bench_stability_main(int argc, char **argv)
{
    const char *csv = NULL;
    bench b;
    memset(&b, 0, sizeof b);
    b.dir = ".";
    b.size = 64;
    b.depth = 10000;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        const char *value = i + 1 < argc ? argv[i + 1] : NULL;
        if (strcmp(a, "--csv") && strcmp(a, "--dir") && strcmp(a, "--size") &&
            strcmp(a, "--depth")) {
            fprintf(stderr, "spancast: error: unknown option '%s'\n", a);
            return 2;
        }
        if (!value) {
            fprintf(stderr, "spancast: error: option '%s' expects a value\n", a);
            return 2;
        }
        i++;
        if (!strcmp(a, "--csv")) {
            csv = value;
        } else if (!strcmp(a, "--dir")) {
            b.dir = value;
        } else if (!strcmp(a, "--depth")) {
            char *end;
            long n = strtol(value, &end, 10);
            if (*end || n < 3 || n > 10000) {
                fprintf(stderr, "spancast: error: --depth expects an integer from 3 to "
                                "10000 (levels of the deep case)\n");
                return 2;
            }
            b.depth = (int)n;
        } else {
            char *end;
            long n = strtol(value, &end, 10);
            if (*end || n < 1 || n > 4096) {
                fprintf(stderr,
                        "spancast: error: --size expects an integer from 1 to 4096 "
                        "(pixels per side)\n");
                return 2;
            }
            b.size = (int)n;
        }
    }
    if (!csv) {
        fprintf(stderr, "spancast: error: missing --csv FILE\n");
        return 2;
    }
    /* Without the cases every row would be empty: say so, and write
     * nothing. */
    char cases[4096];
    struct stat info;
    snprintf(cases, sizeof cases, "%s/tests/stability", b.dir);
    if (stat(cases, &info) != 0 || !S_ISDIR(info.st_mode)) {
        fprintf(stderr,
                "spancast: error: no stability cases in '%s' (run it in the source "
                "folder, or give it with --dir DIR)\n",
                cases);
        return 1;
    }
    run_cases(&b);
    int bad = b.failed;
    for (int i = 0; i < b.count; i++) {
        const stab_result *r = &b.rows[i].r;
        int broken = r->mask_mismatches || r->nan_count || r->depth_violations;
        bad |= broken;
        fprintf(stderr,
                "%-28s %7llu px %6llu hits  mismatches %llu  nan %llu  "
                "max rel depth %.3g  %.3f s%s\n",
                b.rows[i].name, (unsigned long long)r->pixels,
                (unsigned long long)r->hits, (unsigned long long)r->mask_mismatches,
                (unsigned long long)r->nan_count, r->max_rel_depth_error,
                b.rows[i].seconds, broken ? "  FAILED" : "");
    }
    int written = write_csv(csv, &b);
    free(b.rows);
    return !written || bad ? 1 : 0;
}
