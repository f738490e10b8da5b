// sphere(r) with the default $fa = 12, $fs = 2: 30 fragments, 15 rings.
// camera: 35,-45,25,0,0,0
sphere(10);
