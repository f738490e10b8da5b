/* spancast-view: `spancast view MODEL`, an interactive window on a model
 * that reloads when the file changes.
 *
 * `spancast view ...` runs this program (found beside spancast) with the
 * same arguments; it is a program of its own because SDL and the display
 * libraries it links cost every other command about 20 ms to load.
 *
 * The window shows spancast's own renderer (sc_render, the same call and
 * options as `spancast render`). Three threads: this one handles the
 * window, the mouse, the keys and the file watch, and never renders; the
 * render thread (view_worker.c) renders one job at a time; the loading
 * thread (view_loader.c) loads or converts the model.
 *
 * Progressive rendering: every change of the view (mouse, keys, window
 * size, samples, a reloaded model) gives the view a new number. The first
 * frame of a view is coarse: the image scaled down by a step of
 * coarse_scales, chosen from the measured time of the previous coarse
 * frames so that one takes at most FRAME_BUDGET_MS; it is stretched to the
 * window. When the view holds still (no button held, or no motion for
 * STILL_SECONDS) the frame is refined: full size with 1 sample per pixel,
 * then 4, 16, ... up to the target (--spp, keys + and -), each pass adding
 * its samples to the ones before (view_worker.c), so that the last pass
 * shows `spancast render --spp=N`'s image. A refinement in flight is
 * abandoned (sc_render's cancel flag) as soon as the view changes.
 *
 * Keys follow OpenSCAD's View menu where it has them; see usage_text.
 * The preview options of `render` (colour scheme, lighting, preview
 * colours, edges, axes, crosshairs, section planes, ambient occlusion) are
 * read from the command line as `render` reads them and kept in
 * viewer.look; keys toggle them (Ctrl+1 edges, Ctrl+2 axes with their
 * scale marks, Ctrl+3 crosshairs, C the next colour scheme, X a section
 * plane, A ambient occlusion). Every frame is sc_render with them, so the
 * overlays are the renderer's, and the title prints them with the camera.
 *
 * Reloading: the model and, for a .scad, every file OpenSCAD read are
 * watched (watch.c). WATCH_SETTLE_MS after the last change the loading
 * thread loads the model again; the camera stays. A model that fails to
 * load prints its error on stderr, shows it in the title and a red frame,
 * and the last good model stays on screen.
 *
 * Status: the title holds the model, the state, the load time, the last
 * frame's time, size and rays per second, and the view as `render`
 * options. Ctrl+S writes a screenshot: a render at the window's size and
 * the target samples (the refined image itself once refining is done, else
 * the refinement carried on to the end), written by the library's writer,
 * so the file is the one `spancast render` writes with the options printed
 * beside it. With --max-time a screenshot that takes longer is given up,
 * as `render --max-time` gives up, and nothing is written.
 * A click (no drag) picks: the ray of that pixel (sc_scene_pixel_ray) and
 * its spans (sc_scene_spans) go to stdout, the first hit to the title.
 *
 * Headless: without a display SDL fails to start, or starts one of its
 * drivers that show nothing (offscreen, dummy); both are an error, exit 1.
 */
#define _POSIX_C_SOURCE 200809L

#include <SDL.h>

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "cli/cli.h"
#include "cli/scad.h"
#include "cli/view.h"
#include "cli/watch.h"

enum { EXIT_FAILED = 1 };

#define FRAME_BUDGET_MS 25.0 /* a coarse frame's render time, below 33 ms */
#define STILL_SECONDS 0.1    /* no motion this long while dragging: refine */
#define MAX_SPP 1024
#define DEFAULT_AO 8 /* rays per sample when A turns occlusion on */
#define MAX_SCHEMES 64

static const char usage_text[] =
    "usage: spancast view MODEL [--imgsize=W,H] [--spp=N] [--threads=N] [--faithful]\n"
    "                           [--strict] [--max-time=S] [--verbose] [preview options]\n"
    "\n"
    "Opens a window on MODEL (.csg, .scad through OpenSCAD, or a mesh: .stl, .off,\n"
    ".amf or .3mf) and renders it again whenever the file, or a file a .scad\n"
    "model uses, changes.\n"
    "\n"
    "  -D NAME=VALUE   set an OpenSCAD variable for the conversion (repeatable)\n"
    "  --imgsize=W,H   window size (default 800,600)\n"
    "  --spp=N         samples per pixel when the view is still (default 4)\n"
    "  --threads=N     render threads (default 0: all cores)\n"
    "  --faithful      spheres and cylinders as OpenSCAD's polyhedra\n"
    "  --strict        a warning that leaves a part out is an error (a mesh that is\n"
    "                  not closed, a file that cannot be read, a matrix not finite,\n"
    "                  an argument that is no parameter; for a .scad model,\n"
    "                  OpenSCAD's first warning)\n"
    "  --max-time=S    give up a screenshot that takes longer than S seconds\n"
    "  --verbose       print every frame's size and time on stdout\n"
    "\n"
    "preview options, as for 'spancast render' (see spancast --help):\n"
    "  --colorscheme=NAME --preview --lighting=NAME --view=LIST --edge-angle=DEG\n"
    "  --edge-width=PX --view-preset=NAME --section=NX,NY,NZ,D --section-style=STYLE\n"
    "  --ao=N --ao-radius=F --aperture=A --focus=D\n"
    "\n"
    "mouse: left drag rotates (shift: around y), right drag pans (shift: zooms),\n"
    "       wheel zooms, a click prints what the ray under the pointer hits\n"
    "keys:  Ctrl+4..9, Ctrl+0   top, bottom, left, right, front, back, diagonal\n"
    "       Ctrl+Shift+V        view all        Home  reset view\n"
    "       Ctrl+] / Ctrl+[     zoom in / out\n"
    "       P / O               perspective / orthographic\n"
    "       Ctrl+1, Ctrl+2      edges, axes with scale marks (on / off)\n"
    "       Ctrl+3              crosshairs (on / off)\n"
    "       C                   next colour scheme\n"
    "       X                   cut away the half nearer the camera through the\n"
    "                           model's centre / remove the cuts\n"
    "       A                   ambient occlusion (on / off)\n"
    "       + / -               samples per pixel when still (x4 / /4)\n"
    "       Ctrl+S              screenshot (NAME-view-N.png, with its render command)\n"
    "       Ctrl+R, F4, F5      reload now\n"
    "       Q, Esc, Ctrl+Q/W    quit\n";

/* Coarse frames divide the window's sides by one of these. */
static const double coarse_scales[] = {1, 1.5, 2, 2.5, 3, 4, 5, 6, 8, 10, 12, 16, 24, 32};
#define COARSE_STEPS ((int)(sizeof coarse_scales / sizeof coarse_scales[0]))

typedef struct viewer {
    /* the command line */
    const char *path;
    int faithful, verbose, threads;
    int spp;         /* target samples per pixel when still */
    double max_time; /* --max-time: a screenshot's limit in seconds; 0: none */
    /* the window */
    SDL_Window *window;
    SDL_Renderer *renderer;
    SDL_Texture *texture;
    int texture_w, texture_h;
    Uint32 wake_event;
    int width, height; /* the window, and the full image */
    int dirty;         /* draw again */
    char title[16384];
    /* the threads and the watch */
    view_worker *worker;
    view_loader *loader;
    watch_set *watched;
    int change_pending;
    double change_at;
    /* the model and the view */
    view_model *model;
    double load_seconds;
    int loads; /* models loaded so far, shown in the title as "#N" */
    char error[SC_ERROR_MESSAGE_MAX + SC_ERROR_FILE_MAX + 64];   /* the failed load */
    char warning[SC_ERROR_MESSAGE_MAX + SC_ERROR_FILE_MAX + 64]; /* the load's first,
                                                                    and how many more */
    view_camera cam;
    uint64_t view; /* the number of the current view */
    /* the preview options (colour scheme, lighting, overlays, sections,
     * ambient occlusion); the camera, size and samples fields are unused */
    sc_render_options look;
    sc_render_options defaults; /* sc_render_options_init's, to print only changes */
    sc_view_preset preset;      /* --view-preset: the first view */
    int ao_on;                  /* rays per sample when A turns occlusion on */
    char schemes[MAX_SCHEMES][SC_COLOR_SCHEME_NAME_MAX]; /* the names C cycles */
    int scheme_count, scheme_index;
    /* what the window shows */
    uint64_t shown_view;
    int shown_full, shown_spp;
    /* the last frame's figures, and the coarse step */
    double frame_ms, rays_per_second;
    int frame_w, frame_h, frame_spp;
    int coarse_step;
    /* the mouse */
    int buttons; /* SDL button mask held */
    int press_x, press_y, dragged;
    double last_motion;
    char pick[512]; /* the last pick, for the title, until the view changes */
    /* the name of OpenSCAD's export when the model is converted (positions
     * there are put on the source, as its messages are); "" otherwise */
    char export_name[PATH_MAX + 16];
    char note[SC_ERROR_MESSAGE_MAX + SC_ERROR_FILE_MAX + PATH_MAX + 64]; /* passing */
    /* screenshots */
    int shot_busy, shot_requested, shot_number;
    double shot_asked; /* when the screenshot in flight was asked for */
    char shot_path[PATH_MAX];
    char shot_command[4 * PATH_MAX + 2200];
} viewer;

static double seconds_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* ---- the command line ---- */

/* Applies one of render's preview options (value NULL when none was given)
 * to v->look with render's parser, checks and messages; returns 0 or a
 * usage exit status. */
static int apply_preview_option(viewer *v, const char *name, size_t len, int takes_value,
                                const char *value)
{
    if (!takes_value && value)
        return cli_usage_error("option '%.*s' takes no value", (int)len, name);
    if (takes_value && (!value || !*value))
        return cli_usage_error("option '%.*s' expects a value", (int)len, name);
    return cli_apply_preview_option(&v->look, &v->preset, name, len, value);
}

static int parse_args(viewer *v, int argc, char **argv)
{
    int first = argc > 1 && !strcmp(argv[1], "view") ? 2 : 1;
    for (int k = first; k < argc; k++) {
        const char *arg = argv[k];
        if (!strcmp(arg, "--help") || !strcmp(arg, "-h")) {
            fputs(usage_text, stdout);
            exit(0);
        }
        if (arg[0] != '-' || !arg[1]) {
            if (v->path)
                return cli_usage_error("unexpected argument '%s'", arg);
            v->path = arg;
            continue;
        }
        const char *eq = strchr(arg, '=');
        size_t len = eq ? (size_t)(eq - arg) : strlen(arg);
        int preview = cli_preview_option(arg, len);
        /* --sheet, one image of several views, is render's only */
        if (preview >= 0 && !(len == 7 && !strncmp(arg, "--sheet", len))) {
            /* a value may be the next argument, as for render */
            const char *value = eq ? eq + 1 : preview && k + 1 < argc ? argv[++k] : NULL;
            int st = apply_preview_option(v, arg, len, preview, value);
            if (st)
                return st;
            continue;
        }
        if (len == 10 && !strncmp(arg, "--faithful", len) && !eq) {
            v->faithful |= CLI_LOAD_FAITHFUL;
            continue;
        }
        if (len == 8 && !strncmp(arg, "--strict", len) && !eq) {
            v->faithful |= CLI_LOAD_STRICT;
            continue;
        }
        if (len == 9 && !strncmp(arg, "--verbose", len) && !eq) {
            v->verbose = 1;
            continue;
        }
        int takes = (len == 9 && !strncmp(arg, "--imgsize", len)) ||
                    (len == 5 && !strncmp(arg, "--spp", len)) ||
                    (len == 10 && !strncmp(arg, "--max-time", len)) ||
                    (len == 9 && !strncmp(arg, "--threads", len));
        if (!takes)
            return cli_usage_error("unknown option '%s' for 'view'", arg);
        const char *value = eq ? eq + 1 : k + 1 < argc ? argv[++k] : NULL;
        if (!value || !*value)
            return cli_usage_error("option '%s' expects a value", arg);
        long n, w, h;
        if (!strncmp(arg, "--spp", len)) {
            if (!cli_parse_int(value, 1, MAX_SPP, &n))
                return cli_usage_error("--spp expects an integer from 1 to 1024");
            v->spp = (int)n;
        } else if (!strncmp(arg, "--max-time", len)) {
            double seconds;
            if (!cli_parse_number(value, &seconds) || !(seconds > 0 && seconds <= 1e7))
                return cli_usage_error(
                    "--max-time expects seconds above 0 (at most 1e7)");
            v->max_time = seconds;
        } else if (!strncmp(arg, "--threads", len)) {
            if (!cli_parse_int(value, 0, 4096, &n))
                return cli_usage_error("--threads expects a non-negative integer");
            v->threads = cli_load_threads = (int)n;
        } else {
            char wtext[32];
            const char *comma = strchr(value, ',');
            if (!comma || (size_t)(comma - value) >= sizeof wtext)
                return cli_usage_error("--imgsize expects W,H with positive integers");
            memcpy(wtext, value, (size_t)(comma - value));
            wtext[comma - value] = '\0';
            if (!cli_parse_int(wtext, 16, 8192, &w) ||
                !cli_parse_int(comma + 1, 16, 8192, &h))
                return cli_usage_error("--imgsize expects W,H from 16 to 8192");
            v->width = (int)w;
            v->height = (int)h;
        }
    }
    if (!v->path)
        return cli_usage_error("missing input file");
    if (v->look.preview)
        v->faithful |= CLI_LOAD_PREVIEW;
    return 0;
}

/* ---- messages ---- */

static void format_error(const sc_error *error, char *buf, size_t size)
{
    if (error->file[0])
        sc_error_format(error, buf, size);
    else
        snprintf(buf, size, "spancast: error: %s", error->message);
}

/* s quoted for a POSIX shell when it needs it. */
static void shell_quote(const char *s, char *buf, size_t size)
{
    int plain = *s != '\0';
    for (const char *p = s; *p; p++)
        if (!(('a' <= *p && *p <= 'z') || ('A' <= *p && *p <= 'Z') ||
              ('0' <= *p && *p <= '9') || strchr("._/-+,=:", *p)))
            plain = 0;
    if (plain) {
        snprintf(buf, size, "%s", s);
        return;
    }
    size_t n = 0;
    if (n + 1 < size)
        buf[n++] = '\'';
    for (const char *p = s; *p && n + 5 < size; p++) {
        if (*p == '\'') {
            memcpy(buf + n, "'\\''", 4);
            n += 4;
        } else {
            buf[n++] = *p;
        }
    }
    if (n + 1 < size)
        buf[n++] = '\'';
    buf[n] = '\0';
}

static const char *base_name(const char *path)
{
    const char *slash = strrchr(path, '/');
    return slash ? slash + 1 : path;
}

/* ---- the view ---- */

static void view_changed(viewer *v)
{
    v->view++;
    v->pick[0] = '\0';
    view_worker_cancel(v->worker);
}

/* Render options for the current view at w x h pixels and spp samples. */
static sc_render_options view_options(const viewer *v, int w, int h, int spp)
{
    sc_render_options o;
    sc_render_options_init(&o);
    view_camera_apply(&v->cam, &o);
    o.width = w;
    o.height = h;
    o.spp = spp;
    o.threads = v->threads;
    const sc_render_options *look = &v->look;
    o.use_scheme = look->use_scheme;
    o.scheme = look->scheme;
    o.preview = look->preview;
    o.lighting = look->lighting;
    o.view = look->view;
    o.edge_angle_deg = look->edge_angle_deg;
    o.edge_width = look->edge_width;
    o.section_count = look->section_count;
    memcpy(o.section, look->section, sizeof o.section);
    o.section_style = look->section_style;
    o.ao_samples = look->ao_samples;
    o.ao_radius = look->ao_radius;
    o.aperture = look->aperture;
    o.focus = look->focus;
    return o;
}

/* Appends to buf (of size bytes, holding a string) what printf formats. */
static void append(char *buf, size_t size, const char *format, ...)
{
    size_t used = strlen(buf);
    if (used + 1 >= size)
        return;
    va_list args;
    va_start(args, format);
    vsnprintf(buf + used, size - used, format, args);
    va_end(args);
}

/* The view as `render` options: the camera's (view_camera_format), then
 * the preview options that differ from render's defaults, each quoted for a
 * shell where it needs it, every number printed so that it reads back to
 * the same double. Returns buf. */
static const char *view_format(const viewer *v, char *buf, size_t size)
{
    const sc_render_options *look = &v->look, *dflt = &v->defaults;
    view_camera_format(&v->cam, v->width, v->height, v->spp, buf, size);
    if (look->use_scheme) {
        char option[SC_COLOR_SCHEME_NAME_MAX + 32], quoted[2 * sizeof option];
        snprintf(option, sizeof option, "--colorscheme=%s", look->scheme.name);
        shell_quote(option, quoted, sizeof quoted);
        append(buf, size, " %s", quoted);
    }
    if (look->preview)
        append(buf, size, " --preview");
    if (look->lighting == SC_LIGHTING_OPENSCAD)
        append(buf, size, " --lighting=openscad");
    if (look->view) {
        append(buf, size, " --view=");
        for (int k = 0, first = 1; k < 4; k++)
            if (look->view & (1u << k)) {
                append(buf, size, "%s%s", first ? "" : ",", cli_view_names[k]);
                first = 0;
            }
    }
    if (look->edge_angle_deg != dflt->edge_angle_deg)
        append(buf, size, " --edge-angle=%.17g", look->edge_angle_deg);
    if (look->edge_width != dflt->edge_width)
        append(buf, size, " --edge-width=%.17g", look->edge_width);
    for (int k = 0; k < look->section_count; k++)
        append(buf, size, " --section=%.17g,%.17g,%.17g,%.17g", look->section[k][0],
               look->section[k][1], look->section[k][2], look->section[k][3]);
    if (look->section_count && look->section_style == SC_SECTION_HATCH)
        append(buf, size, " --section-style=hatch");
    if (look->ao_samples)
        append(buf, size, " --ao=%d", look->ao_samples);
    if (look->ao_samples && look->ao_radius != dflt->ao_radius)
        append(buf, size, " --ao-radius=%.17g", look->ao_radius);
    if (look->aperture > 0)
        append(buf, size, " --aperture=%.17g", look->aperture);
    if (look->focus > 0)
        append(buf, size, " --focus=%.17g", look->focus);
    return buf;
}

/* Queues a job of the current view: spp samples per pixel, of which the
 * frame holds samples when done (a refinement or a screenshot). */
static void submit(viewer *v, view_job_kind kind, int w, int h, int spp, int samples)
{
    view_job job;
    memset(&job, 0, sizeof job);
    job.kind = kind;
    job.view = v->view;
    job.model = v->model;
    job.options = view_options(v, w, h, spp);
    job.samples = samples;
    if (kind == VIEW_JOB_SHOT)
        snprintf(job.path, sizeof job.path, "%s", v->shot_path);
    view_worker_submit(v->worker, &job);
}

/* Decides what the render thread does next. */
static void schedule(viewer *v)
{
    uint64_t running_view = 0;
    view_job_kind running_kind = VIEW_JOB_COARSE;
    if (!view_worker_idle(v->worker, &running_view, &running_kind)) {
        if (running_kind == VIEW_JOB_REFINE && running_view != v->view)
            view_worker_cancel(v->worker);
        return;
    }
    if (!v->model)
        return;
    if (v->shot_requested) {
        v->shot_requested = 0;
        submit(v, VIEW_JOB_SHOT, v->width, v->height, v->spp, v->spp);
        return;
    }
    if (v->shown_view != v->view) {
        double s = coarse_scales[v->coarse_step];
        int w = (int)lrint(v->width / s), h = (int)lrint(v->height / s);
        submit(v, VIEW_JOB_COARSE, w > 0 ? w : 1, h > 0 ? h : 1, 1, 1);
        return;
    }
    if (v->shown_full && v->shown_spp >= v->spp)
        return; /* done */
    if (v->buttons && seconds_now() - v->last_motion < STILL_SECONDS)
        return; /* still dragging */
    int samples = !v->shown_full ? 1 : v->shown_spp * 4;
    submit(v, VIEW_JOB_REFINE, v->width, v->height, v->spp,
           samples < v->spp ? samples : v->spp);
}

/* Moves the coarse step after a coarse frame of w x h took ms. */
static void adapt_coarse(viewer *v, int w, int h, double ms)
{
    double pixels = (double)w * h, full = (double)v->width * v->height;
    int step = v->coarse_step;
    if (ms > FRAME_BUDGET_MS) {
        while (step + 1 < COARSE_STEPS) {
            double s = coarse_scales[step];
            if (ms * full / (s * s) / pixels <= FRAME_BUDGET_MS)
                break;
            step++;
        }
    } else if (ms < 0.5 * FRAME_BUDGET_MS && step > 0) {
        double s = coarse_scales[step - 1];
        if (ms * full / (s * s) / pixels <= 0.8 * FRAME_BUDGET_MS)
            step--;
    }
    v->coarse_step = step;
}

static void show_frame(viewer *v, view_frame *f)
{
    if (f->status != SC_OK) {
        char text[SC_ERROR_MESSAGE_MAX + SC_ERROR_FILE_MAX + PATH_MAX + 64];
        if (f->status == SC_ERR_CANCELLED) /* a screenshot at its limit */
            snprintf(text, sizeof text,
                     "spancast: error: time limit of %g s exceeded (--max-time); %s "
                     "not written",
                     v->max_time, f->path);
        else
            format_error(&f->error, text, sizeof text);
        fprintf(stderr, "%s\n", text);
        snprintf(v->note, sizeof v->note, "%s", text);
        if (f->kind == VIEW_JOB_SHOT)
            v->shot_busy = 0;
        free(f->rgb);
        return;
    }
    uint64_t rays = f->stats.camera_rays + f->stats.shadow_rays +
                    f->stats.reflection_rays + f->stats.refraction_rays;
    const char *kinds[] = {"coarse", "refine", "shot"};
    if (v->verbose)
        printf("frame %s %dx%d spp %d: %.2f ms, %.2f Mrays/s\n", kinds[f->kind], f->width,
               f->height, f->spp, 1000 * f->seconds,
               f->seconds > 0 ? rays / f->seconds / 1e6 : 0.0);
    if (f->kind == VIEW_JOB_SHOT) {
        v->shot_busy = 0;
        printf("screenshot: %s: %s\n", f->path, v->shot_command);
        snprintf(v->note, sizeof v->note, "wrote %s", f->path);
        fflush(stdout);
        if (f->view != v->view) {
            free(f->rgb);
            return; /* the window keeps its frame */
        }
        /* else it is the refined view: show it */
    }
    fflush(stdout);
    if (f->kind == VIEW_JOB_COARSE)
        adapt_coarse(v, f->width, f->height, 1000 * f->seconds);
    if (f->kind == VIEW_JOB_REFINE && f->view != v->view) {
        free(f->rgb); /* a full frame of an old view would jump back */
        return;
    }
    v->frame_ms = 1000 * f->seconds;
    v->frame_w = f->width;
    v->frame_h = f->height;
    v->frame_spp = f->spp;
    v->rays_per_second = f->seconds > 0 ? rays / f->seconds : 0;
    if (f->view == v->view) {
        v->shown_view = f->view;
        v->shown_full = f->width == v->width && f->height == v->height;
        v->shown_spp = f->spp;
    }
    if (!v->texture || v->texture_w != f->width || v->texture_h != f->height) {
        if (v->texture)
            SDL_DestroyTexture(v->texture);
        v->texture = SDL_CreateTexture(v->renderer, SDL_PIXELFORMAT_RGB24,
                                       SDL_TEXTUREACCESS_STREAMING, f->width, f->height);
        v->texture_w = f->width;
        v->texture_h = f->height;
    }
    if (v->texture)
        SDL_UpdateTexture(v->texture, NULL, f->rgb, f->width * 3);
    free(f->rgb);
    v->dirty = 1;
}

static void draw(viewer *v)
{
    SDL_SetRenderDrawColor(v->renderer, 0xff, 0xff, 0xe5, 0xff); /* OpenSCAD's */
    SDL_RenderClear(v->renderer);
    if (v->texture)
        SDL_RenderCopy(v->renderer, v->texture, NULL, NULL);
    if (v->error[0]) {
        /* A red frame while the file on disk does not load. */
        int t = 4;
        SDL_Rect sides[4] = {{0, 0, v->width, t},
                             {0, v->height - t, v->width, t},
                             {0, 0, t, v->height},
                             {v->width - t, 0, t, v->height}};
        SDL_SetRenderDrawColor(v->renderer, 0xd0, 0x10, 0x10, 0xff);
        SDL_RenderFillRects(v->renderer, sides, 4);
    }
    SDL_RenderPresent(v->renderer);
    v->dirty = 0;
}

static void update_title(viewer *v)
{
    char options[2048], state[64];
    view_format(v, options, sizeof options);
    if (!v->model)
        snprintf(state, sizeof state, "%s",
                 view_loader_busy(v->loader) ? "loading" : "no model yet");
    else if (v->shown_view == v->view && v->shown_full && v->shown_spp >= v->spp)
        snprintf(state, sizeof state, "done");
    else if (v->shown_view == v->view && v->shown_full)
        snprintf(state, sizeof state, "refining (spp %d of %d)", v->shown_spp, v->spp);
    else
        snprintf(state, sizeof state, "moving");
    char title[sizeof v->title];
    snprintf(
        title, sizeof title,
        "spancast view: %s%s%s - %s - load #%d %.3f s, frame %.1f ms (%dx%d, spp %d), "
        "%.2f Mrays/s - %s%s%s%s%s",
        base_name(v->path),
        v->error[0]     ? " - ERROR "
        : v->warning[0] ? " - WARNING "
                        : "",
        v->error[0] ? v->error : v->warning, state, v->loads, v->load_seconds,
        v->frame_ms, v->frame_w, v->frame_h, v->frame_spp, v->rays_per_second / 1e6,
        options, v->pick[0] ? " - " : "", v->pick, v->note[0] ? " - " : "", v->note);
    if (strcmp(title, v->title)) {
        memcpy(v->title, title, sizeof title);
        SDL_SetWindowTitle(v->window, title);
    }
}

/* ---- loading ---- */

static void take_load(viewer *v)
{
    view_load load;
    if (!view_loader_take(v->loader, &load))
        return;
    for (size_t k = 0; k < load.file_count; k++)
        watch_add_file(v->watched, load.files[k]);
    view_load_free_files(&load);
    if (!load.model) {
        format_error(&load.error, v->error, sizeof v->error);
        fprintf(stderr, "%s\n", v->error);
        v->dirty = 1;
        return;
    }
    int first = !v->model;
    view_model_release(v->model);
    v->model = load.model;
    v->load_seconds = load.seconds;
    v->loads++;
    v->error[0] = '\0';
    v->warning[0] = '\0';
    /* Each warning on stderr, as the render command prints it (at the
     * source, not the converted text); the first in the title. */
    char name[PATH_MAX + 16] = "";
    if (load.converted && !scad_converted_name(v->path, name, sizeof name))
        name[0] = '\0';
    snprintf(v->export_name, sizeof v->export_name, "%s", name);
    size_t warnings = sc_scene_warning_count(v->model->scene);
    for (size_t k = 0; k < warnings; k++) {
        sc_error w = *sc_scene_warning(v->model->scene, k);
        if (name[0])
            scad_blame(&w, name, v->path);
        char where[SC_ERROR_FILE_MAX + 32];
        if (w.file[0] && w.line > 0)
            snprintf(where, sizeof where, "%s:%d:%d", w.file, w.line, w.column);
        else
            snprintf(where, sizeof where, "%s", w.file[0] ? w.file : "spancast");
        fprintf(stderr, "%s: warning: %s\n", where, w.message);
        if (k > 0)
            continue;
        char more[48] = "";
        if (warnings > 1)
            snprintf(more, sizeof more, " (and %zu more)", warnings - 1);
        /* The title's copy may be cut short; stderr has it whole. */
        int n =
            snprintf(v->warning, sizeof v->warning, "%s: %s%s", where, w.message, more);
        (void)n;
    }
    if (first) {
        sc_render_options file;
        sc_render_options_init(&file);
        sc_render_options_from_scene(&file, v->model->scene);
        file.preview = v->look.preview; /* framed as what is shown */
        view_camera_reset(&v->cam, v->model->scene, &file);
        if (v->preset) {
            view_camera_preset(&v->cam, v->preset);
            view_camera_view_all(&v->cam, v->model->scene, &v->look);
        }
    }
    printf("loaded %s in %.3f s\n", v->path, load.seconds);
    fflush(stdout);
    v->dirty = 1;
    view_changed(v);
}

/* ---- input ---- */

/* A key's effect, in the title and on stdout. */
static void say(viewer *v, const char *format, ...)
{
    va_list args;
    va_start(args, format);
    vsnprintf(v->note, sizeof v->note, format, args);
    va_end(args);
    printf("%s\n", v->note);
    fflush(stdout);
}

/* Turns one SC_VIEW_* overlay (flags: it and those that go with it) on or
 * off. */
static void toggle_overlay(viewer *v, unsigned flag, unsigned flags, const char *name)
{
    if (v->look.view & flag)
        v->look.view &= ~flags;
    else
        v->look.view |= flags;
    say(v, "%s %s", name, v->look.view & flag ? "on" : "off");
    view_changed(v);
}

/* C: the next of the schemes sc_color_scheme_find knows. */
static void next_scheme(viewer *v)
{
    if (!v->scheme_count)
        return;
    v->scheme_index = (v->scheme_index + 1) % v->scheme_count;
    sc_error error;
    if (sc_render_options_set_scheme(&v->look, v->schemes[v->scheme_index], NULL,
                                     &error) != SC_OK) {
        say(v, "colour scheme: %s", error.message);
        return;
    }
    v->look.use_scheme = 1;
    say(v, "colour scheme %s", v->look.scheme.name);
    view_changed(v);
}

/* X: with no section plane, one through the centre of the model's bounds,
 * facing the camera, keeping the half away from it (n = -forward, so n.p
 * <= n.c is forward.p >= forward.c); the plane stays where it is when the
 * view turns. With section planes (this one or --section), removes them. */
static void toggle_section(viewer *v)
{
    sc_render_options *o = &v->look;
    if (o->section_count) {
        o->section_count = 0;
        say(v, "section off");
        view_changed(v);
        return;
    }
    double lo[3], hi[3], forward[3];
    if (!v->model || !sc_scene_bounds(v->model->scene, lo, hi)) {
        say(v, "section: no model to cut");
        return;
    }
    view_camera_forward(&v->cam, forward);
    double d = 0;
    for (int k = 0; k < 3; k++) {
        o->section[0][k] = -forward[k];
        d += -forward[k] * (lo[k] + hi[k]) / 2;
    }
    o->section[0][3] = d;
    o->section_count = 1;
    say(v, "section on");
    view_changed(v);
}

/* The names sc_color_scheme_find knows, as it lists them in the error for
 * a name it does not know ("... (known: 'Cornfield', 'Metallic', ...)");
 * scheme_index is the current scheme's. */
static void find_schemes(viewer *v)
{
    sc_color_scheme scheme;
    sc_error error;
    v->scheme_count = 0;
    if (sc_color_scheme_find("", NULL, &scheme, &error) == SC_OK)
        return;
    const char *p = strstr(error.message, "(known: ");
    for (p = p ? p + 8 : NULL; p && *p == '\'' && v->scheme_count < MAX_SCHEMES;) {
        const char *end = strchr(p + 1, '\'');
        if (!end)
            break;
        size_t n = (size_t)(end - p - 1);
        if (n < SC_COLOR_SCHEME_NAME_MAX) {
            memcpy(v->schemes[v->scheme_count], p + 1, n);
            v->schemes[v->scheme_count][n] = '\0';
            if (!strcmp(v->schemes[v->scheme_count], v->look.scheme.name))
                v->scheme_index = v->scheme_count;
            v->scheme_count++;
        }
        p = !strncmp(end + 1, ", ", 2) ? end + 3 : NULL;
    }
}

static void request_shot(viewer *v)
{
    if (v->shot_busy || !v->model) {
        snprintf(v->note, sizeof v->note, "%s",
                 v->model ? "a screenshot is being written" : "no model to write");
        return;
    }
    /* A name no file has yet: a screenshot never replaces a file. */
    char stem[256];
    const char *name = base_name(v->path);
    const char *dot = strrchr(name, '.');
    size_t n = dot && dot != name ? (size_t)(dot - name) : strlen(name);
    snprintf(stem, sizeof stem, "%.*s", (int)(n < 200 ? n : 200), name);
    struct stat st;
    do {
        v->shot_number++;
        snprintf(v->shot_path, sizeof v->shot_path, "%s-view-%d.png", stem,
                 v->shot_number);
    } while (stat(v->shot_path, &st) == 0 || errno != ENOENT);
    char options[2048], model[PATH_MAX * 2], out[PATH_MAX * 2];
    view_format(v, options, sizeof options);
    shell_quote(v->path, model, sizeof model);
    shell_quote(v->shot_path, out, sizeof out);
    int len = snprintf(v->shot_command, sizeof v->shot_command,
                       "spancast render %s -o %s %s%s%s", model, out, options,
                       v->faithful & CLI_LOAD_FAITHFUL ? " --faithful" : "",
                       v->faithful & CLI_LOAD_STRICT ? " --strict" : "");
    if (len >= (int)sizeof v->shot_command)
        len = -1;
    /* the model's -D settings, in order, as the model was converted */
    for (int i = 0; i < scad_define_count() && len > 0; i++) {
        char define[PATH_MAX];
        if (strlen(scad_define(i)) * 4 + 3 > sizeof define) { /* quoting could cut it */
            len = -1;
            break;
        }
        shell_quote(scad_define(i), define, sizeof define);
        size_t at = (size_t)len, room = sizeof v->shot_command - at;
        int k = snprintf(v->shot_command + at, room, " -D %s", define);
        len = k > 0 && (size_t)k < room ? len + k : -1;
    }
    if (len < 0) /* cut: say so rather than print a command that differs */
        snprintf(v->shot_command, sizeof v->shot_command,
                 "(the render command, with its -D settings, is too long to print)");
    v->shot_busy = 1;
    v->shot_requested = 1;
    snprintf(v->note, sizeof v->note, "writing %s", v->shot_path);
    v->shot_asked = seconds_now();
    /* A refinement in flight goes on: the screenshot continues its sums. */
}

/* Where a span end's surface is written: file:line:col, or for a model
 * OpenSCAD converted, the source with the line of its export; short: the
 * file's base name (for the title). */
static void place(const viewer *v, const sc_span_end *e, int short_name, char *out,
                  size_t size)
{
    const char *file = e->location.file ? e->location.file : "?";
    if (v->export_name[0] && strcmp(file, v->export_name) == 0)
        snprintf(out, size, "%s (line %d of OpenSCAD's export)",
                 short_name ? base_name(v->path) : v->path, e->location.line);
    else
        snprintf(out, size, "%s:%d:%d", short_name ? base_name(file) : file,
                 e->location.line, e->location.column);
}

static void pick(viewer *v, int x, int y)
{
    if (!v->model || x < 0 || y < 0 || x >= v->width || y >= v->height)
        return;
    sc_render_options o = view_options(v, v->width, v->height, 1);
    sc_ray_query query;
    sc_ray_query_init(&query);
    sc_error error;
    sc_span_list *spans = NULL;
    if (sc_scene_pixel_ray(v->model->scene, &o, x, y, query.origin, query.direction,
                           &error) != SC_OK ||
        sc_scene_spans(v->model->scene, &query, &spans, &error) != SC_OK) {
        char text[SC_ERROR_MESSAGE_MAX + SC_ERROR_FILE_MAX + 64];
        format_error(&error, text, sizeof text);
        fprintf(stderr, "%s\n", text);
        return;
    }
    size_t count = sc_span_list_count(spans);
    double length = sqrt(query.direction[0] * query.direction[0] +
                         query.direction[1] * query.direction[1] +
                         query.direction[2] * query.direction[2]);
    if (count == 0) {
        printf("pick %d,%d: no hit\n", x, y);
        snprintf(v->pick, sizeof v->pick, "pick %d,%d: no hit", x, y);
    } else {
        const sc_span_end *hit = &sc_span_list_get(spans, 0)->in;
        if (hit->leaf >= 0) {
            char where[PATH_MAX + 64];
            place(v, hit, 0, where, sizeof where);
            printf("pick %d,%d: %s (leaf %d) at %s, distance %.9g, %zu span%s\n", x, y,
                   hit->leaf_kind, hit->leaf, where, hit->t * length, count,
                   count == 1 ? "" : "s");
            place(v, hit, 1, where, sizeof where);
            snprintf(v->pick, sizeof v->pick, "pick %d,%d: %s (leaf %d) at %.400s", x, y,
                     hit->leaf_kind, hit->leaf, where);
        } else {
            printf("pick %d,%d: the ray starts inside the solid, %zu span%s\n", x, y,
                   count, count == 1 ? "" : "s");
            snprintf(v->pick, sizeof v->pick, "pick %d,%d: inside", x, y);
        }
        for (size_t k = 0; k < count; k++) {
            const sc_span *s = sc_span_list_get(spans, k);
            const sc_span_end *ends[2] = {&s->in, &s->out};
            printf("  span %zu: length %.9g", k + 1, s->distance);
            for (int e = 0; e < 2; e++) {
                const sc_span_end *end = ends[e];
                printf(", %s t=%.17g", e ? "out" : "in", end->t);
                if (end->leaf >= 0) {
                    char where[PATH_MAX + 64];
                    place(v, end, 0, where, sizeof where);
                    printf(" %s (leaf %d) at %s%s", end->leaf_kind, end->leaf, where,
                           end->subtracted ? " (subtracted)" : "");
                }
            }
            printf("\n");
        }
    }
    fflush(stdout);
    sc_span_list_release(spans);
}

/* Handles one key; returns 0 to quit. */
static int key(viewer *v, const SDL_KeyboardEvent *e)
{
    SDL_Keycode sym = e->keysym.sym;
    int ctrl = (e->keysym.mod & KMOD_CTRL) != 0,
        shift = (e->keysym.mod & KMOD_SHIFT) != 0;
    v->note[0] = '\0';
    if (sym == SDLK_ESCAPE || (!ctrl && sym == SDLK_q) ||
        (ctrl && (sym == SDLK_q || sym == SDLK_w)))
        return 0;
    if (ctrl && sym >= SDLK_0 && sym <= SDLK_9) {
        static const sc_view_preset presets[10] = {
            SC_VIEW_PRESET_DIAGONAL, SC_VIEW_PRESET_NONE,  SC_VIEW_PRESET_NONE,
            SC_VIEW_PRESET_NONE,     SC_VIEW_PRESET_TOP,   SC_VIEW_PRESET_BOTTOM,
            SC_VIEW_PRESET_LEFT,     SC_VIEW_PRESET_RIGHT, SC_VIEW_PRESET_FRONT,
            SC_VIEW_PRESET_BACK};
        int digit = (int)(sym - SDLK_0);
        if (digit == 1) {
            toggle_overlay(v, SC_VIEW_EDGES, SC_VIEW_EDGES, "edges");
        } else if (digit == 2) {
            /* OpenSCAD's Show Axes; its Show Scale Markers goes with them */
            toggle_overlay(v, SC_VIEW_AXES, SC_VIEW_AXES | SC_VIEW_SCALES, "axes");
        } else if (digit == 3) {
            toggle_overlay(v, SC_VIEW_CROSSHAIRS, SC_VIEW_CROSSHAIRS, "crosshairs");
        } else {
            view_camera_preset(&v->cam, presets[digit]);
            say(v, "view %s", sc_view_preset_name(presets[digit]));
            view_changed(v);
        }
        return 1;
    }
    if (ctrl && shift && sym == SDLK_v) {
        if (v->model)
            view_camera_view_all(&v->cam, v->model->scene, &v->look);
        say(v, "view all");
        view_changed(v);
    } else if (ctrl && (sym == SDLK_RIGHTBRACKET || sym == SDLK_LEFTBRACKET)) {
        view_camera_zoom(&v->cam, sym == SDLK_RIGHTBRACKET ? 120 : -120);
        say(v, "zoom %s", sym == SDLK_RIGHTBRACKET ? "in" : "out");
        view_changed(v);
    } else if (sym == SDLK_HOME && v->model) {
        sc_render_options file;
        sc_render_options_init(&file);
        sc_render_options_from_scene(&file, v->model->scene);
        file.preview = v->look.preview;
        view_camera_reset(&v->cam, v->model->scene, &file);
        say(v, "view reset");
        view_changed(v);
    } else if (!ctrl && (sym == SDLK_p || sym == SDLK_o)) {
        v->cam.projection =
            sym == SDLK_p ? SC_PROJECTION_PERSPECTIVE : SC_PROJECTION_ORTHOGRAPHIC;
        say(v, "%s", sym == SDLK_p ? "perspective" : "orthographic");
        view_changed(v);
    } else if (ctrl && sym == SDLK_s) {
        request_shot(v);
    } else if ((ctrl && sym == SDLK_r) || sym == SDLK_F4 || sym == SDLK_F5) {
        say(v, "reloading");
        view_loader_request(v->loader);
    } else if (sym == SDLK_PLUS || sym == SDLK_EQUALS || sym == SDLK_KP_PLUS) {
        v->spp = v->spp * 4 > MAX_SPP ? MAX_SPP : v->spp * 4;
        say(v, "%d samples per pixel", v->spp);
        view_changed(v);
    } else if (sym == SDLK_MINUS || sym == SDLK_KP_MINUS) {
        v->spp = v->spp / 4 < 1 ? 1 : v->spp / 4;
        say(v, "%d samples per pixel", v->spp);
        view_changed(v);
    } else if (!ctrl && sym == SDLK_c) {
        next_scheme(v);
    } else if (!ctrl && sym == SDLK_x) {
        toggle_section(v);
    } else if (!ctrl && sym == SDLK_a) {
        v->look.ao_samples = v->look.ao_samples ? 0 : v->ao_on;
        say(v, "ambient occlusion %s", v->look.ao_samples ? "on" : "off");
        view_changed(v);
    }
    return 1;
}

/* Handles one event; returns 0 to quit. */
static int handle(viewer *v, const SDL_Event *e)
{
    switch (e->type) {
    case SDL_QUIT:
        return 0;
    case SDL_KEYDOWN:
        return key(v, &e->key);
    case SDL_MOUSEBUTTONDOWN:
        v->buttons |= SDL_BUTTON(e->button.button);
        v->press_x = e->button.x;
        v->press_y = e->button.y;
        v->dragged = 0;
        break;
    case SDL_MOUSEBUTTONUP:
        v->buttons &= ~SDL_BUTTON(e->button.button);
        if (e->button.button == SDL_BUTTON_LEFT && !v->dragged)
            pick(v, e->button.x, e->button.y);
        break;
    case SDL_MOUSEMOTION: {
        if (!v->buttons || !v->model)
            break; /* no camera before the first model */
        double dx = e->motion.xrel, dy = e->motion.yrel;
        if (abs(e->motion.x - v->press_x) + abs(e->motion.y - v->press_y) > 2)
            v->dragged = 1;
        if (!v->dragged)
            break;
        int shift = (SDL_GetModState() & KMOD_SHIFT) != 0;
        if (v->buttons & SDL_BUTTON_LMASK)
            view_camera_orbit(&v->cam, dx, dy, shift);
        else if (shift)
            view_camera_zoom(&v->cam, -12.0 * 0.7 * dy);
        else
            view_camera_pan(&v->cam, dx, dy, v->width, v->height);
        v->last_motion = seconds_now();
        view_changed(v);
        break;
    }
    case SDL_MOUSEWHEEL: {
        int y = v->model ? e->wheel.y : 0;
        if (e->wheel.direction == SDL_MOUSEWHEEL_FLIPPED)
            y = -y;
        if (y) {
            view_camera_zoom(&v->cam, 120.0 * y);
            view_changed(v);
        }
        break;
    }
    case SDL_WINDOWEVENT:
        if (e->window.event == SDL_WINDOWEVENT_SIZE_CHANGED) {
            v->width = e->window.data1 > 0 ? e->window.data1 : 1;
            v->height = e->window.data2 > 0 ? e->window.data2 : 1;
            view_changed(v);
        }
        v->dirty = 1;
        break;
    default:
        break;
    }
    return 1;
}

/* Called by the render and loading threads: wakes the window's loop. */
static void wake(void *user)
{
    viewer *v = user;
    SDL_Event e;
    memset(&e, 0, sizeof e);
    e.type = v->wake_event;
    SDL_PushEvent(&e);
}

/* ---- start and loop ---- */

/* Starts SDL on a display that shows something; prints why not and
 * returns 0 without one. */
static int open_display(void)
{
    /* Without either variable SDL would try Wayland (which prints its own
     * complaint) and fall back to its offscreen driver. */
    const char *x11 = getenv("DISPLAY"), *wayland = getenv("WAYLAND_DISPLAY");
    const char *chosen = getenv("SDL_VIDEODRIVER");
    if ((!x11 || !*x11) && (!wayland || !*wayland) && (!chosen || !*chosen)) {
        fputs("spancast: error: view needs a display (neither DISPLAY nor "
              "WAYLAND_DISPLAY is set)\n",
              stderr);
        return 0;
    }
    /* Before SDL_Init, so that SDL_Quit puts it back (view_x11.c). */
    view_x11_guard();
    if (SDL_Init(SDL_INIT_VIDEO) != 0) {
        fprintf(stderr, "spancast: error: view needs a display (%s)\n", SDL_GetError());
        return 0;
    }
    const char *driver = SDL_GetCurrentVideoDriver();
    if (!driver || !strcmp(driver, "offscreen") || !strcmp(driver, "dummy")) {
        fprintf(stderr,
                "spancast: error: view needs a display (SDL's video driver '%s' shows "
                "nothing)\n",
                driver ? driver : "none");
        SDL_Quit();
        return 0;
    }
    return 1;
}

static void run(viewer *v)
{
    int running = 1;
    view_loader_request(v->loader);
    while (running) {
        SDL_Event e;
        if (SDL_WaitEventTimeout(&e, 15)) {
            running = handle(v, &e);
            while (running && SDL_PollEvent(&e))
                running = handle(v, &e);
        }
        if (watch_changed(v->watched)) {
            v->change_pending = 1;
            v->change_at = seconds_now();
        }
        if (v->change_pending &&
            seconds_now() - v->change_at >= WATCH_SETTLE_MS / 1000.0) {
            v->change_pending = 0;
            view_loader_request(v->loader);
        }
        if (v->shot_busy && v->max_time > 0 &&
            seconds_now() - v->shot_asked > v->max_time)
            view_worker_cancel_shot(v->worker);
        take_load(v);
        view_frame frame;
        if (view_worker_take(v->worker, &frame))
            show_frame(v, &frame);
        schedule(v);
        if (v->dirty)
            draw(v);
        update_title(v);
    }
}

int main(int argc, char **argv)
{
    viewer *v = calloc(1, sizeof *v);
    if (!v) {
        fputs("spancast: error: out of memory\n", stderr);
        return EXIT_FAILED;
    }
    v->width = 800;
    v->height = 600;
    v->spp = 4;
    v->coarse_step = 5; /* a quarter of each side, until measured */
    sc_render_options_init(&v->look);
    v->defaults = v->look;
    int status = scad_take_defines(&argc, argv);
    if (!status)
        status = parse_args(v, argc, argv);
    if (status) {
        free(v);
        return status;
    }
    v->ao_on = v->look.ao_samples ? v->look.ao_samples : DEFAULT_AO;
    view_camera_init(&v->cam, &v->look);
    find_schemes(v);
    struct stat st;
    int code = stat(v->path, &st) != 0 ? errno : S_ISDIR(st.st_mode) ? EISDIR : 0;
    if (code) {
        fprintf(stderr, "spancast: error: cannot open '%s': %s\n", v->path,
                strerror(code));
        free(v);
        return EXIT_FAILED;
    }
    sc_error error;
    v->watched = watch_open(&error);
    if (!v->watched) {
        fprintf(stderr, "spancast: error: %s\n", error.message);
        free(v);
        return EXIT_FAILED;
    }
    if (!open_display()) {
        watch_close(v->watched);
        free(v);
        return EXIT_FAILED;
    }
    SDL_SetHint(SDL_HINT_RENDER_SCALE_QUALITY, "linear");
    /* The window shows one image a frame: SDL's software renderer draws it
     * without loading the OpenGL driver stack (Mesa, LLVM), which took
     * longer to load than the model. The environment (SDL_RENDER_DRIVER,
     * SDL_FRAMEBUFFER_ACCELERATION) still chooses otherwise. */
    SDL_SetHint(SDL_HINT_RENDER_DRIVER, "software");
    SDL_SetHint(SDL_HINT_FRAMEBUFFER_ACCELERATION, "0");
    v->wake_event = SDL_RegisterEvents(1);
    v->window = SDL_CreateWindow("spancast view", SDL_WINDOWPOS_UNDEFINED,
                                 SDL_WINDOWPOS_UNDEFINED, v->width, v->height,
                                 SDL_WINDOW_RESIZABLE);
    if (v->window)
        SDL_GetWindowSize(v->window, &v->width, &v->height);
    v->renderer = v->window ? SDL_CreateRenderer(v->window, -1, 0) : NULL;
    v->worker = v->renderer ? view_worker_start(wake, v) : NULL;
    v->loader = v->worker ? view_loader_start(v->path, v->faithful, wake, v) : NULL;
    if (v->wake_event == (Uint32)-1 || !v->loader) {
        fprintf(stderr, "spancast: error: cannot open the window: %s\n", SDL_GetError());
        status = EXIT_FAILED;
    } else {
        run(v);
    }
    view_loader_stop(v->loader);
    view_worker_stop(v->worker);
    view_model_release(v->model);
    if (v->texture)
        SDL_DestroyTexture(v->texture);
    if (v->renderer)
        SDL_DestroyRenderer(v->renderer);
    if (v->window)
        SDL_DestroyWindow(v->window);
    SDL_Quit();
    watch_close(v->watched);
    free(v);
    return status;
}
