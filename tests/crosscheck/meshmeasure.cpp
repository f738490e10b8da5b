// meshmeasure: the reference volume and area of the measure cross-check.
//
// It reads the mesh OpenSCAD exports for a model (STL, as CGAL's reader
// reads it, identical points merged), builds a CGAL Surface_mesh from the
// polygon soup, checks that it is closed, and prints
// CGAL::Polygon_mesh_processing::volume and ::area, the reference values
// `spancast measure --faithful` is held against (measure.sh).
//
// usage: meshmeasure MESH.stl    prints "VOLUME AREA" with 17 digits
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/STL.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <array>
#include <cstdio>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace PMP = CGAL::Polygon_mesh_processing;

int main(int argc, char **argv)
{
    if (argc != 2) {
        std::fprintf(stderr, "usage: meshmeasure MESH.stl\n");
        return 2;
    }
    std::vector<K::Point_3> points;
    std::vector<std::array<std::size_t, 3>> faces;
    if (!CGAL::IO::read_STL(argv[1], points, faces) || faces.empty()) {
        std::fprintf(stderr, "meshmeasure: error: cannot read the STL mesh %s\n",
                     argv[1]);
        return 1;
    }
    PMP::orient_polygon_soup(points, faces);
    Mesh mesh;
    PMP::polygon_soup_to_polygon_mesh(points, faces, mesh);
    if (!CGAL::is_closed(mesh)) {
        std::fprintf(stderr, "meshmeasure: error: the mesh %s is not closed\n", argv[1]);
        return 1;
    }
    if (!PMP::is_outward_oriented(mesh))
        PMP::reverse_face_orientations(mesh);
    std::printf("%.17g %.17g\n", CGAL::to_double(PMP::volume(mesh)),
                CGAL::to_double(PMP::area(mesh)));
    return 0;
}
