// What the CGAL plugin's entry points share (nef.h): each runs its work
// through guarded, so that nothing is thrown across the C boundary.
#ifndef SPANCAST_BUILD_CGAL_GUARDED_H
#define SPANCAST_BUILD_CGAL_GUARDED_H

#include <cstdio>
#include <mutex>
#include <new>
#include <stdexcept>

#include "build/nef.h"

// The lock every entry point holds while it runs. The plugin is built
// without CGAL's own thread safety (CGAL_HAS_NO_THREADS: its lazy exact
// numbers otherwise take a call_once, a futex, at every exact evaluation,
// which with CGAL's assertions on doubled the time of a boolean), so two
// threads that load models at once take turns here instead.
std::mutex &spancast_cgal_lock();

namespace
{

// A mesh that does not bound a volume: NEF_BAD_MESH.
struct bad_mesh : std::runtime_error {
    using std::runtime_error::runtime_error;
};

inline nef_status fail(nef_status status, const char *what, char *err, size_t err_size)
{
    std::snprintf(err, err_size, "%.400s", what);
    return status;
}

// Runs f, turning what it throws into a status.
template <class F> nef_status guarded(F f, char *err, size_t err_size)
{
    std::lock_guard<std::mutex> hold(spancast_cgal_lock());
    try {
        f();
        return NEF_OK;
    } catch (const bad_mesh &e) {
        return fail(NEF_BAD_MESH, e.what(), err, err_size);
    } catch (const std::bad_alloc &) {
        return fail(NEF_NOMEM, "out of memory", err, err_size);
    } catch (const std::exception &e) {
        return fail(NEF_FAILED, e.what(), err, err_size);
    } catch (...) {
        return fail(NEF_FAILED, "unknown failure", err, err_size);
    }
}

} // namespace

#endif
