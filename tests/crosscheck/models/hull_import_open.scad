// hull of an imported mesh that is not closed (open_corner.stl: the three
// faces of a tetrahedron's corner at the axes, without the slanted one),
// alone and beside a cube: OpenSCAD 2021.01 hulls the corners of the mesh
// it reads, closed or not, and prints nothing.
// camera: 18,-20,16,5,3,1
// files: open_corner.stl
hull() import("open_corner.stl");
translate([0, 6, 0]) hull() {
    import("open_corner.stl");
    translate([7, 0, 0]) cube(2);
}
