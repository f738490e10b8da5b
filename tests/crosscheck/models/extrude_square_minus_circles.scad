// linear_extrude of a square minus three circles: exact mode keeps the
// holes round; checked against a 64-gon's mesh.
// camera: 18,-30,40,0,0,2
linear_extrude(height = 4) difference() {
    square([24, 14], center = true);
    for (x = [-7, 0, 7]) translate([x, 0]) circle(r = 3, $fn = 64);
}
