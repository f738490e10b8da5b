// minkowski of a union of two cubes (distributed) and a cylinder.
// camera: 45,-55,40,5,0,0
minkowski() {
    union() {
        cube([20, 4, 2]);
        translate([0, 0, 0]) cube([4, 14, 2]);
    }
    rotate([0, 0, 15]) cylinder(r = 2, h = 1, $fn = 12);
}
