// A polyhedron of two boxes that pass through each other, its faces
// written counter-clockwise seen from outside (OpenSCAD's are clockwise):
// OpenSCAD's CGAL builder takes the faces in that order, and of that mesh
// CGAL makes a Nef polyhedron of both boxes, whose cut is their union.
// Made from the same faces in another order, or wound the other way, the
// Nef polyhedron is one box.
// camera: 1.5,-3,6,1.5,1.5,0.5
linear_extrude(1) projection(cut = true)
    polyhedron(points = [[0, 0, -1], [2, 0, -1], [2, 2, -1], [0, 2, -1],
                         [0, 0, 1], [2, 0, 1], [2, 2, 1], [0, 2, 1],
                         [1, 1, -1], [3, 1, -1], [3, 3, -1], [1, 3, -1],
                         [1, 1, 1], [3, 1, 1], [3, 3, 1], [1, 3, 1]],
               faces = [[3, 2, 1, 0], [4, 5, 6, 7], [0, 1, 5, 4], [1, 2, 6, 5],
                        [2, 3, 7, 6], [3, 0, 4, 7], [11, 10, 9, 8], [12, 13, 14, 15],
                        [8, 9, 13, 12], [9, 10, 14, 13], [10, 11, 15, 14],
                        [11, 8, 12, 15]]);
