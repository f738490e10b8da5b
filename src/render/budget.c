/* The memory and the work a render may take, and the errors of both.
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
 *
 * Work: implicit surfaces are the one kind of leaf whose cost per ray the
 * input decides (a field of frequency 1e118 is undecided at every scale,
 * and the root finder bisects it until its bound of SOLVE_MAX_EVALS per
 * ray). Two limits keep a render finite: that bound per ray, which is
 * an error rather than a silently truncated ray, and a budget for the
 * render as a whole, proportional to its rays: RENDER_MIN_IMPLICIT_EVALS
 * up front, and RENDER_IMPLICIT_EVALS_PER_RAY more for each camera ray,
 * edge neighbour and ambient occlusion ray of each pixel sample done
 * (shadow, reflection and refraction rays share that allowance), credited
 * as each row of a tile is done. Since the credit comes as pixels are
 * done, a field that costs more than the
 * average fails after the allowance, within a second, at any image size. A smooth field
 * needs tens to a few thousand evaluations a ray (docs/limits.md), so only a field that
 * is unresolvable at the image's scale meets either limit.
 */
#define _DEFAULT_SOURCE /* sysconf(_SC_PHYS_PAGES) */

#include <stdint.h>
#include <stdio.h>
#include <unistd.h>

#include "base/cancel.h"
#include "base/error.h"
#include "base/mem.h"
#include "implicit/solve.h"
#include "render/render.h"

/* Checks, before anything is allocated, that the buffers options ask for
 * fit in RENDER_MAX_MEMORY_GIB, in what the process's memory limit leaves
 * (base/mem.h) and in the machine's physical memory, so that
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
    char who[48];
    snprintf(who, sizeof who, "a %dx%d render", o->width, o->height);
    sc_status st = mem_reserve(bytes, who, "its image buffers", error);
    if (st != SC_OK)
        return st;
    long pages = sysconf(_SC_PHYS_PAGES), page_size = sysconf(_SC_PAGESIZE);
    if (pages > 0 && page_size > 0 && bytes > (uint64_t)pages * (uint64_t)page_size)
        return err_set(error, SC_ERR_LIMIT, NULL,
                       "a %dx%d render needs %.1f GiB of image buffers, more than this "
                       "machine's %.1f GiB of memory",
                       o->width, o->height, gib,
                       (double)pages * (double)page_size / (1024.0 * 1024.0 * 1024.0));
    return SC_OK;
}

uint64_t render_work_credit(const sc_render_options *o)
{
    uint64_t rays = 1 + (o->view & SC_VIEW_EDGES ? 8 : 0) + (uint64_t)o->ao_samples;
    return rays * (uint64_t)o->spp * RENDER_IMPLICIT_EVALS_PER_RAY; /* < 2^39 */
}

sc_status render_limit_error(const csg_tree *tree, int reason, uint32_t leaf,
                             const void *prim, sc_error *error)
{
    const sc_location *loc = NULL;
    if (tree && leaf < tree->leaf_count && &tree->leaves[leaf].prim == prim &&
        tree->leaves[leaf].loc.line > 0)
        loc = &tree->leaves[leaf].loc;
    if (reason == CANCEL_RAY_LIMIT)
        return err_set(
            error, SC_ERR_LIMIT, loc,
            "implicit surface needs more than %u evaluations per ray (limit is "
            "%u; the field is not resolvable at this scale)",
            SOLVE_MAX_EVALS, SOLVE_MAX_EVALS);
    return err_set(error, SC_ERR_LIMIT, loc,
                   "implicit surfaces need more than %u evaluations per ray on average "
                   "(limit is %u, after the first %u)",
                   RENDER_IMPLICIT_EVALS_PER_RAY, RENDER_IMPLICIT_EVALS_PER_RAY,
                   RENDER_MIN_IMPLICIT_EVALS);
}

sc_status render_stop_error(const csg_tree *tree, cancel_token *token, sc_error *error)
{
    cancel_reason reason = cancel_check(token);
    if (reason == CANCEL_RAY_LIMIT || reason == CANCEL_BUDGET)
        return render_limit_error(tree, (int)reason, atomic_load(&token->leaf),
                                  atomic_load(&token->prim), error);
    return err_set(error, SC_ERR_CANCELLED, NULL, "interrupted");
}
