// projection() of meshes under a singular transform. OpenSCAD 2021.01
// flattens a mesh's points (PolySet::transform) and projects the faces of
// the flat mesh: the outline of the solid under that map. A box, a sphere
// turned after the flattening, an L-shaped extrusion and polyhedron whose
// end faces are not convex, and a hull under a shear that maps z onto
// x + y, and a hull that takes a cylinder flattened to a disc standing on
// its edge. A union of two solids (a Nef polyhedron) is removed instead, with
// OpenSCAD's warning, and a map of no area in the plane projects nothing.
// camera: 6,-18,14,6,4,0
linear_extrude(1) projection() {
    scale([1, 1, 0]) rotate([30, 40, 10]) cube([3, 2, 1]);
    translate([9, 0, 0]) rotate([20, 0, 0]) scale([1, 0.5, 0]) translate([0, 0, 5]) sphere(3, $fn = 12);
    translate([0, 6, 0]) scale([1, 1, 0]) linear_extrude(2) polygon([[0, 0], [4, 0], [4, 1], [1, 1], [1, 4], [0, 4]]);
    translate([6, 6, 0]) scale([1, 1, 0]) polyhedron(
        points = [[0, 0, 0], [4, 0, 0], [4, 1, 0], [1, 1, 0], [1, 4, 0], [0, 4, 0],
                  [0, 0, 2], [4, 0, 2], [4, 1, 2], [1, 1, 2], [1, 4, 2], [0, 4, 2]],
        faces = [[0, 1, 2, 3, 4, 5], [11, 10, 9, 8, 7, 6], [0, 6, 7, 1], [1, 7, 8, 2],
                 [2, 8, 9, 3], [3, 9, 10, 4], [4, 10, 11, 5], [5, 11, 6, 0]]);
    translate([12, 6, 0]) multmatrix([[1, 0, 0, 0], [0, 1, 0, 0], [1, 1, 0, 0], [0, 0, 0, 1]])
        rotate([45, 0, 0]) hull() { cube(1); translate([2, 2, 2]) sphere(1, $fn = 8); }
    translate([0, 12, 0]) scale([1, 1, 0]) union() { cube(2); translate([3, 0, 0]) cube(1); }
    translate([6, 12, 0]) scale([1, 0, 1]) cube(2);
    translate([10, 12, 0]) hull() {
        cube(1);
        translate([3, 0, 0]) scale([0, 1, 1]) cylinder(h = 3, r = 1, $fn = 12);
    }
}
