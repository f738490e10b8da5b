// A box whose top is a quad out of its plane, its corners over a
// rectangle, so that the two ways to split it tie in the plane the split
// is made in. OpenSCAD 2021.01 moves a polyhedron's points by the
// transforms above it (PolySet::transform, a mirror turning its faces) and
// splits the quad where the render takes it: the rotation decides the
// diagonal, not the points as written.
// camera: 14,-18,20,-2,3,2
rotate([0, 0, 90]) polyhedron(
    points = [[0, 0, 0], [6, 0, 0], [6, 4, 0], [0, 4, 0],
              [0, 0, 4], [6, 0, 3], [6, 4, 3], [0, 4, 3]],
    faces = [[0, 1, 2, 3], [4, 5, 1, 0], [7, 6, 5, 4],
             [5, 6, 2, 1], [6, 7, 3, 2], [7, 4, 0, 3]]);
