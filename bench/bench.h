/* The benchmarks behind `spancast bench` (bench_*.c), run by the program
 * spancast-bench (main.c), which the tool starts: they link the stability
 * harness and the library's internals, which the tool does not. */
#ifndef SPANCAST_BENCH_BENCH_H
#define SPANCAST_BENCH_BENCH_H

/* `spancast bench accuracy --csv FILE [--plot FILE.png] [--rays N]`, with
 * argv[0] the benchmark's name. Returns the exit status. */
int bench_main(int argc, char **argv);

/* `spancast bench stability --csv FILE [--dir DIR] [--size N]
 * [--depth N]`
 * (bench_stability.c), argv[0] "stability". Returns the exit status. */
int bench_stability_main(int argc, char **argv);

/* `spancast bench meshes FILE.csg [--size W,H] [--reps N]` and
 * `spancast bench torus-stl --triangles N FILE.stl` (bench_mesh.c), argv[0]
 * the benchmark's name. Returns the exit status. */
int bench_meshes_main(int argc, char **argv);

#endif
