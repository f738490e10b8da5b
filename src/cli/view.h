/* What the parts of the viewer share (spancast-view: view.c, view_camera.c,
 * view_worker.c, view_loader.c, view_x11.c). The viewer is a front-end on the public
 * API only: it loads with sc_scene_load (or through OpenSCAD, scad.c),
 * renders with sc_render and picks with sc_scene_pixel_ray and
 * sc_scene_spans, so that what the window shows is what `spancast render`
 * writes. Only view.c sees SDL; the other parts are plain C and threads.
 */
#ifndef SPANCAST_CLI_VIEW_H
#define SPANCAST_CLI_VIEW_H

#include <limits.h>
#include <stdatomic.h>
#include <stddef.h>
#include <stdint.h>

#include "spancast/spancast.h"

/* ---- a loaded model, shared by the window and the render thread ---- */

typedef struct view_model {
    atomic_int refs; /* the window's reference, and one per job that renders it */
    sc_scene *scene;
    double load_seconds; /* wall time of the load (and OpenSCAD's conversion) */
} view_model;

/* Takes one more reference; returns model. */
view_model *view_model_retain(view_model *model);

/* Drops a reference; the last one releases the scene. NULL is ignored. */
void view_model_release(view_model *model);

/* ---- Xlib (view_x11.c) ---- */

/* Installs the handler that ignores SDL 2.26's late wake-up (a SendEvent
 * to a window already destroyed) and hands every other X error to the
 * handler before it. Call before SDL_Init: SDL_Quit restores the handler
 * SDL_Init found, and the late error is read inside SDL_Quit. Idempotent. */
void view_x11_guard(void);

/* ---- the camera (view_camera.c) ---- */

/* OpenSCAD's gimbal camera, which `render --camera=TX,TY,TZ,RX,RY,RZ,D`
 * reads: the centre looked at, the rotation in degrees, the distance. */
typedef struct view_camera {
    double center[3];
    double rotate[3];
    double distance;
    double fov_deg;
    sc_projection projection;
} view_camera;

/* The camera before any model is loaded: options' field of view and
 * projection, OpenSCAD's default view (rotation 55, 0, 25 at distance 140
 * from the origin), so that the title's command is one render takes. */
void view_camera_init(view_camera *cam, const sc_render_options *options);
/* The view `render` gives the scene without a camera option: the file's
 * camera() when it has one (as a gimbal camera looking the same way),
 * else OpenSCAD's diagonal view of the whole model. options holds the
 * file's settings (sc_render_options_from_scene). */
void view_camera_reset(view_camera *cam, const sc_scene *scene,
                       const sc_render_options *options);

/* Keeps the rotation and moves centre and distance to show the whole model
 * (OpenSCAD's View All), by the box the render with options frames
 * (sc_scene_frame_bounds: the solid's, or the preview's). */
void view_camera_view_all(view_camera *cam, const sc_scene *scene,
                          const sc_render_options *options);

/* A mouse drag of dx, dy window pixels, as OpenSCAD's QGLView reads it:
 * left rotates (x and z, or x and y with shift), right pans in the view
 * plane, shift-right zooms. */
void view_camera_orbit(view_camera *cam, double dx, double dy, int around_y);
void view_camera_pan(view_camera *cam, double dx, double dy, int width, int height);

/* OpenSCAD's zoom: one wheel notch is 120; positive moves closer. */
void view_camera_zoom(view_camera *cam, double delta);

/* OpenSCAD's View menu's standard views: the rotation `render
 * --view-preset` uses (sc_view_preset_rotation); centre and distance stay,
 * as in OpenSCAD. */
void view_camera_preset(view_camera *cam, sc_view_preset preset);

/* The unit vector the camera looks along (from the eye to the centre). */
void view_camera_forward(const view_camera *cam, double forward[3]);

/* Puts the camera into render options (gimbal mode, fov, projection). */
void view_camera_apply(const view_camera *cam, sc_render_options *options);

/* The view as `render` options ("--camera=... --imgsize=W,H
 * --projection=p --fov=F --spp=N"), every number printed so that it reads
 * back to the same double. Returns buf. */
const char *view_camera_format(const view_camera *cam, int width, int height, int spp,
                               char *buf, size_t size);

/* ---- the render thread (view_worker.c) ---- */

typedef enum view_job_kind {
    VIEW_JOB_COARSE, /* a reduced image while the view moves; never cancelled */
    VIEW_JOB_REFINE, /* full size, some samples; cancelled when the view moves */
    VIEW_JOB_SHOT    /* full quality, written to a file; cancelled only at the
                        --max-time limit */
} view_job_kind;

typedef struct view_job {
    view_job_kind kind;
    uint64_t view;             /* the window's number for the view it shows */
    view_model *model;         /* view_worker_submit takes its own reference */
    sc_render_options options; /* options.spp: the samples of the finished view */
    int samples;         /* VIEW_JOB_REFINE, VIEW_JOB_SHOT: the samples of options.spp the
                            frame holds when done (the passes before it are reused) */
    char path[PATH_MAX]; /* VIEW_JOB_SHOT: the file to write */
} view_job;

typedef struct view_frame {
    view_job_kind kind;
    uint64_t view;
    int width, height, spp; /* spp: the samples the frame holds */
    uint8_t *rgb;   /* 3 bytes per pixel, sRGB, row 0 at the top; the caller frees it */
    double seconds; /* wall time of sc_render and the conversion to sRGB */
    sc_render_stats stats;
    sc_status status; /* SC_OK, or why it failed (a shot that was not written) */
    sc_error error;
    char path[PATH_MAX]; /* VIEW_JOB_SHOT: the file written */
} view_frame;

typedef struct view_worker view_worker;

/* Starts the render thread; wake(user) is called from it when a frame is
 * ready. NULL when the thread cannot be started. */
view_worker *view_worker_start(void (*wake)(void *user), void *user);

/* Queues a job, replacing one queued and not yet started. */
void view_worker_submit(view_worker *worker, const view_job *job);

/* Abandons the job in flight when it is a VIEW_JOB_REFINE (sc_render's
 * cancel flag) and drops the queued one. */
void view_worker_cancel(view_worker *worker);

/* Abandons the job in flight when it is a VIEW_JOB_SHOT (its time limit has
 * passed); its frame comes back with status SC_ERR_CANCELLED, nothing
 * written. */
void view_worker_cancel_shot(view_worker *worker);

/* 1 when nothing runs and nothing is queued. With view non-NULL, *view is
 * the view of the job in flight and *kind its kind (when busy). */
int view_worker_idle(view_worker *worker, uint64_t *view, view_job_kind *kind);

/* Takes the newest finished frame (older ones not taken are dropped);
 * returns 1, or 0 when there is none. */
int view_worker_take(view_worker *worker, view_frame *frame);

/* Stops the thread (abandoning its job) and frees everything. */
void view_worker_stop(view_worker *worker);

/* ---- loading in the background (view_loader.c) ---- */

typedef struct view_load {
    view_model *model; /* the caller's reference; NULL when loading failed */
    sc_error error;    /* why it failed */
    double seconds;
    char **files;      /* the files the model came from (a .scad's includes) */
    size_t file_count; /* the caller frees files with view_load_free_files */
    int converted;     /* the text came from OpenSCAD (scad_load_model) */
} view_load;

void view_load_free_files(view_load *load);

typedef struct view_loader view_loader;

view_loader *view_loader_start(const char *path, int faithful, void (*wake)(void *user),
                               void *user);

/* Asks for a (re)load: starts one now, or one more after the one running. */
void view_loader_request(view_loader *loader);

/* 1 while a load runs or is asked for. */
int view_loader_busy(view_loader *loader);

/* Takes the result of the newest finished load; 1, or 0 when none. */
int view_loader_take(view_loader *loader, view_load *load);

/* Waits for the load in flight (an OpenSCAD conversion included) and frees
 * everything. */
void view_loader_stop(view_loader *loader);

#endif
