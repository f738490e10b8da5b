// A rounded rectangle by offset(r) of a square, extruded with a
// non-uniform scale (OpenSCAD's diagonal slice rule), and a mitred and a
// chamfered offset of a polygon.
// camera: 30,-40,40,6,2,3
linear_extrude(height = 6, scale = [1.4, 0.7]) offset(r = 2) square([10, 4], center = true);
translate([0, 12, 0]) linear_extrude(height = 4, twist = 30)
    offset(delta = 1.5) polygon([[0, 0], [8, 0], [4, 3], [8, 6], [0, 6]]);
translate([14, 12, 0]) linear_extrude(height = 4, scale = 1.2)
    offset(delta = 1, chamfer = true) square(4);
