// import of a DXF drawing (extrude_import_dxf.dxf beside this file) in
// both extrusions: layer "plate" (LINEs and an ARC joined into one outline,
// a CIRCLE and a closed LWPOLYLINE as holes) extruded, layer "ring" (a
// closed LWPOLYLINE) scaled by 0.5 and revolved on top of it.
// camera: 14,-12,16,4,3,2
// files: extrude_import_dxf.dxf
union() {
    linear_extrude(height = 2) import("extrude_import_dxf.dxf", layer = "plate", $fn = 24);
    translate([4, 4, 2]) rotate_extrude($fn = 32)
        import("extrude_import_dxf.dxf", layer = "ring", scale = 0.5);
}
