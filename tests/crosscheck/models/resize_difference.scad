// resize() of a difference that cuts away the cube's far end: OpenSCAD
// sizes the CGAL result's box (x 0..6), not the first child's (0..10); the
// second one mirrors it along x by its negative size, as OpenSCAD mirrors
// a CGAL result.
// camera: 0,-45,40,0,8,2
resize([12, 5, 0], auto = [false, false, true]) difference() {
    cube([10, 4, 4]);
    translate([6, -1, -1]) cube([5, 6, 6]);
    translate([2, 2, -1]) cylinder(r = 1, h = 6, $fn = 16);
}
translate([0, 10, 0]) resize([-12, 0, 0]) difference() {
    cube([10, 4, 4]);
    translate([6, -1, -1]) cube([5, 6, 6]);
}
