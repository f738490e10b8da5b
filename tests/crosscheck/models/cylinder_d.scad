// d, d1, d2 instead of radii; d1/d2 win over d.
// camera: 25,-35,20,7,0,3
cylinder(h = 6, d = 10, $fn = 20);
translate([14, 0, 0]) cylinder(h = 6, d = 100, d1 = 6, d2 = 2, $fn = 11);
