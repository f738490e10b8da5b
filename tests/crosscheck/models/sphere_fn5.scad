// A small odd $fn: 5 fragments, 3 rings.
// camera: 30,-40,20,0,0,0
sphere(r = 10, $fn = 5);
