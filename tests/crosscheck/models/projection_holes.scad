// The outline of extrusions with holes seen from above: each loop of an
// extrusion's cap is a face of its own, so a hole in the top cap looks
// down and must take its part out of the outline's face. A washer, a
// square scaled towards its top (whose hole is the top's, the smallest),
// a tilted ring (the hole narrowed by the tilt), text with counters, and
// an O widened towards its top.
// camera: 16,-48,62,16,6,0
linear_extrude(1) projection()
    linear_extrude(2) difference() { circle(5, $fn = 24); circle(3, $fn = 24); }
translate([13, 0, 0]) linear_extrude(1) projection()
    linear_extrude(height = 1, scale = 0.5) difference() {
        square(8, center = true);
        square(2, center = true);
    }
translate([25, 0, 0]) linear_extrude(1) projection()
    rotate([40, 0, 0]) linear_extrude(3, center = true)
        difference() { square(8, center = true); square(4, center = true); }
translate([0, 8, 0]) linear_extrude(1) projection()
    linear_extrude(2) text("OBA", size = 8, font = "Liberation Sans");
// An O widened towards its top: its hole is the bottom's, which the
// union of the top cap's triangles must leave whole (the union with a
// bridge out to the hole lost the bridge to the clipper's cleaning, and
// the hole's pieces filled).
translate([31, 13, 0]) linear_extrude(1) scale(3) projection()
    linear_extrude(height = 0.64, scale = 1.44)
        text("O", size = 2.82, font = "Liberation Sans", halign = "center", valign = "center");
