// A square twisted by 120 degrees over its height (OpenSCAD's helix slice
// rule from $fa and $fs), and a centred one twisted the other way with
// given slices.
// camera: 30,-40,35,0,0,5
linear_extrude(height = 12, twist = 120) square(6, center = true);
translate([12, 0, 0])
    linear_extrude(height = 10, center = true, twist = -90, slices = 7) square([5, 3]);
