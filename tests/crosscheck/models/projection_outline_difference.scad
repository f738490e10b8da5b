// The outline of booleans seen from above, as OpenSCAD 2021.01 projects the
// mesh of the boolean's CGAL result: a tilted cube with a cylinder taken
// out (the hole shows only where it goes through), and beside it the
// intersection of a tilted cube and a sphere.
// camera: 6,-42,46,6,0,1
linear_extrude(2) projection()
    difference() {
        rotate([30, 20, 0]) cube(10, center = true);
        cylinder(r = 3, h = 30, center = true);
    }
translate([16, 0, 0]) linear_extrude(1) projection(cut = false)
    intersection() {
        rotate([0, 45, 10]) cube(8, center = true);
        translate([0, 0, 2]) sphere(5, $fn = 20);
    }
