// OpenSCAD 2021.01's render unites the objects at a file's top level with
// CGAL, as a union() of them. Beside a minkowski sum that reaches into it,
// a triangle extruded with the scale [1.5, 0.8] and resized (its walls
// cross) makes that union fail ("CGAL error in CGALUtils::applyUnion3D"),
// and the whole model is empty. In --faithful mode spancast takes the top
// level as it takes a boolean over such a mesh (boolean_self_crossing), so
// its render is empty too; it drew both objects.
// camera: 4.48,-5.69,4.98,1.47,0.76,0
// openscad: empty
resize([1.56, 0, 2.34], auto = [true, false, true])
    linear_extrude(height = 0.55, center = true, scale = [1.5, 0.8]) translate([-1.5, 0])
        polygon([[2.34, 0.76], [2.03, -0.19], [2.65, 1.7]]);
minkowski() {
    rotate([73, 21, 50]) linear_extrude(height = 2.71, center = true, scale = [1.5, 0.8])
        translate([-1.5, 0]) polygon([[2.99, 0.68], [0.95, 1.23], [2.42, 1.51]]);
    resize([3.57, 0, 3.84], auto = [true, false, true]) cube([1.73, 2.55, 1.2]);
}
