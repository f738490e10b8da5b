// A mirrored profile with holes, shrunk by offset(r = -0.5), twisted under
// a non-uniform scale; a polygon with a hole path wound like its outline.
// camera: 30,-40,40,2,2,4
linear_extrude(height = 8, center = true, twist = -75, scale = [0.5, 1.5], $fn = 24)
    mirror([1, 0, 0]) offset(r = -0.5) difference() {
        square([10, 6], center = true);
        translate([2.5, 0]) circle(1.2);
        translate([-2.5, 0]) square(2, center = true);
    }
translate([4, 10, 0]) linear_extrude(height = 3, twist = 200)
    polygon([[0, 0], [6, 0], [6, 6], [0, 6], [2, 2], [4, 2], [4, 4], [2, 4]],
            [[0, 1, 2, 3], [4, 5, 6, 7]]);
