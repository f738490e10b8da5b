// A sphere unioned with itself rotated about z by half a fragment, and
// intersected with a copy: coincident cap planes.
// camera: 20,-26,18,0,0,0
union() { sphere(5, $fn = 16); rotate([0, 0, 11.25]) sphere(5, $fn = 16); }
translate([12, 0, 0]) intersection() { sphere(5, $fn = 16); translate([0, 0, 1]) sphere(5, $fn = 16); }
