/* Growable arrays: see grow.h. */
#include "base/grow.h"

#include <stdlib.h>
#include <string.h>

#include "base/mem.h"

/* Reallocates *array of old items to n items of elem bytes; 0 on
 * failure. A large array is advised for huge pages (mem_advise_huge). One
 * that becomes large here moves into a new buffer advised before the copy:
 * realloc would copy it into fresh 4 KiB pages first, one fault each. One
 * that is large already grows by realloc, which moves a block with a
 * mapping of its own by remapping it, its pages kept, instead of copying
 * it into fresh ones (the advice covers the whole mapping, which keeps it
 * whole: mem_advise_huge). */
static int resize(void **array, uint64_t old, uint64_t n, size_t elem)
{
    if (n > SIZE_MAX / elem)
        return 0;
    size_t bytes = (size_t)n * elem;
    if (bytes < MEM_HUGE_MIN || !*array || (size_t)old * elem >= MEM_HUGE_MIN) {
        void *p = realloc(*array, bytes);
        if (!p)
            return 0;
        mem_advise_huge(p, bytes);
        *array = p;
        return 1;
    }
    void *p = malloc(bytes);
    if (!p)
        return 0;
    mem_advise_huge(p, bytes);
    memcpy(p, *array, (size_t)old * elem); /* old < n: no overflow */
    free(*array);
    *array = p;
    return 1;
}

/* The doubled capacity that holds need, or 0 past limit. */
static uint64_t next_capacity(uint64_t cap, uint64_t need, uint64_t limit)
{
    uint64_t n = cap ? cap : 16;
    while (n < need) {
        if (n > limit / 2)
            return need <= limit ? limit : 0;
        n *= 2;
    }
    return n <= limit ? n : need <= limit ? limit : 0;
}

int grow_array(void **array, size_t *cap, size_t need, size_t elem)
{
    if (need <= *cap)
        return 1;
    uint64_t n = next_capacity(*cap, need, SIZE_MAX);
    if (!n || !resize(array, *cap, n, elem))
        return 0;
    *cap = (size_t)n;
    return 1;
}

int grow_array32(void **array, uint32_t *cap, uint32_t need, size_t elem)
{
    if (need <= *cap)
        return 1;
    uint64_t n = next_capacity(*cap, need, UINT32_MAX - 1);
    if (!n || !resize(array, *cap, n, elem))
        return 0;
    *cap = (uint32_t)n;
    return 1;
}
