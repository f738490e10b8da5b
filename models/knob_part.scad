// The fluted knob imported from an STL mesh (made from knob.scad), with a
// shaft bore and a set-screw hole drilled through it.
difference() {
    import("knob.stl");
    translate([0, 0, -1]) cylinder(r = 1.5, h = 20, $fn = 24);
    translate([0, 0, 2]) rotate([90, 0, 0]) cylinder(r = 1, h = 20, $fn = 16);
}
