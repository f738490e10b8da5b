/* Radix sort of 64-bit keys: see sort.h. */
#include "base/sort.h"

#include <stdlib.h>
#include <string.h>

enum { DIGIT_BITS = 16, DIGITS = 64 / DIGIT_BITS, BUCKETS = 1 << DIGIT_BITS };

int sort_u64(uint64_t *keys, size_t n)
{
    if (n < 2)
        return 1;
    uint64_t *other = malloc(n * sizeof *other);
    size_t *count = malloc((size_t)DIGITS * BUCKETS * sizeof *count);
    if (!other || !count) {
        free(other);
        free(count);
        return 0;
    }
    /* every digit's histogram in one pass over the keys */
    memset(count, 0, (size_t)DIGITS * BUCKETS * sizeof *count);
    for (size_t i = 0; i < n; i++)
        for (int d = 0; d < DIGITS; d++)
            count[d * BUCKETS + (keys[i] >> (d * DIGIT_BITS) & (BUCKETS - 1))]++;
    uint64_t *from = keys, *to = other;
    for (int d = 0; d < DIGITS; d++) {
        size_t *c = &count[d * BUCKETS];
        unsigned shift = (unsigned)(d * DIGIT_BITS);
        if (c[from[0] >> shift & (BUCKETS - 1)] == n)
            continue; /* one digit for all: this pass would move nothing */
        size_t start = 0;
        for (size_t b = 0; b < BUCKETS; b++) {
            size_t k = c[b];
            c[b] = start;
            start += k;
        }
        for (size_t i = 0; i < n; i++)
            to[c[from[i] >> shift & (BUCKETS - 1)]++] = from[i];
        uint64_t *t = from;
        from = to;
        to = t;
    }
    if (from != keys)
        memcpy(keys, from, n * sizeof *keys);
    free(other);
    free(count);
    return 1;
}
