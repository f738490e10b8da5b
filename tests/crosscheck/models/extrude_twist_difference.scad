// 2D booleans inside a twisted extrusion: a disc minus three circles and
// a slot, intersected with a square, then a hull and a minkowski sum.
// camera: 35,-45,45,6,4,5
linear_extrude(height = 10, twist = 60, $fn = 32)
    intersection() {
        difference() {
            circle(8);
            for (a = [0, 120, 240]) rotate(a) translate([4.5, 0]) circle(1.5);
            square([10, 1.5], center = true);
        }
        square(13, center = true);
    }
translate([18, 0, 0]) linear_extrude(height = 6, twist = -45, scale = 0.8)
    hull() { circle(2); translate([5, 3]) square(2); }
translate([6, 16, 0]) linear_extrude(height = 5, twist = 90)
    minkowski() { square([6, 2], center = true); circle(1, $fn = 12); }
