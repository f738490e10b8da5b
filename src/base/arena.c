/* Bump-pointer arenas: see arena.h. Blocks form a singly linked list; a reset
 * rewinds to the first block and later allocations walk forward through the
 * blocks already owned before asking malloc for a new one. */
#include "base/arena.h"

#include <stdlib.h>
#include <string.h>

#include "base/mem.h"

void arena_init(arena *a, size_t block_size)
{
    memset(a, 0, sizeof *a);
    a->block_size = block_size ? block_size : 64 * 1024;
}

static void free_blocks(arena_block *b)
{
    while (b) {
        arena_block *next = b->next;
        free(b);
        b = next;
    }
}

void arena_free(arena *a)
{
    free_blocks(a->first);
    free_blocks(a->adopted);
    a->first = a->head = a->adopted = NULL;
    a->used = 0;
    a->owned = 0;
}

static void append_blocks(arena_block **list, arena_block *blocks)
{
    while (*list)
        list = &(*list)->next;
    *list = blocks;
}

void arena_adopt(arena *a, arena *from)
{
    append_blocks(&a->adopted, from->first);
    append_blocks(&a->adopted, from->adopted);
    a->owned += from->owned;
    a->block_allocs += from->block_allocs;
    arena_init(from, from->block_size);
}

void arena_reset(arena *a)
{
    a->head = a->first;
    a->used = 0;
}

void *arena_alloc_slow(arena *a, size_t size)
{
    if (size > SIZE_MAX - ARENA_ALIGN)
        return NULL;
    size = (size + ARENA_ALIGN - 1) & ~(size_t)(ARENA_ALIGN - 1);
    if (size == 0)
        size = ARENA_ALIGN;
    if (!a->head && a->first) {
        a->head = a->first;
        a->used = 0;
    }
    while (a->head) {
        if (a->head->size - a->used >= size) {
            void *p = a->head->data + a->used;
            a->used += size;
            return p;
        }
        if (!a->head->next)
            break;
        a->head = a->head->next;
        a->used = 0;
    }
    /* A request larger than the usual block gets a block rounded up to a
     * multiple of 1/16 to 1/8 of its size (at most 12.5% more): a scratch
     * arena rewound with arena_restore then reuses it for the next requests
     * of a slightly larger size instead of asking malloc for one more block
     * just big enough (span lists that grow by a few spans each time made
     * as many blocks as requests, their total quadratic). */
    size_t block = a->block_size;
    if (a->owned >= ARENA_GROW_FROM) {
        size_t quarter = a->owned / 4;
        block = quarter > ARENA_GROW_MAX ? ARENA_GROW_MAX
                : quarter > block        ? quarter
                                         : block;
    }
    if (size > block) {
        size_t step = 1;
        while (step <= size / 16)
            step *= 2;
        size_t pad = (step - size % step) % step;
        block = pad <= SIZE_MAX - size ? size + pad : size;
    }
    if (block > SIZE_MAX - sizeof(arena_block))
        return NULL;
    arena_block *b = malloc(sizeof(arena_block) + block);
    if (!b)
        return NULL;
    a->block_allocs++;
    a->owned += block;
    b->size = block;
    mem_advise_huge(b->data, block);
    /* Insert after head so blocks already owned further on stay reachable. */
    if (a->head) {
        b->next = a->head->next;
        a->head->next = b;
    } else {
        b->next = a->first;
        a->first = b;
    }
    a->head = b;
    a->used = size;
    return b->data;
}

void *arena_calloc(arena *a, size_t count, size_t size)
{
    if (size && count > SIZE_MAX / size)
        return NULL;
    void *p = arena_alloc(a, count * size);
    if (p)
        memset(p, 0, count * size);
    return p;
}
