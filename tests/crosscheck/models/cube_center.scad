// cube(number, center = true), looked at from below.
// camera: -14,-18,-20,0,0,0
cube(8, center = true);
