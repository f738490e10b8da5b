// The classic: a cube intersected with a sphere, minus three cylinders.
// camera: 20,-26,18,0,0,0
difference() {
    intersection() {
        cube(10, center = true);
        sphere(6.5, $fn = 40);
    }
    cylinder(h = 12, r = 3, center = true, $fn = 24);
    rotate([90, 0, 0]) cylinder(h = 12, r = 3, center = true, $fn = 24);
    rotate([0, 90, 0]) cylinder(h = 12, r = 3, center = true, $fn = 24);
}
