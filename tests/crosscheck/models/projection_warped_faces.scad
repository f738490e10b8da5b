// projection() of a polyhedron whose side quads leave their planes (a
// triangular prism with its top moved off its base): OpenSCAD projects
// each face's outline as it is written (PolysetUtils::project), not the
// triangles its render splits the face into, and where a quad is folded
// the two differ (here by 0.05 at the far corner).
// camera: 3,-9,9,0.07,-1.3,0.5
linear_extrude(1) projection(cut = false) scale([1.12, 1.92, 1.14])
    polyhedron(points = [[1.36, 0.0, 0], [-0.345, 0.598, 0], [-1.25, -2.165, 0],
                         [1.373, 0.183, 2.868], [-0.118, 0.825, 2.779],
                         [-1.153, -2.192, 2.882]],
               faces = [[2, 1, 0], [3, 4, 5], [0, 1, 4, 3], [1, 2, 5, 4], [2, 0, 3, 5]]);
