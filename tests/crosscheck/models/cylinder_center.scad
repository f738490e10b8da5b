// center = true, a hexagonal prism.
// camera: 15,-20,12,0,0,0
cylinder(h = 10, r = 4, center = true, $fn = 6);
