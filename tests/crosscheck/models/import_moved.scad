// An OFF box written in metres, its top out of its plane, scaled to
// millimetres and rotated in a union (a CGAL operation), and rotated
// alone. OpenSCAD 2021.01 moves an import's points by the transforms
// above it (PolySet::transform) before it snaps them to its 2^-20 grid
// and splits the top for CGAL or the render: in millimetres, on the
// diagonal the rotation gives.
// camera: 20,-26,24,0,4,2
// files: import_moved_box.off
union() {
    scale(1000) rotate([0, 0, 90]) import("import_moved_box.off");
    translate([2, 2, 0]) cube(1);
}
translate([0, 9, 0]) rotate([0, 0, 90]) scale(1000) import("import_moved_box.off");
