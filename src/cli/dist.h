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
 * sends them and trace tiles rank 0 hands out (tiles.h).
 */
#ifndef SPANCAST_CLI_DIST_H
#define SPANCAST_CLI_DIST_H

#include <stddef.h>

#include "spancast/spancast.h"

/* Called by `render` before anything else, with main's arguments. In the
 * tool: under mpirun with more than one rank, replaces the process with
 * spancast-mpi (and returns 1, with a message, only when that fails);
 * otherwise returns -1. In spancast-mpi: joins the MPI job (MPI_Init,
 * finalised at exit) and returns -1, or 1 with a message when it cannot. */
int dist_enter(int argc, char **argv);

/* The number of ranks (1 without MPI) and this process's rank. */
int dist_size(void);
int dist_rank(void);

/* With several ranks: rank 0 reads the model's text (converting a .scad
 * with OpenSCAD, once) and sends it to every rank, which loads it under
 * the same name. Returns the same status on every rank; on failure the
 * error of the first rank that failed is in error on rank 0. */
sc_status dist_load(const char *path, const sc_load_options *options, sc_scene **scene,
                    sc_error *error);

/* One render cut into tiles (tiles.c): how to trace tile k, and what rank
 * 0 does with it. */
typedef struct dist_tiles {
    int count; /* tiles, numbered row by row */
    /* Renders tile k (any rank, any thread but one at a time per rank);
     * on success *fb is the tile's buffers, owned by the caller. */
    sc_status (*render)(void *user, int k, sc_framebuffer **fb, sc_error *error);
    /* Rank 0 only: takes tile k, in order k = 0, 1, 2, ... whatever order
     * they were finished in; fb stays the caller's. */
    sc_status (*deliver)(void *user, int k, const sc_framebuffer *fb, sc_error *error);
    void *user;
    int window; /* at most this many tiles handed out beyond the last delivered */
    const volatile sig_atomic_t *cancel; /* stop when set; may be NULL */
} dist_tiles;

/* Renders and delivers every tile. With one rank: here, in order (as
 * dist_run_here). With several: rank 0 hands tiles out one at a time as
 * ranks ask for them (rank 0 traces too, on a thread of its own), receives
 * the results and delivers them in order. Returns when every tile is
 * delivered or the run failed; on rank 0 the status and error are the
 * run's (the first failure on any rank), on the others their own (SC_OK
 * unless they failed themselves). */
sc_status dist_run_tiles(const dist_tiles *job, sc_error *error);

/* Renders and delivers every tile of job in this process, in order,
 * looking at job->cancel between tiles. (tiles.c) */
sc_status dist_run_here(const dist_tiles *job, sc_error *error);

#endif
