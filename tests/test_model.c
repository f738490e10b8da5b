/* Tests of the lowering pass (src/model/lower.c): the typed fields of each
 * lowered kind, which nodes the model holds (no '*' subtrees, no 3D
 * leaves' children; 2D subtrees in the 2D context), the root mark, the table of node
 * kinds, and argument errors, which become the model's last node with the exact message
 * and position. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "model/model.h"
#include "syntax/parse.h"

#include "../fuzz/split_harness.h"

typedef struct lowered {
    parse_tree *syntax;
    model *m;
} lowered;

static lowered lower(const char *text)
{
    lowered l = {NULL, NULL};
    sc_error e;
    if (parse_text("m.csg", text, strlen(text), &l.syntax, &e) != SC_OK)
        fail_msg("parse error: %s", e.message);
    if (model_lower(l.syntax, &l.m, &e) != SC_OK)
        fail_msg("lowering failed: %s", e.message);
    return l;
}

static void release(lowered *l)
{
    model_free(l->m);
    parse_tree_free(l->syntax);
}

static int count_siblings(const model_node *n)
{
    int count = 0;
    for (; n; n = n->next)
        count++;
    return count;
}

static void test_leaves(void **state)
{
    (void)state;
    lowered l = lower("cube(size = [1, 2, 3], center = true);\n"
                      "sphere(d = 4, $fn = 8);\n"
                      "cylinder(h = 5, r = 2, r2 = 1, $fa = 6, $fs = 0.5);\n"
                      "cube(7);\n");
    const model_node *n = l.m->first;
    assert_int_equal(n->kind, MODEL_CUBE);
    assert_true(n->u.cube.size[0] == 1 && n->u.cube.size[1] == 2 &&
                n->u.cube.size[2] == 3);
    assert_true(n->u.cube.center);
    assert_int_equal(n->loc.line, 1);
    assert_int_equal(n->loc.column, 1);
    n = n->next;
    assert_int_equal(n->kind, MODEL_SPHERE);
    assert_true(n->u.sphere.r == 2); /* a diameter halves */
    assert_true(n->u.sphere.res.fn == 8 && n->u.sphere.res.fa == 12 &&
                n->u.sphere.res.fs == 2);
    n = n->next;
    assert_int_equal(n->kind, MODEL_CYLINDER);
    assert_true(n->u.cylinder.h == 5);
    assert_true(n->u.cylinder.r1 == 2); /* from r */
    assert_true(n->u.cylinder.r2 == 1); /* r2 wins over r */
    assert_false(n->u.cylinder.center);
    assert_true(n->u.cylinder.res.fn == 0 && n->u.cylinder.res.fa == 6 &&
                n->u.cylinder.res.fs == 0.5);
    n = n->next;
    assert_true(n->u.cube.size[0] == 7 && n->u.cube.size[2] == 7);
    assert_false(n->u.cube.center);
    assert_null(n->next);
    release(&l);
}

static void test_polyhedron(void **state)
{
    (void)state;
    lowered l =
        lower("polyhedron(points = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]],\n"
              "  faces = [[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]]);\n"
              "polyhedron([[0, 0, 0], [1, 0, 0], [0, 1, 0]], triangles = [[2, 1, "
              "0, 1]]);\n");
    const model_node *n = l.m->first;
    assert_int_equal(n->kind, MODEL_POLYHEDRON);
    assert_int_equal(n->u.polyhedron.point_count, 4);
    assert_int_equal(n->u.polyhedron.face_count, 4);
    assert_true(n->u.polyhedron.points[3].z == 1);
    assert_int_equal(n->u.polyhedron.face_start[4], 12);
    assert_int_equal(n->u.polyhedron.indices[4], 3);
    n = n->next;
    assert_int_equal(n->u.polyhedron.face_count, 1);
    assert_int_equal(n->u.polyhedron.face_start[1], 4);
    assert_int_equal(n->u.polyhedron.indices[0], 2);
    assert_int_equal(n->u.polyhedron.bad_count, 0);
    release(&l);
    /* as OpenSCAD 2021.01 reads faces: an index truncated toward zero, one
     * out of range left out of its face (and listed), then a face of
     * fewer than 3 points left out */
    l = lower("polyhedron([[0, 0, 0], [1, 0, 0], [0, 1, 0]],\n"
              "  [[0, 1, 2.9], [0, 1, 3], [2, -0.5, 1, -1], [1, 0], []]);\n");
    n = l.m->first;
    assert_int_equal(n->u.polyhedron.face_count, 2);
    assert_int_equal(n->u.polyhedron.face_start[0], 0);
    assert_int_equal(n->u.polyhedron.face_start[1], 3);
    assert_int_equal(n->u.polyhedron.face_start[2], 6);
    const uint32_t want[6] = {0, 1, 2, 2, 0, 1};
    for (int i = 0; i < 6; i++)
        assert_int_equal(n->u.polyhedron.indices[i], want[i]);
    assert_int_equal(n->u.polyhedron.bad_count, 2);
    assert_true(n->u.polyhedron.bad[0].value == 3);
    assert_int_equal(n->u.polyhedron.bad[0].face, 1);
    assert_int_equal(n->u.polyhedron.bad[0].place, 2);
    assert_int_equal(n->u.polyhedron.bad[0].loc.line, 2);
    assert_int_equal(n->u.polyhedron.bad[0].loc.column, 24);
    assert_true(n->u.polyhedron.bad[1].value == -1);
    assert_int_equal(n->u.polyhedron.bad[1].face, 2);
    assert_int_equal(n->u.polyhedron.bad[1].place, 3);
    release(&l);
}

/* Malformed points and faces, read as OpenSCAD 2021.01 reads them
 * (primitives.cc): a point is read only where a face reads it, a vector
 * of 2 numbers with z = 0; the first one it cannot convert ends the
 * faces there (the partial face kept, then left out for its fewer than 3
 * points) and is kept in bad_point, with its echo text, for the builder's
 * warning; points that are not a vector are none, faces that are not a
 * vector none, and a face that is not a vector an empty one. */
static void test_polyhedron_malformed(void **state)
{
    (void)state;
    lowered l = lower(
        "polyhedron(points = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, \"a\"], 5], faces "
        "= "
        "[[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]]);\n"
        "polyhedron(points = [[0, 0, 1], [1, 0, 1], [0, 1, 1], [0.25, 0.25], \"x\"], "
        "faces = [[0, 1, 2], 7, [0, 3, 1], [0, 2, 3], [1, 3, 2], [0, 1]]);\n"
        "polyhedron(points = 5, faces = [[0, 1, 2]]);\n"
        "polyhedron(points = [[0, 0, 0], [1, 0, 0], [0, 1, 0]], faces = 7);\n"
        "polyhedron(points = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, inf]], faces = "
        "[[0, 1, 2], [0, 1, 3, 2]]);\n"
        "polyhedron(points = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0.1, 1e6, "
        "0.333333333333, "
        "-0, 1e-7, 123456789, true, undef, \"q\\\"x\\\\y\", [], [[1]], 1e21, 12345.678, "
        "-2.5e-5, -inf, nan]], faces = [[3]]);\n");
    const model_node *n = l.m->first;
    assert_int_equal(n->kind, MODEL_POLYHEDRON);
    assert_null(n->pending);
    const model_bad_point *b = n->u.polyhedron.bad_point;
    assert_non_null(b);
    assert_int_equal(b->index, 3);
    assert_false(b->not_finite);
    assert_int_equal(b->loc.line, 1);
    assert_int_equal(b->loc.column, 55);
    assert_string_equal(b->text, "[0, 0, \"a\"]");
    assert_int_equal(n->u.polyhedron.face_count, 1); /* [0, 1, 2]; [0] left out */
    assert_int_equal(n->u.polyhedron.face_start[1], 3);
    assert_int_equal(n->u.polyhedron.bad_count, 0);
    n = n->next; /* [x, y] is [x, y, 0]; "x" is never read */
    assert_null(n->pending);
    assert_null(n->u.polyhedron.bad_point);
    assert_int_equal(n->u.polyhedron.face_count, 4);
    assert_true(n->u.polyhedron.points[3].x == 0.25 && n->u.polyhedron.points[3].z == 0);
    assert_int_equal(n->u.polyhedron.indices[3], 0);
    assert_int_equal(n->u.polyhedron.indices[4], 3);
    n = n->next; /* no points: every index out of range */
    assert_null(n->pending);
    assert_null(n->u.polyhedron.bad_point);
    assert_int_equal(n->u.polyhedron.point_count, 0);
    assert_int_equal(n->u.polyhedron.face_count, 0);
    assert_int_equal(n->u.polyhedron.bad_count, 3);
    assert_int_equal(n->u.polyhedron.bad[2].place, 2);
    n = n->next; /* faces = 7: no faces */
    assert_null(n->pending);
    assert_null(n->u.polyhedron.bad_point);
    assert_int_equal(n->u.polyhedron.face_count, 0);
    n = n->next; /* inf: the first face kept, the second ends at [0, 1] */
    assert_null(n->pending);
    b = n->u.polyhedron.bad_point;
    assert_non_null(b);
    assert_int_equal(b->index, 3);
    assert_true(b->not_finite);
    assert_string_equal(b->text, "[0, 0, inf]");
    assert_int_equal(n->u.polyhedron.face_count, 1);
    n = n->next; /* OpenSCAD's echo of values */
    b = n->u.polyhedron.bad_point;
    assert_non_null(b);
    assert_string_equal(b->text,
                        "[0.1, 1e+6, 0.333333, 0, 1e-7, 1.23457e+8, true, undef, "
                        "\"q\"x\\y\", [], [[1]], 1e+21, 12345.7, -0.000025, "
                        "-inf, nan]");
    assert_int_equal(n->u.polyhedron.face_count, 0);
    assert_null(n->next);
    release(&l);
    /* below a hull, the same reading (faces of any size kept) */
    l = lower("hull() {\n"
              "  polyhedron(points = [[0, 0, 0], [1, 0, 0], 5], faces = [[0, 1, 2], "
              "[1, 0]]);\n"
              "  polyhedron(points = \"x\", faces = [[0, 1]]);\n"
              "  polyhedron(points = [[0, 0, 0]], faces = [7, [0]]);\n"
              "}\n");
    n = l.m->first->first_child;
    assert_null(n->pending);
    b = n->u.polyhedron.bad_point;
    assert_non_null(b);
    assert_int_equal(b->index, 2);
    assert_string_equal(b->text, "5");
    assert_int_equal(n->u.polyhedron.face_count, 1); /* [0, 1] */
    assert_int_equal(n->u.polyhedron.face_start[1], 2);
    n = n->next;
    assert_null(n->pending);
    assert_int_equal(n->u.polyhedron.bad_count, 2);
    n = n->next;
    assert_null(n->pending);
    assert_null(n->u.polyhedron.bad_point);
    assert_int_equal(n->u.polyhedron.face_count, 2); /* [] and [0] */
    assert_int_equal(n->u.polyhedron.face_start[2], 1);
    release(&l);
}

/* A polygon's malformed points and paths, as OpenSCAD 2021.01 reads
 * them: a point that is not [x, y] of numbers (not inf) empties the
 * polygon (kept in bad_point for the warning); points that are not a
 * vector are none; paths that are not a vector are no paths (all the
 * points), and a path that is not a vector an empty path. */
static void test_polygon_malformed(void **state)
{
    (void)state;
    lowered l =
        lower("polygon(points = [[0, 0], [1, 0], [0, 1], [1, \"a\"]], paths = "
              "[[0, 1, 2]]);\n"
              "polygon(points = [[0, 0], [1, 0], [0, 1]], paths = [[0, 1, 2], 5]);\n"
              "polygon(points = [[0, 0], [1, 0], [0, 1]], paths = 5);\n"
              "polygon(points = \"x\", paths = [[0, 1]]);\n"
              "polygon(points = [[0, 0], [1, 0], [0, 1], [1, 1, 1]]);\n");
    const model_node *n = l.m->first;
    assert_int_equal(n->kind, MODEL_POLYGON);
    assert_null(n->pending);
    const model_polygon *p = n->u.polygon;
    assert_non_null(p->bad_point);
    assert_int_equal(p->bad_point->index, 3);
    assert_int_equal(p->bad_point->loc.column, 43);
    assert_string_equal(p->bad_point->text, "[1, \"a\"]");
    assert_false(p->has_points); /* empty */
    n = n->next;
    assert_null(n->pending);
    p = n->u.polygon;
    assert_null(p->bad_point);
    assert_true(p->has_points && p->has_paths);
    assert_int_equal(p->path_count, 2);
    assert_int_equal(p->path_start[1], 3);
    assert_int_equal(p->path_start[2], 3); /* the 5: an empty path */
    n = n->next;
    assert_null(n->pending);
    p = n->u.polygon;
    assert_true(p->has_points);
    assert_false(p->has_paths);
    assert_int_equal(p->point_count, 3);
    n = n->next;
    assert_null(n->pending);
    p = n->u.polygon;
    assert_true(p->has_points && p->has_paths);
    assert_int_equal(p->point_count, 0);
    assert_int_equal(p->bad_count, 2);
    n = n->next;
    assert_null(n->pending);
    p = n->u.polygon;
    assert_non_null(p->bad_point);
    assert_string_equal(p->bad_point->text, "[1, 1, 1]");
    release(&l);
}

/* The outline OpenSCAD 2021.01's clipper refuses (range_bad, 1-based):
 * a coordinate of 2^46 or more in magnitude is past its range at the
 * scale of 2^16; the double below 2^46 is not; a point in no outline is
 * not tested; the first outline refused ends the polygon. */
static void test_polygon_range(void **state)
{
    (void)state;
    lowered l = lower("polygon([[0, 0], [70368744177664, 0], [0, 1]]);\n"
                      "polygon([[0, 0], [70368744177663.99, 0], [0, 1]]);\n"
                      "polygon([[0, 0], [0, -70368744177664], [1, 1]]);\n"
                      "polygon([[0, 0], [1, 0], [0, 1], [1e14, 0]], [[0, 1, 2]]);\n"
                      "polygon([[0, 0], [1, 0], [0, 1], [1e14, 0], [5, 5], [5, 6]],\n"
                      "        [[0, 1, 2], [3, 4, 5], [0, 2, 1]]);\n");
    static const uint32_t expected[5] = {1, 0, 1, 0, 2};
    const model_node *n = l.m->first;
    for (int i = 0; i < 5; i++, n = n->next) {
        assert_int_equal(n->kind, MODEL_POLYGON);
        assert_int_equal(n->u.polygon->range_bad, expected[i]);
    }
    release(&l);
}

static void test_operations(void **state)
{
    (void)state;
    lowered l = lower("group() {\n"
                      "  multmatrix([[2, 0, 0, 1], [0, 3, 0, 2], [0, 0, 4, 3], [0, 0, 0, "
                      "1]]) {\n"
                      "    color(\"Red\", 0.5) { cube(); }\n"
                      "    color([2, 0.5]) { sphere(); }\n"
                      "    color(\"nosuch\") { sphere(); }\n"
                      "  }\n"
                      "  difference() { cube(); }\n"
                      "  intersection();\n"
                      "}\n");
    const model_node *g = l.m->first;
    assert_int_equal(g->kind, MODEL_UNION);
    assert_int_equal(count_siblings(g->first_child), 3);
    const model_node *x = g->first_child;
    assert_int_equal(x->kind, MODEL_XFORM);
    assert_true(x->u.xform->m[0][0] == 2 && x->u.xform->m[1][1] == 3 &&
                x->u.xform->m[2][2] == 4 && x->u.xform->m[0][3] == 1 &&
                x->u.xform->m[1][3] == 2 && x->u.xform->m[2][3] == 3);
    const model_node *c = x->first_child;
    assert_int_equal(c->kind, MODEL_COLOR);
    assert_true(c->u.color->set);
    assert_true(c->u.color->c[0] == 1 && c->u.color->c[1] == 0 && c->u.color->c[2] == 0);
    assert_true(c->u.color->has_alpha && c->u.color->alpha == 0.5);
    assert_int_equal(c->first_child->kind, MODEL_CUBE);
    c = c->next;
    assert_true(c->u.color->set);
    /* As written: the builder clamps; the warning is the instantiation's. */
    assert_true(c->u.color->c[0] == 2 && c->u.color->c[1] == 0.5 &&
                c->u.color->c[2] == 1);
    assert_int_equal(l.m->notes.count, 2);
    assert_int_equal(l.m->notes.items[0].line, 4);
    assert_int_equal(l.m->notes.items[0].column, 12);
    c = c->next;
    assert_false(c->u.color->set);
    assert_string_equal(l.m->notes.items[1].message, "Unable to parse color \"nosuch\"");
    assert_int_equal(x->next->kind, MODEL_DIFFERENCE);
    assert_int_equal(x->next->next->kind, MODEL_INTERSECTION);
    assert_null(x->next->next->first_child);
    release(&l);
}

/* multmatrix(m) as OpenSCAD 2021.01 reads it (transform.cc), without a
 * word: the identity, each entry that m has as a number replacing the
 * identity's (missing rows and columns, extra ones and entries that are
 * not numbers leave it), then everything divided by the bottom right
 * entry when that is not 1, and the rest of the bottom row dropped; an
 * entry that is not finite after the division removes the subtree. Each
 * was checked with openscad -o x.stl on the same line. */
static void test_matrix_as_openscad_reads_it(void **state)
{
    (void)state;
    static const struct {
        const char *m;
        double want[3][4];
        int not_finite;
    } cases[] = {
        {"5", {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}}, 0},
        {"[]", {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}}, 0},
        {"[1, 2, 3]", {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}}, 0},
        {"[[1, 0, 0, 5], [0, 1, 0, 0], [0, 0, 1, 0]]",
         {{1, 0, 0, 5}, {0, 1, 0, 0}, {0, 0, 1, 0}},
         0},
        {"[[1, 0, 0, \"a\"], [0, 1, 0, 2]]",
         {{1, 0, 0, 0}, {0, 1, 0, 2}, {0, 0, 1, 0}},
         0},
        {"[[2, 0, 0, 1, 7], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1], [1, 1, 1, 1]]",
         {{2, 0, 0, 1}, {0, 1, 0, 0}, {0, 0, 1, 0}},
         0},
        {"[[1, 0, 0, 3], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 2]]",
         {{0.5, 0, 0, 1.5}, {0, 0.5, 0, 0}, {0, 0, 0.5, 0}},
         0},
        {"[[1, 0, 0, 3], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, -1]]",
         {{-1, 0, 0, -3}, {0, -1, 0, 0}, {0, 0, -1, 0}},
         0},
        {"[[1, 0, 0, 3], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0.5, 1]]",
         {{1, 0, 0, 3}, {0, 1, 0, 0}, {0, 0, 1, 0}},
         0},
        {"[[1, 0, 0, 3], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, true]]",
         {{1, 0, 0, 3}, {0, 1, 0, 0}, {0, 0, 1, 0}},
         0},
        {"[[1, 0, 0, 3], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 0]]", {{0}}, 1},
        {"[[1, 0, 0, 3], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, nan, 1]]", {{0}}, 1},
    };
    for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
        char text[256];
        snprintf(text, sizeof text, "multmatrix(%s) cube();", cases[i].m);
        lowered l = lower(text);
        const model_node *x = l.m->first;
        assert_int_equal(x->kind, MODEL_XFORM);
        assert_int_equal(x->not_finite, cases[i].not_finite);
        for (int r = 0; r < 3 && !cases[i].not_finite; r++)
            for (int k = 0; k < 4; k++)
                if (x->u.xform->m[r][k] != cases[i].want[r][k])
                    fail_msg("multmatrix(%s): entry [%d][%d] is %g, OpenSCAD's is %g",
                             cases[i].m, r, k, x->u.xform->m[r][k], cases[i].want[r][k]);
        release(&l);
    }
}

static void test_what_is_lowered(void **state)
{
    (void)state;
    /* '*' subtrees and a leaf's children are never read: not even an
     * unknown name there is an error. */
    lowered l = lower("*cube(size = \"no\");\n"
                      "cube() { nosuch(); }\n"
                      "union() { *sphere(); !sphere(); %cube(); }\n"
                      "linear_extrude(1) { circle(1); }\n");
    const model_node *n = l.m->first;
    assert_int_equal(n->kind, MODEL_CUBE);
    assert_int_equal(n->child_count, 1);
    assert_null(n->first_child);
    n = n->next;
    assert_int_equal(count_siblings(n->first_child), 2);
    assert_true(n->first_child->is_root);
    assert_true(n->first_child->modifiers & MODEL_MOD_ROOT);
    assert_true(n->first_child->next->modifiers & MODEL_MOD_BACKGROUND);
    assert_false(n->first_child->next->is_root);
    assert_true(l.m->has_root);
    n = n->next;
    assert_int_equal(n->kind, MODEL_LINEAR_EXTRUDE);
    assert_true(n->u.linear_extrude->height == 1 && n->u.linear_extrude->plain);
    assert_null(n->next);
    n = n->first_child; /* its 2D subtree is lowered */
    assert_int_equal(n->kind, MODEL_CIRCLE);
    assert_null(n->pending);
    assert_true(n->u.circle->r == 1 && !n->u.circle->has_d);
    release(&l);
}

/* The points context: hull's children, read as its builder reads them,
 * errors kept; each resize's subtree lowered once more for measuring, and
 * a resize inside another measured from the same nodes. */
static void test_points_context(void **state)
{
    (void)state;
    lowered l = lower("hull() {\n"
                      "  color(c = 7) { cube(2); }\n"
                      "  polyhedron(points = [[0, 0, 0], [1, 0, 0], [0, 1, 0]], faces = "
                      "[[0, 1, 5]]);\n"
                      "  circle(r = \"x\");\n"
                      "  torus(r1 = \"x\");\n"
                      "}\n"
                      "resize([2, 0, 0]) { resize(newsize = [3, 3, 3], auto = true) "
                      "{ sphere(1); } }\n");
    const model_node *h = l.m->first, *n = h->first_child;
    assert_int_equal(h->kind, MODEL_HULL);
    assert_int_equal(n->kind, MODEL_COLOR);
    assert_null(n->pending); /* color reads no arguments here */
    assert_true(n->first_child->u.cube.size[2] == 2);
    n = n->next;
    assert_int_equal(n->kind, MODEL_POLYHEDRON);
    /* an index out of range is left out, for the builder to warn of, as
     * OpenSCAD leaves it out; the face keeps its two points for the hull */
    assert_null(n->pending);
    assert_int_equal(n->u.polyhedron.face_count, 1);
    assert_int_equal(n->u.polyhedron.face_start[1], 2);
    assert_int_equal(n->u.polyhedron.bad_count, 1);
    assert_true(n->u.polyhedron.bad[0].value == 5);
    assert_int_equal(n->u.polyhedron.bad[0].face, 0);
    assert_int_equal(n->u.polyhedron.bad[0].place, 2);
    assert_int_equal(n->u.polyhedron.bad[0].loc.line, 3);
    n = n->next;
    assert_int_equal(n->kind, MODEL_CIRCLE);
    /* read as in the 2D context, as OpenSCAD reads it: r of another kind
     * is the default, without a word */
    assert_null(n->pending);
    assert_true(n->u.circle->r == 1 && !n->u.circle->has_d);
    n = n->next;
    /* spancast's own nodes keep their errors, for the builder */
    assert_int_equal(n->kind, MODEL_TORUS);
    assert_string_equal(n->pending->message,
                        "wrong type for argument 'r1' of 'torus' (expected a number)");
    const model_node *outer = h->next, *inner = outer->first_child;
    assert_int_equal(outer->kind, MODEL_RESIZE);
    assert_true(outer->u.resize->size[0] == 2 && outer->u.resize->size[1] == 0);
    const model_node *measured = outer->u.resize->measured;
    assert_non_null(measured);
    assert_int_equal(measured->kind, MODEL_RESIZE);
    assert_null(measured->u.resize->measured);
    assert_int_equal(inner->kind, MODEL_RESIZE);
    assert_true(inner->u.resize->autosize[0] == 1 && inner->u.resize->size[2] == 3);
    assert_ptr_equal(inner->u.resize->measured, measured->first_child);
    assert_int_equal(inner->first_child->kind, MODEL_SPHERE);
    release(&l);
}

/* The 2D context: an argument error stays in its node, for the builder
 * that reads it, and lowering goes on; an argument of OpenSCAD's of the
 * wrong kind is its default, as OpenSCAD 2021.01 reads it (a size with a
 * warning: test_wrong_types); color takes no arguments there; a
 * polygon index out of range is left out of its path and listed, and one
 * that is not a number ends the paths before it. */
static void test_twod_context(void **state)
{
    (void)state;
    lowered l =
        lower("linear_extrude(1) {\n"
              "  offset(r = \"x\") { square([2, 3], true); }\n"
              "  color(c = 7) { polygon([[0, 0], [1, 0], [0, 1]], [[0, 1], [2, 9, 1], "
              "[0, \"x\"]]); "
              "}\n"
              "  multmatrix([[1, 0, 0, 2], [0, 1, 0, 3], [0, 0, 1, 0], [0, 0, 0, 1]])\n"
              "    { text(\"ab\", size = 5); }\n"
              "}\n"
              "cube(size = \"no\");\n"
              "torus(r1 = \"no\");\n");
    const model_node *e = l.m->first, *n = e->first_child;
    assert_int_equal(n->kind, MODEL_OFFSET);
    assert_null(n->pending); /* neither r nor delta: r = 1, as OpenSCAD */
    assert_true(!n->u.offset->has_r && !n->u.offset->has_delta);
    assert_true(n->u.offset->delta == 1);
    const model_node *k = n->first_child;
    assert_int_equal(k->kind, MODEL_SQUARE);
    assert_true(k->u.square->sx == 2 && k->u.square->sy == 3 && k->u.square->center);
    n = n->next;
    assert_int_equal(n->kind, MODEL_COLOR);
    assert_null(n->pending);
    const model_polygon *p = n->first_child->u.polygon;
    assert_int_equal(p->point_count, 3);
    assert_true(p->has_points && p->has_paths);
    assert_int_equal(p->path_count, 3);
    assert_int_equal(p->path_start[1], 2);
    assert_int_equal(p->path_start[2], 4); /* without the 9 */
    assert_int_equal(p->path_start[3], 6); /* the "x" read as 0, as OpenSCAD */
    assert_int_equal(p->index[2], 2);
    assert_int_equal(p->index[3], 1);
    assert_int_equal(p->index[4], 0);
    assert_int_equal(p->index[5], 0);
    assert_int_equal(p->bad_count, 1);
    assert_true(p->bad[0].value == 9);
    assert_int_equal(p->bad[0].face, 1);
    assert_int_equal(p->bad[0].place, 1);
    n = n->next;
    assert_int_equal(n->kind, MODEL_XFORM);
    assert_true(n->u.xform->m[0][3] == 2 && n->u.xform->m[1][3] == 3);
    assert_int_equal(n->first_child->kind, MODEL_TEXT);
    assert_string_equal(n->first_child->u.text->text, "ab");
    assert_true(n->first_child->u.text->size == 5);
    /* the exact builders read height and center, the faithful one all */
    assert_null(e->pending);
    assert_null(e->u.linear_extrude->exact_error);
    /* the 3D model after it: the cube of size 1, then its own error */
    assert_int_equal(e->next->kind, MODEL_CUBE);
    assert_true(e->next->u.cube.size[0] == 1 && e->next->u.cube.size[2] == 1);
    assert_int_equal(e->next->next->kind, MODEL_ERROR);
    assert_null(e->next->next->next);
    release(&l);
    l = lower("linear_extrude(center = 1, slices = \"x\", twist = [1], scale = [2]) "
              "{ circle(); }\n"
              "rotate_extrude(file = \"a.dxf\") { circle(); }\n");
    e = l.m->first;
    assert_null(e->u.linear_extrude->exact_error);
    assert_null(e->pending);
    assert_true(e->u.linear_extrude->plain && !e->u.linear_extrude->center);
    assert_true(e->u.linear_extrude->height == 100 && e->u.linear_extrude->slices == 0);
    assert_true(e->u.linear_extrude->twist == 0 && e->u.linear_extrude->sx == 1 &&
                e->u.linear_extrude->sy == 1);
    /* the file form: the drawing is the only child, the written ones left
     * out as OpenSCAD leaves them out */
    assert_null(e->next->pending);
    const model_node *drawing = e->next->first_child;
    assert_int_equal(drawing->kind, MODEL_IMPORT);
    assert_null(drawing->next);
    assert_string_equal(drawing->u.drawing->file, "a.dxf");
    assert_int_equal(drawing->u.drawing->format, MODEL_DRAWING_DXF);
    assert_true(drawing->u.drawing->scale == 1);
    release(&l);
}

static void test_shading_and_curved(void **state)
{
    (void)state;
    lowered l =
        lower("light(position = [1, 2, 3], color = \"red\", radius = 0.5);\n"
              "light(direction = [0, 0, -1]);\n"
              "camera(eye = [9, 0, 0], center = [0, 0, 0], fov = 30);\n"
              "background(color = [0.1, 0.2, 0.3]);\n"
              "material(reflect = 0.25, color = \"blue\") { torus(3, 1); }\n"
              "quadric([1, 1, 1, 0, 0, 0, 0, 0, 0, -1], [[-1, -1, -1], [1, 1, -2]]);\n"
              "implicit(\"x*x + y*y + z*z - 1\", [[-2, -2, -2], [2, 2, 2]]);\n");
    const model_node *n = l.m->first;
    assert_int_equal(n->kind, MODEL_LIGHT);
    assert_int_equal(n->u.light->kind, SHADING_LIGHT_POINT);
    assert_true(n->u.light->position.z == 3 && n->u.light->radius == 0.5);
    assert_true(n->u.light->color[0] == 1 && n->u.light->color[1] == 0);
    n = n->next;
    assert_int_equal(n->u.light->kind, SHADING_LIGHT_DIRECTIONAL);
    assert_true(n->u.light->direction.z == -1); /* local: the builder places it */
    n = n->next;
    assert_int_equal(n->kind, MODEL_CAMERA);
    assert_true(n->u.camera->eye[0] == 9 && n->u.camera->fov_deg == 30);
    n = n->next;
    assert_int_equal(n->kind, MODEL_BACKGROUND);
    assert_true(n->u.background[2] == 0.3f);
    n = n->next;
    assert_int_equal(n->kind, MODEL_MATERIAL);
    assert_true(n->u.material->material.reflect == 0.25);
    assert_true(n->u.material->has_color && n->u.material->color[2] == 1);
    assert_int_equal(n->first_child->kind, MODEL_TORUS);
    assert_true(n->first_child->u.torus->r1 == 3 && n->first_child->u.torus->r2 == 1);
    assert_null(n->first_child->u.torus->empty);
    n = n->next;
    assert_int_equal(n->kind, MODEL_QUADRIC);
    assert_true(n->u.quadric->a[9] == -1);
    assert_string_equal(n->u.quadric->empty, "quadric with an empty box is empty");
    n = n->next;
    assert_int_equal(n->kind, MODEL_IMPLICIT);
    assert_true(n->u.implicit->program.count > 0);
    assert_true(n->u.implicit->tolerance == 4e-6); /* 1e-6 of the box's side */
    assert_null(n->u.implicit->empty);
    release(&l);
}

static void test_kind_of(void **state)
{
    (void)state;
    /* One table: every name OpenSCAD writes has its kind. */
    assert_int_equal(model_kind_of("group"), MODEL_UNION);
    assert_int_equal(model_kind_of("render"), MODEL_UNION);
    assert_int_equal(model_kind_of("multmatrix"), MODEL_XFORM);
    assert_int_equal(model_kind_of("circle"), MODEL_CIRCLE);
    assert_int_equal(model_kind_of("linear_extrude"), MODEL_LINEAR_EXTRUDE);
    assert_int_equal(model_kind_of("halfspace"), MODEL_HALFSPACE);
    assert_int_equal(model_kind_of("roof"), MODEL_UNSUPPORTED);
    assert_int_equal(model_kind_of("projection"), MODEL_PROJECTION);
    assert_int_equal(model_kind_of("Cube"), MODEL_UNKNOWN);
    assert_int_equal(model_kind_of(""), MODEL_UNKNOWN);
    assert_true(model_is_leaf(MODEL_SPHERE) && model_is_leaf(MODEL_HULL));
    assert_false(model_is_leaf(MODEL_RESIZE) || model_is_leaf(MODEL_LIGHT));
    assert_true(model_is_2d(MODEL_OFFSET) && !model_is_2d(MODEL_CUBE));
    assert_true(model_is_2d(MODEL_PROJECTION) && model_is_leaf(MODEL_PROJECTION));
}

/* text must lower to a model whose last node is the error expected. */
static void check_error(const char *text, sc_status status, const char *expected)
{
    lowered l = lower(text);
    const model_node *n = l.m->first, *last = NULL;
    while (n) {
        last = n;
        n = n->first_child ? n->first_child : n->next;
    }
    assert_non_null(last);
    assert_int_equal(last->kind, MODEL_ERROR);
    assert_int_equal(last->u.error->status, status);
    char buf[1024];
    assert_string_equal(sc_error_format(last->u.error, buf, sizeof buf), expected);
    release(&l);
}

static void test_errors(void **state)
{
    (void)state;
    check_error("cube();\ntorus(r1 = \"a\");\nnosuch();\n", SC_ERR_SEMANTIC,
                "m.csg:2:12: error: wrong type for argument 'r1' of 'torus' (expected a "
                "number)");
    check_error("group() { nosuch(); torus(r1 = \"a\"); }", SC_ERR_SEMANTIC,
                "m.csg:1:32: error: wrong type for argument 'r1' of 'torus' (expected a "
                "number)");
    check_error("union() { roof(); }", SC_ERR_UNSUPPORTED,
                "m.csg:1:11: error: 'roof' is not supported yet");
    check_error("sphere($fn = 1e9);", SC_ERR_LIMIT,
                "m.csg:1:14: error: $fn 1e+09 is too large (limit is 65536)");
    check_error("light(position = [0, 0, 0], direction = [0, 0, 1]);", SC_ERR_SEMANTIC,
                "m.csg:1:1: error: 'light' needs either position or direction");
    check_error("material(reflect = 0.6, transmit = 0.6) { cube(); }", SC_ERR_SEMANTIC,
                "m.csg:1:1: error: 'material': reflect + transmit must not exceed 1");
    check_error("torus(1, 2);", SC_ERR_SEMANTIC,
                "m.csg:1:1: error: torus minor radius r2 = 2 must be smaller than its "
                "major radius r1 = 1");
    check_error("implicit(\"x $\", [[0, 0, 0], [1, 1, 1]]);", SC_ERR_SYNTAX,
                "m.csg:1:13: error: unexpected character '$' in expression");
}

static void notes_text(const model *m, char *out, size_t size);

/* A name OpenSCAD does not know is left out with its subtree, as OpenSCAD
 * leaves out what it cannot instantiate: not an operand, not searched for
 * '!', in 3D and 2D alike; the model goes on after it. */
static void test_unknown_left_out(void **state)
{
    (void)state;
    lowered l = lower("difference() { foo(1) { !cube(5); } cube(1); sphere(1); }\n"
                      "!bar(); linear_extrude(1) { baz(); square(1); }");
    const model_node *d = l.m->first;
    assert_int_equal(d->kind, MODEL_DIFFERENCE);
    assert_int_equal(count_siblings(d->first_child), 2);
    assert_int_equal(d->first_child->kind, MODEL_CUBE);
    assert_int_equal(d->first_child->next->kind, MODEL_SPHERE);
    const model_node *e = d->next;
    assert_non_null(e);
    assert_int_equal(count_siblings(e->first_child), 1);
    assert_null(e->next);
    assert_false(l.m->has_root);
    assert_int_equal(l.m->notes.count, 3);
    char notes[1024];
    notes_text(l.m, notes, sizeof notes);
    assert_string_equal(notes, "1:16: Ignoring unknown module 'foo'\n"
                               "2:2: Ignoring unknown module 'bar'\n"
                               "2:29: Ignoring unknown module 'baz'\n");
    release(&l);
}

/* The model's argument warnings, one "line:column: message" a line. */
static void notes_text(const model *m, char *out, size_t size)
{
    size_t used = 0;
    out[0] = '\0';
    for (size_t i = 0; i < m->notes.count && used < size; i++) {
        const sc_error *e = &m->notes.items[i];
        int k = snprintf(out + used, size - used, "%d:%d: %s\n", e->line, e->column,
                         e->message);
        assert_true(k > 0);
        used += (size_t)k;
    }
    assert_true(used < size);
}

static void check_notes(const char *text, const char *expected)
{
    lowered l = lower(text);
    char got[4096];
    notes_text(l.m, got, sizeof got);
    assert_string_equal(got, expected);
    release(&l);
}

/* OpenSCAD 2021.01's warnings of arguments (params.h), as it prints them
 * for the same calls (openscad -o x.csg): a name that is no parameter ($
 * names aside), a name given twice (after the position that gave it, not
 * before), positional arguments past the last (once a call); none for
 * group, union, difference and intersection, for '*' subtrees and for a
 * primitive's children, but for '%' ones and for children that are left
 * out later; timestamp, which OpenSCAD's export writes, silently. */
static void test_argument_warnings(void **state)
{
    (void)state;
    check_notes("cube(size = 2, center = true, $fn = 3, $zz = 1);", "");
    check_notes("cube(size = 2, centre = true);",
                "1:16: variable centre not specified as parameter\n");
    check_notes("cube(1, true, 3, zz = 1, size = 2, zz = 3);",
                "1:15: Too many unnamed arguments supplied\n"
                "1:18: variable zz not specified as parameter\n"
                "1:26: argument size supplied more than once\n"
                "1:36: variable zz not specified as parameter\n"
                "1:36: argument zz supplied more than once\n");
    check_notes("cube(center = true, 2, true);", "");
    check_notes("cube($fn = 1, $fn = 2);",
                "1:15: argument $fn supplied more than once\n");
    check_notes("cylinder(1, 2, 3, true, 5, 6);",
                "1:25: Too many unnamed arguments supplied\n");
    check_notes("cylinder(h = 1, r = 1, d2 = 3, convexity = 2);",
                "1:32: variable convexity not specified as parameter\n"
                "1:1: Cylinder parameters ambiguous\n");
    check_notes("group(1, zz = 2) { union(zz = 1) cube(1); difference(3) cube(1); "
                "intersection(q = 1) cube(1); }",
                "");
    check_notes("hull(1) cube(1);", "1:6: Too many unnamed arguments supplied\n");
    /* a primitive's children: not instantiated, warned of before its own
     * arguments; '*' ones are never read; import's are ignored silently */
    check_notes("cube(1, zz = 1) { sphere(q = 1); }",
                "1:1: module cube() does not support child modules\n"
                "1:9: variable zz not specified as parameter\n");
    check_notes("cube(1) { *sphere(1); } cube(1) { } import(\"x.stl\") cube(zz = 1);",
                "");
    /* a name OpenSCAD does not know: left out with its children, which
     * are never instantiated, so never checked */
    check_notes("group() { frobnicate(zz = 1) { cube(zz = 2); } cube(1, zz = 3); }",
                "1:11: Ignoring unknown module 'frobnicate'\n"
                "1:56: variable zz not specified as parameter\n");
    check_notes("%cube(1) sphere(1);",
                "1:2: module cube() does not support child modules\n");
    check_notes("*cube(zz = 1); %sphere(yy = 1); *union() { cube(xx = 1); }",
                "1:24: variable yy not specified as parameter\n");
    check_notes("cube(1) { sphere(zz = 1); } linear_extrude(height = 1, v = 1) "
                "cube(ww = 1);",
                "1:1: module cube() does not support child modules\n"
                "1:56: variable v not specified as parameter\n"
                "1:68: variable ww not specified as parameter\n");
    check_notes("import(file = \"x.stl\", layer = \"\", origin = [0, 0], scale = 1, "
                "convexity = 1, $fn = 0, $fa = 12, $fs = 2, timestamp = 0, id = 1);",
                "1:122: variable id not specified as parameter\n");
    check_notes("color(\"red\", 0.5, alpha = 1, 2) cube(1);",
                "1:19: argument alpha supplied more than once\n"
                "1:30: Too many unnamed arguments supplied\n");
    /* many arguments: the names given are hashed, with the same result */
    char many[4096];
    size_t used = (size_t)snprintf(many, sizeof many, "cube(");
    for (int i = 0; i < 40; i++)
        used += (size_t)snprintf(many + used, sizeof many - used, "%s$a%d = 1, ",
                                 i == 20 ? "size = 1, " : "", i % 30);
    snprintf(many + used, sizeof many - used, "size = 2);");
    lowered l = lower(many);
    assert_int_equal(l.m->notes.count, 11);
    for (size_t i = 0; i + 1 < l.m->notes.count; i++)
        assert_non_null(strstr(l.m->notes.items[i].message, "$a"));
    assert_string_equal(l.m->notes.items[10].message,
                        "argument size supplied more than once");
    release(&l);
}

/* What OpenSCAD 2021.01 goes on to say as it instantiates a primitive,
 * after its arguments (openscad -o x.csg prints the same): $fs and $fa
 * below 0.01 (its own or passed down, at the node), a radius given with
 * its diameter (at the radius), a cylinder's r with r1 or r2. */
static void test_primitive_warnings(void **state)
{
    (void)state;
    check_notes("sphere(r = 2, d = 10);",
                "1:8: Ignoring radius variable 'r' as diameter 'd' is defined too.\n");
    check_notes("cylinder(h = 1, d = 1, d1 = 2, r1 = 3);",
                "1:32: Ignoring radius variable 'r1' as diameter 'd1' is defined too.\n"
                "1:1: Cylinder parameters ambiguous\n");
    check_notes("cylinder(1, 2, 3, d2 = 4);",
                "1:16: Ignoring radius variable 'r2' as diameter 'd2' is defined too.\n");
    check_notes("cylinder(h = 1, r = 1, r1 = \"a\", d2 = \"b\");", "");
    check_notes("cube(1, $fs = 0, $fa = 0);",
                "1:1: $fs too small - clamping to 0.010000\n"
                "1:1: $fa too small - clamping to 0.010000\n");
    check_notes("sphere(1, $fa = -1, $fs = 0.01);",
                "1:1: $fa too small - clamping to 0.010000\n");
    check_notes("multmatrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]], "
                "$fs = 0.001) { sphere(1); union($fa = 0) cube(1); }",
                "1:85: $fs too small - clamping to 0.010000\n"
                "1:111: $fs too small - clamping to 0.010000\n");
    check_notes("linear_extrude(height = 1, $fs = 0) offset(r = 1) circle(1, $fa = 0);",
                "1:51: $fs too small - clamping to 0.010000\n"
                "1:51: $fa too small - clamping to 0.010000\n");
    /* the same names again: their warnings remembered as none, the values
     * checked each time */
    check_notes("sphere(1, $fs = 1); sphere(1, $fs = 0); sphere(1, $fs = 0);",
                "1:21: $fs too small - clamping to 0.010000\n"
                "1:41: $fs too small - clamping to 0.010000\n");
    check_notes("cube(1, zz = 1); cube(1, zz = 1);",
                "1:9: variable zz not specified as parameter\n"
                "1:26: variable zz not specified as parameter\n");
    check_notes("sphere(r = 1, d = 2); sphere(r = 1, d = 2);",
                "1:8: Ignoring radius variable 'r' as diameter 'd' is defined too.\n"
                "1:30: Ignoring radius variable 'r' as diameter 'd' is defined too.\n");
    /* colours: OpenSCAD's warnings, and silence for the "no colour" its
     * export writes for a name it could not parse */
    check_notes(
        "color([1.25, 0, -0.05, 2]) cube(1); color(\"nosuch\") cube(1);\n"
        "color([-1, -1, -1, 1]) cube(1); color(5, alpha = 9) cube(1); "
        "color([1, \"x\", 0.5], \"y\") cube(1);",
        "1:8: color() expects numbers between 0.0 and 1.0. Value of 1.2 is out of "
        "range\n"
        "1:17: color() expects numbers between 0.0 and 1.0. Value of -0.1 is out of "
        "range\n"
        "1:24: color() expects numbers between 0.0 and 1.0. Value of 2.0 is out of "
        "range\n"
        "1:43: Unable to parse color \"nosuch\"\n");
    /* a call over several lines: OpenSCAD's line, the statement's, and
     * the column of what is wrong only on it; the colour name in lower
     * case, as OpenSCAD looked it up; a component as the float OpenSCAD
     * holds (1.00000001 is 1) */
    check_notes(
        "cube(\n  size = 1, centre = true,\n  zz = 2\n) sphere(r = 1);\ncolor(\n  "
        "\"BluRple\"\n) cube(1); color([0, 1.00000001, 0]) cube(1);",
        "1:1: module cube() does not support child modules\n"
        "1:1: variable centre not specified as parameter\n"
        "1:1: variable zz not specified as parameter\n"
        "5:1: Unable to parse color \"blurple\"\n");
    check_notes("circle(r = 1, d = 4, $fs = 0);",
                "1:1: $fs too small - clamping to 0.010000\n"
                "1:8: Ignoring radius variable 'r' as diameter 'd' is defined too.\n");
}

/* Arguments of OpenSCAD's modules of the wrong kind, as OpenSCAD 2021.01
 * reads them (openscad -o x.csg on the same calls exports these values
 * and prints these warnings): the default, with a warning for the size of
 * a cube or square (at it, on the statement's line), silently for the
 * rest; a $fs or $fa that is not a number is 0, clamped with the warning;
 * a $fn that is not a number is 0. */
static void test_wrong_types(void **state)
{
    (void)state;
    check_notes(
        "cube(size = \"a\"); cube([1, 2]); cube([1, true, 3], center = 1);\n"
        "cube(size = [1, 2, 3]); cube(undef); cube(7); square([1, 2, 3]);\n"
        "square(size = [\"a\", 1]); square([3, 4]);\n"
        "cube(\n  [1, [2], 3]);",
        "1:13: Unable to convert cube(size=\"a\", ...) parameter to a number or a "
        "vec3 of numbers\n"
        "1:24: Unable to convert cube(size=[1, 2], ...) parameter to a number or a "
        "vec3 of numbers\n"
        "1:38: Unable to convert cube(size=[1, true, 3], ...) parameter to a "
        "number or a vec3 of numbers\n"
        "2:54: Unable to convert square(size=[1, 2, 3], ...) parameter to a "
        "number or a vec2 of numbers\n"
        "3:15: Unable to convert square(size=[\"a\", 1], ...) parameter to a "
        "number or a vec2 of numbers\n"
        "4:1: Unable to convert cube(size=[1, [2], 3], ...) parameter to a "
        "number or a vec3 of numbers\n");
    check_notes("sphere(1, $fs = \"a\", $fa = true, $fn = [3]); circle(1, $fs = undef);\n"
                "multmatrix($fa = [1]) { sphere(1); }",
                "1:1: $fs too small - clamping to 0.010000\n"
                "1:1: $fa too small - clamping to 0.010000\n"
                "1:46: $fs too small - clamping to 0.010000\n"
                "2:25: $fa too small - clamping to 0.010000\n");
    /* an origin that is not [x, y] of numbers (naming linear_extrude for
     * import, as OpenSCAD does); linear_extrude's scale, which OpenSCAD
     * checks only where an origin is given (openscad -o x.csg prints these
     * for the same text) */
    check_notes(
        "import(file = \"a.stl\", origin = \"a\"); import(\"b.dxf\", origin = [1, "
        "2]);\nimport(\"c.svg\", origin = [1, [2]]); import(\"d.dxf\", origin = "
        "undef);\nrotate_extrude(file = \"e.dxf\", origin = 3); linear_extrude("
        "origin = 3) square(1);",
        "1:33: linear_extrude(..., origin=\"a\") could not be converted\n"
        "2:26: linear_extrude(..., origin=[1, [2]]) could not be converted\n"
        "3:41: rotate_extrude(..., origin=3) could not be converted\n"
        "3:69: linear_extrude(..., origin=3) could not be converted\n"
        "3:45: linear_extrude(..., scale=undef) could not be converted\n");
    check_notes("linear_extrude(origin = [0, 0], scale = 2) square(1);\n"
                "linear_extrude(origin = [0, 0], scale = [1, \"a\"]) square(1);\n"
                "linear_extrude(1, scale = \"a\") square(1);",
                "2:41: linear_extrude(..., scale=[1, \"a\"]) could not be converted\n");
    /* radii and heights of another kind: the defaults, the other radius
     * where one is a number, no "ambiguous" with one that is not */
    check_notes("sphere(r = \"a\"); sphere(r = 2, d = [4]); cylinder(h = 1, r = 5, r1 = "
                "\"a\", d2 = true);",
                "");
    lowered l =
        lower("cube([1, 2], center = 1);\n"
              "cube(2, center = true);\n"
              "sphere(r = \"a\", $fs = \"b\", $fn = true);\n"
              "sphere(r = 2, d = [4]);\n"
              "sphere(r = undef, d = 6);\n"
              "cylinder(h = \"a\", r = 5, r1 = \"b\", d2 = true, center = \"c\");\n"
              "cylinder(h = 2, r = [1], d1 = 4);\n");
    const model_node *n = l.m->first;
    assert_int_equal(n->kind, MODEL_CUBE);
    assert_true(n->u.cube.size[0] == 1 && n->u.cube.size[1] == 1 &&
                n->u.cube.size[2] == 1 && !n->u.cube.center);
    n = n->next;
    assert_true(n->u.cube.size[1] == 2 && n->u.cube.center);
    n = n->next;
    assert_int_equal(n->kind, MODEL_SPHERE);
    assert_true(n->u.sphere.r == 1 && n->u.sphere.res.fn == 0 &&
                n->u.sphere.res.fa == 12 && n->u.sphere.res.fs == MODEL_F_MINIMUM);
    n = n->next;
    assert_true(n->u.sphere.r == 2);
    n = n->next;
    assert_true(n->u.sphere.r == 3);
    n = n->next;
    assert_int_equal(n->kind, MODEL_CYLINDER);
    assert_true(n->u.cylinder.h == 1 && n->u.cylinder.r1 == 5 && n->u.cylinder.r2 == 5 &&
                !n->u.cylinder.center);
    n = n->next;
    assert_true(n->u.cylinder.h == 2 && n->u.cylinder.r1 == 2 && n->u.cylinder.r2 == 1);
    assert_null(n->next);
    release(&l);
    /* in the 2D context: circle, square, offset, text, the extrusions and
     * projection; each node's values as OpenSCAD exports them */
    l = lower("rotate_extrude(angle = \"a\", convexity = \"b\", $fa = \"c\") {\n"
              "  circle(r = 2, d = \"a\");\n"
              "  square(size = \"a\", center = 1);\n"
              "  offset(r = \"a\", delta = 2, chamfer = 1) square(1);\n"
              "  text(5, size = \"a\", font = 3, halign = true, spacing = [1]);\n"
              "  projection(cut = \"yes\", convexity = \"a\") cube(1);\n"
              "}\n"
              "linear_extrude(height = [1], scale = [2, \"a\"], twist = \"t\") "
              "circle(d = \"a\");\n"
              "linear_extrude(2, scale = [2, 3]) resize(newsize = [2, \"a\", 3], auto = "
              "[1, \"a\", 0]) circle(1);\n");
    const model_node *e = l.m->first;
    assert_int_equal(e->kind, MODEL_ROTATE_EXTRUDE);
    assert_null(e->pending);
    assert_true(e->u.rotate_extrude->angle == 360 && e->u.rotate_extrude->res.fa == 0);
    n = e->first_child;
    assert_null(n->pending);
    assert_true(n->u.circle->r == 2 && !n->u.circle->has_d);
    n = n->next;
    assert_null(n->pending);
    assert_true(n->u.square->sx == 1 && n->u.square->sy == 1 && !n->u.square->center);
    n = n->next;
    assert_null(n->pending);
    assert_true(!n->u.offset->has_r && n->u.offset->has_delta &&
                n->u.offset->delta == 2 && !n->u.offset->chamfer);
    n = n->next;
    assert_int_equal(n->kind, MODEL_TEXT);
    assert_null(n->pending);
    assert_string_equal(n->u.text->text, "");
    assert_int_equal(n->u.text->length, 0);
    assert_true(n->u.text->size == 10 && n->u.text->spacing == 1);
    assert_string_equal(n->u.text->font, "");
    assert_string_equal(n->u.text->halign, "left");
    n = n->next;
    assert_int_equal(n->kind, MODEL_PROJECTION);
    assert_null(n->pending);
    assert_false(n->u.projection.cut);
    e = e->next;
    assert_int_equal(e->kind, MODEL_LINEAR_EXTRUDE);
    assert_null(e->pending);
    assert_null(e->u.linear_extrude->exact_error);
    assert_true(e->u.linear_extrude->height == 100 && e->u.linear_extrude->plain);
    assert_true(e->first_child->u.circle->r == 1);
    e = e->next;
    assert_false(e->u.linear_extrude->plain);
    assert_true(e->u.linear_extrude->sx == 2 && e->u.linear_extrude->sy == 3);
    n = e->first_child;
    assert_int_equal(n->kind, MODEL_RESIZE);
    assert_null(n->pending);
    assert_true(n->u.resize->size[0] == 2 && n->u.resize->size[1] == 0 &&
                n->u.resize->size[2] == 3);
    assert_true(n->u.resize->autosize[0] == 1 && n->u.resize->autosize[1] == 1 &&
                n->u.resize->autosize[2] == 0);
    release(&l);
}

/* A node's own $fn, $fa and $fs (model_resolution_of): the last of each
 * wins, names that only start like them do not count, a value that is not
 * a number is 0, as OpenSCAD takes it; clamped only when asked. */
static void test_own_resolution(void **state)
{
    (void)state;
    static const struct {
        const char *text;
        double fn, fa, fs;
    } cases[] = {
        {"cylinder(h = 1, r1 = 1, r2 = 9, center = true);", 0, 12, 2},
        {"sphere($fn = 64, $fs = 0.5, $fa = \"x\", r = 1);", 64, 0, 0.5},
        {"sphere($fn = 3, $fnx = 7, $f = 1, $fz = 2, $fs = 4, $fn = 5, $fs = [1]);", 5,
         12, 0},
        {"sphere($fn = true, $fa = undef, $fs = \"2\");", 0, 0, 0},
        {"sphere($fs = 0, $fa = -1);", 0, -1, 0},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        lowered l = lower(cases[i].text);
        double fn, fa, fs;
        model_resolution_of(l.syntax->first, 0, &fn, &fa, &fs);
        assert_true(fn == cases[i].fn && fa == cases[i].fa && fs == cases[i].fs);
        model_resolution_of(l.syntax->first, 1, &fn, &fa, &fs);
        assert_true(fa ==
                    (cases[i].fa < MODEL_F_MINIMUM ? MODEL_F_MINIMUM : cases[i].fa));
        assert_true(fs ==
                    (cases[i].fs < MODEL_F_MINIMUM ? MODEL_F_MINIMUM : cases[i].fs));
        release(&l);
    }
}

/* $fn, $fa and $fs as OpenSCAD 2021.01 looks them up in a hand-written
 * file (its export writes them on every node): a node's own, else the
 * nearest ancestor's that passes them on (not group, union, difference,
 * intersection), each on its own; $fa and $fs clamped to 0.01 in a
 * primitive, not in the other nodes. */
static void test_resolution_passed_down(void **state)
{
    (void)state;
    lowered l =
        lower("multmatrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]], "
              "$fn = 6, $fs = 0) {\n"
              "  group() { sphere(1); }\n"
              "  color(\"red\", $fa = 5) sphere(2, $fn = 3);\n"
              "}\n"
              "group($fn = 5) sphere(3);\n"
              "union($fn = 5) { cylinder(h = 1, r = 1, $fs = 0.5); }\n"
              "linear_extrude(height = 1, $fn = 7, $fs = 0) offset(r = 1) "
              "circle(1);\n");
    const model_node *m = l.m->first, *s = m->first_child->first_child;
    assert_int_equal(s->kind, MODEL_SPHERE);
    assert_true(s->u.sphere.res.fn == 6 && s->u.sphere.res.fa == 12 &&
                s->u.sphere.res.fs == MODEL_F_MINIMUM);
    s = m->first_child->next->first_child;
    assert_int_equal(s->kind, MODEL_SPHERE);
    assert_true(s->u.sphere.res.fn == 3 && s->u.sphere.res.fa == 5 &&
                s->u.sphere.res.fs == MODEL_F_MINIMUM);
    s = m->next->first_child;
    assert_true(s->u.sphere.res.fn == 0 && s->u.sphere.res.fa == 12 &&
                s->u.sphere.res.fs == 2);
    s = m->next->next->first_child;
    assert_int_equal(s->kind, MODEL_CYLINDER);
    assert_true(s->u.cylinder.res.fn == 0 && s->u.cylinder.res.fs == 0.5);
    const model_node *e = m->next->next->next, *o = e->first_child;
    assert_int_equal(o->kind, MODEL_OFFSET);
    assert_true(o->u.offset->res.fn == 7 && o->u.offset->res.fs == 0);
    const model_node *c = o->first_child;
    assert_int_equal(c->kind, MODEL_CIRCLE);
    assert_true(c->u.circle->res.fn == 7 && c->u.circle->res.fs == MODEL_F_MINIMUM);
    release(&l);
}

/* Two models are the same node for node: kind, name, position, flags,
 * children, errors (split_harness.h). */
static void same_nodes(const model_node *a, const model_node *b)
{
    assert_true(split_same_nodes(a, b));
}

/* The streamed lowering (model_stream) makes the model model_lower makes
 * from the whole tree: the root found across statements, '*' subtrees and
 * leaves' children, the stop at the first argument error, the subtrees
 * kept for resize and for the shading nodes that check their children. */
static void test_stream(void **state)
{
    (void)state;
    static const char *const texts[] = {
        "union() { multmatrix([[1, 0, 0, 1], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]])"
        " { sphere(1); } cube(2); }",
        "cube(1); group() { sphere(2); !cube(2); } !sphere(3);",
        "sphere(1) { !cube(1); } cube(2); group() { !cylinder(h = 1, r = 1); }",
        "*group() { !cube(1); } sphere(1);",
        "cube(1); sphere(r = \"a\"); cube(2); !cube(3);",
        "union() { group() { cube(\"x\"); } sphere(1); }",
        "cube(\"x\") { sphere(1); cube(2); }",
        "resize([2, 2, 2]) { cube(1); resize([3, 3, 3]) { sphere(1); } }\n"
        "hull() { resize([1, 1, 1]) { cube(1); } cube(2); }\n"
        "resize([4, 4, 4]) { hull() { resize([1, 1, 1]) { cube(1); } } }",
        "group() { resize([2, 2, 2]) { !cube(1); } }",
        "light(position = [1, 2, 3]) { cube(1); } cube(2);",
        "light(position = [1, 2, 3]) { !cube(1); } sphere(1);",
        "camera(eye = [9, 0, 0], center = [0, 0, 0]) { }",
        "linear_extrude(height = 1) { circle(1); square(2); } sphere(3) { cube(); }",
        "minkowski() { cube(1); sphere(1); } frobnicate(); cube(1);",
        "material(reflect = 0.25) { torus(3, 1); } color(\"red\") { %cube(1); }",
        "cube(1, zz = 1) { sphere(q = 1); } *group() { cube(a = 1); }\n"
        "resize([1, 1, 1], b = 1) { cube(1, 2, 3); resize(c = 2) sphere(d = 1, r = 2); "
        "}\n"
        "light(position = [1, 2, 3]) { cube(e = 1); } hull(1) { cube(size = 1, size = "
        "2); }",
        "group() { cube(q = 1); } cube(\"x\"); sphere(zz = 1);",
        "resize([1, 1, 1]) { cube(1, zz = 1) sphere(1); polyhedron(q = 1) { *cube(1); } "
        "}\n"
        "union() { sphere(1) { cube(1) { cylinder(1, 2, 3, 4, 5); } } cube(x = 1); }",
        "difference() { foo(a = 1) { !cube(5); } cube(1); } !bar(); "
        "linear_extrude(1) { baz() square(1); resize([1, 1]) { qux(); circle(1); } }",
    };
    for (size_t i = 0; i < sizeof texts / sizeof texts[0]; i++) {
        lowered whole = lower(texts[i]);
        model_stream *s;
        sc_error e;
        assert_int_equal(model_stream_new("m.csg", &s, &e), SC_OK);
        parse_sink sink = model_stream_sink(s);
        parse_tree *names;
        if (parse_stream("m.csg", texts[i], strlen(texts[i]), &sink, &names, &e) != SC_OK)
            fail_msg("parse error: %s", e.message);
        model *m;
        assert_int_equal(model_stream_finish(s, &m), SC_OK);
        assert_int_equal(m->has_root, whole.m->has_root);
        same_nodes(m->first, whole.m->first);
        char a[4096], b[4096];
        notes_text(m, a, sizeof a);
        notes_text(whole.m, b, sizeof b);
        assert_string_equal(a, b);
        model_free(m);
        parse_tree_free(names);
        release(&whole);
    }
}

/* A parse split in two threads (parse_sink's fork) at every place in the
 * text makes the model, the warnings and the error a whole streamed parse
 * makes: the second part's nodes, warnings, counts and names joined after
 * the first's, and a part that cannot be joined (an error in it, a root,
 * a lowering stopped, a boundary the scan misread) read again by the
 * first thread. */
static void test_stream_split(void **state)
{
    (void)state;
    static const char *const texts[] = {
        "union() { multmatrix([[1, 0, 0, 1], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]])"
        " { sphere(1); } cube(2); sphere(3); cylinder(h = 1, r = 2); cube([1, 2, 3]); }",
        "cube(1); sphere(2); cylinder(h = 2, r1 = 1, r2 = 0); cube(3); sphere(4);",
        "group() { cube(1); sphere(2); !cube(2); sphere(5); cube(4); } !sphere(3);",
        "difference() { cube(9); sphere(1); { sphere(2); cube(1); } sphere(3); cube(2); "
        "}",
        "union() { cube(1); sphere(r = \"a\"); cube(2); sphere(1); cube(3); }",
        "union() { cube(1); sphere(2); cube(3); sphere(4); cube(\"x\"); sphere(5); }",
        "cube(1) { sphere(1); sphere(2); sphere(3); sphere(4); }\nsphere(1, q = 2);",
        "union() { cube(1, zz = 1); sphere(q = 1); cube(a = 2); frobnicate(); sphere(2); "
        "*cube(3); %sphere(3); #cube(4); }",
        "union() { resize([2, 2, 2]) { cube(1); sphere(1); } cube(2); resize([1, 1, 1]) "
        "sphere(2); cube(3); }",
        "linear_extrude(height = 1) { circle(1); square(2); circle(3); square(4); } "
        "sphere(3);",
        "union() { light(position = [1, 2, 3]) { cube(1); } cube(2); sphere(1); cube(3); "
        "}",
        "union() {\n\tcube(1);\n\t// a comment; with a } brace\n\tsphere(2);\n"
        "\t/* another { one; */ cube(3);\n\tcolor(\"a;b}c\") sphere(4);\n\tcube(5);\n}\n",
        "union() { multmatrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) "
        "cube(1); multmatrix([[1, 0, 0, 1], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) "
        "cube(2); ; ; cube(3); }",
        "union() { cube(1); sphere(2); cube(3) sphere(; cube(4); }",
        "union() { cube(1); sphere(2); cube(3); } } cube(4); sphere(5);",
        "union() { cube(1); sphere(2); cube(3); sphere(4); cube(5);",
        "union() { cube(1); sphere(2); \"open; string } cube(3); }",
        "union() { cube(1); sphere(2); /* open comment; } cube(3); }",
        "union() { cube(1); sphere(2); cube(3); x = 1; sphere(4); }",
    };
    size_t splits = 0, places = 0;
    for (size_t i = 0; i < sizeof texts / sizeof texts[0]; i++) {
        size_t length = strlen(texts[i]);
        for (size_t at = 1; at < length; at++) {
            int split;
            if (split_one(texts[i], length, at, &split) != 0)
                fail_msg("text %zu split at %zu: not the whole parse's result", i, at);
            splits += (size_t)split;
            places++;
        }
    }
    /* most places split: the test reads both paths */
    assert_true(3 * splits > places);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_leaves),
        cmocka_unit_test(test_polyhedron),
        cmocka_unit_test(test_polyhedron_malformed),
        cmocka_unit_test(test_polygon_malformed),
        cmocka_unit_test(test_polygon_range),
        cmocka_unit_test(test_operations),
        cmocka_unit_test(test_matrix_as_openscad_reads_it),
        cmocka_unit_test(test_what_is_lowered),
        cmocka_unit_test(test_twod_context),
        cmocka_unit_test(test_points_context),
        cmocka_unit_test(test_shading_and_curved),
        cmocka_unit_test(test_kind_of),
        cmocka_unit_test(test_errors),
        cmocka_unit_test(test_unknown_left_out),
        cmocka_unit_test(test_argument_warnings),
        cmocka_unit_test(test_stream_split),
        cmocka_unit_test(test_primitive_warnings),
        cmocka_unit_test(test_wrong_types),
        cmocka_unit_test(test_own_resolution),
        cmocka_unit_test(test_resolution_passed_down),
        cmocka_unit_test(test_stream),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
