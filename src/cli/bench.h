/* Benchmarks of the spancast command (src/cli/bench_*.c). */
#ifndef SPANCAST_CLI_BENCH_H
#define SPANCAST_CLI_BENCH_H

/* `spancast bench accuracy --csv FILE [--plot FILE.png] [--rays N]`, with
 * argv[0] the benchmark's name. Returns the exit status. */
int bench_main(int argc, char **argv);

/* `spancast bench stability --csv FILE [--dir DIR] [--size N]
 * [--depth N]`
 * (bench_stability.c), argv[0] "stability". Returns the exit status. */
int bench_stability_main(int argc, char **argv);

#endif
