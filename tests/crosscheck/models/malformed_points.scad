// Malformed polyhedron and polygon arguments, read as OpenSCAD 2021.01
// reads them (primitives.cc): a point no face reads is never read, [x, y]
// is [x, y, 0], a face or path that is not a vector is an empty one, and
// paths that are not a vector are none (all the points). A point that a
// face reads first and cannot be converted ends the faces there (here
// before any face: nothing), and a polygon point that cannot be converted
// empties the polygon; spancast warns of both, as OpenSCAD logs them.
// camera: 14,-18,16,4,4,1
polyhedron(points = [[0, 0, 4], [4, 0, 4], [0, 4, 4], [1, 1], "junk"],
           faces = [[0, 1, 2], 7, [0, 3, 1], [0, 2, 3], [1, 3, 2], []]);
translate([6, 0, 0])
    linear_extrude(height = 2)
        polygon(points = [[0, 0], [4, 0], [4, 4], [0, 4]], paths = [[0, 1, 2, 3], 5]);
translate([0, 6, 0])
    linear_extrude(height = 3)
        polygon(points = [[0, 0], [4, 0], [0, 4]], paths = 5);
translate([6, 6, 0]) {
    linear_extrude(height = 5)
        polygon(points = [[0, 0], [4, 0], [0, 4], [1, "a"]]);
    polyhedron(points = [[0, 0, "a"], [4, 0, 0], [0, 4, 0], [0, 0, 4]],
               faces = [[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]]);
}
