// Point indices that are not numbers, which OpenSCAD 2021.01 reads as 0
// (Value::toDouble): a polygon path [0, 1, 2, "a", 3] folds back to its
// first point, and a polyhedron face ["x", 3, 2] is [0, 3, 2].
// camera: 12,-16,14,3,2,1
linear_extrude(height = 2)
    polygon(points = [[0, 0], [6, 0], [6, 4], [0, 4]], paths = [[0, 1, 2, "a", 3]]);
translate([0, 6, 0])
    polyhedron(points = [[0, 0, 0], [4, 0, 0], [0, 4, 0], [0, 0, 4]],
               faces = [[0, 2, 1], [0, 1, 3], [1, 2, 3], ["x", 3, 2]]);
