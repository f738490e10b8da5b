// rotate_extrude of a projection: the section at z = 0 of a sphere
// intersected with a cube, moved off the axis, revolved.
// camera: 30,-40,30,0,0,0
rotate_extrude($fn = 40) translate([6, 0]) projection(cut = true)
    intersection() { sphere(3, $fn = 24); cube(4.4, center = true); }
