/* Reading the public calls' sized options: see options.h. The minimum
 * sizes are the structs as the ABI was first recorded (abi/); fields
 * appended since are the ones an older caller's struct ends before. */
#include "api/options.h"

#include <omp.h>
#include <stddef.h>

#include "base/error.h"
#include "base/sized.h"
#include "build/build.h"

sc_status options_load(const sc_load_options *in, sc_load_options *out, sc_error *error)
{
    sc_load_options_init(out);
    if (!in)
        return SC_OK;
    sc_status st = sized_read(out, sizeof *out, in, SIZED_MIN(sc_load_options, faithful),
                              "sc_load_options", error);
    if (st == SC_OK && out->threads < 0)
        return err_set(error, SC_ERR_ARGUMENT, NULL,
                       "thread count must not be negative (got %d)", out->threads);
    return st;
}

sc_status options_measure(const sc_measure_options *in, sc_measure_options *out,
                          sc_error *error)
{
    sc_measure_options_init(out);
    if (!in)
        return SC_OK;
    return sized_read(out, sizeof *out, in, SIZED_MIN(sc_measure_options, cancel),
                      "sc_measure_options", error);
}

sc_status options_ray_query(const sc_ray_query *in, sc_ray_query *out, sc_error *error)
{
    sc_ray_query_init(out);
    if (!in)
        return SC_OK;
    return sized_read(out, sizeof *out, in, SIZED_MIN(sc_ray_query, both_ways),
                      "sc_ray_query", error);
}

int options_threads_begin(int threads)
{
    if (threads <= 0)
        return 0;
    int saved = omp_get_max_threads();
    omp_set_num_threads(threads);
    return saved;
}

int options_thread_count(int threads)
{
    return threads > 0 ? threads : omp_get_max_threads();
}

void options_threads_end(int saved)
{
    if (saved > 0)
        omp_set_num_threads(saved);
}

int options_build_flags(const sc_load_options *o)
{
    return (o->faithful ? BUILD_FAITHFUL : 0) | (o->strict ? BUILD_STRICT : 0) |
           (o->no_preview ? BUILD_NO_PREVIEW : 0);
}
