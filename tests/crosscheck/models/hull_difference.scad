// The hull of a cube with a corner cut away by a sphere, and of a rotated
// cube drilled through: the hull takes the vertices of each difference's
// mesh, so the cut corner stays cut and the drilled hole vanishes.
// camera: 35,-45,30,5,0,0
hull() {
    difference() {
        cube(10, center = true);
        translate([5, -5, 5]) sphere(r = 4, $fn = 16);
    }
    translate([14, 0, 0]) rotate([0, 0, 30]) difference() {
        cube(4, center = true);
        cylinder(r = 1, h = 10, center = true, $fn = 12);
    }
}
