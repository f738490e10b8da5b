// spancast-cgal.so: the only code that links CGAL, GMP and MPFR (nef.h).
//
// Solids are CGAL Nef polyhedra over the exact-constructions kernel, as
// OpenSCAD 2021.01 builds the booleans under a hull() or minkowski(): a
// polygon mesh becomes a surface mesh (points at one position merged, faces
// triangulated, oriented outward) and then a Nef polyhedron; booleans are
// Nef's; hull() takes every vertex of the result (OpenSCAD's applyHull);
// minkowski() takes the vertices of each volume of CGAL's convex
// decomposition (OpenSCAD's applyMinkowski). Coordinates are exact inside
// and rounded to doubles only on the way out, as OpenSCAD rounds them.
//
// Every entry point catches what CGAL throws (failed preconditions on a
// mesh that is not a valid solid, bad_alloc) and returns it as a status
// with a message.
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Nef_polyhedron_3.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/convert_nef_polyhedron_to_polygon_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/convex_decomposition_3.h>

#include <gmp.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <new>
#include <set>
#include <stdexcept>
#include <vector>

#include "build/nef.h"

namespace
{

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using Point = Kernel::Point_3;
using Nef = CGAL::Nef_polyhedron_3<Kernel>;
using Mesh = CGAL::Surface_mesh<Point>;
using Polyhedron = CGAL::Polyhedron_3<Kernel>;
namespace PMP = CGAL::Polygon_mesh_processing;

struct bad_mesh : std::runtime_error {
    using std::runtime_error::runtime_error;
};

nef_status fail(nef_status status, const char *what, char *err, size_t err_size)
{
    std::snprintf(err, err_size, "%.400s", what);
    return status;
}

// Runs f, turning what it throws into a status.
template <class F> nef_status guarded(F f, char *err, size_t err_size)
{
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

// GMP's own allocator aborts the process when memory runs out (under
// --max-memory, say). The plugin is GMP's only user in spancast, so from
// its loading on, GMP allocates through these, which throw bad_alloc
// instead: the entry points turn that into NEF_NOMEM and a clean error.
// (The exception crosses GMP's C frames, which carry unwind tables on
// every Debian architecture; what GMP had half built is lost, on a path
// that ends the load.)
void *gmp_allocate(size_t size)
{
    void *p = std::malloc(size);
    if (!p)
        throw std::bad_alloc();
    return p;
}

void *gmp_reallocate(void *old, size_t, size_t size)
{
    void *p = std::realloc(old, size);
    if (!p)
        throw std::bad_alloc();
    return p;
}

void gmp_release(void *p, size_t)
{
    std::free(p);
}

__attribute__((constructor)) void gmp_throwing_allocator()
{
    mp_set_memory_functions(gmp_allocate, gmp_reallocate, gmp_release);
}

// Copies point sets into a nef_parts (malloc'd arrays).
void to_parts(const std::vector<std::vector<Point>> &sets, nef_parts *out)
{
    size_t total = 0;
    for (const auto &s : sets)
        total += s.size();
    if (total > UINT32_MAX / 4 || sets.size() > UINT32_MAX / 4)
        throw std::runtime_error("too many points");
    double *points = static_cast<double *>(std::malloc((3 * total + 1) * sizeof *points));
    uint32_t *start =
        static_cast<uint32_t *>(std::malloc((sets.size() + 1) * sizeof *start));
    if (!points || !start) {
        std::free(points);
        std::free(start);
        throw std::bad_alloc();
    }
    size_t k = 0;
    start[0] = 0;
    for (size_t i = 0; i < sets.size(); i++) {
        for (const Point &p : sets[i]) {
            points[3 * k] = CGAL::to_double(p.x());
            points[3 * k + 1] = CGAL::to_double(p.y());
            points[3 * k + 2] = CGAL::to_double(p.z());
            k++;
        }
        start[i + 1] = static_cast<uint32_t>(k);
    }
    out->points = points;
    out->start = start;
    out->count = static_cast<uint32_t>(sets.size());
}

} // namespace

struct nef_solid {
    Nef nef;
};

extern "C" {

__attribute__((visibility("default"))) nef_status
spancast_nef_from_mesh(const double *points, uint32_t point_count,
                       const uint32_t *indices, const uint32_t *face_start,
                       uint32_t face_count, nef_solid **out, char *err, size_t err_size)
{
    *out = nullptr;
    return guarded(
        [&] {
            // Points at one position become one (a polyhedron may repeat
            // its corners per face).
            std::map<std::array<double, 3>, std::size_t> seen;
            std::vector<Point> unique;
            std::vector<std::size_t> index_of(point_count);
            for (uint32_t i = 0; i < point_count; i++) {
                std::array<double, 3> key = {points[3 * i], points[3 * i + 1],
                                             points[3 * i + 2]};
                auto found = seen.emplace(key, unique.size());
                if (found.second)
                    unique.emplace_back(key[0], key[1], key[2]);
                index_of[i] = found.first->second;
            }
            std::vector<std::vector<std::size_t>> polygons;
            for (uint32_t f = 0; f < face_count; f++) {
                std::vector<std::size_t> polygon;
                for (uint32_t i = face_start[f]; i < face_start[f + 1]; i++) {
                    if (indices[i] >= point_count)
                        throw bad_mesh("a face names a point that does not exist");
                    std::size_t k = index_of[indices[i]];
                    if (polygon.empty() || polygon.back() != k)
                        polygon.push_back(k);
                }
                while (polygon.size() > 1 && polygon.front() == polygon.back())
                    polygon.pop_back();
                if (std::set<std::size_t>(polygon.begin(), polygon.end()).size() >= 3)
                    polygons.push_back(std::move(polygon));
            }
            if (polygons.empty()) {
                *out = new nef_solid{Nef(Nef::EMPTY)};
                return;
            }
            PMP::orient_polygon_soup(unique, polygons);
            Mesh mesh;
            PMP::polygon_soup_to_polygon_mesh(unique, polygons, mesh);
            if (!CGAL::is_closed(mesh) || !CGAL::is_valid_polygon_mesh(mesh))
                throw bad_mesh("the mesh is not closed");
            PMP::triangulate_faces(mesh);
            if (!PMP::is_outward_oriented(mesh))
                PMP::reverse_face_orientations(mesh);
            *out = new nef_solid{Nef(mesh)};
        },
        err, err_size);
}

__attribute__((visibility("default"))) nef_status
spancast_nef_empty(nef_solid **out, char *err, size_t err_size)
{
    *out = nullptr;
    return guarded([&] { *out = new nef_solid{Nef(Nef::EMPTY)}; }, err, err_size);
}

__attribute__((visibility("default"))) nef_status
spancast_nef_apply(nef_solid *a, nef_op op, const nef_solid *b, char *err,
                   size_t err_size)
{
    return guarded(
        [&] {
            switch (op) {
            case NEF_UNION:
                a->nef += b->nef;
                break;
            case NEF_DIFFERENCE:
                a->nef -= b->nef;
                break;
            case NEF_INTERSECTION:
                a->nef *= b->nef;
                break;
            }
        },
        err, err_size);
}

__attribute__((visibility("default"))) int spancast_nef_is_empty(const nef_solid *s)
{
    return s->nef.is_empty();
}

__attribute__((visibility("default"))) nef_status
spancast_nef_vertices(const nef_solid *s, nef_parts *out, char *err, size_t err_size)
{
    std::memset(out, 0, sizeof *out);
    return guarded(
        [&] {
            std::vector<std::vector<Point>> sets(1);
            Nef::Vertex_const_iterator v;
            CGAL_forall_vertices(v, s->nef) sets[0].push_back(v->point());
            to_parts(sets, out);
        },
        err, err_size);
}

__attribute__((visibility("default"))) nef_status
spancast_nef_convex_parts(const nef_solid *s, nef_parts *out, char *err, size_t err_size)
{
    std::memset(out, 0, sizeof *out);
    return guarded(
        [&] {
            std::vector<std::vector<Point>> sets;
            if (!s->nef.is_empty()) {
                Nef decomposed = s->nef;
                CGAL::convex_decomposition_3(decomposed);
                // The first volume is the outer one; the marked ones after
                // it are the convex parts.
                auto volume = decomposed.volumes_begin();
                for (++volume; volume != decomposed.volumes_end(); ++volume) {
                    if (!volume->mark())
                        continue;
                    Polyhedron part;
                    decomposed.convert_inner_shell_to_polyhedron(volume->shells_begin(),
                                                                 part);
                    std::vector<Point> set;
                    for (auto p = part.points_begin(); p != part.points_end(); ++p)
                        set.push_back(*p);
                    if (!set.empty())
                        sets.push_back(std::move(set));
                }
            }
            to_parts(sets, out);
        },
        err, err_size);
}

__attribute__((visibility("default"))) nef_status
spancast_nef_triangles(const nef_solid *s, nef_parts *out, char *err, size_t err_size)
{
    std::memset(out, 0, sizeof *out);
    return guarded(
        [&] {
            // The boundary of every volume, triangulated and oriented away
            // from the solid (OpenSCAD turns its Nef results into polygons
            // the same way before projecting them).
            std::vector<std::vector<Point>> sets(1);
            if (!s->nef.is_empty()) {
                std::vector<Point> points;
                std::vector<std::vector<std::size_t>> polygons;
                CGAL::convert_nef_polyhedron_to_polygon_soup(s->nef, points, polygons,
                                                             true);
                for (const auto &polygon : polygons) {
                    if (polygon.size() != 3)
                        throw std::runtime_error("a face was not triangulated");
                    for (std::size_t k : polygon)
                        sets[0].push_back(points[k]);
                }
            }
            to_parts(sets, out);
        },
        err, err_size);
}

__attribute__((visibility("default"))) void spancast_nef_release(nef_solid *s)
{
    delete s;
}
}
