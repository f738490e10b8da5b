/* A short program on the query calls of libspancast: it loads a model (the
 * file named on the command line, or a drilled cube given as text), prints
 * where the line along x through (0, 5, 5) enters and leaves it, whether two
 * points are inside, and its volume, area and centroid with their error
 * bounds.
 *
 *   cc query.c -lspancast ...   (CMake builds it as spancast-query-example)
 *   ./spancast-query-example [MODEL.csg]
 */
#include <stdio.h>
#include <string.h>

#include "spancast/spancast.h"

static const char drilled[] =
    "difference() {\n"
    "  cube(size = [10, 10, 10]);\n"
    "  multmatrix([[1, 0, 0, 5], [0, 1, 0, 5], [0, 0, 1, -1], [0, 0, 0, 1]]) {\n"
    "    cylinder(h = 12, r1 = 2, r2 = 2);\n"
    "  }\n"
    "}\n";

static int failed(const char *what, const sc_error *error)
{
    char text[SC_ERROR_MESSAGE_MAX + SC_ERROR_FILE_MAX + 64];
    fprintf(stderr, "%s: %s\n", what, sc_error_format(error, text, sizeof text));
    return 1;
}

int main(int argc, char **argv)
{
    sc_load_options load;
    sc_load_options_init(&load);
    sc_scene *scene = NULL;
    sc_error error;
    sc_status st = argc > 1
                       ? sc_scene_load(argv[1], &load, &scene, &error)
                       : sc_scene_load_string("drilled.csg", drilled, strlen(drilled),
                                              &load, &scene, &error);
    if (st != SC_OK)
        return failed("load", &error);

    /* Spans: the line y = 5, z = 5 along +x, over the whole line. */
    sc_ray_query ray;
    sc_ray_query_init(&ray);
    ray.origin[1] = 5;
    ray.origin[2] = 5;
    ray.direction[0] = 1;
    ray.both_ways = 1;
    sc_span_list *spans = NULL;
    if (sc_scene_spans(scene, &ray, &spans, &error) != SC_OK) {
        sc_scene_release(scene);
        return failed("spans", &error);
    }
    for (size_t k = 0; k < sc_span_list_count(spans); k++) {
        const sc_span *s = sc_span_list_get(spans, k);
        printf("span %zu: x from %g to %g (%s at line %d to %s at line %d%s)\n", k,
               s->in.point[0], s->out.point[0], s->in.leaf_kind, s->in.location.line,
               s->out.leaf_kind, s->out.location.line,
               s->in.subtracted || s->out.subtracted ? ", a subtracted surface" : "");
    }
    sc_span_list_release(spans);

    /* Membership: the hole's axis and a point in the wall. */
    static const char *const where_names[] = {"out", "in", "on"};
    double points[2][3] = {{5, 5, 5}, {1, 1, 1}};
    for (int k = 0; k < 2; k++) {
        int where;
        if (sc_scene_inside(scene, points[k], &where, &error) != SC_OK) {
            sc_scene_release(scene);
            return failed("inside", &error);
        }
        printf("point (%g, %g, %g): %s\n", points[k][0], points[k][1], points[k][2],
               where_names[where]);
    }

    /* Measures, to a relative tolerance of 1e-3. */
    sc_measure_options options;
    sc_measure_options_init(&options);
    options.tolerance = 1e-3;
    sc_measure m;
    sc_measure_init(&m); /* sets m.size, so a later, larger sc_measure stays compatible */
    st = sc_scene_measure(scene, &options, &m, &error);
    sc_scene_release(scene);
    if (st != SC_OK)
        return failed("measure", &error);
    printf("volume %.6g +- %.2g\n", m.volume.value, m.volume.error);
    printf("area %.6g +- %.2g\n", m.area.value, m.area.error);
    printf("centroid (%.4g, %.4g, %.4g)\n", m.centroid[0].value, m.centroid[1].value,
           m.centroid[2].value);
    return 0;
}
