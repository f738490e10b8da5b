// Coordinates past 1e12 and below the clipper's range (2^46, about
// 7.04e13, is 2^62 at its 2^16 scale): the union, the offset and the
// difference go through Clipper at its full 128-bit range, as OpenSCAD
// 2021.01 takes them; the result is then scaled down to be seen.
// camera: 30,-70,150,30,28,5
linear_extrude(height = 10) scale(1e-12) difference() {
    union() {
        polygon([[0, 0], [6e13, 0], [0, 6e13]]);
        translate([3.5e13, 3.5e13]) offset(delta = 4e12) square(2e13);
    }
    translate([1e13, 1e13]) circle(r = 8e12, $fn = 24);
}
