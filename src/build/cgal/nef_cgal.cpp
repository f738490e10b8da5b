// spancast-cgal.so: the only code that links CGAL, GMP and MPFR (nef.h).
//
// Solids are CGAL Nef polyhedra over the exact-constructions kernel, as
// OpenSCAD 2021.01 builds the booleans under a hull() or minkowski(): a
// polygon mesh becomes a surface mesh (points at one position merged,
// faces triangulated, wound inward as OpenSCAD winds them) and then a Nef
// polyhedron; booleans are Nef's; hull() takes every vertex of the result
// (OpenSCAD's applyHull); minkowski() takes the vertices of each volume of
// CGAL's convex decomposition (OpenSCAD's applyMinkowski). Coordinates are exact inside
// and rounded to doubles only on the way out, as OpenSCAD rounds them.
//
// Every entry point catches what CGAL throws (failed preconditions on a
// mesh that is not a valid solid, failed assertions, which are on in
// every build type as in OpenSCAD's CGAL, bad_alloc) and returns it as a
// status with a message.
// CGAL's headers are built with our warning flags: at -O3 (a Release
// build), GCC 12 reports -Wmaybe-uninitialized inside CGAL's
// chained_map.h, instantiated by convex_decomposition_3, which
// -DSPANCAST_WERROR=ON makes an error. That code is CGAL's, not ours, so
// the warning is off for its headers only (the pragmas apply to the code
// by where it is written, in the headers included between push and pop);
// the code of this file keeps every warning.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Extended_cartesian.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Nef_polyhedron_2.h>
#include <CGAL/Nef_polyhedron_3.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/convex_hull_3.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Polyhedron_incremental_builder_3.h>
#include <CGAL/Polyhedron_items_with_id_3.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/boost/graph/convert_nef_polyhedron_to_polygon_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/convex_decomposition_3.h>
#pragma GCC diagnostic pop

#include <gmp.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <cmath>
#include <cstring>
#include <list>
#include <map>
#include <new>
#include <set>
#include <stdexcept>
#include <vector>

#include "build/cgal/guarded.h"
#include "build/nef.h"

namespace
{

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using Point = Kernel::Point_3;
using Nef = CGAL::Nef_polyhedron_3<Kernel>;
using Mesh = CGAL::Surface_mesh<Point>;
using Polyhedron = CGAL::Polyhedron_3<Kernel>;
namespace PMP = CGAL::Polygon_mesh_processing;

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

// ---- faces with holes ----
//
// A face of several loops (a cap of an extrusion: the outlines and holes
// of a 2D region) is triangulated here, not fanned: a fan of a face that
// is not convex, or one triangle set per loop, overlaps itself, and Nef_3
// built from overlapping triangles is not a valid polyhedron; its later
// booleans then read freed or missing halfedges (SNC_external_structure's
// pair_up_halfedges walked off a list end on GEB.scad's letters). The
// loops go into a constrained Delaunay triangulation in the plane of the
// face's largest normal component, and the triangles nested inside an odd
// number of loops are the face (the even-odd rule, which is the region's
// own rule, as its loops neither cross nor overlap).

struct Vertex_index {
    std::size_t k = SIZE_MAX; // the mesh point of a triangulation vertex
};

using Kernel_2 = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<Vertex_index, Kernel_2>;
using Fb_base = CGAL::Constrained_triangulation_face_base_2<Kernel_2>;
using Fb = CGAL::Triangulation_face_base_with_info_2<int, Kernel_2, Fb_base>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Cdt =
    CGAL::Constrained_Delaunay_triangulation_2<Kernel_2, Tds, CGAL::Exact_predicates_tag>;

// Nesting level of every face, as OpenSCAD 2021.01's mark_domains
// (Polygon2d-CGAL.cc) sets it: the faces reached from the infinite face
// without crossing a constrained edge are level 0, and each face across a
// constrained edge from level k is k + 1, breadth first; the odd levels
// are the region (the even-odd rule).
void mark_domains(Cdt &cdt)
{
    for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f)
        f->info() = -1;
    std::list<Cdt::Edge> border;
    auto mark = [&](Cdt::Face_handle from, int level) {
        if (from->info() != -1)
            return;
        std::list<Cdt::Face_handle> queue{from};
        while (!queue.empty()) {
            Cdt::Face_handle f = queue.front();
            queue.pop_front();
            if (f->info() != -1)
                continue;
            f->info() = level;
            for (int i = 0; i < 3; i++) {
                Cdt::Face_handle g = f->neighbor(i);
                if (g->info() != -1)
                    continue;
                if (cdt.is_constrained(Cdt::Edge(f, i)))
                    border.push_back(Cdt::Edge(f, i));
                else
                    queue.push_back(g);
            }
        }
    };
    mark(cdt.infinite_face(), 0);
    while (!border.empty()) {
        Cdt::Edge e = border.front();
        border.pop_front();
        Cdt::Face_handle g = e.first->neighbor(e.second);
        if (g->info() == -1)
            mark(g, e.first->info() + 1);
    }
}

// Appends to polygons the triangles of the face whose loops are loops
// (indices into the points xyz), as even-odd nesting of the loops makes it.
void triangulate_loops(const std::vector<std::array<double, 3>> &xyz,
                       const std::vector<std::vector<std::size_t>> &loops,
                       std::vector<std::vector<std::size_t>> &polygons)
{
    // Newell's normal of all loops together: holes run the other way and
    // take from it, and the axis of its largest component is left out.
    double normal[3] = {0, 0, 0};
    for (const auto &loop : loops) {
        for (std::size_t i = 0; i < loop.size(); i++) {
            const auto &a = xyz[loop[i]], &b = xyz[loop[(i + 1) % loop.size()]];
            normal[0] += (a[1] - b[1]) * (a[2] + b[2]);
            normal[1] += (a[2] - b[2]) * (a[0] + b[0]);
            normal[2] += (a[0] - b[0]) * (a[1] + b[1]);
        }
    }
    int axis = 0;
    for (int i = 1; i < 3; i++) {
        if (std::fabs(normal[i]) > std::fabs(normal[axis]))
            axis = i;
    }
    if (!(std::fabs(normal[axis]) > 0))
        throw bad_mesh("a face with holes has no area");
    int u = (axis + 1) % 3, v = (axis + 2) % 3;
    Cdt cdt;
    for (const auto &loop : loops) {
        std::vector<Cdt::Vertex_handle> corner;
        for (std::size_t k : loop) {
            Cdt::Vertex_handle h = cdt.insert(Kernel_2::Point_2(xyz[k][u], xyz[k][v]));
            if (h->info().k != SIZE_MAX && h->info().k != k)
                throw bad_mesh("two points of a face lie on one another in its plane");
            h->info().k = k;
            corner.push_back(h);
        }
        for (std::size_t i = 0; i < corner.size(); i++)
            cdt.insert_constraint(corner[i], corner[(i + 1) % corner.size()]);
    }
    mark_domains(cdt);
    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
        if (f->info() % 2 == 1)
            polygons.push_back(
                {f->vertex(0)->info().k, f->vertex(1)->info().k, f->vertex(2)->info().k});
    }
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

// ---- faces out of their planes, as OpenSCAD's CGAL meets them ----
//
// OpenSCAD 2021.01 makes a Nef polyhedron of a polyhedron that is not
// convex straight from the faces as given, with CGAL's assertions on.
// polygon_mesh_to_nef_3 then checks, at each corner of a face of more
// than three points, that the corner's two neighbours lie in the plane
// through the corner along the face's Newell normal. The first check to
// fail throws; OpenSCAD triangulates the faces and tries again only for
// the message of the first check of its loop (the neighbour after the
// corner), and CGAL 5's messages for the other two checks are not the
// ones it looks for, so there the polyhedron is lost.

// The polyhedron's topology is all the checks need of CGAL's polyhedron,
// so it is kept over doubles; each point's place in a plane is decided
// exactly (a floating-point filter first, exact rationals where it cannot
// tell), as CGAL's exact kernel decides it in OpenSCAD.
using Fast = CGAL::Exact_predicates_inexact_constructions_kernel;
using Plane_polyhedron = CGAL::Polyhedron_3<Fast, CGAL::Polyhedron_items_with_id_3>;
using Plane_hds = Plane_polyhedron::HalfedgeDS;

// CGAL's polyhedron of the faces, built as OpenSCAD builds it
// (CGAL_Build_PolySet): every point added in the order given, then each
// face its builder takes; added[i] is the given face of facet i.
class Build_faces : public CGAL::Modifier_base<Plane_hds>
{
  public:
    Build_faces(const double *points, uint32_t point_count, const uint32_t *indices,
                const uint32_t *face_start, uint32_t face_count,
                std::vector<uint32_t> &added)
        : points_(points), point_count_(point_count), indices_(indices),
          face_start_(face_start), face_count_(face_count), added_(added)
    {
    }
    void operator()(Plane_hds &hds) override
    {
        CGAL::Polyhedron_incremental_builder_3<Plane_hds> builder(hds, false);
        builder.begin_surface(point_count_, face_count_);
        for (uint32_t i = 0; i < point_count_; i++)
            builder.add_vertex(
                Fast::Point_3(points_[3 * i], points_[3 * i + 1], points_[3 * i + 2]));
        for (uint32_t f = 0; f < face_count_; f++) {
            std::vector<std::size_t> face;
            for (uint32_t i = face_start_[f]; i < face_start_[f + 1]; i++) {
                if (indices_[i] >= point_count_)
                    throw bad_mesh("a face names a point that does not exist");
                face.push_back(indices_[i]);
            }
            if (face.size() >= 3 && builder.test_facet(face.begin(), face.end())) {
                builder.add_facet(face.begin(), face.end());
                added_.push_back(f);
            }
        }
        builder.end_surface();
    }

  private:
    const double *points_;
    uint32_t point_count_;
    const uint32_t *indices_, *face_start_;
    uint32_t face_count_;
    std::vector<uint32_t> &added_;
};

// N . (q - v) for the Newell normal N of the polygon p, in NT.
template <class NT>
NT newell_dot(const std::vector<Fast::Point_3> &p, const Fast::Point_3 &q,
              const Fast::Point_3 &v)
{
    NT nx = 0, ny = 0, nz = 0;
    for (std::size_t i = 0; i < p.size(); i++) {
        const Fast::Point_3 &a = p[i], &b = p[(i + 1) % p.size()];
        NT ax = a.x(), ay = a.y(), az = a.z(), bx = b.x(), by = b.y(), bz = b.z();
        nx += (ay - by) * (az + bz);
        ny += (az - bz) * (ax + bx);
        nz += (ax - bx) * (ay + by);
    }
    NT dx = NT(q.x()) - NT(v.x()), dy = NT(q.y()) - NT(v.y()), dz = NT(q.z()) - NT(v.z());
    return nx * dx + ny * dy + nz * dz;
}

// Whether q - v leaves the plane through the origin along the Newell normal
// of the polygon p (CGAL's Sphere_circle::has_on, negated), exactly.
bool off_plane(const std::vector<Fast::Point_3> &p, const Fast::Point_3 &q,
               const Fast::Point_3 &v)
{
    {
        CGAL::Protect_FPU_rounding<true> rounding;
        CGAL::Interval_nt_advanced x = newell_dot<CGAL::Interval_nt_advanced>(p, q, v);
        if (x.inf() > 0 || x.sup() < 0)
            return true;
    }
    return !CGAL::is_zero(newell_dot<CGAL::Exact_rational>(p, q, v));
}

} // namespace

// CGAL's polyhedron of polygons, built as OpenSCAD builds it
// (CGAL_Build_PolySet): each polygon's points in the order given, reversed
// where reverse is set, the points added in the order the polygons first
// name them, then each polygon the builder takes. Of a mesh that crosses
// itself CGAL makes a Nef polyhedron that depends on that order (two
// boxes that overlap, in one polyhedron: both boxes as OpenSCAD builds
// them, one box from the same faces as CGAL's polygon soup builds them).
class Build_polygons : public CGAL::Modifier_base<Polyhedron::HalfedgeDS>
{
  public:
    Build_polygons(const std::vector<Point> &points,
                   const std::vector<std::vector<std::size_t>> &polygons, bool reverse)
        : points_(points), polygons_(polygons), reverse_(reverse)
    {
    }
    void operator()(Polyhedron::HalfedgeDS &hds) override
    {
        std::vector<std::size_t> number(points_.size(), SIZE_MAX);
        std::vector<std::size_t> order;
        std::vector<std::vector<std::size_t>> faces;
        for (const auto &polygon : polygons_) {
            std::vector<std::size_t> face;
            for (std::size_t k = 0; k < polygon.size(); k++) {
                std::size_t i = polygon[reverse_ ? polygon.size() - 1 - k : k];
                if (number[i] == SIZE_MAX) {
                    number[i] = order.size();
                    order.push_back(i);
                }
                face.push_back(number[i]);
            }
            faces.push_back(std::move(face));
        }
        CGAL::Polyhedron_incremental_builder_3<Polyhedron::HalfedgeDS> builder(hds,
                                                                               false);
        builder.begin_surface(order.size(), faces.size());
        for (std::size_t i : order)
            builder.add_vertex(points_[i]);
        for (const auto &face : faces) {
            if (face.size() >= 3 && builder.test_facet(face.begin(), face.end()))
                builder.add_facet(face.begin(), face.end());
        }
        builder.end_surface();
    }

  private:
    const std::vector<Point> &points_;
    const std::vector<std::vector<std::size_t>> &polygons_;
    bool reverse_;
};

// CGAL's polyhedron over inexact constructions copied into one over exact
// ones, as OpenSCAD copies a convex hull (CGALUtils::copyPolyhedron): each
// vertex in order, then each facet from its first halfedge on.
class Copy_hull : public CGAL::Modifier_base<Polyhedron::HalfedgeDS>
{
  public:
    explicit Copy_hull(const CGAL::Polyhedron_3<Fast> &from) : from_(from) {}
    void operator()(Polyhedron::HalfedgeDS &hds) override
    {
        CGAL::Polyhedron_incremental_builder_3<Polyhedron::HalfedgeDS> builder(hds, true);
        builder.begin_surface(from_.size_of_vertices(), from_.size_of_facets(),
                              from_.size_of_halfedges());
        std::map<CGAL::Polyhedron_3<Fast>::Vertex_const_handle, std::size_t> index;
        for (auto v = from_.vertices_begin(); v != from_.vertices_end(); ++v) {
            index.emplace(v, index.size());
            builder.add_vertex(Point(v->point().x(), v->point().y(), v->point().z()));
        }
        for (auto f = from_.facets_begin(); f != from_.facets_end(); ++f) {
            builder.begin_facet();
            auto h = f->facet_begin(), end = h;
            do
                builder.add_vertex_to_facet(index.at(h->vertex()));
            while (++h != end);
            builder.end_facet();
        }
        builder.end_surface();
    }

  private:
    const CGAL::Polyhedron_3<Fast> &from_;
};

struct nef_solid {
    Nef nef;
};

std::mutex &spancast_cgal_lock()
{
    static std::mutex lock;
    return lock;
}

extern "C" {

__attribute__((visibility("default"))) nef_status
spancast_nef_from_mesh(const double *points, uint32_t point_count,
                       const uint32_t *indices, const uint32_t *loop_start,
                       const uint32_t *face_loops, uint32_t face_count, int written,
                       nef_solid **out, char *err, size_t err_size)
{
    *out = nullptr;
    return guarded(
        [&] {
            // Points at one position become one (a polyhedron may repeat
            // its corners per face).
            std::map<std::array<double, 3>, std::size_t> seen;
            std::vector<std::array<double, 3>> xyz;
            std::vector<std::size_t> index_of(point_count);
            for (uint32_t i = 0; i < point_count; i++) {
                std::array<double, 3> key = {points[3 * i], points[3 * i + 1],
                                             points[3 * i + 2]};
                auto found = seen.emplace(key, xyz.size());
                if (found.second)
                    xyz.push_back(key);
                index_of[i] = found.first->second;
            }
            std::vector<Point> unique;
            unique.reserve(xyz.size());
            for (const auto &p : xyz)
                unique.emplace_back(p[0], p[1], p[2]);
            std::vector<std::vector<std::size_t>> polygons;
            for (uint32_t f = 0; f < face_count; f++) {
                uint32_t first = face_loops ? face_loops[f] : f;
                uint32_t end = face_loops ? face_loops[f + 1] : f + 1;
                std::vector<std::vector<std::size_t>> loops;
                for (uint32_t l = first; l < end; l++) {
                    std::vector<std::size_t> loop;
                    for (uint32_t i = loop_start[l]; i < loop_start[l + 1]; i++) {
                        if (indices[i] >= point_count)
                            throw bad_mesh("a face names a point that does not exist");
                        std::size_t k = index_of[indices[i]];
                        if (loop.empty() || loop.back() != k)
                            loop.push_back(k);
                    }
                    while (loop.size() > 1 && loop.front() == loop.back())
                        loop.pop_back();
                    if (std::set<std::size_t>(loop.begin(), loop.end()).size() >= 3)
                        loops.push_back(std::move(loop));
                }
                if (loops.size() == 1)
                    polygons.push_back(std::move(loops[0]));
                else if (loops.size() > 1)
                    triangulate_loops(xyz, loops, polygons);
            }
            if (polygons.empty()) {
                *out = new nef_solid{Nef(Nef::EMPTY)};
                return;
            }
            if (!PMP::is_polygon_soup_a_polygon_mesh(polygons))
                PMP::orient_polygon_soup(unique, polygons);
            // Each face reversed, as OpenSCAD hands CGAL every mesh: its
            // builder (CGAL_Build_PolySet) reverses each polygon of a
            // PolySet. A shape's or an extrusion's polygons face outward,
            // so CGAL gets them inward, whatever order they come in here;
            // a polyhedron's (written 1) are its faces back to front
            // (OpenSCAD's are clockwise seen from outside), so CGAL gets
            // them in the order written, either way (written 2: mirrored
            // on the way here, so kept as they come). The Nef polyhedron of
            // a closed mesh that does not cross itself is the same either
            // way; of one that does, it is not: a thin twisted extrusion
            // outward made a structure on which the next boolean crashed
            // inside CGAL, where inward gives the solid OpenSCAD renders; a
            // polyhedron of two boxes that cross, written counter-clockwise,
            // is both boxes in OpenSCAD, and inward it would be one.
            bool reverse = written == 1;
            if (!written) {
                Polyhedron probe;
                PMP::polygon_soup_to_polygon_mesh(unique, polygons, probe);
                if (!CGAL::is_closed(probe) || !CGAL::is_valid_polygon_mesh(probe))
                    throw bad_mesh("the mesh is not closed");
                PMP::triangulate_faces(probe);
                reverse = PMP::is_outward_oriented(probe);
            }
            Polyhedron mesh;
            Build_polygons build(unique, polygons, reverse);
            mesh.delegate(build);
            if (!CGAL::is_closed(mesh) || !CGAL::is_valid_polygon_mesh(mesh))
                throw bad_mesh("the mesh is not closed");
            PMP::triangulate_faces(mesh);
            *out = new nef_solid{Nef(mesh)};
        },
        err, err_size);
}

__attribute__((visibility("default"))) nef_status
spancast_nef_plane_check(const double *points, uint32_t point_count,
                         const uint32_t *indices, const uint32_t *face_start,
                         uint32_t face_count, int *verdict, uint32_t where[2], char *err,
                         size_t err_size)
{
    *verdict = 0;
    return guarded(
        [&] {
            Plane_polyhedron poly;
            std::vector<uint32_t> added;
            Build_faces build(points, point_count, indices, face_start, face_count,
                              added);
            poly.delegate(build);
            if (poly.size_of_facets() != added.size())
                return; // the builder gave up: nothing more to check
            std::vector<std::vector<Fast::Point_3>> corners; // of each facet, in order
            std::size_t id = 0;
            for (auto f = poly.facets_begin(); f != poly.facets_end(); ++f) {
                f->id() = id++;
                std::vector<Fast::Point_3> p;
                auto h = f->halfedge();
                do {
                    p.push_back(h->vertex()->point());
                    h = h->next();
                } while (h != f->halfedge());
                corners.push_back(p.size() > 3 ? std::move(p)
                                               : std::vector<Fast::Point_3>());
            }
            // which: 1 the neighbour after the corner, 2 the one before, 3
            // either at the face that closes the corner's cycle
            auto fails = [&](Plane_polyhedron::Halfedge_const_handle in,
                             Plane_polyhedron::Halfedge_const_handle neighbour,
                             Plane_polyhedron::Vertex_const_handle corner) {
                if (in->is_border())
                    return false;
                std::size_t i = in->facet()->id();
                if (corners[i].empty() ||
                    !off_plane(corners[i], neighbour->opposite()->vertex()->point(),
                               corner->point()))
                    return false;
                where[0] = added[i];
                return true;
            };
            static const char *const expressions[] = {
                "", "ss_circle.has_on(sp)", "ss_circle.has_on(sv_prev->point())",
                "ss_circle.has_on(sp_0)", "ss_circle.has_on(sv_prev->point())"};
            uint32_t corner = 0;
            for (auto v = poly.vertices_begin(); v != poly.vertices_end();
                 ++v, corner++) {
                std::vector<Plane_polyhedron::Halfedge_const_handle> in;
                CGAL::Halfedge_around_target_circulator<Plane_polyhedron> h(v->halfedge(),
                                                                            poly),
                    end(h);
                do
                    in.push_back(*h);
                while (++h != end);
                std::size_t k = in.size(), failed = 0;
                for (std::size_t j = 1; j < k && !failed; j++)
                    failed = fails(in[j - 1], in[j], v)       ? 1
                             : fails(in[j - 1], in[j - 1], v) ? 2
                                                              : 0;
                if (!failed)
                    failed = fails(in[k - 1], in[0], v)       ? 3
                             : fails(in[k - 1], in[k - 1], v) ? 4
                                                              : 0;
                if (failed) {
                    *verdict = failed == 1 ? 1 : 2;
                    where[1] = corner;
                    std::snprintf(err, err_size, "%s", expressions[failed]);
                    return;
                }
            }
        },
        err, err_size);
}

// As OpenSCAD 2021.01 makes a Nef polyhedron of a mesh it finds convex
// (createNefPolyhedronFromPolySet): CGAL's convex_hull_3 of every corner
// of every polygon, in order, over inexact constructions, copied into an
// exact polyhedron; 3 corners or fewer make the empty solid.
__attribute__((visibility("default"))) nef_status
spancast_nef_hull(const double *corners, uint32_t count, nef_solid **out, char *err,
                  size_t err_size)
{
    *out = nullptr;
    return guarded(
        [&] {
            if (count <= 3) {
                *out = new nef_solid{Nef(Nef::EMPTY)};
                return;
            }
            std::list<Fast::Point_3> points;
            for (uint32_t i = 0; i < count; i++)
                points.emplace_back(corners[3 * i], corners[3 * i + 1],
                                    corners[3 * i + 2]);
            CGAL::Polyhedron_3<Fast> hull;
            CGAL::convex_hull_3(points.begin(), points.end(), hull);
            if (hull.size_of_facets() < 4 || !hull.is_closed()) { // flat: no solid
                *out = new nef_solid{Nef(Nef::EMPTY)};
                return;
            }
            Polyhedron exact;
            Copy_hull copy(hull);
            exact.delegate(copy);
            *out = new nef_solid{Nef(exact)};
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

__attribute__((visibility("default"))) nef_status
spancast_nef_copy(const nef_solid *s, nef_solid **out, char *err, size_t err_size)
{
    *out = nullptr;
    return guarded([&] { *out = new nef_solid{s->nef}; }, err, err_size);
}

// As CGAL_Nef_polyhedron::transform: a matrix whose determinant (in
// doubles) is 0 empties the solid; any other is taken exactly, each entry
// the rational number its double is, and maps the solid exactly.
__attribute__((visibility("default"))) nef_status
spancast_nef_transform(nef_solid *s, const double m[12], char *err, size_t err_size)
{
    return guarded(
        [&] {
            if (s->nef.is_empty())
                return;
            double det = m[0] * (m[5] * m[10] - m[6] * m[9]) -
                         m[1] * (m[4] * m[10] - m[6] * m[8]) +
                         m[2] * (m[4] * m[9] - m[5] * m[8]);
            if (det == 0) {
                s->nef = Nef(Nef::EMPTY);
                return;
            }
            Kernel::Aff_transformation_3 t(m[0], m[1], m[2], m[3], m[4], m[5], m[6], m[7],
                                           m[8], m[9], m[10], m[11], 1);
            s->nef.transform(t);
        },
        err, err_size);
}

__attribute__((visibility("default"))) int spancast_nef_is_empty(const nef_solid *s)
{
    std::lock_guard<std::mutex> hold(spancast_cgal_lock());
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

// ---- the section by z = 0, as OpenSCAD cuts ----
//
// OpenSCAD 2021.01's CGALUtils::project(N, true): N intersected with the
// plane z = 0 (PLANE_ONLY), or where CGAL throws there, with a box of
// |x|, |y| <= 1e8 and |z| <= 0.001; then its ZRemover flattens every
// facet of the result that looks up: each cycle of the facet's points
// (the target of each edge's source, rounded to doubles) is a 2D Nef
// polyhedron over Extended_cartesian<Gmpq>, its boundary included, the
// facet's first cycle united with what was flattened before and each
// later one intersected with it; the marked faces of that are the
// section's loops, each face's outline then its holes.

using Kernel2 = CGAL::Extended_cartesian<CGAL::Gmpq>;
using Nef2 = CGAL::Nef_polyhedron_2<Kernel2>;

struct Flatten {
    Nef2 out;
    void visit(Nef::Vertex_const_handle) {}
    void visit(Nef::Halfedge_const_handle) {}
    void visit(Nef::SHalfedge_const_handle) {}
    void visit(Nef::SHalfloop_const_handle) {}
    void visit(Nef::SFace_const_handle) {}
    void visit(Nef::Halffacet_const_handle facet)
    {
        if (facet->plane().orthogonal_direction() != CGAL::Direction_3<Kernel>(0, 0, 1))
            return;
        int cycle = 0;
        Nef::Halffacet_cycle_const_iterator c;
        CGAL_forall_facet_cycles_of(c, facet)
        {
            if (!c.is_shalfedge())
                continue;
            Nef::SHalfedge_around_facet_const_circulator e(c), end(e);
            std::vector<Nef2::Explorer::Point> contour;
            CGAL_For_all(e, end)
            {
                Point p = e->source()->target()->point();
                contour.push_back(Nef2::Explorer::Point(CGAL::to_double(p.x()),
                                                        CGAL::to_double(p.y())));
            }
            if (contour.empty())
                continue;
            Nef2 loop(contour.begin(), contour.end(), Nef2::INCLUDED);
            if (cycle++ == 0)
                out += loop;
            else
                out *= loop;
        }
    }
};

// The loops of a flattened section's marked faces (the points of
// standard vertices only), as parts of z = 0 points.
void section_loops(const Nef2 &flat, std::vector<std::vector<Point>> &loops)
{
    Nef2::Explorer ex = flat.explorer();
    auto add = [&](Nef2::Explorer::Halfedge_around_face_const_circulator e) {
        std::vector<Point> loop;
        Nef2::Explorer::Halfedge_around_face_const_circulator end(e);
        CGAL_For_all(e, end)
        {
            if (!ex.is_standard(ex.target(e)))
                continue;
            Nef2::Explorer::Point q = ex.point(ex.target(e));
            loop.push_back(Point(CGAL::to_double(q.x()), CGAL::to_double(q.y()), 0));
        }
        if (!loop.empty())
            loops.push_back(std::move(loop));
    };
    for (auto f = ex.faces_begin(); f != ex.faces_end(); ++f) {
        if (!f->mark())
            continue;
        add(ex.face_cycle(f));
        for (auto h = ex.holes_begin(f); h != ex.holes_end(f); ++h)
            add(Nef2::Explorer::Halfedge_around_face_const_circulator(h));
    }
}

// s cut by z = 0 as OpenSCAD cuts it: empty where CGAL fails both ways
// (OpenSCAD logs CGAL's error, and its cut is empty).
Nef plane_cut(const Nef &s)
{
    try {
        return s.intersection(Nef::Plane_3(0, 0, 1, 0), Nef::PLANE_ONLY);
    } catch (const CGAL::Failure_exception &) {
        try {
            std::vector<Point> corners;
            for (int k = 0; k < 8; k++)
                corners.push_back(Point(k & 1 ? 1e8 : -1e8, k & 2 ? 1e8 : -1e8,
                                        k & 4 ? 0.001 : -0.001));
            Polyhedron box;
            CGAL::convex_hull_3(corners.begin(), corners.end(), box);
            return Nef(box).intersection(s);
        } catch (const CGAL::Failure_exception &) {
            return Nef();
        }
    }
}

__attribute__((visibility("default"))) void spancast_nef_release(nef_solid *s)
{
    std::lock_guard<std::mutex> hold(spancast_cgal_lock());
    delete s;
}

__attribute__((visibility("default"))) nef_status
spancast_nef_section(const nef_solid *s, nef_parts *out, int *missed, char *err,
                     size_t err_size)
{
    std::memset(out, 0, sizeof *out);
    *missed = 0;
    return guarded(
        [&] {
            std::vector<std::vector<Point>> loops;
            Nef cut = s->nef.is_empty() ? Nef() : plane_cut(s->nef);
            if (cut.is_empty()) {
                *missed = 1;
            } else {
                Flatten flat;
                Nef::Volume_const_iterator v;
                try {
                    for (v = cut.volumes_begin(); v != cut.volumes_end(); ++v) {
                        Nef::Shell_entry_const_iterator shell;
                        for (shell = v->shells_begin(); shell != v->shells_end(); ++shell)
                            cut.visit_shell_objects(Nef::SFace_const_handle(shell), flat);
                    }
                    section_loops(flat.out, loops);
                } catch (const CGAL::Failure_exception &e) {
                    // OpenSCAD logs it and has no section
                    loops.clear();
                    *missed = 2;
                    std::snprintf(err, err_size, "%.400s", e.what());
                }
            }
            to_parts(loops, out);
        },
        err, err_size);
}

__attribute__((visibility("default"))) nef_status
spancast_nef_self_crossing(const double *corners, uint32_t tri_count, int *crossing,
                           char *err, size_t err_size)
{
    *crossing = 0;
    return guarded(
        [&] {
            using Fast = CGAL::Exact_predicates_inexact_constructions_kernel;
            std::vector<Fast::Point_3> points;
            std::vector<std::array<std::size_t, 3>> tris;
            std::map<std::array<double, 3>, std::size_t> index;
            for (uint32_t t = 0; t < tri_count; t++) {
                std::array<std::size_t, 3> tri;
                for (int k = 0; k < 3; k++) {
                    const double *c = &corners[9 * (size_t)t + 3 * k];
                    auto at = index.emplace(std::array<double, 3>{c[0], c[1], c[2]},
                                            points.size());
                    if (at.second)
                        points.push_back(Fast::Point_3(c[0], c[1], c[2]));
                    tri[k] = at.first->second;
                }
                tris.push_back(tri);
            }
            if (!PMP::is_polygon_soup_a_polygon_mesh(tris))
                return; // not a surface: the section's own rules take it
            CGAL::Surface_mesh<Fast::Point_3> mesh;
            PMP::polygon_soup_to_polygon_mesh(points, tris, mesh);
            *crossing = PMP::does_self_intersect(mesh);
        },
        err, err_size);
}
}

// ---- the caps of an extrusion, as OpenSCAD triangulates them ----
//
// OpenSCAD 2021.01's Polygon2d::tessellate, step by step: the same calls
// on the same triangulation (CGAL's constrained Delaunay triangulation
// over Epick with exact predicates), so that the triangles, their order
// and their first corners are OpenSCAD's, and then its mark_domains.

extern "C" __attribute__((visibility("default"))) nef_status
spancast_nef_tessellate(const double *xy, const uint32_t *start, uint32_t contour_count,
                        uint32_t **tris, uint32_t *tri_count, char *err, size_t err_size)
{
    *tris = nullptr;
    *tri_count = 0;
    return guarded(
        [&] {
            Cdt cdt;
            for (uint32_t k = 0; k < contour_count; k++) {
                uint32_t first = start[k], end = start[k + 1];
                if (end == first)
                    continue;
                auto put = [&](uint32_t i) {
                    Cdt::Vertex_handle h =
                        cdt.insert(Kernel_2::Point_2(xy[2 * i], xy[2 * i + 1]));
                    if (h->info().k == SIZE_MAX)
                        h->info().k = i;
                    return h;
                };
                Cdt::Vertex_handle prev = put(end - 1);
                for (uint32_t i = first; i < end; i++) {
                    Cdt::Vertex_handle curr = put(i);
                    if (prev != curr) {
                        cdt.insert_constraint(prev, curr);
                        prev = curr;
                    }
                }
            }
            mark_domains(cdt);
            std::vector<uint32_t> out;
            for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
                if (f->info() % 2 != 1)
                    continue;
                for (int i = 0; i < 3; i++)
                    out.push_back(static_cast<uint32_t>(f->vertex(i)->info().k));
            }
            if (out.size() / 3 > UINT32_MAX)
                throw std::runtime_error("too many triangles");
            if (!out.empty()) {
                *tris = static_cast<uint32_t *>(std::malloc(out.size() * sizeof **tris));
                if (!*tris)
                    throw std::bad_alloc();
                std::memcpy(*tris, out.data(), out.size() * sizeof **tris);
            }
            *tri_count = static_cast<uint32_t>(out.size() / 3);
        },
        err, err_size);
}
