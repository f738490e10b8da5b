/* Radix sort of 64-bit keys: see sort.h. */
#include "base/sort.h"

#include <stdlib.h>
#include <string.h>

enum { FEW = 32, SMALL = 65536 };

/* Sorts n keys in place by insertion (a few keys). */
static void insertion_sort(uint64_t *keys, size_t n)
{
    for (size_t i = 1; i < n; i++) {
        uint64_t key = keys[i];
        size_t j = i;
        for (; j > 0 && keys[j - 1] > key; j--)
            keys[j] = keys[j - 1];
        keys[j] = key;
    }
}

int sort_u64(uint64_t *keys, size_t n)
{
    if (n <= FEW) {
        insertion_sort(keys, n);
        return 1;
    }
    /* 16-bit digits for many keys, 8-bit ones below SMALL, whose
     * histograms (2 MB against 16 KB) would cost more than the keys */
    unsigned bits = n < SMALL ? 8 : 16, digits = 64 / bits;
    size_t buckets = (size_t)1 << bits, mask = buckets - 1;
    uint64_t *other = malloc(n * sizeof *other);
    size_t *count = calloc(digits * buckets, sizeof *count);
    if (!other || !count) {
        free(other);
        free(count);
        return 0;
    }
    /* every digit's histogram in one pass over the keys */
    for (size_t i = 0; i < n; i++)
        for (unsigned d = 0; d < digits; d++)
            count[d * buckets + (keys[i] >> (d * bits) & mask)]++;
    uint64_t *from = keys, *to = other;
    for (unsigned d = 0; d < digits; d++) {
        size_t *c = &count[d * buckets];
        unsigned shift = d * bits;
        if (c[from[0] >> shift & mask] == n)
            continue; /* one digit for all: this pass would move nothing */
        size_t start = 0;
        for (size_t b = 0; b < buckets; b++) {
            size_t k = c[b];
            c[b] = start;
            start += k;
        }
        for (size_t i = 0; i < n; i++)
            to[c[from[i] >> shift & mask]++] = from[i];
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
