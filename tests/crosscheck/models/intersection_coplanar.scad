// Intersections sharing faces: a cube and a cylinder of the same height,
// and a cube with a sphere cut at its equator.
// camera: 25,-35,25,7,0,3
intersection() {
    cube([6, 6, 6]);
    cylinder(h = 6, r = 6, $fn = 16);
}
translate([14, 0, 0]) intersection() {
    translate([-5, -5, 0]) cube([10, 10, 5]);
    sphere(5, $fn = 18);
}
