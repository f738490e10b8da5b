// Extrusions inside CGAL booleans, whose caps have holes and concave
// outlines: the outline of a holed plate stood on end with a block taken
// out, and a holed U-shaped prism summed with a sphere (OpenSCAD splits it
// into convex parts through CGAL). CGAL takes each cap as one face with
// holes, as OpenSCAD tessellates it; a fan per contour overlaps itself.
// camera: 12,-40,40,12,2,1
linear_extrude(1) projection()
    difference() {
        rotate([90, 0, 0]) linear_extrude(10, center = true)
            difference() { square(8, center = true); circle(2, $fn = 16); }
        translate([3, 0, 0]) cube([3, 12, 3], center = true);
    }
translate([14, -4, 0]) minkowski() {
    linear_extrude(2) difference() {
        polygon([[0, 0], [8, 0], [8, 8], [6, 8], [6, 2], [2, 2], [2, 8], [0, 8]]);
        translate([3.5, 0.5]) square(1);
    }
    sphere(0.5, $fn = 8);
}
