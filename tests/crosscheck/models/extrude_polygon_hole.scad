// linear_extrude of a polygon with a hole (paths), beside a union of a
// square and an overlapping triangle, rotated and mirrored: polygons only,
// so the exact solid is the mesh's.
// camera: -30,-55,60,2,1,0
rotate([0, 0, 20]) linear_extrude(height = 5, center = true)
    polygon(points = [[0, 0], [20, 0], [20, 14], [10, 20], [0, 14],
                      [5, 4], [15, 4], [15, 12], [5, 12]],
            paths = [[0, 1, 2, 3, 4], [5, 6, 7, 8]]);
mirror([1, 0, 0]) translate([2, -12, 0]) linear_extrude(height = 3) {
    square([10, 4]);
    translate([2, 0]) polygon([[0, 0], [4, 8], [8, 0]]);
}
