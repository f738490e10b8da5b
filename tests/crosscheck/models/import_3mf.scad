// import of a 3MF mesh: import_3mf.3mf, OpenSCAD's own 3MF export of a
// cube with a 12-sided hole, read through lib3mf as OpenSCAD reads it;
// imported twice, moved and turned.
// camera: 40,-45,45,14,6,5
// files: import_3mf.3mf
translate([1, 2, 3]) import("import_3mf.3mf");
translate([20, 0, 0]) rotate([0, 0, 30]) import("import_3mf.3mf");
