// A thin profile twisted in two slices: the walls on either side of its
// sliver pass through one another, so the extrusion's mesh crosses itself.
// Under hull() and minkowski() the intersection is a CGAL Nef polyhedron,
// made of the mesh as OpenSCAD hands it over (its faces wound inward); the
// next boolean of the one wound outward crashed inside CGAL.
// camera: 3,-12,9,2,-0.5,1
module sliver()
    linear_extrude(height = 1.85, twist = 21)
        polygon([[-0.53, 1.14], [1.71, 1.05], [-1.23, 1.04], [-0.25, 1.35], [-0.12, 1.63],
                 [1.94, 1.3]]);
hull() intersection() { sliver(); cube(5, center = true); }
translate([0, -3, 0]) minkowski() {
    intersection() { sliver(); cube(5, center = true); }
    cube(0.2);
}
translate([4, 0, 0]) difference() { sliver(); translate([0, 0, 1]) cube(5, center = true); }
