/* The viewer's loading thread.
 *
 * Loading a .scad model means running OpenSCAD (scad.c), which can take
 * seconds; a .csg loads fast but a large one still takes a while. Both run
 * on this thread so that the window keeps answering, and the last good
 * model stays on screen until the new one is ready. A request made while a
 * load runs starts one more load when it ends (the file changed again
 * during the load), never two at once. Each load records the files it read
 * (the model, and for a .scad everything OpenSCAD's dependency file names)
 * for the window to watch.
 */
#define _POSIX_C_SOURCE 200809L

#include "cli/view.h"

#include <pthread.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "cli/cli.h"
#include "cli/scad.h"

struct view_loader {
    pthread_t thread;
    pthread_mutex_t lock;
    pthread_cond_t changed;
    int stopping, requested, loading;
    int has_result;
    view_load result; /* the newest finished load not yet taken */
    char *path;
    int faithful;
    void (*wake)(void *user);
    void *user;
};

static double seconds_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

void view_load_free_files(view_load *load)
{
    for (size_t k = 0; k < load->file_count; k++)
        free(load->files[k]);
    free(load->files);
    load->files = NULL;
    load->file_count = 0;
}

static void add_file(void *user, const char *file)
{
    view_load *load = user;
    char *copy = strdup(file);
    char **grown = realloc(load->files, (load->file_count + 1) * sizeof *grown);
    if (!copy || !grown) {
        free(copy);
        if (grown)
            load->files = grown;
        return; /* not watched: the worst is a missed reload */
    }
    load->files = grown;
    load->files[load->file_count++] = copy;
}

static void load_once(const view_loader *l, view_load *load)
{
    memset(load, 0, sizeof *load);
    double start = seconds_now();
    add_file(load, l->path);
    sc_load_options lo;
    sc_load_options_init(&lo);
    cli_load_options(&lo, l->faithful);
    sc_scene *scene = NULL;
    sc_status st = scad_load_model(l->path, &lo, &scene, &load->error, add_file, load,
                                   NULL, &load->converted);
    load->seconds = seconds_now() - start;
    if (st != SC_OK)
        return;
    load->model = calloc(1, sizeof *load->model);
    if (!load->model) {
        sc_scene_release(scene);
        memset(&load->error, 0, sizeof load->error);
        load->error.status = SC_ERR_NOMEM;
        strcpy(load->error.message, "out of memory");
        return;
    }
    atomic_init(&load->model->refs, 1);
    load->model->scene = scene;
    load->model->load_seconds = load->seconds;
}

static void drop_result(view_load *load)
{
    view_model_release(load->model);
    view_load_free_files(load);
}

static void *loader_main(void *arg)
{
    view_loader *l = arg;
    pthread_mutex_lock(&l->lock);
    for (;;) {
        while (!l->stopping && !l->requested)
            pthread_cond_wait(&l->changed, &l->lock);
        if (l->stopping)
            break;
        l->requested = 0;
        l->loading = 1;
        pthread_mutex_unlock(&l->lock);

        view_load load;
        load_once(l, &load);

        pthread_mutex_lock(&l->lock);
        l->loading = 0;
        if (l->has_result)
            drop_result(&l->result);
        l->result = load;
        l->has_result = 1;
        pthread_mutex_unlock(&l->lock);
        l->wake(l->user);
        pthread_mutex_lock(&l->lock);
    }
    pthread_mutex_unlock(&l->lock);
    return NULL;
}

view_loader *view_loader_start(const char *path, int faithful, void (*wake)(void *user),
                               void *user)
{
    view_loader *l = calloc(1, sizeof *l);
    if (!l)
        return NULL;
    l->path = strdup(path);
    if (!l->path) {
        free(l);
        return NULL;
    }
    l->faithful = faithful;
    l->wake = wake;
    l->user = user;
    pthread_mutex_init(&l->lock, NULL);
    pthread_cond_init(&l->changed, NULL);
    if (pthread_create(&l->thread, NULL, loader_main, l) != 0) {
        pthread_cond_destroy(&l->changed);
        pthread_mutex_destroy(&l->lock);
        free(l->path);
        free(l);
        return NULL;
    }
    return l;
}

void view_loader_request(view_loader *l)
{
    pthread_mutex_lock(&l->lock);
    l->requested = 1;
    pthread_cond_signal(&l->changed);
    pthread_mutex_unlock(&l->lock);
}

int view_loader_busy(view_loader *l)
{
    pthread_mutex_lock(&l->lock);
    int busy = l->requested || l->loading;
    pthread_mutex_unlock(&l->lock);
    return busy;
}

int view_loader_take(view_loader *l, view_load *load)
{
    pthread_mutex_lock(&l->lock);
    int has = l->has_result;
    if (has) {
        *load = l->result;
        l->has_result = 0;
    }
    pthread_mutex_unlock(&l->lock);
    return has;
}

void view_loader_stop(view_loader *l)
{
    if (!l)
        return;
    pthread_mutex_lock(&l->lock);
    l->stopping = 1;
    pthread_cond_signal(&l->changed);
    pthread_mutex_unlock(&l->lock);
    pthread_join(l->thread, NULL);
    if (l->has_result)
        drop_result(&l->result);
    pthread_cond_destroy(&l->changed);
    pthread_mutex_destroy(&l->lock);
    free(l->path);
    free(l);
}
