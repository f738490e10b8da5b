// A fluted knob: the source of knob.stl (openscad -o knob.stl knob.scad).
difference() {
    cylinder(r = 10, h = 8, $fn = 48);
    for (i = [0 : 11])
        rotate([0, 0, i * 30]) translate([10.5, 0, -1]) cylinder(r = 2, h = 10, $fn = 16);
    translate([0, 0, 4]) cylinder(r = 3, h = 5, $fn = 24);
}
