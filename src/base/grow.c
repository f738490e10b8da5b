/* Growable arrays: see grow.h. */
#include "base/grow.h"

#include <stdlib.h>

/* Reallocates *array to n items of elem bytes; 0 on failure. */
static int resize(void **array, uint64_t n, size_t elem)
{
    if (n > SIZE_MAX / elem)
        return 0;
    void *p = realloc(*array, (size_t)n * elem);
    if (!p)
        return 0;
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
    if (!n || !resize(array, n, elem))
        return 0;
    *cap = (size_t)n;
    return 1;
}

int grow_array32(void **array, uint32_t *cap, uint32_t need, size_t elem)
{
    if (need <= *cap)
        return 1;
    uint64_t n = next_capacity(*cap, need, UINT32_MAX - 1);
    if (!n || !resize(array, n, elem))
        return 0;
    *cap = (uint32_t)n;
    return 1;
}
