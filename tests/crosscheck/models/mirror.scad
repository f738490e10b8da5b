// Mirrors (determinant -1) of asymmetric solids.
// camera: 30,-40,25,0,0,3
translate([5, 0, 0]) cylinder(h = 6, r1 = 3, r2 = 1, $fn = 7);
mirror([1, 0, 0]) translate([5, 0, 0]) cylinder(h = 6, r1 = 3, r2 = 1, $fn = 7);
mirror([0, 1, 1]) translate([0, 4, 8]) sphere(2, $fn = 9);
