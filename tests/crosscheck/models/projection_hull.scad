// projection of a hull, cut and seen from above, extruded side by side:
// the hull of OpenSCAD's sphere and cylinder polygons, cut at z = 0, and
// its outline.
// camera: 4,-22,30,3,6,0
linear_extrude(2) projection(cut = true)
    hull() { translate([0, 0, -3]) sphere(2); translate([6, 0, 2]) cylinder(r = 1, h = 2); }
translate([0, 12, 0]) linear_extrude(1) projection()
    hull() { translate([0, 0, -3]) sphere(2); translate([6, 0, 2]) cylinder(r = 1, h = 2); }
