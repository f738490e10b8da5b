/* spancast-bench: the benchmarks of `spancast bench` (bench.h). The tool
 * itself links only the public API; `spancast bench NAME ...` starts this
 * program beside it with the same arguments after "bench", so the harnesses
 * (stability.c) and the internals the benchmarks measure (primitives, root
 * finders) stay out of the tool.
 *
 *   spancast-bench accuracy --csv FILE [--plot FILE.png] [--rays N]
 *   spancast-bench stability --csv FILE [--dir DIR] [--size N] [--depth N]
 *   spancast-bench meshes FILE.csg [--size W,H] [--reps N]
 *   spancast-bench torus-stl --triangles N FILE.stl
 */
#include <string.h>

#include "bench/bench.h"

int main(int argc, char **argv)
{
    if (argc > 1 && !strcmp(argv[1], "stability"))
        return bench_stability_main(argc - 1, argv + 1);
    if (argc > 1 && (!strcmp(argv[1], "meshes") || !strcmp(argv[1], "torus-stl")))
        return bench_meshes_main(argc - 1, argv + 1);
    return bench_main(argc - 1, argv + 1);
}
