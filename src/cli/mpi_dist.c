/* dist.h on Open MPI: spancast-mpi, the tool that `mpirun -np N spancast
 * render ...` runs on every rank (the tool hands over to it: dist_local.c).
 *
 * Loading: rank 0 reads the model (a .scad converted once, by OpenSCAD on
 * rank 0) and broadcasts its text and name; every rank loads that text, so
 * the other ranks need no copy of the model, only of the files it
 * imports. The ranks then agree on the outcome (the first failing rank's
 * error goes to rank 0).
 *
 * Work (the runs of tiles of a render, the jobs of a batch): a queue on
 * rank 0. Each other rank asks for a piece, does it (a render with all its
 * threads), sends the result (its number, then the bytes its pack makes:
 * the ranks run the same build on the same kind of machine) and gets the
 * next piece in reply, until rank 0 answers -1. Rank 0 works too, on a
 * thread of its own that takes pieces from the same queue; its main
 * thread is the coordinator, the only thread that calls MPI
 * (MPI_THREAD_FUNNELED). The coordinator delivers results in order;
 * pieces are handed out in order and at most `window` beyond the oldest
 * undelivered one, which bounds what rank 0 holds. Waiting is done by
 * polling with short sleeps (MPI_Test, MPI_Iprobe), never by a blocking
 * call, because Open MPI's blocking calls spin a core that the tracing
 * threads of the same machine want.
 *
 * Measure, overlaps and compare share the lines of each round of their
 * integration instead (share_lines): every rank casts its run, the runs are
 * gathered on every rank, and every rank adds them all up, in one order.
 *
 * Messages only go from the ranks to rank 0 and back, so a failure is
 * simple: the failing rank sends its error instead of a result, rank 0
 * stops handing out work and answers every rank's next request with -1.
 * Messages of the ranks other than 0 are silenced (main points their stdout
 * and stderr at /dev/null): rank 0 prints the command's output and the
 * first error.
 */
#define _POSIX_C_SOURCE 200809L

#include "cli/dist.h"

#include <errno.h>
#include <limits.h>
#include <mpi.h>
#include <pthread.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "base/error.h"
#include "cli/cli.h"
#include "cli/scad.h"
#include "formats/file.h"

enum { TAG_ASK = 1, TAG_TILE, TAG_DONE, TAG_FAIL, TAG_ERROR };

/* Sleeps 100 microseconds: a poll's pause, short beside a piece of work. */
static void nap(void)
{
    struct timespec pause = {0, 100000};
    nanosleep(&pause, NULL);
}

static void finalize(void)
{
    int finalized = 0;
    MPI_Finalized(&finalized);
    if (!finalized)
        MPI_Finalize();
}

int dist_enter(int argc, char **argv)
{
    (void)argc;
    (void)argv;
    /* Started outside mpirun (a batch's job, run by its own path): the
     * plain tool, without MPI. */
    const char *size = getenv("OMPI_COMM_WORLD_SIZE");
    if (!size || atoi(size) <= 1)
        return -1;
    int provided = 0;
    if (MPI_Init_thread(NULL, NULL, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS) {
        fprintf(stderr, "spancast: error: cannot join the MPI job (MPI_Init failed)\n");
        return 1;
    }
    atexit(finalize);
    if (provided < MPI_THREAD_FUNNELED) {
        fprintf(stderr, "spancast: error: this MPI library does not allow threads\n");
        return 1;
    }
    return -1; /* main has silenced the ranks other than 0 */
}

int dist_size(void)
{
    int initialized = 0, n = 1;
    MPI_Initialized(&initialized);
    if (initialized)
        MPI_Comm_size(MPI_COMM_WORLD, &n);
    return n;
}

int dist_rank(void)
{
    int initialized = 0, rank = 0;
    MPI_Initialized(&initialized);
    if (initialized)
        MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    return rank;
}

int dist_agree(int status)
{
    if (dist_size() == 1)
        return status;
    int largest = status;
    MPI_Allreduce(&status, &largest, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
    return largest;
}

/* Waits for request without spinning. */
static void wait_for(MPI_Request *request)
{
    int done = 0;
    MPI_Test(request, &done, MPI_STATUS_IGNORE);
    while (!done) {
        nap();
        MPI_Test(request, &done, MPI_STATUS_IGNORE);
    }
}

/* MPI_Bcast of size bytes from rank 0, in pieces an int can count. */
static void broadcast_bytes(void *data, size_t size)
{
    const size_t piece = (size_t)1 << 30;
    for (size_t at = 0; at < size; at += piece) {
        size_t n = size - at < piece ? size - at : piece;
        MPI_Bcast((char *)data + at, (int)n, MPI_BYTE, 0, MPI_COMM_WORLD);
    }
}

/* Rank 0's part of loading: the text and the name to load it under, as
 * the commands take MODEL (scad_read_model). */
static sc_status read_model(const char *path, const sc_load_options *options, char **text,
                            size_t *size, char *name, size_t name_size, sc_error *error)
{
    return scad_read_model(path, options, text, size, name, name_size, error,
                           &(scad_stop){&cli_stop, NULL});
}

sc_status dist_load(const char *path, const sc_load_options *options, sc_scene **scene,
                    sc_error *error)
{
    *scene = NULL;
    int ranks = dist_size(), rank = dist_rank();
    if (ranks == 1)
        return scad_load_model(path, options, scene, error, NULL, NULL, NULL, NULL);
    char *text = NULL, name[PATH_MAX + 16] = "";
    size_t size = 0;
    int64_t head[3] = {SC_OK, 0, 0}; /* status, text bytes, name bytes */
    memset(error, 0, sizeof *error);
    if (rank == 0) {
        head[0] = read_model(path, options, &text, &size, name, sizeof name, error);
        head[1] = (int64_t)size;
        head[2] = (int64_t)strlen(name);
    }
    MPI_Bcast(head, 3, MPI_INT64_T, 0, MPI_COMM_WORLD);
    if (head[0] != SC_OK) {
        error->status = (sc_status)head[0];
        free(text);
        return (sc_status)head[0];
    }
    if (rank != 0) {
        /* the fonts rank 0's conversion registered, each rank for itself */
        if (scad_is_source(path))
            scad_register_fonts(path);
        size = (size_t)head[1];
        text = malloc(size + 1);
        if (!text) /* this rank cannot take part: MPI_Abort ends the job */
            MPI_Abort(MPI_COMM_WORLD, 1);
        text[size] = '\0';
    }
    MPI_Bcast(name, (int)head[2] + 1, MPI_CHAR, 0, MPI_COMM_WORLD);
    broadcast_bytes(text, size);
    /* A mesh's one-line model is loaded as one process loads it, for the
     * same messages (each rank reads the mesh, as it reads an import). */
    /* Text OpenSCAD wrote (loaded under another name than the file's) is
     * its export, whose arguments OpenSCAD has already warned of. */
    sc_load_options export;
    if (options)
        export = *options;
    else
        sc_load_options_init(&export);
    export.openscad_export = strcmp(name, path) != 0;
    sc_status st = scad_is_mesh(path)
                       ? sc_scene_load_mesh(path, options, scene, error)
                       : sc_scene_load_string(name, text, size, &export, scene, error);
    free(text);
    /* Agree: the first rank that failed, if any, says why. */
    int mine = st == SC_OK ? ranks : rank, first = ranks;
    MPI_Allreduce(&mine, &first, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
    if (first == ranks)
        return SC_OK;
    sc_scene_release(*scene);
    *scene = NULL;
    if (first != 0 && rank == first)
        MPI_Send(error, (int)sizeof *error, MPI_BYTE, 0, TAG_ERROR, MPI_COMM_WORLD);
    if (first != 0 && rank == 0)
        MPI_Recv(error, (int)sizeof *error, MPI_BYTE, first, TAG_ERROR, MPI_COMM_WORLD,
                 MPI_STATUS_IGNORE);
    int status = st;
    MPI_Bcast(&status, 1, MPI_INT, first, MPI_COMM_WORLD);
    error->status = (sc_status)status;
    /* An error in OpenSCAD's converted text is put on the source, as one
     * load's is (scad.c), never on the name it was loaded under. */
    if (rank == 0 && strcmp(name, path) != 0)
        scad_blame(error, name, path);
    return (sc_status)status;
}

/* ---- the lines of measure, overlaps and compare ---- */

/* sc_measure_options.share_lines: every rank's outcome to every rank, then,
 * when all succeeded, every rank's run of records (in place: run p is
 * records count*p/ranks up to count*(p+1)/ranks, the library's cut). Each
 * rank computes the same counts, so every rank takes the same branch and
 * calls the same collectives. Non-blocking collectives polled by wait_for,
 * so that a rank that finished its run early sleeps instead of spinning a
 * core the others are tracing on. */
static int share_lines(void *user, void *records, size_t size, size_t count,
                       int outcome[3])
{
    (void)user;
    int ranks = dist_size();
    if (size > INT_MAX || count > INT_MAX)
        return 0; /* the same answer on every rank */
    int *all = malloc((size_t)ranks * 3 * sizeof *all);
    int *counts = malloc((size_t)ranks * sizeof *counts);
    int *starts = malloc((size_t)ranks * sizeof *starts);
    if (!all || !counts || !starts) /* this rank cannot take part */
        MPI_Abort(MPI_COMM_WORLD, 1);
    MPI_Request request;
    MPI_Iallgather(outcome, 3, MPI_INT, all, 3, MPI_INT, MPI_COMM_WORLD, &request);
    wait_for(&request);
    int failed = 0;
    for (int p = 0; p < ranks && !failed; p++)
        if (all[p * 3] != SC_OK) {
            memcpy(outcome, &all[p * 3], 3 * sizeof *outcome);
            failed = 1;
        }
    if (!failed) {
        for (int p = 0; p < ranks; p++) {
            uint64_t first = (uint64_t)count * (uint64_t)p / (uint64_t)ranks;
            uint64_t end = (uint64_t)count * (uint64_t)(p + 1) / (uint64_t)ranks;
            starts[p] = (int)first;
            counts[p] = (int)(end - first);
        }
        MPI_Datatype record;
        MPI_Type_contiguous((int)size, MPI_BYTE, &record);
        MPI_Type_commit(&record);
        MPI_Iallgatherv(MPI_IN_PLACE, 0, MPI_DATATYPE_NULL, records, counts, starts,
                        record, MPI_COMM_WORLD, &request);
        wait_for(&request);
        MPI_Type_free(&record);
    }
    free(all);
    free(counts);
    free(starts);
    return 1;
}

/* sc_measure_options.share_box: the smallest lo and largest hi, as one
 * reduction of lo and -hi (negation is exact). */
static int share_box(void *user, double box[6])
{
    (void)user;
    double mine[6], least[6];
    for (int i = 0; i < 3; i++) {
        mine[i] = box[i];
        mine[3 + i] = -box[3 + i];
    }
    MPI_Request request;
    MPI_Iallreduce(mine, least, 6, MPI_DOUBLE, MPI_MIN, MPI_COMM_WORLD, &request);
    wait_for(&request);
    for (int i = 0; i < 3; i++) {
        box[i] = least[i];
        box[3 + i] = -least[3 + i];
    }
    return 1;
}

void dist_share_lines(sc_measure_options *options)
{
    int ranks = dist_size();
    if (ranks <= 1)
        return;
    options->parts = ranks;
    options->part = dist_rank();
    options->share_lines = share_lines;
    options->share_box = share_box;
    options->share_user = NULL;
}

/* ---- a rank other than 0 ---- */

/* A piece's result as one message: its number, then its bytes
 * (malloc'd; NULL when out of memory). */
static char *message_of(const dist_work *job, int k, const void *result, size_t *size)
{
    size_t bytes = 0;
    void *packed = job->pack(job->user, result, &bytes);
    if (!packed)
        return NULL;
    char *msg = bytes + sizeof(int32_t) < (size_t)INT_MAX
                    ? malloc(sizeof(int32_t) + bytes)
                    : NULL;
    if (msg) {
        int32_t number = k;
        memcpy(msg, &number, sizeof number);
        memcpy(msg + sizeof number, packed, bytes);
        *size = sizeof number + bytes;
    }
    free(packed);
    return msg;
}

static sc_status work(const dist_work *job, sc_error *error)
{
    sc_status failed = SC_OK;
    int32_t ask = 0;
    MPI_Send(&ask, 1, MPI_INT32_T, 0, TAG_ASK, MPI_COMM_WORLD);
    for (;;) {
        int32_t k = -1;
        MPI_Request request;
        MPI_Irecv(&k, 1, MPI_INT32_T, 0, TAG_TILE, MPI_COMM_WORLD, &request);
        wait_for(&request);
        if (k < 0 || k >= job->count)
            return failed;
        void *result = NULL;
        sc_error mine;
        sc_status st = job->run(job->user, k, &result, &mine);
        size_t size = 0;
        char *msg = st == SC_OK ? message_of(job, k, result, &size) : NULL;
        if (result)
            job->release(job->user, result);
        if (st == SC_OK && !msg)
            st = err_nomem(&mine, NULL);
        if (st != SC_OK) {
            if (failed == SC_OK) {
                failed = st;
                *error = mine;
            }
            MPI_Isend(&mine, (int)sizeof mine, MPI_BYTE, 0, TAG_FAIL, MPI_COMM_WORLD,
                      &request);
            wait_for(&request);
            continue;
        }
        MPI_Isend(msg, (int)size, MPI_BYTE, 0, TAG_DONE, MPI_COMM_WORLD, &request);
        wait_for(&request);
        free(msg);
    }
}

/* ---- rank 0 ---- */

typedef struct coordinator {
    const dist_work *job;
    pthread_mutex_t lock;
    pthread_cond_t wake; /* for the local tracer: a delivery, or stop */
    int next;            /* the next piece to hand out */
    int delivered;       /* pieces delivered, in order */
    int stop;            /* a failure or an interrupt: hand out no more */
    int local_done;      /* the local tracer has returned */
    void **held;         /* finished pieces not yet delivered: piece k at
                            k % window, for delivered <= k < delivered + window */
    sc_status status;    /* the first failure */
    sc_error error;
} coordinator;

/* Records a failure (the first one wins) and stops. Called locked. */
static void fail_locked(coordinator *c, sc_status st, const sc_error *error)
{
    if (c->status == SC_OK) {
        c->status = st;
        c->error = *error;
        c->error.status = st;
    }
    c->stop = 1;
    pthread_cond_broadcast(&c->wake);
}

/* Whether piece next may be handed out now. Called locked. */
static int can_hand_out(const coordinator *c)
{
    return !c->stop && c->next < c->job->count && c->next < c->delivered + c->job->window;
}

/* Rank 0's own working thread. */
static void *trace_locally(void *arg)
{
    coordinator *c = arg;
    const dist_work *job = c->job;
    for (;;) {
        pthread_mutex_lock(&c->lock);
        while (!can_hand_out(c) && !c->stop && c->next < job->count)
            pthread_cond_wait(&c->wake, &c->lock);
        if (!can_hand_out(c)) {
            c->local_done = 1;
            pthread_mutex_unlock(&c->lock);
            return NULL;
        }
        int k = c->next++;
        pthread_mutex_unlock(&c->lock);
        void *result = NULL;
        sc_error error;
        sc_status st = job->run(job->user, k, &result, &error);
        pthread_mutex_lock(&c->lock);
        if (st != SC_OK)
            fail_locked(c, st, &error);
        else
            c->held[k % job->window] = result;
        pthread_mutex_unlock(&c->lock);
    }
}

/* Delivers the next result if it is here; returns 1 when it did something. */
static int deliver_next(coordinator *c)
{
    const dist_work *job = c->job;
    pthread_mutex_lock(&c->lock);
    void *result = NULL;
    int k = c->delivered;
    if (!c->stop && k < job->count) {
        result = c->held[k % job->window];
        c->held[k % job->window] = NULL;
    }
    pthread_mutex_unlock(&c->lock);
    if (!result)
        return 0;
    sc_error error;
    sc_status st = job->deliver(job->user, k, result, &error);
    job->release(job->user, result);
    pthread_mutex_lock(&c->lock);
    if (st != SC_OK)
        fail_locked(c, st, &error);
    else
        c->delivered++;
    pthread_cond_broadcast(&c->wake);
    pthread_mutex_unlock(&c->lock);
    return 1;
}

/* Receives one message if there is one: a request, a result or a
 * failure; its sender joins the ranks waiting for work. Returns 1 when it
 * did. */
static int receive(coordinator *c, int *waiting, int *waiting_count)
{
    int here = 0;
    MPI_Status status;
    MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &here, &status);
    if (!here)
        return 0;
    int size = 0;
    MPI_Get_count(&status, MPI_BYTE, &size);
    char *msg = malloc(size > 0 ? (size_t)size : 1);
    if (!msg) {
        fprintf(stderr, "spancast: error: out of memory for a result from rank %d\n",
                status.MPI_SOURCE);
        MPI_Abort(MPI_COMM_WORLD, 1);
    }
    MPI_Recv(msg, size, MPI_BYTE, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD,
             MPI_STATUS_IGNORE);
    pthread_mutex_lock(&c->lock);
    if (status.MPI_TAG == TAG_DONE) {
        int32_t k = -1;
        void *result = NULL;
        if ((size_t)size >= sizeof k) {
            memcpy(&k, msg, sizeof k);
            result =
                c->job->unpack(c->job->user, msg + sizeof k, (size_t)size - sizeof k);
        }
        if (!result) {
            sc_error error;
            err_set(&error, SC_ERR_NOMEM, NULL,
                    "a result from rank %d could not be taken", status.MPI_SOURCE);
            fail_locked(c, SC_ERR_NOMEM, &error);
        }
        if (result && !c->stop && k >= c->delivered && k < c->next &&
            !c->held[k % c->job->window])
            c->held[k % c->job->window] = result;
        else if (result)
            c->job->release(c->job->user, result);
    } else if (status.MPI_TAG == TAG_FAIL && (size_t)size == sizeof(sc_error)) {
        sc_error error;
        memcpy(&error, msg, sizeof error);
        error.message[sizeof error.message - 1] = '\0';
        error.file[sizeof error.file - 1] = '\0';
        fail_locked(c, error.status != SC_OK ? error.status : SC_ERR_IO, &error);
    }
    pthread_mutex_unlock(&c->lock);
    free(msg);
    waiting[(*waiting_count)++] = status.MPI_SOURCE;
    return 1;
}

/* Answers the waiting ranks: a piece each while there are pieces within
 * the window, -1 (stop) once there are none left or the run failed.
 * Returns the number of ranks told to stop. */
static int hand_out(coordinator *c, int *waiting, int *waiting_count)
{
    int stopped = 0;
    pthread_mutex_lock(&c->lock);
    while (*waiting_count > 0) {
        int32_t k;
        if (c->stop || c->next >= c->job->count)
            k = -1;
        else if (can_hand_out(c))
            k = c->next++;
        else
            break; /* the window is full: wait for a delivery */
        int rank = waiting[--*waiting_count];
        MPI_Send(&k, 1, MPI_INT32_T, rank, TAG_TILE, MPI_COMM_WORLD);
        stopped += k < 0;
    }
    pthread_mutex_unlock(&c->lock);
    return stopped;
}

static sc_status coordinate(const dist_work *job, int ranks, sc_error *error)
{
    coordinator c;
    memset(&c, 0, sizeof c);
    c.job = job;
    c.held = calloc((size_t)job->window, sizeof *c.held);
    int *waiting = malloc((size_t)ranks * sizeof *waiting);
    int waiting_count = 0, stopped = 0;
    if (!c.held || !waiting) {
        free(c.held);
        free(waiting);
        MPI_Abort(MPI_COMM_WORLD, 1); /* the other ranks wait for rank 0 */
    }
    pthread_mutex_init(&c.lock, NULL);
    pthread_cond_init(&c.wake, NULL);
    pthread_t tracer;
    int tracing = pthread_create(&tracer, NULL, trace_locally, &c) == 0;
    if (!tracing)
        c.local_done = 1; /* the other ranks trace it all */
    for (;;) {
        int busy = deliver_next(&c);
        busy |= receive(&c, waiting, &waiting_count);
        stopped += hand_out(&c, waiting, &waiting_count);
        pthread_mutex_lock(&c.lock);
        if (job->cancel && *job->cancel && !c.stop) {
            sc_error interrupted;
            err_set(&interrupted, SC_ERR_CANCELLED, NULL, "interrupted");
            fail_locked(&c, SC_ERR_CANCELLED, &interrupted);
        }
        int finished =
            stopped == ranks - 1 && c.local_done && (c.stop || c.delivered == job->count);
        pthread_mutex_unlock(&c.lock);
        if (finished)
            break;
        if (!busy)
            nap();
    }
    if (tracing)
        pthread_join(tracer, NULL);
    for (int k = 0; k < job->window; k++)
        if (c.held[k])
            job->release(job->user, c.held[k]);
    free(c.held);
    free(waiting);
    pthread_cond_destroy(&c.wake);
    pthread_mutex_destroy(&c.lock);
    if (c.status != SC_OK)
        *error = c.error;
    return c.status;
}

sc_status dist_run(const dist_work *job, sc_error *error)
{
    int ranks = dist_size();
    if (ranks == 1)
        return dist_run_here(job, error);
    return dist_rank() == 0 ? coordinate(job, ranks, error) : work(job, error);
}
