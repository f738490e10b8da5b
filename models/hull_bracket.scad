// A hull-built bracket: two rounded bosses joined by a hull (spheres and
// cylinders), a pad with edges rounded by minkowski, and a knob scaled to
// size with resize, drilled by a plain difference.
// Exported to hull_bracket.csg with:
//   openscad -o "$PWD/hull_bracket.csg" "$PWD/hull_bracket.scad"
$fn = 40;

difference() {
    union() {
        // the arm: the hull of two bosses
        hull() {
            cylinder(r = 8, h = 6);
            translate([40, 0, 0]) cylinder(r = 5, h = 6);
            translate([20, 0, 10]) sphere(r = 3);
        }
        // a pad with rounded edges
        translate([0, -25, 0]) minkowski() {
            cube([30, 12, 2]);
            sphere(r = 2, $fn = 16);
        }
        // a knob scaled to 10 x 10 x 14
        translate([40, 0, 6]) resize([10, 10, 14]) sphere(r = 1);
    }
    cylinder(r = 4, h = 30, center = true);
    translate([40, 0, 0]) cylinder(r = 2, h = 30, center = true);
}
