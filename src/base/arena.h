/* Bump-pointer arenas.
 *
 * Scene data (tree nodes, polyhedron planes, names) lives in an arena freed
 * with the scene. Ray queries use a per-thread scratch arena that is reset
 * after every pixel sample: arena_reset keeps the blocks it has, so after the
 * first few samples the render loop allocates nothing. Size arithmetic is
 * checked for overflow; an allocation that cannot be satisfied returns NULL.
 * An arena that has grown large (ARENA_GROW_FROM: the typed model of a
 * million leaves) takes new blocks of a quarter of what it owns, up to
 * ARENA_GROW_MAX, advised for huge pages (mem_advise_huge), so that
 * hundreds of megabytes come in a few blocks with few first-touch faults
 * rather than in thousands of small ones; small arenas keep their block
 * size, and at most a quarter of a large one's memory lies unused in its
 * newest block.
 */
#ifndef SPANCAST_BASE_ARENA_H
#define SPANCAST_BASE_ARENA_H

#include <stddef.h>
#include <stdint.h>

#define ARENA_GROW_FROM ((size_t)16 << 20)
#define ARENA_GROW_MAX ((size_t)64 << 20)

typedef struct arena_block arena_block;

/* A block: the header, then size usable bytes. Visible here only so that
 * arena_alloc's common case (the request fits in the block being filled)
 * can be inlined into the render loop's callers. */
struct arena_block {
    arena_block *next;
    size_t size; /* usable bytes after the header */
    _Alignas(16) unsigned char data[];
};

enum { ARENA_ALIGN = 16 };

typedef struct arena {
    arena_block *head;     /* block being filled */
    arena_block *first;    /* first block: blocks form a list kept across resets */
    size_t block_size;     /* minimum size of a new block */
    size_t used;           /* bytes handed out in head */
    uint64_t block_allocs; /* malloc calls made, for the no-malloc-in-loop check */
    size_t owned;          /* bytes in all blocks */
    arena_block *adopted;  /* blocks taken from other arenas (arena_adopt):
                              freed with this one, never reused */
} arena;

void arena_init(arena *a, size_t block_size);
/* Frees every block. */
void arena_free(arena *a);
/* Moves every block of from into a, whose allocations they stay: they
 * are freed with a and never handed out again (a reset keeps them full).
 * from is then empty, as after arena_init with its block size. A model
 * lowered in two parts takes the second part's memory this way. */
void arena_adopt(arena *a, arena *from);
/* Forgets every allocation but keeps the blocks for reuse. */
void arena_reset(arena *a);
/* arena_alloc's general case: a request of no size or of a huge one, or
 * one that needs the next block (or a new one). */
void *arena_alloc_slow(arena *a, size_t size);

/* Returns size bytes aligned to 16, or NULL when out of memory. The common
 * case, a request of 1 byte to 1 GiB that fits in the block being filled,
 * is a bump of a->used here; every other goes to arena_alloc_slow, which
 * checks the size arithmetic (rounding the size below 1 GiB up to 16
 * cannot overflow). */
static inline void *arena_alloc(arena *a, size_t size)
{
    arena_block *h = a->head;
    size_t rounded = (size + ARENA_ALIGN - 1) & ~(size_t)(ARENA_ALIGN - 1);
    if (h && size - 1 < ((size_t)1 << 30) && h->size - a->used >= rounded) {
        void *p = h->data + a->used;
        a->used += rounded;
        return p;
    }
    return arena_alloc_slow(a, size);
}
/* Returns count * size bytes (zeroed), NULL on overflow or out of memory. */
void *arena_calloc(arena *a, size_t count, size_t size);

/* Saves and restores the allocation point, to free a temporary tail. */
typedef struct arena_mark {
    arena_block *block;
    size_t used;
} arena_mark;

/* Inline: the render loop saves and restores around every operand. */
static inline arena_mark arena_save(const arena *a)
{
    arena_mark m = {a->head, a->used};
    return m;
}

static inline void arena_restore(arena *a, arena_mark mark)
{
    a->head = mark.block;
    a->used = mark.used;
}

#endif
