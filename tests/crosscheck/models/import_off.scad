// import of an OFF file (import_off_part.off beside this file: a
// non-convex arrow prism with a colour after each face), with a cube
// unioned on top of it.
// camera: 17,-19,15,5,2,2
// files: import_off_part.off
union() {
    import("import_off_part.off");
    translate([1, 1.5, 3]) cube([2, 1, 2]);
}
