// Seen from inside: the eye sits in the cavity of a hollow box with a
// pillar and a ball, looking at the inner walls.
// camera: -6,-6,-4,5,3,2
difference() {
    cube(20, center = true);
    cube(18, center = true);
}
translate([4, 2, -9]) cylinder(h = 18, r = 1.5, $fn = 10);
translate([-3, 5, 3]) sphere(2, $fn = 14);
