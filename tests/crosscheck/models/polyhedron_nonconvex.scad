// A non-convex polyhedron: an L-shaped prism (quad faces, wound as
// OpenSCAD expects), with a hole drilled through its long arm.
// camera: 40,-45,35,6,4,3
difference() {
    polyhedron(points = [[0, 0, 0], [12, 0, 0], [12, 4, 0], [4, 4, 0], [4, 10, 0], [0, 10, 0],
                         [0, 0, 6], [12, 0, 6], [12, 4, 6], [4, 4, 6], [4, 10, 6], [0, 10, 6]],
               faces = [[5, 4, 3, 2, 1, 0], [6, 7, 8, 9, 10, 11],
                        [0, 1, 7, 6], [1, 2, 8, 7], [2, 3, 9, 8],
                        [3, 4, 10, 9], [4, 5, 11, 10], [5, 0, 6, 11]]);
    translate([8, -1, 3]) rotate([-90, 0, 0]) cylinder(r = 1.5, h = 6, $fn = 20);
}
