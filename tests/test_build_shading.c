/* Tests of the shading nodes (src/build/build_shading.c): light, material,
 * camera and background as the builder reads them into the scene's shading
 * record, the materials leaves get, how material() and color() nest (the
 * inner one wins), and the exact messages of bad arguments.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>

#include <cmocka.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "build/scene.h"
#include "spancast/spancast.h"

static sc_scene *load(const char *text)
{
    sc_scene *s = NULL;
    sc_error e;
    if (sc_scene_load_string("m.csg", text, strlen(text), NULL, &s, &e) != SC_OK)
        fail_msg("%s:%d:%d: %s", e.file, e.line, e.column, e.message);
    return s;
}

static void check_error(const char *text, const char *expected)
{
    sc_scene *s = (sc_scene *)1;
    sc_error e;
    assert_int_equal(sc_scene_load_string("m.csg", text, strlen(text), NULL, &s, &e),
                     SC_ERR_SEMANTIC);
    assert_null(s);
    char buf[1024];
    assert_string_equal(sc_error_format(&e, buf, sizeof buf), expected);
}

static int near(double a, double b)
{
    return fabs(a - b) < 1e-12;
}

static void test_lights(void **state)
{
    (void)state;
    sc_scene *s =
        load("light(position = [1, 2, 3]);\n"
             "multmatrix([[2, 0, 0, 10], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {\n"
             "  light(position = [1, 0, 0], color = \"red\", intensity = 2, "
             "radius = 0.5);\n"
             "  light(direction = [0, 0, -2]);\n"
             "}\n"
             "%light(position = [0, 0, 0]);\n"
             "*light(position = [0, 0, 0]);\n"
             "cube();\n");
    const shading *look = scene_shading(s);
    assert_int_equal(look->light_count, 3);
    const shading_light *l = look->lights;
    assert_int_equal(l[0].kind, SHADING_LIGHT_POINT);
    assert_true(near(l[0].position.x, 1) && near(l[0].position.y, 2) &&
                near(l[0].position.z, 3));
    assert_true(l[0].radius == 0 && l[0].intensity == 1 && l[0].color[1] == 1);
    /* transformed: position, and the radius by the largest axis scale */
    assert_true(near(l[1].position.x, 12) && near(l[1].position.y, 0));
    assert_true(near(l[1].radius, 1.0));
    assert_true(l[1].color[0] == 1 && l[1].color[1] == 0 && l[1].intensity == 2);
    assert_int_equal(l[2].kind, SHADING_LIGHT_DIRECTIONAL);
    assert_true(near(l[2].direction.z, -1));
    sc_scene_release(s);
}

/* Materials: leaves outside any material() get material 0; nesting gives
 * the inner material; a material()'s colour wins over a color() inside it,
 * and a color() over a material() colour inside it: the outermost colour
 * wins, as OpenSCAD 2021.01's preview keeps the outermost color(). */
static void test_materials(void **state)
{
    (void)state;
    sc_scene *s = load("cube();\n"
                       "material(color = [0, 0, 1], reflect = 0.5) {\n"
                       "  sphere();\n"
                       "  color([1, 0, 0]) { sphere(); }\n"
                       "  material(transmit = 0.8, ior = 1.33) { cylinder(); }\n"
                       "}\n"
                       "color([0, 1, 0]) { material(color = [1, 1, 1], checker = 2, "
                       "color2 = [0, 0, 0]) { cube(); } }\n");
    const shading *look = scene_shading(s);
    const csg_tree *t = scene_tree(s);
    assert_int_equal(t->leaf_count, 5);
    assert_int_equal(look->material_count, 4);
    assert_int_equal(t->leaves[0].material, 0);
    assert_true(look->materials[0].reflect == 0 && look->materials[0].transmit == 0);
    assert_int_equal(t->leaves[1].material, 1);
    assert_true(look->materials[1].reflect == 0.5);
    assert_true(t->leaves[1].color[2] == 1 && t->leaves[1].color[0] == 0);
    assert_int_equal(t->leaves[2].material, 1);
    assert_true(t->leaves[2].color[0] == 0 &&
                t->leaves[2].color[2] == 1); /* the material's, outer */
    assert_int_equal(t->leaves[3].material, 2);
    assert_true(look->materials[2].transmit == 0.8 && look->materials[2].ior == 1.33);
    assert_true(look->materials[2].reflect == 0); /* not inherited */
    assert_true(t->leaves[3].color[2] == 1);      /* the colour is inherited */
    assert_int_equal(t->leaves[4].material, 3);
    assert_true(t->leaves[4].color[1] == 1 && t->leaves[4].color[0] == 0); /* outer */
    assert_true(look->materials[3].checker == 2);
    sc_scene_release(s);
}

static void test_camera_and_background(void **state)
{
    (void)state;
    sc_scene *s = load("camera(eye = [1, 2, 3], center = [0, 0, 0], up = [0, 1, 0], "
                       "fov = 30, projection = \"orthographic\");\n"
                       "background(color = [0.1, 0.2, 0.3]);\ncube();\n");
    const shading *look = scene_shading(s);
    assert_true(look->has_camera && look->has_background);
    assert_true(look->background[2] == 0.3f);
    sc_render_options o;
    sc_render_options_init(&o);
    assert_int_equal(sc_render_options_from_scene(&o, s), 1);
    assert_int_equal(o.camera_mode, SC_CAMERA_VECTOR);
    assert_true(o.camera[0] == 1 && o.camera[2] == 3 && o.camera[5] == 0);
    assert_true(o.up[1] == 1 && o.up[2] == 0);
    assert_true(o.fov_deg == 30);
    assert_int_equal(o.projection, SC_PROJECTION_ORTHOGRAPHIC);
    sc_scene_release(s);
    /* no camera() node: options stay as they are */
    s = load("cube();\n");
    sc_render_options_init(&o);
    assert_int_equal(sc_render_options_from_scene(&o, s), 0);
    assert_int_equal(o.camera_mode, SC_CAMERA_AUTO);
    assert_false(scene_shading(s)->has_background);
    sc_scene_release(s);
}

static void test_errors(void **state)
{
    (void)state;
    check_error("light();",
                "m.csg:1:1: error: 'light' needs either position or direction");
    check_error("light(position = [0, 0, 0], direction = [1, 0, 0]);",
                "m.csg:1:1: error: 'light' needs either position or direction");
    check_error("light(direction = [0, 0, 0]);",
                "m.csg:1:19: error: argument 'direction' of 'light' must not be zero");
    check_error("light(direction = [0, 0, 1], radius = 2);",
                "m.csg:1:39: error: a directional light has no radius");
    check_error("light(position = [0, 0]);",
                "m.csg:1:18: error: wrong type for argument 'position' of 'light' "
                "(expected a vector of 3 numbers)");
    check_error("light(position = [0, 0, 0], intensity = -1);",
                "m.csg:1:41: error: argument 'intensity' of 'light' must be a "
                "non-negative number");
    check_error("light(position = [0, 0, 0]) { cube(); }",
                "m.csg:1:1: error: 'light' takes no children");
    check_error("material(color = [2, 0, 0]) { cube(); }",
                "m.csg:1:19: error: wrong type for argument 'color' of 'material' "
                "(expected a vector of 3 or 4 numbers in 0..1 or a colour name)");
    check_error("material(color = \"nocolour\") { cube(); }",
                "m.csg:1:18: error: unknown colour 'nocolour'");
    check_error("material(reflect = 1.5) { cube(); }",
                "m.csg:1:20: error: argument 'reflect' of 'material' must be a number "
                "in 0..1");
    check_error("material(reflect = 0.6, transmit = 0.6) { cube(); }",
                "m.csg:1:1: error: 'material': reflect + transmit must not exceed 1");
    check_error("material(checker = 0) { cube(); }",
                "m.csg:1:20: error: argument 'checker' of 'material' must be a positive "
                "number");
    check_error("material(ior = 0) { cube(); }",
                "m.csg:1:16: error: argument 'ior' of 'material' must be a positive "
                "number up to 1000");
    check_error("camera(eye = [0, 0, 1]);",
                "m.csg:1:1: error: 'camera' needs eye and center");
    check_error("camera(eye = [0, 0, 1], center = [0, 0, 1]);",
                "m.csg:1:1: error: camera eye and centre are the same point");
    check_error("camera(eye = [0, 0, 1], center = [0, 0, 0], projection = \"fish\");",
                "m.csg:1:58: error: wrong type for argument 'projection' of 'camera' "
                "(expected \"perspective\" or \"orthographic\")");
    check_error("camera(eye = [0, 0, 1], center = [0, 0, 0], fov = 180);",
                "m.csg:1:51: error: argument 'fov' of 'camera' must be between 0 and 180 "
                "degrees");
    check_error("background();", "m.csg:1:1: error: 'background' needs a color");
    /* errors are errors even in subtrees that are not built */
    check_error("%material(reflect = 2) { cube(); }",
                "m.csg:1:21: error: argument 'reflect' of 'material' must be a number "
                "in 0..1");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_lights),
        cmocka_unit_test(test_materials),
        cmocka_unit_test(test_camera_and_background),
        cmocka_unit_test(test_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
