// minkowski() of a non-convex polygon and a circle in a 2D model: Clipper's
// Minkowski sum, as OpenSCAD's applyMinkowski2D, drawn flat.
// camera: 5,-12,26,5,4,0
// 2d: flat
minkowski() {
    difference() {
        square([10, 8]);
        translate([3, 2]) square([4, 10]);
    }
    circle(r = 1, $fn = 12);
}
