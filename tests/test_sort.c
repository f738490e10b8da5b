/* Tests of the radix sort of 64-bit keys (src/base/sort.c) against qsort,
 * on the key shapes the builders sort: packed pairs of small point
 * indices (whose high digits are all the same, so their passes are
 * skipped), full 64-bit keys, repeats, sorted and reversed runs, and the
 * sizes 0, 1 and 2; and every size each way of sorting takes (insertion
 * for a few keys, 8-bit digits below 65,536, 16-bit ones from there).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>

#include <cmocka.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "base/sort.h"

static int compare(const void *a, const void *b)
{
    uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
    return x < y ? -1 : x > y;
}

static uint64_t state = 0x9e3779b97f4a7c15u;

static uint64_t next(void) /* splitmix64 */
{
    uint64_t z = (state += 0x9e3779b97f4a7c15u);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
    return z ^ (z >> 31);
}

/* Sorts keys both ways and compares the results. */
static void check(const uint64_t *keys, size_t n)
{
    uint64_t *a = malloc((n ? n : 1) * sizeof *a), *b = malloc((n ? n : 1) * sizeof *b);
    assert_non_null(a);
    assert_non_null(b);
    if (n) {
        memcpy(a, keys, n * sizeof *a);
        memcpy(b, keys, n * sizeof *b);
    }
    assert_int_equal(sort_u64(a, n), 1);
    qsort(b, n, sizeof *b, compare);
    if (n)
        assert_memory_equal(a, b, n * sizeof *a);
    free(a);
    free(b);
}

static void test_shapes(void **unused)
{
    (void)unused;
    enum { N = 100000 };
    uint64_t *k = malloc(N * sizeof *k);
    assert_non_null(k);
    for (size_t n = 0; n < 3; n++) {
        for (size_t i = 0; i < n; i++)
            k[i] = next();
        check(k, n);
    }
    for (size_t i = 0; i < N; i++) /* full keys */
        k[i] = next();
    check(k, N);
    for (size_t i = 0; i < N; i++) { /* edges of a mesh of 30000 points */
        uint64_t p = next() % 30000, q = next() % 30000;
        k[i] = p << 32 | q;
    }
    check(k, N);
    for (size_t i = 0; i < N; i++) /* few values, many repeats */
        k[i] = next() % 7 << 48;
    check(k, N);
    for (size_t i = 0; i < N; i++) /* all equal */
        k[i] = 42;
    check(k, N);
    for (size_t i = 0; i < N; i++) /* sorted, then reversed */
        k[i] = (uint64_t)i * 0x10001u;
    check(k, N);
    for (size_t i = 0; i < N; i++)
        k[i] = (uint64_t)(N - i) << 40 | i;
    check(k, N);
    free(k);
}

/* The sizes around each change of method, each with full keys, packed
 * index pairs and repeats. */
static void test_sizes(void **unused)
{
    (void)unused;
    static const size_t sizes[] = {3,  15,  16,   17,    31,    32,
                                   33, 100, 1000, 65535, 65536, 65537};
    uint64_t *k = malloc(65537 * sizeof *k);
    assert_non_null(k);
    for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; s++) {
        size_t n = sizes[s];
        for (size_t i = 0; i < n; i++)
            k[i] = next();
        check(k, n);
        for (size_t i = 0; i < n; i++)
            k[i] = (next() % 300) << 32 | next() % 300;
        check(k, n);
        for (size_t i = 0; i < n; i++)
            k[i] = next() % 3;
        check(k, n);
        for (size_t i = 0; i < n; i++)
            k[i] = (uint64_t)(n - i);
        check(k, n);
    }
    free(k);
}

int main(void)
{
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_shapes),
                                       cmocka_unit_test(test_sizes)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
