// The old file forms of both extrusions, which OpenSCAD 2021.01 still
// reads (deprecated): linear_extrude(file, layer, origin, scale) with its
// scale [2, 2] scaling the drawing and then its top, rotate_extrude(file,
// layer, scale) revolving a drawing; extrude_import_dxf.dxf beside it.
// camera: 30,-40,40,8,6,3
// files: extrude_import_dxf.dxf
union() {
    linear_extrude(file = "extrude_import_dxf.dxf", layer = "plate", height = 2,
                   scale = 1.5, origin = [1, 1], $fn = 24);
    translate([4, 4, 2]) rotate_extrude(file = "extrude_import_dxf.dxf", layer = "ring",
                                        scale = 0.5, $fn = 32);
}
