/* dist.h for the tool itself, which does not link Open MPI: one rank.
 *
 * Under mpirun with several ranks, `render` hands over to spancast-mpi
 * (the same program on MPI, mpi_dist.c), found where the tool finds its
 * other helpers; a build without Open MPI has none, and says so rather
 * than let every rank render and write the whole image.
 */
#define _POSIX_C_SOURCE 200809L

#include "cli/dist.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cli/scad.h"
#include "formats/file.h"

/* The number of ranks Open MPI's mpirun says the job has (it sets
 * OMPI_COMM_WORLD_SIZE in every rank's environment); 1 outside mpirun. */
static int launcher_size(void)
{
    const char *size = getenv("OMPI_COMM_WORLD_SIZE");
    if (!size)
        return 1;
    char *end;
    long n = strtol(size, &end, 10);
    return *size && !*end && n > 1 && n < 1 << 24 ? (int)n : 1;
}

int dist_enter(int argc, char **argv)
{
    (void)argc;
    int ranks = launcher_size();
    if (ranks <= 1)
        return -1;
    char path[4096];
    if (!file_beside_program("spancast-mpi", path, sizeof path) ||
        access(path, X_OK) != 0) {
        fprintf(stderr,
                "spancast: error: running under mpirun with %d ranks, but this build has "
                "no MPI support (no spancast-mpi beside spancast)\n",
                ranks);
        return 1;
    }
    /* Rank 0 traces beside its coordinator, and ranks often share a
     * machine: OpenMP's threads should sleep, not spin, between renders
     * (read by the OpenMP runtime when spancast-mpi starts; the user's own
     * setting stays). */
    setenv("OMP_WAIT_POLICY", "passive", 0);
    argv[0] = path; /* spancast-mpi render MODEL ... */
    execv(path, argv);
    fprintf(stderr, "spancast: error: cannot run '%s': %s\n", path, strerror(errno));
    return 1;
}

int dist_size(void)
{
    return 1;
}

int dist_rank(void)
{
    return 0;
}

int dist_agree(int status)
{
    return status;
}

void dist_share_lines(sc_measure_options *options)
{
    (void)options; /* one rank casts every line */
}

sc_status dist_load(const char *path, const sc_load_options *options, sc_scene **scene,
                    sc_error *error)
{
    return scad_load_model(path, options, scene, error, NULL, NULL, NULL, NULL);
}

sc_status dist_run(const dist_work *work, sc_error *error)
{
    return dist_run_here(work, error);
}
