// import of AMF meshes: import_amf.amf, OpenSCAD's own AMF export of a
// cube with a 12-sided hole (one object), and import_amf_two.amf, written
// by hand with two disjoint objects (a cube and a prism), which OpenSCAD
// unites; both moved, the second turned.
// camera: 40,-45,45,14,5,5
// files: import_amf.amf import_amf_two.amf
translate([1, 2, 3]) import("import_amf.amf");
translate([20, 0, 0]) rotate([0, 0, 30]) import("import_amf_two.amf");
