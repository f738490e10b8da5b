// A boolean of a mesh that passes through itself is, in --faithful mode,
// the Nef polyhedron OpenSCAD 2021.01's CGAL makes of it, which no rule on
// the mesh follows, and where one of CGAL's assertions fails, OpenSCAD's
// result. A thin profile twisted a quarter turn (its walls cross),
// intersected with a cylinder: CGAL fails ("CGAL error in
// CGALUtils::applyBinaryOperator intersection") and OpenSCAD keeps the
// extrusion alone, which spancast drew as the intersection.
// camera: 3.36,-6.77,7.08,-0.25,0.97,1.1
module sliver()
    linear_extrude(height = 2.2, twist = 90)
        polygon([[-0.54, 0.59], [0.03, 0.56], [-0.27, 0.6], [-1.64, 1.14]]);
intersection() { sliver(); cylinder(r = 0.83, h = 1.2, $fn = 10); }
