// A convex polyhedron (a truncated pyramid) next to a cube.
// camera: 25,-30,20,4,2,2
polyhedron(points = [[0, 0, 0], [6, 0, 0], [6, 6, 0], [0, 6, 0],
                     [1.5, 1.5, 4], [4.5, 1.5, 4], [4.5, 4.5, 4], [1.5, 4.5, 4]],
           faces = [[0, 1, 2, 3], [4, 5, 1, 0], [5, 6, 2, 1], [6, 7, 3, 2],
                    [7, 4, 0, 3], [7, 6, 5, 4]]);
translate([8, 0, 0]) cube([3, 3, 3]);
