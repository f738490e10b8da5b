// linear_extrude (no twist) of circles: OpenSCAD's polygon for $fn and for
// $fa/$fs, centred and not, one standing on a cube.
// camera: 35,-40,35,4,2,3
linear_extrude(height = 8, center = true) circle(r = 4, $fn = 40);
translate([10, 0, 0]) linear_extrude(height = 3) circle(d = 5);
translate([0, 10, -4]) difference() {
    cube([6, 6, 6]);
    translate([3, 3, -1]) linear_extrude(height = 8) circle(r = 2, $fn = 7);
}
