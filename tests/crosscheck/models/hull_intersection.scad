// The hull of a cube and a cylinder intersected (a bought part in a printer
// assembly), beside a small cube: hull() of a boolean takes the vertices of
// the boolean's mesh, where the cylinder's edges cross the cube's faces.
// camera: 30,-40,25,4,0,0
hull() {
    intersection() {
        cube(10, center = true);
        cylinder(r = 6, h = 20, center = true, $fn = 32);
    }
    translate([12, 0, 3]) cube(2, center = true);
}
