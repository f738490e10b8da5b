// A non-convex polyhedron (an L-shaped prism) summed with a sphere: OpenSCAD
// splits the polyhedron into convex parts (CGAL's convex decomposition) and
// unites the hulls of the pairwise sums.
// camera: 30,-40,35,6,6,2
minkowski() {
    polyhedron(points = [[0, 0, 0], [12, 0, 0], [12, 4, 0], [4, 4, 0], [4, 12, 0],
                         [0, 12, 0], [0, 0, 4], [12, 0, 4], [12, 4, 4], [4, 4, 4],
                         [4, 12, 4], [0, 12, 4]],
               faces = [[5, 4, 3, 2, 1, 0], [6, 7, 8, 9, 10, 11], [0, 1, 7, 6],
                        [1, 2, 8, 7], [2, 3, 9, 8], [3, 4, 10, 9], [4, 5, 11, 10],
                        [5, 0, 6, 11]]);
    sphere(r = 1.5, $fn = 10);
}
