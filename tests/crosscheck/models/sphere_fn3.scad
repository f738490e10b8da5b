// The smallest $fn (3), and a $fn below 3 (clamped to 3).
// camera: 20,-30,15,4,0,0
sphere(r = 4, $fn = 3);
translate([9, 0, 0]) sphere(r = 3, $fn = 1);
