// import of AMF and 3MF files of several overlapping objects, which
// OpenSCAD 2021.01 unites with CGAL: import_objects_overlap.amf and .3mf
// (the same three objects, written by hand) hold a cube, a box wound inside
// out that overlaps it, and an octahedron that overlaps both; a triangle
// soup of them would count the overlaps twice and the inside-out box
// against the cube. The AMF as it is, the 3MF moved and turned.
// camera: 60,-70,70,22,12,8
// files: import_objects_overlap.amf import_objects_overlap.3mf
import("import_objects_overlap.amf");
translate([30, 0, 0]) rotate([0, 0, 20]) import("import_objects_overlap.3mf");
