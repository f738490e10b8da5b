/* Renders a model into memory with libspancast and prints what the image
 * holds: how many pixels the solid covers, whether the centre pixel is one
 * of them, and the mean colour of those pixels; then, when asked, writes
 * the colour image to a file (the format follows its extension).
 *
 *   render_buffer MODEL.csg [OUT.png]
 *
 * Build against the installed library:
 *   cc render_buffer.c $(pkg-config --cflags --libs spancast) -o render_buffer
 * or with CMake's find_package(spancast) (examples/CMakeLists.txt).
 */
#include <spancast/spancast.h>

#include <stdio.h>

int main(int argc, char **argv)
{
    if (argc != 2 && argc != 3) {
        fprintf(stderr, "usage: render_buffer MODEL.csg [OUT.png]\n");
        return 2;
    }
    printf("libspancast %s (header %s)\n", sc_version(), SPANCAST_VERSION_STRING);

    sc_error error;
    char message[2048];
    sc_load_options load;
    sc_load_options_init(&load);
    sc_scene *scene = NULL;
    if (sc_scene_load(argv[1], &load, &scene, &error) != SC_OK) {
        fprintf(stderr, "%s\n", sc_error_format(&error, message, sizeof message));
        return 1;
    }

    /* The default camera looks at the model's centre and shows all of it. */
    sc_render_options options;
    sc_render_options_init(&options);
    sc_render_options_from_scene(&options, scene);
    options.width = 160;
    options.height = 120;
    options.want_color = 1;
    options.want_mask = 1;
    sc_framebuffer *fb = NULL;
    if (sc_render(scene, &options, &fb, &error) != SC_OK) {
        fprintf(stderr, "%s\n", sc_error_format(&error, message, sizeof message));
        sc_scene_release(scene);
        return 1;
    }

    /* The framebuffer is opaque: its size and buffers come from getters,
     * and the buffers belong to it. */
    int width = sc_framebuffer_width(fb), height = sc_framebuffer_height(fb);
    const uint8_t *mask = sc_framebuffer_mask(fb);
    const float *color = sc_framebuffer_color(fb);
    size_t hits = 0;
    double sum[3] = {0, 0, 0};
    for (int j = 0; j < height; j++)
        for (int i = 0; i < width; i++) {
            size_t k = (size_t)j * (size_t)width + (size_t)i;
            if (!mask[k])
                continue;
            hits++;
            for (int c = 0; c < 3; c++)
                sum[c] += color[3 * k + c];
        }
    size_t centre = (size_t)(height / 2) * (size_t)width + (size_t)(width / 2);
    printf("image %dx%d\n", width, height);
    printf("hit pixels %zu of %zu\n", hits, (size_t)width * (size_t)height);
    printf("centre %s\n", mask[centre] ? "hit" : "miss");
    if (hits)
        printf("mean colour of the solid %.3f %.3f %.3f\n", sum[0] / (double)hits,
               sum[1] / (double)hits, sum[2] / (double)hits);
    sc_render_stats stats;
    sc_render_stats_init(&stats);
    if (sc_framebuffer_get_stats(fb, &stats, &error) == SC_OK)
        printf("camera rays %llu\n", (unsigned long long)stats.camera_rays);

    int status = 0;
    if (argc == 3) {
        if (sc_framebuffer_write_color(fb, argv[2], &error) == SC_OK) {
            printf("wrote %s\n", argv[2]);
        } else {
            fprintf(stderr, "%s\n", sc_error_format(&error, message, sizeof message));
            status = 1;
        }
    }
    sc_framebuffer_release(fb);
    sc_scene_release(scene);
    return status;
}
