// The section projection(cut = true) makes is, in OpenSCAD 2021.01, a
// polygon marked sanitized (convertToPolygon2d), its outlines
// counter-clockwise and its holes clockwise, and a minkowski sum or an
// offset keeps each contour's direction: the hole stays a hole. spancast
// marked the section not sanitized, so both turned the hole
// counter-clockwise first and filled it. The first is OpenSCAD's own test
// ("Verify hole winding order", testdata/scad/2D/features/
// projection-cut-tests.scad).
// camera: 4,-26,30,4,0,0
linear_extrude(1) minkowski() {
    projection(cut = true) difference() {
        cube(10, center = true);
        cube([5, 5, 20], center = true);
    }
    square(1);
}
translate([14, 0, 0]) linear_extrude(1) offset(delta = 1)
    projection(cut = true) difference() {
        cube(10, center = true);
        cube([5, 5, 20], center = true);
    }
