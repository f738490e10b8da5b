// projection(cut = true) through a part-turn rotate_extrude of a ring:
// the cut crosses its end caps, each one face for the outline and one
// for the hole, so the section's loops run along the cap's line both
// ways. The section is two strips, as OpenSCAD's exact cut has them; a
// union of the loops that joined them by a bridge of no width across the
// hole drew the bridge's walls once extruded. Scaled up after the cut.
// camera: 4,-30,40,-3,0,0
linear_extrude(1) scale(3) projection(cut = true)
    scale([0.73, 0.65, 0.42]) rotate_extrude($fn = 12, angle = 239)
        translate([3.11, 0]) difference() { circle(r = 1.1, $fn = 6); circle(r = 0.34, $fn = 12); }
