// A partial revolution: 270 degrees of a square with a round bead, so the
// two end caps (the profile itself) face the camera.
// camera: 20,-24,16,0,0,2
rotate_extrude(angle = 270, $fn = 36) {
    translate([4, 0]) square([3, 5]);
    translate([7, 2.5]) circle(r = 1.5, $fn = 12);
}
