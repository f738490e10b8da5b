/* Lists where a ray enters and leaves a model's solid, with libspancast's
 * span query: the parameter t and the point of each end, the leaf whose
 * surface it is, and the length inside.
 *
 *   spans_ray MODEL.csg OX OY OZ DX DY DZ
 *
 * Points on the ray are origin + t * direction, t >= 0; t is in units of
 * the direction as given.
 *
 * Build against the installed library:
 *   cc spans_ray.c $(pkg-config --cflags --libs spancast) -o spans_ray
 * or with CMake's find_package(spancast) (examples/CMakeLists.txt).
 */
#include <spancast/spancast.h>

#include <stdio.h>
#include <stdlib.h>

static void print_end(const char *what, const sc_span_end *end)
{
    printf("  %s t=%.17g (%.17g, %.17g, %.17g)", what, end->t, end->point[0],
           end->point[1], end->point[2]);
    if (end->leaf >= 0)
        printf(" %s#%d at %s:%d:%d%s", end->leaf_kind, end->leaf,
               end->location.file ? end->location.file : "?", end->location.line,
               end->location.column, end->subtracted ? " subtracted" : "");
    else
        printf(" (ray start)");
    printf("\n");
}

int main(int argc, char **argv)
{
    if (argc != 8) {
        fprintf(stderr, "usage: spans_ray MODEL.csg OX OY OZ DX DY DZ\n");
        return 2;
    }
    sc_ray_query query;
    sc_ray_query_init(&query);
    for (int k = 0; k < 3; k++) {
        query.origin[k] = strtod(argv[2 + k], NULL);
        query.direction[k] = strtod(argv[5 + k], NULL);
    }

    sc_error error;
    char message[2048];
    sc_load_options load;
    sc_load_options_init(&load);
    sc_scene *scene = NULL;
    if (sc_scene_load(argv[1], &load, &scene, &error) != SC_OK) {
        fprintf(stderr, "%s\n", sc_error_format(&error, message, sizeof message));
        return 1;
    }
    sc_span_list *spans = NULL;
    if (sc_scene_spans(scene, &query, &spans, &error) != SC_OK) {
        fprintf(stderr, "%s\n", sc_error_format(&error, message, sizeof message));
        sc_scene_release(scene);
        return 1;
    }
    size_t count = sc_span_list_count(spans);
    printf("%zu span%s\n", count, count == 1 ? "" : "s");
    for (size_t k = 0; k < count; k++) {
        const sc_span *span = sc_span_list_get(spans, k);
        printf("span %zu: distance %.17g\n", k + 1, span->distance);
        print_end("in ", &span->in);
        print_end("out", &span->out);
    }
    sc_span_list_release(spans);
    sc_scene_release(scene);
    return 0;
}
