// A plate with through holes; also checked in exact mode.
// camera: 18,-30,40,0,0,0
difference() {
    cube([24, 14, 4], center = true);
    for (x = [-7, 0, 7]) translate([x, 0, 0]) cylinder(h = 6, r = 3, center = true, $fn = 64);
}
