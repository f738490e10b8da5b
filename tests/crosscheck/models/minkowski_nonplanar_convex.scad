// A box whose top quad is out of its plane (one corner lowered) summed with a
// cube, as written and mirrored. Split on its diagonal 5-7 the box has a
// valley, but OpenSCAD 2021.01's minkowski asks PolySet::is_convex of the
// faces as written, which finds it convex, and sums the hull of its points.
// camera: 22,-26,20,4,4,3
minkowski() {
    polyhedron(points = [[0, 0, 0], [6, 0, 0], [6, 5, 0], [0, 5, 0], [0, 0, 5], [6, 0, 4],
                         [6, 5, 5], [0, 5, 5]],
               faces = [[0, 1, 2, 3], [7, 6, 5, 4], [5, 6, 2, 1], [6, 7, 3, 2], [7, 4, 0, 3],
                        [4, 5, 1], [4, 1, 0]]);
    cube(0.5);
}
translate([-2, 0, 0]) minkowski() {
    mirror([1, 0, 0])
        polyhedron(points = [[0, 0, 0], [6, 0, 0], [6, 5, 0], [0, 5, 0], [0, 0, 5], [6, 0, 4],
                             [6, 5, 5], [0, 5, 5]],
                   faces = [[0, 1, 2, 3], [7, 6, 5, 4], [5, 6, 2, 1], [6, 7, 3, 2],
                            [7, 4, 0, 3], [4, 5, 1], [4, 1, 0]]);
    cube(0.5);
}
