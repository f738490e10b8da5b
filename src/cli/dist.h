/* Running one command across the ranks of an MPI job.
 *
 * `mpirun -np N spancast render ...` starts N copies of the tool. The tool
 * itself does not link Open MPI (MPI_Init alone costs a third of a second
 * outside mpirun, and the library a few milliseconds of every start): it
 * links dist_local.c, which sees from the environment that it runs under
 * mpirun with more than one rank and replaces itself with spancast-mpi,
 * found beside it. spancast-mpi is the same program linked with
 * mpi_dist.c instead, which implements these calls on MPI. With one rank,
 * or without mpirun, nothing here does anything.
 *
 * Rank 0 is where the command's files are read and written and its
 * messages printed; the other ranks load the scene from the text rank 0
 * sends them and do the work rank 0 hands out: tiles of a render
 * (tiles.h), jobs of a batch (batch.c); or their share of the lines of
 * measure, overlaps and compare (check.c), which every rank adds up.
 */
#ifndef SPANCAST_CLI_DIST_H
#define SPANCAST_CLI_DIST_H

#include <stddef.h>

#include "spancast/spancast.h"

/* Called by `render` before anything else, with main's arguments. In the
 * tool: under mpirun with more than one rank, replaces the process with
 * spancast-mpi (and returns 1, with a message, only when that fails);
 * otherwise returns -1. In spancast-mpi: under mpirun with more than one
 * rank, joins the MPI job (MPI_Init, finalised at exit) and returns -1, or
 * 1 with a message when it cannot; otherwise returns -1 (the plain
 * tool). */
int dist_enter(int argc, char **argv);

/* The number of ranks (1 without MPI) and this process's rank. */
int dist_size(void);
int dist_rank(void);

/* The largest of status over all ranks, on every rank (status itself with
 * one rank). A rank must not leave before the others know: Open MPI's
 * MPI_Finalize waits for every rank, so a rank that stopped alone, on an
 * error the others did not see, would leave them all waiting. */
int dist_agree(int status);

/* With several ranks, sets options to share the lines of an integration
 * (measure, overlaps, compare) among them: each rank casts its run of
 * every round's lines and the ranks exchange them, so every rank adds up
 * all lines in the same order and the result is bit for bit that of one
 * process (sc_measure_options.parts). With one rank, does nothing. */
void dist_share_lines(sc_measure_options *options);

/* With several ranks: rank 0 reads the model's text (converting a .scad
 * with OpenSCAD, once) and sends it to every rank, which loads it under
 * the same name. Returns the same status on every rank; on failure the
 * error of the first rank that failed is in error on rank 0. */
sc_status dist_load(const char *path, const sc_load_options *options, sc_scene **scene,
                    sc_error *error);

/* Work cut into numbered pieces (the runs of tiles of a render: tiles.c;
 * the jobs of a batch: batch.c), done on any rank, delivered on rank 0 in
 * order. A result is an object of the caller's, turned into bytes and
 * back to travel between ranks. */
typedef struct dist_work {
    int count; /* pieces, numbered from 0 */
    /* Does piece k (on any rank; on rank 0 on a thread of its own, one
     * piece at a time per rank); on success *result is the caller's. */
    sc_status (*run)(void *user, int k, void **result, sc_error *error);
    /* result as bytes (malloc'd, *size of them; NULL when out of memory),
     * and back (NULL when malformed or out of memory). */
    void *(*pack)(void *user, const void *result, size_t *size);
    void *(*unpack)(void *user, const void *bytes, size_t size);
    /* Rank 0 only: takes piece k's result, in order k = 0, 1, 2, ...
     * whatever order they were finished in. */
    sc_status (*deliver)(void *user, int k, const void *result, sc_error *error);
    void (*release)(void *user, void *result); /* frees a result */
    void *user;
    int window; /* at most this many pieces handed out beyond the last delivered */
    const volatile sig_atomic_t *cancel; /* stop when set; may be NULL */
} dist_work;

/* Does and delivers every piece. With one rank: here, in order (as
 * dist_run_here). With several: rank 0 hands pieces out one at a time as
 * ranks ask for them (rank 0 works too, on a thread of its own), receives
 * the results and delivers them in order. Returns when every piece is
 * delivered or the run failed; on rank 0 the status and error are the
 * run's (the first failure on any rank), on the others their own (SC_OK
 * unless they failed themselves). */
sc_status dist_run(const dist_work *work, sc_error *error);

/* Does and delivers every piece of work in this process, in order,
 * looking at work->cancel between pieces. (tiles.c) */
sc_status dist_run_here(const dist_work *work, sc_error *error);

#endif
