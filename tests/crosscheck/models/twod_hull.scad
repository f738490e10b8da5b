// hull() of 2D shapes in a 2D model (no extrusion): OpenSCAD's convex hull
// of the square's and the circles' polygon points, drawn flat.
// camera: 6,-14,24,6,2,0
// 2d: flat
hull() {
    square([3, 2], center = true);
    translate([10, 4]) circle(r = 2, $fn = 24);
    translate([5, -3]) circle(d = 1.5, $fn = 7);
}
