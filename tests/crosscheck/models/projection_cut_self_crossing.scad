// A cut through a twisted extrusion whose walls pass through one another
// (200 degrees in 3 slices, a concave profile scaled unevenly): OpenSCAD
// cuts the Nef polyhedron CGAL makes of that mesh, which keeps a small
// triangular hole where the walls cross, where the sections of the
// triangles, united, are solid. Seen from above through the hole.
// camera: 1.1,0.9,3,1.1,0.9,0
linear_extrude(1) projection(cut = true) translate([0, 0, -0.6])
    linear_extrude(height = 1.21, twist = 200, slices = 3, scale = [1.3, 0.7])
        polygon([[-1.82, 0.78], [-0.92, 0.51], [-0.54, 0.99], [1.94, 0.99],
                 [-1.86, 1.82], [-1.13, 0.77]]);
