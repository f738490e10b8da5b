// OpenSCAD's leniency: what it leaves out with a warning is left out, and a
// negative resize is as 0. The cube in the extrusion and the circle in the
// union are ignored, the resize keeps x and doubles y (and z, by auto),
// and the import of a file that does not exist is empty.
// camera: 45,-60,50,10,8,2
linear_extrude(height = 3) {
    square([10, 6]);
    translate([20, 0, 0]) cube(5);
}
translate([0, 12, 0]) union() {
    cylinder(h = 4, r = 3, $fn = 24);
    circle(r = 8);
}
translate([14, 10, 0]) resize([-10, 8, 0], auto = [false, false, true]) cube([4, 4, 2]);
import("lenient_not_there.stl");
