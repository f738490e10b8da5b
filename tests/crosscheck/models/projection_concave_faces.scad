// projection(cut = false) of solids whose top faces are not convex: an
// extruded L and a polyhedron on a concave quadrilateral, and that
// polyhedron without its top (not closed: its faces projected as they
// are, the bottom turned up). Their caps are fans of triangles that
// overlap, some wound back; the projection is the L (area 12) and the
// concave quad (area 3), not their hulls (16 and 4).
// camera: 8,-14,16,3,2,0.5
linear_extrude(1) {
    projection() linear_extrude(2) difference() { square(4); square(2); }
    translate([7, 2]) projection()
        polyhedron(points = [[2, 0, 0], [0, 2, 0], [-2, 0, 0], [0, 0.5, 0], [2, 0, 2],
                             [0, 2, 2], [-2, 0, 2], [0, 0.5, 2]],
                   faces = [[0, 1, 2, 3], [7, 6, 5, 4], [0, 4, 5, 1], [1, 5, 6, 2],
                            [2, 6, 7, 3], [3, 7, 4, 0]]);
    translate([7, -3]) projection()
        polyhedron(points = [[2, 0, 0], [0, 2, 0], [-2, 0, 0], [0, 0.5, 0], [2, 0, 2],
                             [0, 2, 2], [-2, 0, 2], [0, 0.5, 2]],
                   faces = [[0, 1, 2, 3], [0, 4, 5, 1], [1, 5, 6, 2], [2, 6, 7, 3],
                            [3, 7, 4, 0]]);
}
