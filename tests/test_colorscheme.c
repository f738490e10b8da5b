/* Tests of the colour-scheme reader (src/formats/colorscheme.c) on scheme
 * folders written here: Cornfield's built-in colours, a file read as
 * OpenSCAD reads it, files OpenSCAD would pass over (a colour missing, a
 * colour in another form, not JSON, not *.json), the first of two files
 * with one name winning, names listed in index order in the error, the
 * render options' scheme with its 2D colours, and Debian's folder (scripts/deps installs
 * openscad; without it the last test fails).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>

#include <cmocka.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "spancast/spancast.h"

static char folder[512];

static void write_file(const char *name, const char *text)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/%s", folder, name);
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs(text, f);
    fclose(f);
}

/* A scheme file with every key; colour `bad_key` replaced by `bad` when
 * bad_key is not NULL (an empty bad drops the key). */
static void write_scheme(const char *file, const char *name, int index,
                         const char *background, const char *bad_key, const char *bad)
{
    static const char *const keys[] = {
        "background",      "axes-color",   "opencsg-face-front", "opencsg-face-back",
        "cgal-face-front", "cgal-face-2d", "cgal-face-back",     "cgal-edge-front",
        "cgal-edge-back",  "cgal-edge-2d", "crosshair"};
    static const char *const values[] = {"",        "#010203", "#102030", "#405060",
                                         "#708090", "#0a0b0c", "#a0b0c0", "#d0e0f0",
                                         "#ff0000", "#0d0e0f", "#800000"};
    char text[2048];
    int n = snprintf(text, sizeof text,
                     "{ \"name\": \"%s\", \"index\": %d, \"show-in-gui\": true,\n"
                     "  \"colors\": {\n",
                     name, index);
    const char *sep = "";
    for (int k = 0; k < 11; k++) {
        const char *v = k == 0 ? background : values[k];
        if (bad_key && !strcmp(keys[k], bad_key)) {
            if (!*bad)
                continue;
            v = bad;
        }
        n += snprintf(text + n, sizeof text - (size_t)n, "%s    \"%s\": \"%s\"", sep,
                      keys[k], v);
        sep = ",\n";
    }
    snprintf(text + n, sizeof text - (size_t)n, "\n  }\n}\n");
    write_file(file, text);
}

static int setup(void **state)
{
    (void)state;
    snprintf(folder, sizeof folder, "%s", SPANCAST_TEST_WORK);
    mkdir(folder, 0755);
    write_scheme("b.json", "Beta", 1200, "#aabbcc", NULL, NULL);
    write_scheme("a.json", "Alpha", 1100, "#112233", NULL, NULL);
    write_scheme("missing.json", "Missing", 1300, "#000000", "crosshair", "");
    write_scheme("short.json", "Short", 1400, "#000000", "axes-color", "#fff");
    write_scheme("dup.json", "Zed", 900, "#123456", NULL, NULL);
    write_scheme("dup2.json", "Zed", 950, "#654321", NULL, NULL);
    write_scheme("other.txt", "Other", 1500, "#000000", NULL, NULL);
    write_file("broken.json", "{ \"name\": \"Broken\", ");
    return 0;
}

static void check_rgb(const float c[3], unsigned rgb)
{
    assert_true(c[0] == (float)((rgb >> 16) & 0xff) / 255.0f);
    assert_true(c[1] == (float)((rgb >> 8) & 0xff) / 255.0f);
    assert_true(c[2] == (float)(rgb & 0xff) / 255.0f);
}

/* Cornfield, as OpenSCAD 2021.01 builds it in, with or without a folder. */
static void test_cornfield(void **state)
{
    (void)state;
    sc_color_scheme s;
    sc_color_scheme_default(&s);
    assert_string_equal(s.name, "Cornfield");
    check_rgb(s.background, 0xffffe5);
    check_rgb(s.axes, 0x000000);
    check_rgb(s.face_front, 0xf9d72c);
    check_rgb(s.face_back, 0x9dcb51);
    check_rgb(s.render_face, 0xf9d72c);
    check_rgb(s.render_face_back, 0x9dcb51);
    check_rgb(s.edge, 0xffec5e);
    check_rgb(s.crosshair, 0x800000);
    sc_color_scheme found;
    sc_error e;
    assert_int_equal(sc_color_scheme_find("Cornfield", "/nonexistent", &found, &e),
                     SC_OK);
    assert_memory_equal(&found, &s, sizeof s);
}

static void test_read(void **state)
{
    (void)state;
    sc_color_scheme s;
    sc_error e;
    assert_int_equal(sc_color_scheme_find("Alpha", folder, &s, &e), SC_OK);
    assert_string_equal(s.name, "Alpha");
    check_rgb(s.background, 0x112233);
    check_rgb(s.axes, 0x010203);
    check_rgb(s.face_front, 0x102030);
    check_rgb(s.face_back, 0x405060);
    check_rgb(s.render_face, 0x708090);
    check_rgb(s.render_face_back, 0xa0b0c0);
    check_rgb(s.edge, 0xd0e0f0);
    check_rgb(s.crosshair, 0x800000);
}

/* sc_render_options_set_scheme: the scheme and its two 2D colours, which
 * sc_color_scheme has no room for; Cornfield's by default; options kept
 * on failure; options from a header without them refused. */
static void test_set_scheme(void **state)
{
    (void)state;
    sc_render_options o;
    sc_render_options_init(&o);
    check_rgb(o.face_2d, 0x00bf99);
    check_rgb(o.edge_2d, 0xff0000);
    sc_error e;
    assert_int_equal(o.use_scheme, 0);
    assert_int_equal(sc_render_options_set_scheme(&o, "Alpha", folder, &e), SC_OK);
    assert_int_equal(o.use_scheme, 1);
    assert_string_equal(o.scheme.name, "Alpha");
    check_rgb(o.scheme.background, 0x112233);
    check_rgb(o.face_2d, 0x0a0b0c);
    check_rgb(o.edge_2d, 0x0d0e0f);
    sc_render_options kept = o;
    assert_int_equal(sc_render_options_set_scheme(&o, "Missing", folder, &e),
                     SC_ERR_ARGUMENT);
    assert_memory_equal(&o, &kept, sizeof o);
    assert_int_equal(sc_render_options_set_scheme(&o, "Cornfield", folder, &e), SC_OK);
    check_rgb(o.face_2d, 0x00bf99);
    check_rgb(o.edge_2d, 0xff0000);
    o.size = offsetof(sc_render_options, face_2d);
    kept = o;
    assert_int_equal(sc_render_options_set_scheme(&o, "Alpha", folder, &e),
                     SC_ERR_ARGUMENT);
    assert_memory_equal(&o, &kept, sizeof o);
    assert_int_equal(sc_render_options_set_scheme(NULL, "Alpha", folder, &e),
                     SC_ERR_ARGUMENT);
}

/* The files OpenSCAD passes over are not schemes; the names are listed by
 * index, Cornfield (1000) among them; of two files named Zed only one
 * counts. */
static void test_unknown_lists_names(void **state)
{
    (void)state;
    sc_color_scheme s;
    sc_error e;
    assert_int_equal(sc_color_scheme_find("Missing", folder, &s, &e), SC_ERR_ARGUMENT);
    assert_string_equal(e.message, "unknown colour scheme 'Missing' (known: 'Zed', "
                                   "'Cornfield', 'Alpha', 'Beta')");
    assert_int_equal(sc_color_scheme_find("Short", folder, &s, &e), SC_ERR_ARGUMENT);
    assert_int_equal(sc_color_scheme_find("Other", folder, &s, &e), SC_ERR_ARGUMENT);
    assert_int_equal(sc_color_scheme_find("Broken", folder, &s, &e), SC_ERR_ARGUMENT);
    assert_int_equal(sc_color_scheme_find("Zed", folder, &s, &e), SC_OK);
    assert_int_equal(sc_color_scheme_find(NULL, folder, &s, &e), SC_ERR_ARGUMENT);
}

/* Debian's openscad package: the ten schemes OpenSCAD 2021.01 ships. */
static void test_debian_folder(void **state)
{
    (void)state;
    if (access(SC_COLOR_SCHEME_FOLDER "/metallic.json", R_OK) != 0)
        fail_msg("no %s/metallic.json: is openscad installed (scripts/deps)?",
                 SC_COLOR_SCHEME_FOLDER);
    static const char *const names[] = {
        "Metallic",  "Sunset",    "Starnight", "BeforeDawn",     "Nature",
        "DeepOcean", "Solarized", "Tomorrow",  "Tomorrow Night", "Monotone"};
    for (size_t k = 0; k < sizeof names / sizeof names[0]; k++) {
        sc_color_scheme s;
        sc_error e;
        if (sc_color_scheme_find(names[k], NULL, &s, &e) != SC_OK)
            fail_msg("%s: %s", names[k], e.message);
        assert_string_equal(s.name, names[k]);
    }
    sc_color_scheme s;
    sc_error e;
    assert_int_equal(sc_color_scheme_find("Metallic", NULL, &s, &e), SC_OK);
    check_rgb(s.background, 0xaaaaff);
    check_rgb(s.edge, 0xff0000);
    sc_render_options o;
    sc_render_options_init(&o);
    assert_int_equal(sc_render_options_set_scheme(&o, "Solarized", NULL, &e), SC_OK);
    check_rgb(o.face_2d, 0x6c71c4);
    check_rgb(o.edge_2d, 0xb58800);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_cornfield),     cmocka_unit_test(test_read),
        cmocka_unit_test(test_set_scheme),    cmocka_unit_test(test_unknown_lists_names),
        cmocka_unit_test(test_debian_folder),
    };
    return cmocka_run_group_tests(tests, setup, NULL);
}
