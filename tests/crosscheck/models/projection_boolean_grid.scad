// The outline of an intersection, which OpenSCAD projects from its CGAL
// Nef polyhedron: the cube and the twisted extrusion reach CGAL with their
// points on OpenSCAD's grid of 2^-20, and where the wall cuts the cube's
// top that moves a corner of the outline into the next cell of the
// clipper's grid of 2^-16 (1.5e-5 across a side wall).
// camera: 2.16,-3.59,3.83,0.15,0.72,0.5
linear_extrude(1) projection() intersection() {
    cube(2.19, center = true);
    linear_extrude(height = 1.17, twist = 45, slices = 2, scale = 0.6)
        polygon([[-0.41, 1.23], [1.96, 1.75], [-1.35, 1.15], [0.06, 1.01]]);
}
