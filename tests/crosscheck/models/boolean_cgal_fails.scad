// A thin profile twisted a quarter turn crosses itself, and CGAL's
// intersection of it with a cylinder fails one of its assertions. OpenSCAD
// 2021.01 logs "CGAL error in CGALUtils::applyBinaryOperator intersection"
// and keeps the intersection as it was before that operand, the extrusion
// alone, taking no later operand (the cube of the third); spancast does the
// same, with the error as a warning. Under hull() and projection().
// camera: 3,-9,8,2,0.5,0.8
module sliver()
    linear_extrude(height = 2.2, twist = 90)
        polygon([[-0.54, 0.59], [0.03, 0.56], [-0.27, 0.6], [-1.64, 1.14]]);
hull() intersection() { sliver(); cylinder(r = 0.83, h = 1.2, $fn = 10); }
translate([4, 0, 0]) linear_extrude(1) projection()
    intersection() { sliver(); cylinder(r = 0.83, h = 1.2, $fn = 10); cube(0.5); }
