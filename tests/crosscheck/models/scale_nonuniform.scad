// Non-uniform scales, before and after rotations.
// camera: 30,-40,25,4,0,0
scale([2, 0.5, 1]) sphere(4, $fn = 20);
translate([12, 0, 0]) rotate([30, 20, 10]) scale([1, 3, 0.5])
    cylinder(h = 4, r = 2, center = true, $fn = 10);
