// A frustum, r1 > r2, and one with r1 < r2.
// camera: 25,-35,20,6,0,4
cylinder(h = 8, r1 = 5, r2 = 2, $fn = 24);
translate([12, 0, 0]) cylinder(h = 8, r1 = 1.5, r2 = 4, $fn = 7);
