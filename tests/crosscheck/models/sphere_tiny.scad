// Small radii: below $fs the count stays at 5.
// camera: 1.2,-1.6,1,0.3,0,0
sphere(r = 0.2);
translate([0.6, 0, 0]) sphere(r = 0.15, $fs = 0.01, $fa = 6);
