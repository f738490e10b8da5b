// cube(size) with a vector size, at the origin.
// camera: 30,-40,25,5,10,2.5
cube([10, 20, 5]);
