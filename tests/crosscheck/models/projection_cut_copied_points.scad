// A cut through a box whose faces use two copies of two of its corners
// (points 8 and 9 repeat 5 and 6): OpenSCAD 2021.01 merges the copies when
// it makes the Nef polyhedron it cuts, so the box is closed and cut to a
// rectangle, as the box is drawn.
// camera: 8,-12,14,2,3,0.5
linear_extrude(1) projection(cut = true) translate([0, 0, -1])
    polyhedron(points = [[0, 0, 0], [3.81, 0, 0], [3.81, 6.47, 0], [0, 6.47, 0], [0, 0, 5.34],
                         [3.81, 0, 5.34], [3.81, 6.47, 5.34], [0, 6.47, 5.34], [3.81, 0, 5.34],
                         [3.81, 6.47, 5.34]],
               faces = [[4, 5, 1, 0], [7, 6, 5, 4], [8, 6, 2, 1], [9, 7, 3, 2], [7, 4, 0, 3],
                        [0, 1, 2], [0, 2, 3]]);
