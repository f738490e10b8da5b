// A spinning top whose profile touches the axis at its tip and along its
// stem, and a clockwise partial sweep of a profile drawn at x < 0.
// camera: 22,-26,18,0,0,4
rotate_extrude($fn = 24)
    polygon([[0, 0], [5, 5], [4, 7], [1, 7], [1, 10], [0, 10]]);
translate([0, 0, -4]) rotate_extrude(angle = -120, $fn = 24)
    polygon([[-2, 0], [-6, 0], [-6, 2], [-2, 3]]);
