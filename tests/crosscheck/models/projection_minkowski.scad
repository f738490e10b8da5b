// minkowski() inside projection, cut and seen from above, and a hull of a
// difference: OpenSCAD 2021.01 projects or cuts the CGAL result of the
// child (the union of the sums of convex parts, the hull of the boolean's
// vertices). An L of two blocks summed with a tilted cylinder, a cube with
// a corner taken out, hulled.
// camera: 9,-38,52,9,9,1
linear_extrude(2) projection()
    minkowski() {
        difference() { cube([10, 10, 4]); translate([4, 4, -1]) cube(10); }
        rotate([60, 0, 0]) cylinder(r = 1, h = 2, center = true, $fn = 8);
    }
translate([14, 0, 0]) linear_extrude(1) projection(cut = true)
    minkowski() {
        translate([0, 0, -2]) cube([6, 6, 4]);
        rotate([0, 0, 20]) sphere(1.5, $fn = 10);
    }
translate([0, 14, 0]) linear_extrude(1.5) projection(cut = true)
    translate([0, 0, -1])
        hull() { difference() { cube(6); translate([-1, -1, -1]) cube(4); } }
