// hull() of meshes under a singular transform. OpenSCAD 2021.01 flattens
// a mesh's points (PolySet::transform) and hulls the flat corners: a cube
// with a square sheet above it, a sphere with a sheet cut from a turned
// cylinder. A union of two solids (a Nef polyhedron) under the flattening
// map is removed instead, with OpenSCAD's warning "Scaling a 3D object
// with 0 - removing object", and the hull is the cube's.
// camera: 4,-12,10,3,2,1
hull() { cube(1); translate([2, 0, 3]) scale([1, 1, 0]) cube(1); }
translate([5, 0, 0]) hull() {
    cube(1);
    translate([2, 0, 3]) scale([1, 1, 0]) union() { cube(1); translate([0, 2, 0]) cube(1); }
}
translate([0, 5, 0]) hull() {
    sphere(1, $fn = 8);
    rotate([30, 0, 0]) scale([1, 0, 1]) translate([0, 0, 2]) cylinder(r = 1, h = 2, $fn = 8);
}
