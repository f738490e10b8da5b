// cylinder(h, r) with defaults: 13 fragments (2 pi 4 / 2 = 12.6).
// camera: 20,-25,18,0,0,5
cylinder(h = 10, r = 4);
