// projection() of polyhedra without volume: sheets given both ways, a
// square, an L (faces that are not convex) turned and stood on edge, and
// a square given as four triangles up and one pentagon down. OpenSCAD
// 2021.01 projects each face's outline (PolysetUtils::project), turned
// counter-clockwise, and unites them.
// camera: 5,-10,14,5,4,0
L = [[0, 0, 0], [4, 0, 0], [4, 1, 0], [1, 1, 0], [1, 4, 0], [0, 4, 0]];
linear_extrude(1) projection() {
    polyhedron(points = [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], faces = [[0, 1, 2, 3], [3, 2, 1, 0]]);
    translate([3, 0, 0]) rotate([40, 20, 10]) polyhedron(points = L, faces = [[0, 1, 2, 3, 4, 5], [5, 4, 3, 2, 1, 0]]);
    translate([0, 6, 0]) rotate([90, 0, 0]) polyhedron(points = L, faces = [[0, 1, 2, 3, 4, 5], [5, 4, 3, 2, 1, 0]]);
    translate([8, 6, 0]) polyhedron(points = [[0, 0, 0], [2, 0, 0], [2, 2, 0], [0, 2, 0], [1, 1, 0]],
                                    faces = [[0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4], [4, 3, 2, 1, 0]]);
}
