// Looking down the axis of a fine sphere at its pole.
// camera: 0.3,0.2,40,0,0,0
sphere(10, $fn = 64);
