// sphere(d = ...), and d winning over r.
// camera: 20,-25,15,5,0,0
sphere(d = 7, $fn = 16);
translate([10, 0, 0]) sphere(r = 100, d = 5, $fn = 10);
