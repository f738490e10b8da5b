// A twisted extrusion reaches CGAL as OpenSCAD 2021.01's PolySet reaches
// it: each cap in the triangles of Polygon2d::tessellate (CGAL's
// constrained Delaunay triangulation of the profile, the top one after the
// twist and scale), the caps first, before the sides. Where the extrusion
// crosses itself, the Nef polyhedron depends on those triangles, and so
// does whether CGAL's next boolean fails an assertion. Left: an
// intersection under hull() that CGAL takes (spancast's one-face caps made
// it fail, and the hull was the cone's). Right: a union that OpenSCAD's
// CGAL fails ("CGAL error in CGALUtils::applyUnion3D"), so the difference,
// its projection and the extrusion of that are empty (spancast drew them).
// camera: 2.5,-10,9,2.5,1,0.8
hull() intersection() {
    translate([0.801, 0.974, 0.742]) cylinder(r1 = 1.26, r2 = 1.49, h = 1.68, $fn = 10);
    scale([1.3, 1, 1.1]) linear_extrude(height = 1.2, twist = 30, scale = 0.7)
        polygon([[-0.71, 0.62], [-0.88, 1.61], [-0.64, 1.18], [0.62, 1.11], [1.53, 1.11]]);
}
translate([4, 0, 0]) linear_extrude(1) projection() difference() {
    union() {
        cylinder(r = 0.65, h = 1.2, $fn = 10);
        linear_extrude(height = 2.46, twist = 150, slices = 1)
            polygon([[0.23, 0.7], [-0.32, 1.31], [0.28, 1.34], [0.73, 0.65]]);
    }
    cube(0.1);
}
