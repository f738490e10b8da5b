/* `spancast render --animate=N` and `--turntable=N`: a sequence of frames,
 * and `--video=FILE` to encode them.
 *
 * Frame i of N is OpenSCAD's: a .scad model is evaluated at
 * $t = i * (1.0 / N), computed exactly as OpenSCAD's own --animate does
 * (openscad.cc, 2021.01), and written to the output's name with the frame
 * number in five digits before the extension: -o frame.png gives
 * frame00000.png, frame00001.png, ... A .csg or mesh (.stl, .off, .amf, .3mf) model is
 * already evaluated; its frames differ only by the turntable. With
 * --turntable the camera turns about the vertical axis through its centre
 * (the model's centre with the automatic camera) by 360 degrees over the
 * whole sequence, frame i at 360 i / N.
 *
 * Motion blur across $t: with --shutter=OPEN,CLOSE (fractions of a frame's
 * interval 1 / N, 0 <= OPEN <= CLOSE <= 1) every frame is the mean of
 * --subframes=K renders at the midpoints of K equal parts of
 * [i + OPEN, i + CLOSE] / N, each a fresh evaluation of the .scad (and a
 * turntable angle), in linear light. A closed shutter (the default, or
 * OPEN = CLOSE) takes the frame's instant alone.
 *
 * --video=FILE hands the frames to ffmpeg (Debian's package) once they are
 * all written: H.264 in yuv420p at --fps (default 24), the size padded to
 * even numbers as that format needs. ffmpeg writes a temporary file beside
 * the target, renamed into place when it succeeds, so a failure never
 * destroys an earlier video; as for images, the target keeps its mode, and
 * a symbolic link stays one (the file it names is replaced).
 */
#define _POSIX_C_SOURCE 200809L

#include "cli/frames.h"

#include <errno.h>
#include <math.h>
#include <spawn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "cli/cli.h"
#include "cli/scad.h"
#include "formats/file.h"
#include "formats/framebuffer.h"

extern char **environ;

void frames_job_init(frames_job *job)
{
    memset(job, 0, sizeof *job);
    job->subframes = 8;
    job->fps = 24;
}

int frames_name(const char *output, int frame, char *out, size_t size)
{
    const char *slash = strrchr(output, '/');
    const char *dot = strrchr(output, '.');
    if (!dot || (slash && dot < slash))
        dot = output + strlen(output);
    int n = snprintf(out, size, "%.*s%05d%s", (int)(dot - output), output, frame, dot);
    return n > 0 && (size_t)n < size;
}

/* The printf pattern of the frames' names for ffmpeg: "%" doubled in the
 * name, "%05d" where the number goes. */
static int frames_pattern(const char *output, char *out, size_t size)
{
    const char *slash = strrchr(output, '/');
    const char *dot = strrchr(output, '.');
    if (!dot || (slash && dot < slash))
        dot = output + strlen(output);
    size_t k = 0;
    for (const char *p = output; *p; p++) {
        if (p == dot) {
            if (k + 5 >= size)
                return 0;
            memcpy(out + k, "%05d", 4);
            k += 4;
        }
        if (k + 3 >= size)
            return 0;
        if (*p == '%')
            out[k++] = '%';
        out[k++] = *p;
    }
    if (!*dot) {
        if (k + 5 >= size)
            return 0;
        memcpy(out + k, "%05d", 4);
        k += 4;
    }
    out[k] = '\0';
    return 1;
}

/* Turns the camera of o by deg degrees about the vertical axis through its
 * centre (see above). */
static void turn_camera(sc_render_options *o, double deg)
{
    switch (o->camera_mode) {
    case SC_CAMERA_AUTO:
        o->camera_mode = SC_CAMERA_GIMBAL;
        o->camera[0] = o->camera[1] = o->camera[2] = 0;
        o->camera[3] = 55; /* OpenSCAD's default view rotation and distance */
        o->camera[4] = 0;
        o->camera[5] = 25 + deg;
        o->camera[6] = 140;
        o->viewall = o->autocenter = 1;
        break;
    case SC_CAMERA_GIMBAL:
        o->camera[5] += deg;
        break;
    case SC_CAMERA_VECTOR: {
        double a = deg * 3.14159265358979323846 / 180, c = cos(a), s = sin(a);
        double x = o->camera[0] - o->camera[3], y = o->camera[1] - o->camera[4];
        o->camera[0] = o->camera[3] + c * x - s * y;
        o->camera[1] = o->camera[4] + s * x + c * y;
        break;
    }
    }
}

/* Runs ffmpeg on the written frames; returns 0 or an exit status after
 * printing why. */
static int encode_video(const frames_job *job)
{
    char pattern[4096], temp[4096], rate[32];
    /* the file replaced: through a symbolic link, which stays */
    char *target = file_output_target(job->video);
    if (!target) {
        fprintf(stderr, "spancast: error: cannot encode '%s': out of memory\n",
                job->video);
        return CLI_EXIT_FAILED;
    }
    const char *slash = strrchr(target, '/');
    const char *ext = strrchr(target, '.');
    if (!ext || (slash && ext < slash))
        ext = "";
    if (!frames_pattern(job->output, pattern, sizeof pattern) ||
        snprintf(temp, sizeof temp, "%.*s.tmp%ld%s", (int)(strlen(target) - strlen(ext)),
                 target, (long)getpid(), ext) >= (int)sizeof temp) {
        fprintf(stderr, "spancast: error: cannot encode '%s': the name is too long\n",
                job->video);
        free(target);
        return CLI_EXIT_FAILED;
    }
    snprintf(rate, sizeof rate, "%.17g", job->fps);
    char *argv[] = {
        "ffmpeg",   "-y",      "-loglevel", "error", "-framerate",
        rate,       "-i",      pattern,     "-vf",   "pad=ceil(iw/2)*2:ceil(ih/2)*2",
        "-pix_fmt", "yuv420p", temp,        NULL};
    pid_t pid;
    int spawned = posix_spawnp(&pid, "ffmpeg", NULL, NULL, argv, environ);
    if (spawned != 0) {
        fprintf(stderr,
                "spancast: error: cannot encode '%s': ffmpeg is not installed "
                "('ffmpeg' %s); the frames are written\n",
                job->video,
                spawned == ENOENT ? "was not found in PATH" : strerror(spawned));
        free(target);
        return CLI_EXIT_FAILED;
    }
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR)
        ;
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        unlink(temp);
        fprintf(stderr, "spancast: error: ffmpeg could not encode '%s'\n", job->video);
        free(target);
        return CLI_EXIT_FAILED;
    }
    int replaced = file_replace(temp, target), why = errno;
    free(target);
    if (!replaced) {
        fprintf(stderr, "spancast: error: cannot write '%s': %s\n", job->video,
                strerror(why));
        unlink(temp);
        return CLI_EXIT_FAILED;
    }
    return 0;
}

int frames_run(const frames_job *job)
{
    int n = job->animate > 0 ? job->animate : job->turntable;
    int scad = scad_is_source(job->input);
    int blur = job->shutter[1] > job->shutter[0];
    int parts = blur ? job->subframes : 1;
    sc_load_options lo;
    sc_load_options_init(&lo);
    cli_load_options(&lo, job->faithful);
    sc_scene *fixed = NULL; /* a model without $t, loaded once */
    sc_error error;
    if (!scad) {
        fixed = cli_load(job->input, job->faithful);
        if (!fixed)
            return CLI_EXIT_FAILED;
        if (!job->turntable)
            fprintf(stderr,
                    "spancast: warning: --animate: %s is not a .scad, so $t changes "
                    "nothing and every frame is the same image (--turntable turns the "
                    "camera)\n",
                    job->input);
    }
    int status = 0;
    float *sum = NULL;
    for (int i = 0; i < n && status == 0; i++) {
        double t = i * (1.0 / n); /* OpenSCAD's $t of frame i */
        sc_framebuffer *first = NULL;
        for (int k = 0; k < parts && status == 0; k++) {
            double tk = t;
            if (blur)
                tk = t + (job->shutter[0] +
                          (k + 0.5) * (job->shutter[1] - job->shutter[0]) / parts) /
                             n;
            sc_scene *scene = fixed;
            if (scad) {
                if (scad_load_at(job->input, &lo, tk, &scene, &error,
                                 &(scad_stop){&cli_stop, cli_loading_flag()}) != SC_OK) {
                    cli_print_error(&error);
                    status = CLI_EXIT_FAILED;
                    break;
                }
            }
            sc_render_options o;
            status = job->options_for(job->user, scene, &o);
            if (status == 0 && job->turntable > 0)
                turn_camera(&o, 360.0 * tk);
            sc_framebuffer *fb = NULL;
            if (status == 0 && sc_render(scene, &o, &fb, &error) != SC_OK) {
                if (error.status == SC_ERR_CANCELLED)
                    status = FRAMES_INTERRUPTED;
                else
                    cli_print_error(&error);
                if (!status)
                    status = error.status == SC_ERR_ARGUMENT ? CLI_EXIT_USAGE
                                                             : CLI_EXIT_FAILED;
            }
            if (scad)
                sc_scene_release(scene);
            if (status)
                break;
            size_t values = (size_t)fb->width * (size_t)fb->height * 3;
            if (!first) {
                first = fb;
                if (parts > 1) {
                    free(sum);
                    sum = calloc(values, sizeof *sum);
                    if (!sum) {
                        fputs("spancast: error: out of memory\n", stderr);
                        status = CLI_EXIT_FAILED;
                        break;
                    }
                }
            }
            if (parts > 1) {
                for (size_t v = 0; v < values; v++)
                    sum[v] += fb->color[v] / (float)parts;
            }
            if (fb != first)
                sc_framebuffer_release(fb);
        }
        if (status == 0 && first) {
            if (parts > 1)
                memcpy(first->color, sum,
                       (size_t)first->width * first->height * 3 * sizeof *sum);
            char name[4096];
            if (!frames_name(job->output, i, name, sizeof name)) {
                fprintf(stderr,
                        "spancast: error: cannot write '%s': the name is too long\n",
                        job->output);
                status = CLI_EXIT_FAILED;
            } else if (sc_framebuffer_write_color(first, name, &error) != SC_OK) {
                if (error.status == SC_ERR_CANCELLED) {
                    status = FRAMES_INTERRUPTED;
                } else {
                    cli_print_error(&error);
                    status = CLI_EXIT_FAILED;
                }
            } else if (!job->quiet) {
                fprintf(stderr, "spancast: wrote %s ($t = %.17g)\n", name, t);
            }
        }
        sc_framebuffer_release(first);
    }
    free(sum);
    sc_scene_release(fixed);
    if (status == 0 && job->video) {
        status = encode_video(job);
        if (status == 0 && !job->quiet)
            fprintf(stderr, "spancast: wrote %s (%d frames at %g per second)\n",
                    job->video, n, job->fps);
    }
    return status;
}
