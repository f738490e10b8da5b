/* Tests of image output (src/formats/image_io.c and its back ends).
 *
 * Each writer's file is read back twice, through image_read (PNG and EXR
 * read directly) and through OpenImageIO in the plugin, which must agree,
 * and compared with the framebuffer; depth keeps +inf. The failure cases
 * check the exact messages and that a failed write leaves an existing
 * target as it was and no temporary file behind.
 */
#define _DEFAULT_SOURCE /* setgroups */

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>

#include <cmocka.h>
#include <dirent.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <grp.h>
#include <pwd.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include "formats/color.h"
#include "formats/image_backend.h"
#include "formats/image_io.h"
#include "formats/image_read.h"
#include "spancast/spancast.h"

#ifndef SPANCAST_TEST_WORK
#define SPANCAST_TEST_WORK "test_image_io.work"
#endif

static char work[1024];

static const char *path_in_work(char *buf, size_t size, const char *name)
{
    snprintf(buf, size, "%s/%s", work, name);
    return buf;
}

static int setup(void **state)
{
    (void)state;
    snprintf(work, sizeof work, "%s", SPANCAST_TEST_WORK);
    char cmd[2200];
    snprintf(cmd, sizeof cmd, "rm -rf '%s' && mkdir -p '%s'", work, work);
    return system(cmd) == 0 ? 0 : -1;
}

/* A 5 x 3 framebuffer with a gradient, a mask and a depth with misses. */
static sc_framebuffer *make_fb(void)
{
    sc_framebuffer *fb = calloc(1, sizeof *fb);
    fb->width = 5;
    fb->height = 3;
    size_t n = 15;
    fb->color = malloc(n * 3 * sizeof(float));
    fb->mask = malloc(n);
    fb->depth = malloc(n * sizeof(float));
    for (size_t p = 0; p < n; p++) {
        fb->color[3 * p + 0] = (float)p / 14.0f;
        fb->color[3 * p + 1] = 1.0f - (float)p / 14.0f;
        fb->color[3 * p + 2] = 0.5f;
        fb->mask[p] = (p % 3) ? 255 : 0;
        fb->depth[p] = (p % 3) ? 1.25f + (float)p : INFINITY;
    }
    return fb;
}

/* Entries of the work folder whose names start with '.' other than . and
 * .. (leftover temporaries). */
static int hidden_entries(void)
{
    DIR *d = opendir(work);
    assert_non_null(d);
    int count = 0;
    struct dirent *e;
    while ((e = readdir(d)))
        if (e->d_name[0] == '.' && strcmp(e->d_name, ".") && strcmp(e->d_name, ".."))
            count++;
    closedir(d);
    return count;
}

static void read_back(const char *path, image_data *img)
{
    char err[512];
    if (!image_read(path, img, err, sizeof err))
        fail_msg("%s", err);
    /* OpenImageIO, an independent reader, sees the same pixels */
    imgio_plugin plugin;
    if (!imgio_plugin_open(&plugin, err, sizeof err))
        fail_msg("%s", err);
    image_data other;
    int ok = plugin.read(path, &other, err, sizeof err);
    imgio_plugin_close(&plugin);
    if (!ok)
        fail_msg("%s", err);
    assert_int_equal(other.width, img->width);
    assert_int_equal(other.height, img->height);
    assert_int_equal(other.channels, img->channels);
    size_t values = (size_t)img->width * (size_t)img->height * (size_t)img->channels;
    /* OpenImageIO turns 8-bit values into floats by a product, image_read by
     * a division: the last bit may differ */
    for (size_t k = 0; k < values; k++)
        if (other.pixels[k] != img->pixels[k] &&
            !(fabsf(other.pixels[k] - img->pixels[k]) < 1e-6f))
            fail_msg("%s: value %zu: %.9g here, %.9g through OpenImageIO", path, k,
                     (double)img->pixels[k], (double)other.pixels[k]);
    image_data_free(&other);
}

static float float_bits(uint32_t bits)
{
    float v;
    memcpy(&v, &bits, sizeof v);
    return v;
}

/* The 8-bit encoder by table gives color_linear_to_srgb8's byte: at every
 * threshold and the float before it (where the code changes), at every
 * bucket's first float and the float before it (where the table's start
 * changes), at every 4099th float of [0, 1] (a run over all of them,
 * about 10^9, found no difference), and at values outside it. The
 * thresholds are where the code changes: the float before each has a
 * smaller code. */
static void test_srgb8_thresholds(void **state)
{
    (void)state;
    color_srgb8_table *table = malloc(sizeof *table);
    assert_non_null(table);
    color_srgb8_table_init(table);
    const float *t = table->above;
    for (unsigned k = 0; k < COLOR_SRGB8_THRESHOLDS; k++) {
        uint32_t bits;
        memcpy(&bits, &t[k], sizeof bits);
        assert_int_equal(color_srgb8_encode(table, t[k]), k + 1);
        assert_int_equal(color_linear_to_srgb8(t[k]), k + 1);
        assert_int_equal(color_srgb8_encode(table, float_bits(bits - 1)),
                         color_linear_to_srgb8(float_bits(bits - 1)));
        assert_true(color_linear_to_srgb8(float_bits(bits - 1)) <= k);
    }
    for (uint32_t b = 1; b < COLOR_SRGB8_BUCKETS; b++) {
        uint32_t bits = b << 16;
        assert_int_equal(color_srgb8_encode(table, float_bits(bits)),
                         color_linear_to_srgb8(float_bits(bits)));
        assert_int_equal(color_srgb8_encode(table, float_bits(bits - 1)),
                         color_linear_to_srgb8(float_bits(bits - 1)));
    }
    for (uint32_t bits = 0; bits <= 0x3f800000u; bits += 4099)
        assert_int_equal(color_srgb8_encode(table, float_bits(bits)),
                         color_linear_to_srgb8(float_bits(bits)));
    const float outside[] = {NAN, -INFINITY, -1, -0.0f, 0, 1, 1.5f, INFINITY};
    for (size_t k = 0; k < sizeof outside / sizeof *outside; k++)
        assert_int_equal(color_srgb8_encode(table, outside[k]),
                         color_linear_to_srgb8(outside[k]));
    free(table);
}

static void test_color_png(void **state)
{
    (void)state;
    sc_framebuffer *fb = make_fb();
    char path[1100];
    sc_error e;
    path_in_work(path, sizeof path, "color.png");
    assert_int_equal(sc_framebuffer_write_color(fb, path, &e), SC_OK);
    image_data img;
    read_back(path, &img);
    assert_int_equal(img.width, 5);
    assert_int_equal(img.height, 3);
    assert_int_equal(img.channels, 3);
    for (size_t k = 0; k < 45; k++) {
        /* linear values, sRGB-encoded in 8-bit files */
        float want = color_linear_to_srgb8(fb->color[k]) / 255.0f;
        assert_true(fabsf(img.pixels[k] - want) < 1e-6f);
    }
    image_data_free(&img);
    /* float formats keep the values */
    path_in_work(path, sizeof path, "color.exr");
    assert_int_equal(sc_framebuffer_write_color(fb, path, &e), SC_OK);
    read_back(path, &img);
    assert_int_equal(img.channels, 3);
    assert_memory_equal(img.pixels, fb->color, 45 * sizeof(float));
    image_data_free(&img);
    assert_int_equal(hidden_entries(), 0);
    sc_framebuffer_release(fb);
}

static void test_mask_and_depth(void **state)
{
    (void)state;
    sc_framebuffer *fb = make_fb();
    char path[1100];
    sc_error e;
    image_data img;
    path_in_work(path, sizeof path, "mask.png");
    assert_int_equal(sc_framebuffer_write_mask(fb, path, &e), SC_OK);
    read_back(path, &img);
    assert_int_equal(img.channels, 1);
    for (size_t p = 0; p < 15; p++)
        assert_true(img.pixels[p] == (fb->mask[p] ? 1.0f : 0.0f));
    image_data_free(&img);

    const char *names[] = {"depth.exr", "depth.tif", "DEPTH.EXR"};
    for (int k = 0; k < 3; k++) {
        path_in_work(path, sizeof path, names[k]);
        assert_int_equal(sc_framebuffer_write_depth(fb, path, &e), SC_OK);
        read_back(path, &img);
        assert_int_equal(img.channels, 1);
        for (size_t p = 0; p < 15; p++) {
            if (isinf(fb->depth[p]))
                assert_true(isinf(img.pixels[p]) && img.pixels[p] > 0);
            else
                assert_true(img.pixels[p] == fb->depth[p]);
        }
        image_data_free(&img);
    }
    assert_int_equal(hidden_entries(), 0);
    sc_framebuffer_release(fb);
}

static void test_format_errors(void **state)
{
    (void)state;
    sc_framebuffer *fb = make_fb();
    sc_error e;
    assert_int_equal(sc_framebuffer_write_color(fb, "x.foo", &e), SC_ERR_ARGUMENT);
    assert_string_equal(e.message, "cannot write 'x.foo': unknown image format");
    assert_int_equal(sc_framebuffer_write_mask(fb, "noextension", &e), SC_ERR_ARGUMENT);
    assert_string_equal(e.message, "cannot write 'noextension': unknown image format");
    assert_int_equal(sc_framebuffer_write_color(fb, "dir.png/name", &e), SC_ERR_ARGUMENT);
    assert_string_equal(e.message, "cannot write 'dir.png/name': unknown image format");
    assert_int_equal(sc_framebuffer_write_depth(fb, "d.png", &e), SC_ERR_ARGUMENT);
    assert_string_equal(e.message, "cannot write depth to 'd.png': depth needs a "
                                   "floating-point format (.exr or .tif)");
    assert_int_equal(imgio_check("a.PNG", IMGIO_COLOR, &e), SC_OK);
    assert_int_equal(imgio_check("a.jpg", IMGIO_MASK, &e), SC_OK);
    assert_int_equal(imgio_check("a.jpg", IMGIO_DEPTH, &e), SC_ERR_ARGUMENT);

    sc_framebuffer none;
    memset(&none, 0, sizeof none);
    assert_int_equal(sc_framebuffer_write_depth(&none, "d.exr", &e), SC_ERR_ARGUMENT);
    assert_string_equal(e.message, "the framebuffer has no depth buffer");
    sc_framebuffer_release(fb);
}

static void write_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs(text, f);
    fclose(f);
}

static void test_failures_keep_target(void **state)
{
    (void)state;
    sc_framebuffer *fb = make_fb();
    char path[1100], dir[1100];
    sc_error e;

    /* a folder that does not exist */
    path_in_work(path, sizeof path, "missing/out.png");
    assert_int_equal(sc_framebuffer_write_color(fb, path, &e), SC_ERR_IO);
    char want[1300];
    snprintf(want, sizeof want, "cannot write '%s': No such file or directory", path);
    assert_string_equal(e.message, want);

    /* a "folder" that is a file */
    path_in_work(dir, sizeof dir, "plain");
    write_text(dir, "x");
    path_in_work(path, sizeof path, "plain/out.png");
    assert_int_equal(sc_framebuffer_write_color(fb, path, &e), SC_ERR_IO);
    snprintf(want, sizeof want, "cannot write '%s': Not a directory", path);
    assert_string_equal(e.message, want);

    /* the target is a folder: the image is written, the rename fails, and
     * the temporary goes away */
    path_in_work(path, sizeof path, "taken.png");
    assert_int_equal(mkdir(path, 0755), 0);
    assert_int_equal(sc_framebuffer_write_color(fb, path, &e), SC_ERR_IO);
    snprintf(want, sizeof want, "cannot write '%s': Is a directory", path);
    assert_string_equal(e.message, want);
    struct stat st;
    assert_int_equal(stat(path, &st), 0);
    assert_true(S_ISDIR(st.st_mode));
    assert_int_equal(hidden_entries(), 0);

    /* an existing target is replaced whole on success */
    path_in_work(path, sizeof path, "replace.png");
    write_text(path, "old contents");
    assert_int_equal(sc_framebuffer_write_mask(fb, path, &e), SC_OK);
    image_data img;
    read_back(path, &img);
    assert_int_equal(img.width, 5);
    image_data_free(&img);
    assert_int_equal(hidden_entries(), 0);
    sc_framebuffer_release(fb);
}

/* The read-only folder case, in folder dir: a write into dir/readonly
 * must fail with the exact message and leave the file there as it was, with
 * no temporary beside it. Runs in a child process, so it reports with its
 * exit status: 0 when every check holds, else the number of the check that
 * failed (its reason on stderr). */
static int readonly_case(sc_framebuffer *fb, const char *dir)
{
    char sub[1200], path[1300], want[1500];
    snprintf(sub, sizeof sub, "%s/readonly", dir);
    snprintf(path, sizeof path, "%s/out.png", sub);
    if (mkdir(sub, 0755) != 0)
        return 1;
    FILE *f = fopen(path, "w");
    if (!f || fputs("old", f) < 0 || fclose(f) != 0)
        return 2;
    if (chmod(sub, 0555) != 0)
        return 3;
    sc_error e;
    sc_status st = sc_framebuffer_write_color(fb, path, &e);
    snprintf(want, sizeof want, "cannot write '%s': Permission denied", path);
    if (st != SC_ERR_IO || strcmp(e.message, want) != 0) {
        fprintf(stderr, "read-only folder: status %d, '%s'\n", (int)st,
                st == SC_OK ? "" : e.message);
        return 4;
    }
    char buf[8] = {0};
    f = fopen(path, "r");
    if (!f || !fgets(buf, sizeof buf, f) || strcmp(buf, "old") != 0) {
        fprintf(stderr, "read-only folder: the file now holds '%s'\n", buf);
        return 5;
    }
    fclose(f);
    DIR *d = opendir(sub);
    int entries = 0;
    for (struct dirent *x; d && (x = readdir(d));)
        entries += strcmp(x->d_name, ".") && strcmp(x->d_name, "..");
    if (d)
        closedir(d);
    if (entries != 1) {
        fprintf(stderr, "read-only folder: %d entries, not just out.png\n", entries);
        return 6;
    }
    chmod(sub, 0755);
    return 0;
}

/* A write into a folder without write permission. Root may write anywhere,
 * so as root the case runs in a child that has dropped to 'nobody', in a
 * folder of /tmp that user owns (the build tree may sit under a folder it
 * cannot enter); as any other user it runs in the work folder. */
static void test_readonly_folder(void **state)
{
    (void)state;
    sc_framebuffer *fb = make_fb();
    char dir[1100];
    const struct passwd *nobody = NULL;
    if (geteuid() == 0) {
        nobody = getpwnam("nobody");
        assert_non_null(nobody);
        snprintf(dir, sizeof dir, "/tmp/spancast-io.XXXXXX");
        assert_non_null(mkdtemp(dir));
        assert_int_equal(chown(dir, nobody->pw_uid, nobody->pw_gid), 0);
    } else {
        path_in_work(dir, sizeof dir, "unprivileged");
        assert_int_equal(mkdir(dir, 0755), 0);
    }
    fflush(NULL);
    pid_t child = fork();
    assert_true(child >= 0);
    if (child == 0) {
        if (nobody && (setgroups(0, NULL) != 0 || setgid(nobody->pw_gid) != 0 ||
                       setuid(nobody->pw_uid) != 0 || geteuid() == 0))
            _exit(100);
        _exit(readonly_case(fb, dir));
    }
    int status = 0;
    assert_int_equal(waitpid(child, &status, 0), child);
    if (nobody) {
        char cmd[1200];
        snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
        assert_int_equal(system(cmd), 0);
    }
    assert_true(WIFEXITED(status));
    assert_int_equal(WEXITSTATUS(status), 0);
    sc_framebuffer_release(fb);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_srgb8_thresholds),
        cmocka_unit_test(test_color_png),
        cmocka_unit_test(test_mask_and_depth),
        cmocka_unit_test(test_format_errors),
        cmocka_unit_test(test_failures_keep_target),
        cmocka_unit_test(test_readonly_folder),
    };
    return cmocka_run_group_tests(tests, setup, NULL);
}
