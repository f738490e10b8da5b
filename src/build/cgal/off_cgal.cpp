// spancast-cgal.so's OFF builder (nef.h: off_build): CGAL's polyhedron
// builder run on an OFF file's faces as CGAL's OFF reader runs it
// (Polyhedron_scan_OFF), which OpenSCAD 2021.01's import() of an OFF file
// calls: its verdict, its message, and its assertions.
//
// This file is built with CGAL's assertions on in every build type (as in
// OpenSCAD's CGAL: where one fails, OpenSCAD stops, and so does the
// check), while the rest of the plugin, whose Nef polyhedra they slow by
// half, is not. Its polyhedron's types are its own (a kernel no other
// file uses), so no template of the builder is shared with a file built
// the other way.
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Polyhedron_incremental_builder_3.h>
#include <CGAL/Simple_cartesian.h>

#include <cstdint>
#include <cstdio>
#include <iostream>
#include <sstream>
#include <string>

#include "build/cgal/guarded.h"
#include "build/nef.h"

namespace
{

using Kernel = CGAL::Simple_cartesian<double>;
using Polyhedron = CGAL::Polyhedron_3<Kernel>;
using Hds = Polyhedron::HalfedgeDS;

// CGAL's polyhedron of an OFF file's faces, built as its OFF reader builds
// it (Polyhedron_scan_OFF): every point, then each face whole, without
// test_facet; the first face the builder fails on loses the polyhedron.
class Build_off : public CGAL::Modifier_base<Hds>
{
  public:
    Build_off(uint32_t point_count, const uint32_t *indices, const uint32_t *face_start,
              uint32_t face_count)
        : point_count_(point_count), indices_(indices), face_start_(face_start),
          face_count_(face_count)
    {
    }
    uint32_t refused = UINT32_MAX; // the face the builder failed on
    uint32_t current = 0;          // the face it is on
    void operator()(Hds &hds) override
    {
        // verbose: its message is the one OpenSCAD prints
        CGAL::Polyhedron_incremental_builder_3<Hds> builder(hds, true);
        builder.begin_surface(point_count_, face_count_);
        for (uint32_t i = 0; i < point_count_; i++)
            builder.add_vertex(Polyhedron::Point_3(0, 0, 0));
        for (uint32_t f = 0; f < face_count_ && !builder.error(); f++) {
            current = f;
            builder.begin_facet();
            for (uint32_t i = face_start_[f]; i < face_start_[f + 1]; i++)
                builder.add_vertex_to_facet(indices_[i]);
            builder.end_facet();
            if (builder.error())
                refused = f;
        }
        if (!builder.error() && builder.check_unconnected_vertices() &&
            !builder.remove_unconnected_vertices())
            refused = face_count_;
        if (builder.error() || refused != UINT32_MAX)
            builder.rollback();
        else
            builder.end_surface();
    }

  private:
    uint32_t point_count_;
    const uint32_t *indices_, *face_start_;
    uint32_t face_count_;
};

} // namespace

extern "C" {

__attribute__((visibility("default"))) nef_status
spancast_nef_off_build(uint32_t point_count, const uint32_t *indices,
                       const uint32_t *face_start, uint32_t face_count, uint32_t *refused,
                       char *err, size_t err_size)
{
    *refused = UINT32_MAX;
    err[0] = '\0';
    return guarded(
        [&] {
            for (uint32_t i = 0; i < face_start[face_count]; i++)
                if (indices[i] >= point_count)
                    throw bad_mesh("a face names a point that does not exist");
            Polyhedron poly;
            Build_off build(point_count, indices, face_start, face_count);
            // the builder writes its reason to std::cerr: taken from there
            // (the plugin's lock keeps every other user of CGAL out)
            std::ostringstream said;
            std::streambuf *was = std::cerr.rdbuf(said.rdbuf());
            try {
                poly.delegate(build);
            } catch (const CGAL::Failure_exception &e) {
                // an assertion (OpenSCAD stops there): on the face it was on
                std::cerr.rdbuf(was);
                *refused = build.current;
                throw std::runtime_error("CGAL's assertion " + e.expression() + " fails");
            } catch (...) {
                std::cerr.rdbuf(was);
                throw;
            }
            std::cerr.rdbuf(was);
            *refused = build.refused;
            // its first "input error: ..." line
            std::string text = said.str();
            std::size_t at = text.find("error: ");
            if (at != std::string::npos) {
                std::size_t end = text.find('\n', at);
                if (end != std::string::npos && end > at && text[end - 1] == '.')
                    end--; // the sentence's stop: the message is quoted
                std::snprintf(err, err_size, "%.300s",
                              text.substr(at + 7, end == std::string::npos
                                                      ? std::string::npos
                                                      : end - at - 7)
                                  .c_str());
            }
        },
        err, err_size);
}

} // extern "C"
