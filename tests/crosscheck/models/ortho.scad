// Orthographic projection of a drilled block.
// camera: 30,-40,30,5,5,5
// projection: o
difference() {
    cube(10);
    translate([5, 5, -1]) cylinder(h = 12, r = 3, $fn = 20);
    translate([-1, 5, 5]) rotate([0, 90, 0]) cylinder(h = 12, r = 2, $fn = 15);
}
