/* The memory limit of the process, for the checks before large
 * allocations and for the message of a failed one.
 *
 * The limit is the process's own RLIMIT_DATA (setrlimit; `spancast
 * --max-memory` sets it): the kernel refuses every private writable
 * mapping past it (the heap, malloc's mmaps, thread stacks), so an
 * allocation past it fails with NULL, which every caller turns into
 * SC_ERR_NOMEM, instead of succeeding on overcommit and killing the
 * process when its pages are touched. The library keeps no limit of its
 * own (it has no global state): a program that sets RLIMIT_DATA gets the
 * same checks.
 *
 * On top of that backstop, the few allocations whose size is known before
 * they are made and that can be large (a render's image buffers) are
 * compared first with what the limit leaves, through mem_reserve, so that
 * the error names what needed the memory and how much, before any work. A
 * failed allocation anywhere else says "out of memory" and, under a limit,
 * which limit was reached (err_nomem).
 */
#ifndef SPANCAST_BASE_MEM_H
#define SPANCAST_BASE_MEM_H

#include <stdint.h>

#include "spancast/spancast.h"

/* The soft RLIMIT_DATA of the process in bytes, 0 when there is none. */
uint64_t mem_limit(void);

/* The process's data memory now, as RLIMIT_DATA counts it (VmData of
 * /proc/self/status), in bytes; 0 when it cannot be read. */
uint64_t mem_in_use(void);

/* Whether bytes more fit under the limit now: SC_OK (also without a
 * limit), or SC_ERR_LIMIT with "WHO needs N MiB for WHAT, more than the
 * memory limit of L MiB leaves (U MiB in use)": who and what are noun
 * phrases ("a 4000x3000 render", "its image buffers"). */
sc_status mem_reserve(uint64_t bytes, const char *who, const char *what, sc_error *error);

/* Under a memory limit, rewrites an SC_ERR_NOMEM error without a source
 * position to name the work that needed the memory: "WHAT ran out of
 * memory: the memory limit of L MiB is reached" (what: "loading
 * 'm.csg'"). Any other error, or no limit, is left as it is. */
void mem_blame(sc_error *error, const char *what);

/* Advises the kernel that the large buffer p[0 .. bytes), freshly
 * allocated or grown and about to be written through, be backed by huge
 * pages where the system offers them on request (Linux transparent huge
 * pages in "madvise" mode): its first touch then costs one fault per 2 MiB
 * instead of one per 4 KiB page, which is most of the system time of
 * loading a million-leaf model. A buffer of at least MEM_HUGE_MIN bytes is
 * advised whole, from the start of its first page to the end of its last:
 * the C library keeps so large a block in a mapping of its own, and advice
 * on part of a mapping splits it, after which realloc can no longer move
 * the block by remapping its pages and copies it into fresh ones instead.
 * The kernel backs only the 2 MiB-aligned parts with huge pages; smaller
 * buffers, other systems and a refusal leave everything as it was. The
 * buffer stays the caller's. */
#define MEM_HUGE_MIN ((size_t)8 << 20)
void mem_advise_huge(void *p, size_t bytes);

/* Faults in the whole pages of [p, p + bytes) for writing, on a thread of
 * its own (madvise MADV_POPULATE_WRITE), leaving their contents as they
 * are: memory that the caller is about to fill front to back is cleared
 * by the kernel on another core meanwhile, and the caller's writes find
 * it mapped (a million leaves: 190 MB that the builder's walk would fault
 * in one page at a time). Returns NULL where it does nothing (a kernel
 * without the advice, a range under MEM_HUGE_MIN, no thread); the memory
 * must stay mapped until mem_prefault_end, which waits for the thread. */
typedef struct mem_prefault mem_prefault;
mem_prefault *mem_prefault_start(void *p, size_t bytes);
void mem_prefault_end(mem_prefault *f);

/* Writes bytes as "12.3 MiB" (or KiB, GiB) into buf of size n; returns
 * buf. */
const char *mem_format(uint64_t bytes, char *buf, int n);

#endif
