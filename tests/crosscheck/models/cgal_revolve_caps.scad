// rotate_extrude below 360 degrees inside CGAL booleans, whose end caps
// are a holed and a concave profile: a holed square swept through 250
// degrees summed with a cube (OpenSCAD splits it into convex parts through
// CGAL), and the outline of a U swept through 200 degrees with a slot cut
// across it. CGAL takes each end cap as one face with holes, as OpenSCAD
// tessellates it; a fan per contour overlaps itself.
// camera: 8,-40,45,8,0,2
minkowski() {
    rotate_extrude(angle = 250, $fn = 6)
        translate([5, 0]) difference() { square(6, center = true); square(2, center = true); }
    cube(0.5);
}
translate([20, 0, 0]) linear_extrude(1) projection()
    difference() {
        rotate_extrude(angle = 200, $fn = 10)
            polygon([[2, 0], [8, 0], [8, 8], [6, 8], [6, 2], [4, 2], [4, 8], [2, 8]]);
        translate([0, 0, 4]) cube([20, 3, 10], center = true);
    }
