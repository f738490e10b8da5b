// Unions of several solids under projection(), with and without a cut,
// in one extrusion (the model one solid that OpenSCAD draws as it is):
// OpenSCAD makes each union a CGAL Nef polyhedron first, and CGAL's
// builder takes no cone on a ring (its walls meet only at the apex), no
// box without a lid and no pinched prism (its edge of four faces), where
// the box alone would be projected as it is: OpenSCAD prints that each is
// not closed and projects the rest. spancast leaves them out with the
// same message as a warning.
// camera: 4,-12,16,3,1,0
linear_extrude(1) {
    projection() translate([0.26, -0.14, -0.4]) union() {
        translate([-1.07, -1.15, -0.38]) linear_extrude(height = 2.08, scale = 0)
            circle(r = 0.57, $fn = 5);
        translate([-0.88, 0.54, -0.14]) linear_extrude(height = 0.76, scale = 0)
            difference() { circle(r = 2, $fn = 8); circle(r = 1, $fn = 6); }
        translate([1, 1, 0]) polyhedron( // a box without its lid
            points = [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0],
                      [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]],
            faces = [[0, 1, 2, 3], [0, 4, 5, 1], [1, 5, 6, 2], [2, 6, 7, 3], [3, 7, 4, 0]]);
    }
    translate([5, 0]) projection(cut = true) translate([0, 0, -0.2]) union() {
        linear_extrude(height = 1) square([2, 1]);
        translate([0, 2, 0]) linear_extrude(height = 0.5)
            union() { square(1); translate([1, 1]) square(1); }
    }
}
