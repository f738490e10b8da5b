/* Tests of the growable arrays (src/base/grow.c) and of the huge-page
 * advice their large arrays get (mem_advise_huge in src/base/mem.c): an
 * array that grows past MEM_HUGE_MIN moves to a new buffer and keeps every
 * item, a failed growth leaves the array as it was, and on a Linux kernel
 * with transparent huge pages the large buffer's mapping carries the
 * advice (the "hg" flag of /proc/self/smaps), while a buffer so advised
 * can still be moved by remapping, its pages kept.
 */
#define _DEFAULT_SOURCE /* getrusage */

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>

#include <cmocka.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/grow.h"
#include "base/mem.h"
#include "test_faults.h"
#include "test_util.h"

#include <sys/mman.h>
#include <unistd.h>

/* Items appended one at a time, past MEM_HUGE_MIN bytes (3 Mi items of 8
 * bytes is 24 MiB), all kept through every move. */
static void test_grow_keeps_items(void **state)
{
    (void)state;
    uint64_t *v = NULL;
    size_t cap = 0, n = (size_t)3 << 20;
    for (size_t i = 0; i < n; i++) {
        assert_int_equal(grow_array((void **)&v, &cap, i + 1, sizeof *v), 1);
        v[i] = (uint64_t)i * 2654435761u;
    }
    assert_true(cap >= n && cap < 2 * n);
    assert_true(cap * sizeof *v >= MEM_HUGE_MIN);
    for (size_t i = 0; i < n; i++)
        assert_true(v[i] == (uint64_t)i * 2654435761u);
    free(v);

    uint32_t *w = NULL;
    uint32_t cap32 = 0, n32 = (uint32_t)5 << 20;
    for (uint32_t i = 0; i < n32; i++) {
        assert_int_equal(grow_array32((void **)&w, &cap32, i + 1, sizeof *w), 1);
        w[i] = ~i;
    }
    for (uint32_t i = 0; i < n32; i++)
        assert_true(w[i] == ~i);
    free(w);
}

/* A growth whose size overflows fails and leaves array and capacity. */
static void test_grow_failure_keeps_array(void **state)
{
    (void)state;
    double *v = NULL;
    size_t cap = 0;
    assert_int_equal(grow_array((void **)&v, &cap, 3, sizeof *v), 1);
    v[0] = 1.5;
    double *before = v;
    size_t cap_before = cap;
    assert_int_equal(grow_array((void **)&v, &cap, SIZE_MAX / 4, sizeof *v), 0);
    assert_ptr_equal(v, before);
    assert_int_equal(cap, cap_before);
    assert_true(v[0] == 1.5);
    free(v);
}

/* The VmFlags line of the mapping of /proc/self/smaps that holds addr,
 * copied into flags (size n); 0 when there is none. */
static int mapping_flags(uintptr_t addr, char *flags, size_t n)
{
    FILE *f = fopen("/proc/self/smaps", "r");
    if (!f)
        return 0;
    char line[512];
    int inside = 0, found = 0;
    while (fgets(line, sizeof line, f)) {
        unsigned long lo, hi;
        if (sscanf(line, "%lx-%lx ", &lo, &hi) == 2) { /* a mapping's first line */
            inside = addr >= lo && addr < hi;
        } else if (inside && strncmp(line, "VmFlags:", 8) == 0) {
            snprintf(flags, n, "%s", line + 8);
            found = 1;
            break;
        }
    }
    fclose(f);
    return found;
}

/* Whether the kernel has transparent huge pages to advise. */
static int have_huge_pages(void)
{
    FILE *thp = fopen("/sys/kernel/mm/transparent_hugepage/enabled", "r");
    if (!thp)
        return 0;
    fclose(thp);
    return 1;
}

/* A large grown array lies in a mapping advised for huge pages (run only
 * where the kernel has them); small ones are left alone. */
static void test_large_array_advised(void **state)
{
    (void)state;
    unsigned char *v = NULL;
    size_t cap = 0, n = (size_t)32 << 20;
    assert_int_equal(grow_array((void **)&v, &cap, 1, 1), 1);
    assert_int_equal(grow_array((void **)&v, &cap, n, 1), 1);
    memset(v, 7, n);
    char flags[512];
    assert_int_equal(mapping_flags((uintptr_t)(v + n / 2), flags, sizeof flags), 1);
    assert_non_null(strstr(flags, " hg"));
    free(v);

    /* Advice on a small or missing buffer is nothing at all. */
    char small[64];
    mem_advise_huge(small, sizeof small);
    mem_advise_huge(NULL, MEM_HUGE_MIN);
}

/* After a buffer of n bytes grew to 2n and all of it was written: the
 * faults (counted with huge pages off, when counted) cover about the new
 * half. AddressSanitizer's realloc always copies: there only the contents
 * are checked. */
static void check_new_half_faulted(long faults, size_t n, size_t page, int counted)
{
    test_huge_pages_on(counted);
#if defined(__GLIBC__) && !defined(__SANITIZE_ADDRESS__)
    assert_true(counted);
    long pages = (long)(2 * n / page);
    assert_true(faults > pages / 4);     /* the new half is fresh */
    assert_true(faults < pages * 3 / 4); /* the old half is not */
#else
    (void)faults;
    (void)n;
    (void)page;
    (void)counted;
#endif
}

/* A large buffer advised for huge pages and written keeps its pages when
 * realloc grows it: the C library moves a block this large by remapping
 * its mapping, which works only while the advice has not split the
 * mapping in parts. Growing 48 MiB to 96 MiB and writing all of it then
 * faults in about the new half (counted with huge pages off, one fault a
 * page); a copy into a new mapping faults in all of it. AddressSanitizer's
 * realloc always copies: there only the contents are checked. */
static void test_advised_buffer_remaps(void **state)
{
    (void)state;
    size_t n = (size_t)48 << 20, page = (size_t)sysconf(_SC_PAGESIZE);
    int counted = test_huge_pages_off();
    unsigned char *v = malloc(n);
    assert_non_null(v);
    mem_advise_huge(v, n);
    memset(v, 3, n);
    long before = test_minor_faults();
    unsigned char *w = realloc(v, 2 * n);
    assert_non_null(w);
    mem_advise_huge(w, 2 * n);
    for (size_t i = 0; i < n; i += page)
        assert_int_equal(w[i], 3);
    memset(w + n, 4, n);
    long faults = test_minor_faults() - before;
    free(w);
    check_new_half_faulted(faults, n, page, counted);
}

/* A grown array that is already large keeps its pages when it grows
 * again: grow_array moves it by remapping (as realloc does for a block
 * with a mapping of its own) rather than copying it into a new buffer.
 * Growing 48 MiB to 96 MiB and writing all of it faults in about the new
 * half (huge pages off, one fault a page). */
static void test_large_array_grows_in_place(void **state)
{
    (void)state;
    size_t n = (size_t)48 << 20, page = (size_t)sysconf(_SC_PAGESIZE);
    int counted = test_huge_pages_off();
    unsigned char *v = NULL;
    size_t cap = 0;
    assert_int_equal(grow_array((void **)&v, &cap, n, 1), 1);
    memset(v, 3, n);
    long before = test_minor_faults();
    assert_int_equal(grow_array((void **)&v, &cap, 2 * n, 1), 1);
    for (size_t i = 0; i < n; i += page)
        assert_int_equal(v[i], 3);
    memset(v + n, 4, n);
    long faults = test_minor_faults() - before;
    free(v);
    check_new_half_faulted(faults, n, page, counted);
}

/* mem_prefault: a range faulted in on a thread of its own while the
 * caller fills it keeps what the caller writes, and once it ends, the rest
 * of the range is resident, so writing it faults no more (counted with
 * huge pages off, one fault a page). Where the kernel lacks the advice
 * (before Linux 5.14), only the contents are checked. */
static void test_prefault(void **state)
{
    (void)state;
    size_t n = (size_t)32 << 20, page = (size_t)sysconf(_SC_PAGESIZE);
    int counted = test_huge_pages_off();
    unsigned char *v = malloc(n);
    assert_non_null(v);
    int advice = 0;
#ifdef MADV_POPULATE_WRITE
    advice = madvise((void *)(((uintptr_t)v + page - 1) & ~(uintptr_t)(page - 1)), page,
                     MADV_POPULATE_WRITE) == 0;
#endif
    mem_prefault *f = mem_prefault_start(v, n);
    for (size_t i = 0; i < n / 2; i++) /* meanwhile, the first half */
        v[i] = (unsigned char)(i * 7);
    mem_prefault_end(f);
    size_t pages = n / page;
    unsigned char *resident = malloc(pages + 1);
    assert_non_null(resident);
    uintptr_t second = ((uintptr_t)v + n / 2 + page - 1) & ~(uintptr_t)(page - 1);
    size_t second_pages = ((uintptr_t)v + n - second) / page;
    assert_int_equal(mincore((void *)second, second_pages * page, resident), 0);
    size_t in = 0;
    for (size_t i = 0; i < second_pages; i++)
        in += resident[i] & 1;
    long before = test_minor_faults();
    for (size_t i = n / 2; i < n; i++)
        v[i] = (unsigned char)(i * 7);
    long faults = test_minor_faults() - before;
    for (size_t i = 0; i < n; i++)
        if (v[i] != (unsigned char)(i * 7))
            fail_msg("byte %zu changed", i);
    test_huge_pages_on(counted);
    if (advice) {
        assert_int_equal(in, second_pages);
#if defined(__SANITIZE_ADDRESS__)
        (void)faults; /* its shadow's pages fault too */
#else
        if (counted)
            assert_true(faults < (long)second_pages / 16);
#endif
    }
    free(resident);
    free(v);
    /* Nothing to do: a small range, none at all. */
    char small[64];
    assert_null(mem_prefault_start(small, sizeof small));
    assert_null(mem_prefault_start(NULL, MEM_HUGE_MIN));
    mem_prefault_end(NULL);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_grow_keeps_items),
        cmocka_unit_test(test_grow_failure_keeps_array),
        cmocka_unit_test(test_advised_buffer_remaps),
        cmocka_unit_test(test_large_array_grows_in_place),
        cmocka_unit_test(test_prefault),
    };
    const struct CMUnitTest advised[] = {
        cmocka_unit_test(test_large_array_advised),
    };
    int failed = cmocka_run_group_tests(tests, NULL, NULL);
    if (failed)
        return failed;
    if (!have_huge_pages()) {
        fprintf(stderr, "test_grow: no transparent huge pages: advice not tested\n");
        return 77; /* skipped */
    }
    return cmocka_run_group_tests(advised, NULL, NULL);
}
