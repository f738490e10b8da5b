/* Sorting of 64-bit keys (sort.c): least significant digit first radix
 * sort, 16 bits a pass (8 below 65,536 keys), a pass skipped where every
 * key has the same digit (the high bits of packed point indices, mostly).
 * Linear in n where qsort is n log n with a call per comparison: a mesh of
 * 4 million triangles checks its 12 million edges in a tenth of the time.
 * A few keys (32 or fewer) are sorted by insertion, without memory: a
 * model of 40,000 small meshes spent three quarters of its load clearing
 * 16-bit histograms.
 */
#ifndef SPANCAST_BASE_SORT_H
#define SPANCAST_BASE_SORT_H

#include <stddef.h>
#include <stdint.h>

/* Sorts keys[0 .. n) ascending; returns 1, or 0 with keys unchanged when
 * memory for a copy of them runs out (never for 32 keys or fewer). */
int sort_u64(uint64_t *keys, size_t n);

#endif
