// linear_extrude (no twist) of a square plate with a pentagonal hole, given
// as one polygon with two paths (the inner path is a hole), beside a
// prism of a non-convex polygon.
// camera: 40,-45,40,12,6,3
linear_extrude(height = 5)
    polygon(points = [[0, 0], [16, 0], [16, 12], [0, 12],
                      [8, 3], [11, 5], [10, 9], [6, 9], [5, 5]],
            paths = [[0, 1, 2, 3], [4, 5, 6, 7, 8]]);
translate([19, 0, 0]) linear_extrude(height = 7, center = true)
    polygon([[0, 0], [6, 0], [6, 10], [3, 4], [0, 10]]);
