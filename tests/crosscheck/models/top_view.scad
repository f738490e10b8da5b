// Straight down (the camera's fallback basis) on a grid of cubes whose
// edges fall on pixel centres.
// camera: 0,0,50,0,0,0
// projection: o
for (i = [-2:2], j = [-2:2]) translate([i * 2, j * 2, 0]) cube(1);
sphere(0.8, $fn = 12);
