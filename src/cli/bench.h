/* Benchmarks of the spancast command (src/cli/bench_accuracy.c). */
#ifndef SPANCAST_CLI_BENCH_H
#define SPANCAST_CLI_BENCH_H

/* `spancast bench accuracy --csv FILE [--plot FILE.png] [--rays N]`, with
 * argv[0] the benchmark's name. Returns the exit status. */
int bench_main(int argc, char **argv);

#endif
