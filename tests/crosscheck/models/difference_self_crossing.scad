// A difference whose first operand passes through itself (a triangle
// extruded with the scale [1.5, 0.8], resized: its walls cross) and whose
// second is a minkowski sum: OpenSCAD 2021.01's CGAL fails the difference
// ("CGAL error in CGALUtils::applyBinaryOperator difference") and keeps
// the first operand. In --faithful mode spancast takes such a boolean as
// CGAL's solid (boolean_self_crossing), so it does the same; it drew the
// difference.
// camera: 4.48,-5.69,4.98,1.47,0.76,0
difference() {
    resize([1.56, 0, 2.34], auto = [true, false, true])
        linear_extrude(height = 0.55, center = true, scale = [1.5, 0.8]) translate([-1.5, 0])
            polygon([[2.34, 0.76], [2.03, -0.19], [2.65, 1.7]]);
    minkowski() {
        rotate([73, 21, 50]) linear_extrude(height = 2.71, center = true, scale = [1.5, 0.8])
            translate([-1.5, 0]) polygon([[2.99, 0.68], [0.95, 1.23], [2.42, 1.51]]);
        resize([3.57, 0, 3.84], auto = [true, false, true]) cube([1.73, 2.55, 1.2]);
    }
}
