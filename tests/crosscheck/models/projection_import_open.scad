// projection of an imported mesh that is not closed (open_corner.stl: the
// three faces of a tetrahedron's corner at the axes, without the slanted
// one), extruded: OpenSCAD 2021.01 projects its faces as they are, closed
// or not, and prints nothing (flat, only the face looking down has area;
// tilted, all three), while a cut needs a CGAL Nef polyhedron: OpenSCAD
// prints "The given mesh is not closed!" and leaves the mesh out of the
// section, and the cube beside it is cut as ever; a hull of the mesh is a
// solid, which the cut takes.
// camera: 8,-16,22,6,5,0
// files: open_corner.stl
linear_extrude(1) projection() import("open_corner.stl");
translate([6, 0, 0]) linear_extrude(1) projection()
    rotate([20, 30, 0]) import("open_corner.stl");
translate([0, 8, 0]) linear_extrude(1) projection(cut = true) {
    translate([0, 0, -1]) import("open_corner.stl");
    translate([8, 2, 0]) cube(2, center = true);
}
translate([0, 8, 0]) linear_extrude(1) projection(cut = true)
    translate([0, 0, -1]) hull() import("open_corner.stl");
