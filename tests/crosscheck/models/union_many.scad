// A union of 200 objects: a 10 x 10 grid of cubes with small spheres on top.
// camera: 45,-40,40,15,15,0
for (i = [0:9], j = [0:9]) {
    translate([3 * i, 3 * j, 0]) cube(2);
    translate([3 * i + 1, 3 * j + 1, 2.4]) sphere(0.6, $fn = 6);
}
