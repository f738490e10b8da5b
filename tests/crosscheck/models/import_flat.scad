// 2D imports outside an extrusion, in a 2D model: import_svg.svg and the
// "plate" layer of extrude_import_dxf.dxf united, moved and cut by a
// circle, drawn flat. OpenSCAD takes a .svg or .dxf import as 2D
// by its extension, wherever it stands.
// camera: 25,-25,80,25,20,0
// files: import_svg.svg extrude_import_dxf.dxf
// 2d: flat
difference() {
    union() {
        import("import_svg.svg");
        translate([-10, 0]) import("extrude_import_dxf.dxf", layer = "plate", $fn = 24);
    }
    translate([30, 20]) circle(r = 4, $fn = 20);
}
