/* The viewer's render thread.
 *
 * One thread renders one job at a time with sc_render (whose own threads
 * share the tiles), converts the colour to 8-bit sRGB for the window, and
 * leaves the frame in a slot the window takes it from; the window never
 * waits for a render. A job queued while another runs replaces any job
 * queued before it, so the thread always starts on the newest view.
 *
 * Abandoning: view_worker_cancel sets the cancel flag sc_render polls
 * inside its tiles (the cancel token of base/cancel.h, the same one an
 * interrupt of `spancast render` stops: before every pixel and sample, and
 * in the root finders and mesh walks), for a refinement job only, so a
 * slow frame is given up within milliseconds of the view moving. A coarse
 * frame is kept within the frame budget by its size and always finishes,
 * so that a drag shows frames even when the mouse moves faster than they
 * come; a screenshot finishes unless the window stops it at the user's
 * --max-time (view_worker_cancel_shot).
 *
 * Refining: the refinement passes of a view and its screenshot render the
 * samples of one render of spp samples in turn (sc_render_options'
 * sample_start, sample_count and sample_sum): each pass adds its samples
 * to the running sums kept here and shows their mean, so no sample is
 * rendered twice, and the pass that reaches spp shows exactly the image
 * `spancast render --spp=N` writes. A screenshot continues the sums of
 * its view, and once they hold all spp samples it writes the last pass's
 * framebuffer without rendering again. The sums belong to this thread;
 * a pass that is abandoned spoils them, and the next one starts over.
 *
 * Locking: one mutex guards the queue, the slot and the flags; the render
 * runs without it. The cancel flag is the API's volatile sig_atomic_t,
 * written under the mutex and read by sc_render's threads.
 */
#define _POSIX_C_SOURCE 200809L

#include "base/error.h"
#include "cli/view.h"

#include <math.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define SRGB_STEPS 4096 /* entries of the linear-to-sRGB table */

struct view_worker {
    pthread_t thread;
    pthread_mutex_t lock;
    pthread_cond_t changed;
    int stopping;
    int has_queued, running;
    view_job queued, current;
    volatile sig_atomic_t cancel; /* the running job's sc_render cancel flag */
    int has_frame;
    view_frame frame; /* the newest finished frame not yet taken */
    void (*wake)(void *user);
    void *user;
    uint8_t srgb[SRGB_STEPS + 1]; /* linear [0, 1] in SRGB_STEPS steps to sRGB */
    /* The refinement's running sums (the render thread's own, no lock). */
    double *sum;       /* 3 per pixel, sum_width x sum_height */
    size_t sum_length; /* doubles allocated */
    uint64_t sum_view; /* the view they were rendered for */
    int sum_width, sum_height, sum_spp;
    int sum_samples;          /* samples summed in every pixel; 0: none, or spoilt */
    sc_framebuffer *finished; /* the pass that brought them to sum_spp, or NULL */
};

view_model *view_model_retain(view_model *model)
{
    atomic_fetch_add(&model->refs, 1);
    return model;
}

void view_model_release(view_model *model)
{
    if (model && atomic_fetch_sub(&model->refs, 1) == 1) {
        sc_scene_release(model->scene);
        free(model);
    }
}

static double seconds_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* The sRGB transfer function (IEC 61966-2-1), for the display only: the
 * screenshot goes through the library's own writer. */
static void fill_srgb(uint8_t *table)
{
    for (int k = 0; k <= SRGB_STEPS; k++) {
        double v = (double)k / SRGB_STEPS;
        double e = v <= 0.0031308 ? 12.92 * v : 1.055 * pow(v, 1 / 2.4) - 0.055;
        table[k] = (uint8_t)lrint(e * 255);
    }
}

static void convert(const view_worker *w, const sc_framebuffer *fb, uint8_t *rgb)
{
    size_t n = (size_t)sc_framebuffer_width(fb) * (size_t)sc_framebuffer_height(fb) * 3;
    const float *color = sc_framebuffer_color(fb);
    for (size_t k = 0; k < n; k++) {
        float v = color[k];
        int step = v >= 1.0f ? SRGB_STEPS : v > 0.0f ? (int)(v * SRGB_STEPS + 0.5f) : 0;
        rgb[k] = w->srgb[step];
    }
}

static void free_frame(view_frame *frame)
{
    free(frame->rgb);
    frame->rgb = NULL;
}

/* Sets up options to continue the running sums up to job->samples (a
 * refinement or a screenshot), starting them over when they belong to
 * another view, size or sample count. 0 when out of memory. */
static int continue_sums(view_worker *w, const view_job *job, sc_render_options *options)
{
    int end = job->samples;
    int start = w->sum_samples;
    if (w->sum_view != job->view || w->sum_width != options->width ||
        w->sum_height != options->height || w->sum_spp != options->spp || start >= end)
        start = 0;
    if (start == 0) {
        size_t n = (size_t)options->width * (size_t)options->height * 3;
        if (n > w->sum_length) {
            free(w->sum);
            w->sum_length = 0;
            w->sum = malloc(n * sizeof *w->sum);
            if (!w->sum)
                return 0;
            w->sum_length = n;
        }
        memset(w->sum, 0, n * sizeof *w->sum);
        w->sum_view = job->view;
        w->sum_width = options->width;
        w->sum_height = options->height;
        w->sum_spp = options->spp;
    }
    w->sum_samples = 0; /* spoilt until the pass finishes */
    sc_framebuffer_release(w->finished);
    w->finished = NULL;
    options->sample_start = start;
    options->sample_count = end - start;
    options->sample_sum = w->sum;
    return 1;
}

/* Whether the sums hold all of the screenshot job's samples already. */
static int shot_finished(const view_worker *w, const view_job *job)
{
    const sc_render_options *o = &job->options;
    return job->kind == VIEW_JOB_SHOT && w->finished && w->sum_view == job->view &&
           w->sum_width == o->width && w->sum_height == o->height &&
           w->sum_spp == o->spp && w->sum_samples == o->spp;
}

/* Renders job into frame; returns 0 when the job was abandoned (a
 * screenshot stopped at its time limit comes back, as SC_ERR_CANCELLED). */
static int run_job(view_worker *w, const view_job *job, view_frame *frame)
{
    memset(frame, 0, sizeof *frame);
    frame->kind = job->kind;
    frame->view = job->view;
    frame->width = job->options.width;
    frame->height = job->options.height;
    frame->spp = job->kind == VIEW_JOB_COARSE ? job->options.spp : job->samples;
    memcpy(frame->path, job->path, sizeof frame->path);
    sc_render_options options = job->options;
    options.want_color = 1;
    options.cancel = &w->cancel; /* set for a refinement, or when stopping */
    double start = seconds_now();
    sc_framebuffer *fb = NULL;
    if (shot_finished(w, job)) {
        fb = w->finished; /* the image on screen: nothing to render */
        w->finished = NULL;
        frame->status = SC_OK;
    } else if (job->kind != VIEW_JOB_COARSE && !continue_sums(w, job, &options)) {
        frame->status = err_nomem(&frame->error, NULL);
    } else {
        frame->status = sc_render(job->model->scene, &options, &fb, &frame->error);
    }
    if (frame->status == SC_OK && job->kind != VIEW_JOB_COARSE)
        w->sum_samples = job->samples;
    if (frame->status == SC_ERR_CANCELLED)
        return job->kind == VIEW_JOB_SHOT;
    if (frame->status == SC_OK) {
        sc_render_stats_init(&frame->stats);
        sc_framebuffer_get_stats(fb, &frame->stats, NULL);
        frame->rgb = malloc((size_t)sc_framebuffer_width(fb) *
                            (size_t)sc_framebuffer_height(fb) * 3);
        if (frame->rgb)
            convert(w, fb, frame->rgb);
        else
            frame->status = SC_ERR_NOMEM;
        frame->seconds = seconds_now() - start;
        if (job->kind == VIEW_JOB_SHOT)
            frame->status = sc_framebuffer_write_color(fb, job->path, &frame->error);
    }
    if (frame->status == SC_OK && job->kind != VIEW_JOB_COARSE &&
        job->samples == job->options.spp)
        w->finished = fb; /* kept for a screenshot of this view */
    else
        sc_framebuffer_release(fb);
    return 1;
}

static void *worker_main(void *arg)
{
    view_worker *w = arg;
    pthread_mutex_lock(&w->lock);
    for (;;) {
        while (!w->stopping && !w->has_queued)
            pthread_cond_wait(&w->changed, &w->lock);
        if (w->stopping)
            break;
        w->current = w->queued;
        w->has_queued = 0;
        w->running = 1;
        w->cancel = 0;
        pthread_mutex_unlock(&w->lock);

        view_frame frame;
        int done = run_job(w, &w->current, &frame);
        view_model_release(w->current.model);

        pthread_mutex_lock(&w->lock);
        w->running = 0;
        w->current.model = NULL;
        if (done) {
            if (w->has_frame)
                free_frame(&w->frame);
            w->frame = frame;
            w->has_frame = 1;
        }
        pthread_mutex_unlock(&w->lock);
        w->wake(w->user); /* a frame, or room for the next job */
        pthread_mutex_lock(&w->lock);
    }
    pthread_mutex_unlock(&w->lock);
    return NULL;
}

view_worker *view_worker_start(void (*wake)(void *user), void *user)
{
    view_worker *w = calloc(1, sizeof *w);
    if (!w)
        return NULL;
    w->wake = wake;
    w->user = user;
    fill_srgb(w->srgb);
    pthread_mutex_init(&w->lock, NULL);
    pthread_cond_init(&w->changed, NULL);
    if (pthread_create(&w->thread, NULL, worker_main, w) != 0) {
        pthread_cond_destroy(&w->changed);
        pthread_mutex_destroy(&w->lock);
        free(w);
        return NULL;
    }
    return w;
}

void view_worker_submit(view_worker *w, const view_job *job)
{
    view_model_retain(job->model);
    pthread_mutex_lock(&w->lock);
    if (w->has_queued)
        view_model_release(w->queued.model);
    w->queued = *job;
    w->has_queued = 1;
    pthread_cond_signal(&w->changed);
    pthread_mutex_unlock(&w->lock);
}

void view_worker_cancel(view_worker *w)
{
    pthread_mutex_lock(&w->lock);
    if (w->has_queued && w->queued.kind != VIEW_JOB_SHOT) {
        view_model_release(w->queued.model);
        w->has_queued = 0;
    }
    if (w->running && w->current.kind == VIEW_JOB_REFINE)
        w->cancel = 1;
    pthread_mutex_unlock(&w->lock);
}

void view_worker_cancel_shot(view_worker *w)
{
    pthread_mutex_lock(&w->lock);
    if (w->running && w->current.kind == VIEW_JOB_SHOT)
        w->cancel = 1;
    pthread_mutex_unlock(&w->lock);
}

int view_worker_idle(view_worker *w, uint64_t *view, view_job_kind *kind)
{
    pthread_mutex_lock(&w->lock);
    int idle = !w->running && !w->has_queued;
    if (view && w->running) {
        *view = w->current.view;
        *kind = w->current.kind;
    }
    pthread_mutex_unlock(&w->lock);
    return idle;
}

int view_worker_take(view_worker *w, view_frame *frame)
{
    pthread_mutex_lock(&w->lock);
    int has = w->has_frame;
    if (has) {
        *frame = w->frame;
        w->has_frame = 0;
    }
    pthread_mutex_unlock(&w->lock);
    return has;
}

void view_worker_stop(view_worker *w)
{
    if (!w)
        return;
    pthread_mutex_lock(&w->lock);
    w->stopping = 1;
    if (w->running)
        w->cancel = 1; /* whatever the job, it stops inside its tile */
    pthread_cond_signal(&w->changed);
    pthread_mutex_unlock(&w->lock);
    pthread_join(w->thread, NULL);
    if (w->has_queued)
        view_model_release(w->queued.model);
    if (w->has_frame)
        free_frame(&w->frame);
    sc_framebuffer_release(w->finished);
    free(w->sum);
    pthread_cond_destroy(&w->changed);
    pthread_mutex_destroy(&w->lock);
    free(w);
}
