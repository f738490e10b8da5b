/* Counting first touches of memory, for the tests that check that a
 * buffer's pages are reused (test_csg.c, test_grow.c). The includer
 * defines _DEFAULT_SOURCE (getrusage) before any header. */
#ifndef SPANCAST_TESTS_TEST_FAULTS_H
#define SPANCAST_TESTS_TEST_FAULTS_H

#include <sys/resource.h>
#if defined(__linux__)
#include <sys/prctl.h>
#endif

/* Faults of first touch (minor page faults) of the process so far. */
static inline long test_minor_faults(void)
{
    struct rusage u;
    return getrusage(RUSAGE_SELF, &u) == 0 ? u.ru_minflt : 0;
}

/* Turns transparent huge pages off for this process, so that a fault is
 * one 4 KiB page: 1, or 0 where that cannot be done (and faults are not
 * counted). */
static inline int test_huge_pages_off(void)
{
#if defined(__linux__)
    return prctl(PR_SET_THP_DISABLE, 1, 0, 0, 0) == 0;
#else
    return 0;
#endif
}

/* Turns them on again after test_huge_pages_off returned off. */
static inline void test_huge_pages_on(int off)
{
#if defined(__linux__)
    if (off)
        assert_int_equal(prctl(PR_SET_THP_DISABLE, 0, 0, 0, 0), 0);
#else
    (void)off;
#endif
}

#endif
