// A cone with its apex up (r2 = 0).
// camera: 20,-25,15,0,0,5
cylinder(h = 10, r1 = 5, r2 = 0, $fn = 12);
