// A centred cone with its apex down (r1 = 0), seen from below.
// camera: 18,-22,-14,0,0,0
cylinder(h = 10, r1 = 0, r2 = 5, $fn = 9, center = true);
