// minkowski of two differences (each split into convex parts), each moved,
// scaled or rotated, inside a rotation: the parts carry their transforms
// into the sums.
// camera: 25,-20,25,8,8,4
translate([10, 0, 0]) rotate([0, 0, 90]) minkowski() {
    translate([5, 0, 0]) difference() {
        cube([4, 2, 2]);
        cube([1, 1, 10], center = true);
    }
    translate([0, 0, 3]) scale([2, 1, 1]) difference() {
        cube(1);
        cube(0.5);
    }
}
