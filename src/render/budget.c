/* The memory a render needs, checked before anything is allocated.
 *
 * A render holds its buffers (the image, or the --region crop of it) whole
 * until they are written: colour and normal take 12 bytes a pixel, depth
 * and id 4, mask 1. Everything else (the tree, per-thread scratch arenas)
 * is small beside them at any size where the check matters. An image
 * larger than this allows is rendered tile by tile by the command line,
 * each tile a crop of its own. Allocating first and failing later is not good enough: on
 * Linux, malloc of an oversized buffer usually succeeds and the process is
 * killed when the pages are touched, far into the render. So the sum is
 * compared with a fixed limit, which makes the error the same on every
 * machine, and with the machine's physical memory (sysconf), which catches
 * the smaller machines.
 */
#define _DEFAULT_SOURCE /* sysconf(_SC_PHYS_PAGES) */

#include <stdint.h>
#include <unistd.h>

#include "base/error.h"
#include "render/render.h"

/* Checks, before anything is allocated, that the buffers options ask for
 * fit in RENDER_MAX_MEMORY_GIB and in the machine's physical memory, so that
 * a huge image is a clear error rather than an out-of-memory kill. The
 * sizes cannot overflow: at most 2^36 pixels of 33 bytes. */
sc_status render_check_memory(const sc_render_options *o, sc_error *error)
{
    uint64_t per_pixel = (o->want_color ? 3 * sizeof(float) : 0) +
                         (o->want_depth ? sizeof(float) : 0) + (o->want_mask ? 1 : 0) +
                         (o->want_normal ? 3 * sizeof(float) : 0) +
                         (o->want_id ? sizeof(int32_t) : 0);
    uint64_t bytes = (uint64_t)o->width * (uint64_t)o->height * per_pixel;
    double gib = (double)bytes / (1024.0 * 1024.0 * 1024.0);
    if (bytes > (uint64_t)RENDER_MAX_MEMORY_GIB << 30)
        return err_set(error, SC_ERR_LIMIT, NULL,
                       "a %dx%d render needs %.1f GiB of image buffers (limit is %d GiB)",
                       o->width, o->height, gib, RENDER_MAX_MEMORY_GIB);
    long pages = sysconf(_SC_PHYS_PAGES), page_size = sysconf(_SC_PAGESIZE);
    if (pages > 0 && page_size > 0 && bytes > (uint64_t)pages * (uint64_t)page_size)
        return err_set(error, SC_ERR_LIMIT, NULL,
                       "a %dx%d render needs %.1f GiB of image buffers, more than this "
                       "machine's %.1f GiB of memory",
                       o->width, o->height, gib,
                       (double)pages * (double)page_size / (1024.0 * 1024.0 * 1024.0));
    return SC_OK;
}
