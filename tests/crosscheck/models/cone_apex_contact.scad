// A cone whose apex touches a cube's face, and a cone sharing its base
// with a cylinder (coincident caps).
// camera: 22,-30,22,5,0,6
cube([10, 10, 2]);
translate([5, 5, 2]) cylinder(h = 6, r1 = 0, r2 = 3, $fn = 10);
translate([15, 0, 0]) {
    cylinder(h = 4, r = 2.5, $fn = 14);
    translate([0, 0, 4]) cylinder(h = 4, r1 = 2.5, r2 = 0, $fn = 14);
}
