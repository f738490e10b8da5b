/* The process's memory limit: see mem.h. */
#define _DEFAULT_SOURCE /* getrlimit, madvise, sysconf */

#include "base/mem.h"

#include <pthread.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/resource.h>
#include <unistd.h>

#include "base/error.h"

uint64_t mem_limit(void)
{
    struct rlimit r;
    if (getrlimit(RLIMIT_DATA, &r) != 0 || r.rlim_cur == RLIM_INFINITY)
        return 0;
    return (uint64_t)r.rlim_cur;
}

uint64_t mem_in_use(void)
{
    FILE *f = fopen("/proc/self/status", "r");
    if (!f)
        return 0;
    char line[256];
    unsigned long long kib = 0;
    while (fgets(line, sizeof line, f))
        if (sscanf(line, "VmData: %llu kB", &kib) == 1)
            break;
    fclose(f);
    return (uint64_t)kib * 1024;
}

/* The system's page size (4096 when it will not say). */
static inline uintptr_t page_size(void)
{
    long size = sysconf(_SC_PAGESIZE);
    return size > 0 ? (uintptr_t)size : 4096;
}

void mem_advise_huge(void *p, size_t bytes)
{
#ifdef MADV_HUGEPAGE
    if (!p || bytes < MEM_HUGE_MIN)
        return;
    uintptr_t page = page_size();
    uintptr_t start = (uintptr_t)p & ~(page - 1);
    uintptr_t end = ((uintptr_t)p + bytes + page - 1) & ~(page - 1);
    (void)madvise((void *)start, end - start, MADV_HUGEPAGE); /* advice only */
#else
    (void)p;
    (void)bytes;
#endif
}

struct mem_prefault {
    pthread_t thread;
    void *start;
    size_t length;
};

static void *prefault_main(void *arg)
{
#ifdef MADV_POPULATE_WRITE
    mem_prefault *f = arg;
    (void)madvise(f->start, f->length, MADV_POPULATE_WRITE); /* a hint: errors are moot */
#else
    (void)arg;
#endif
    return NULL;
}

mem_prefault *mem_prefault_start(void *p, size_t bytes)
{
#ifdef MADV_POPULATE_WRITE
    uintptr_t page = page_size();
    uintptr_t start = ((uintptr_t)p + page - 1) & ~(page - 1);
    uintptr_t end = ((uintptr_t)p + bytes) & ~(page - 1);
    if (!p || bytes < MEM_HUGE_MIN || end <= start)
        return NULL;
    mem_prefault *f = malloc(sizeof *f);
    if (!f)
        return NULL;
    f->start = (void *)start;
    f->length = end - start;
    if (pthread_create(&f->thread, NULL, prefault_main, f) != 0) {
        free(f);
        return NULL;
    }
    return f;
#else
    (void)p;
    (void)bytes;
    return NULL;
#endif
}

void mem_prefault_end(mem_prefault *f)
{
    if (!f)
        return;
    pthread_join(f->thread, NULL);
    free(f);
}

const char *mem_format(uint64_t bytes, char *buf, int n)
{
    double b = (double)bytes;
    if (b >= 1024.0 * 1024 * 1024)
        snprintf(buf, (size_t)n, "%.1f GiB", b / (1024.0 * 1024 * 1024));
    else if (b >= 1024.0 * 1024)
        snprintf(buf, (size_t)n, "%.1f MiB", b / (1024.0 * 1024));
    else
        snprintf(buf, (size_t)n, "%.1f KiB", b / 1024.0);
    return buf;
}

sc_status mem_reserve(uint64_t bytes, const char *who, const char *what, sc_error *error)
{
    uint64_t limit = mem_limit();
    if (!limit)
        return SC_OK;
    uint64_t used = mem_in_use();
    if (used <= limit && bytes <= limit - used)
        return SC_OK;
    char need[32], lim[32], in_use[32];
    return err_set(error, SC_ERR_LIMIT, NULL,
                   "%s needs %s for %s, more than the memory limit of %s leaves (%s in "
                   "use)",
                   who, mem_format(bytes, need, sizeof need), what,
                   mem_format(limit, lim, sizeof lim),
                   mem_format(used, in_use, sizeof in_use));
}

void mem_blame(sc_error *error, const char *what)
{
    uint64_t limit = mem_limit();
    if (!limit || !error || error->status != SC_ERR_NOMEM || error->line > 0)
        return;
    char lim[32];
    err_set(error, SC_ERR_NOMEM, NULL,
            "%s ran out of memory: the memory limit of %s is reached", what,
            mem_format(limit, lim, sizeof lim));
}
