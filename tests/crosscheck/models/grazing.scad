// Grazing rays: the eye lies in the plane of the top face of a block and
// looks along it; a cylinder is seen almost edge-on along its axis.
// camera: -30,-3,5,10,5,5
cube([20, 10, 5]);
translate([5, 15, 0]) cube([10, 3, 12]);
translate([25, 5, 5]) rotate([0, 89, 0]) cylinder(h = 6, r = 3, $fn = 16);
