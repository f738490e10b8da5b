// import of an ASCII STL (import_stl_part.stl beside this file: a stepped,
// non-convex block), drilled through.
// camera: 35,-40,30,5,4,3
// files: import_stl_part.stl
difference() {
    import("import_stl_part.stl");
    translate([2.5, 4, -1]) cylinder(r = 1, h = 10, $fn = 16);
}
