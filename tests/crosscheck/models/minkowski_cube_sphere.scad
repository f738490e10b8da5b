// minkowski of a plate and a sphere: a plate with rounded edges.
// camera: 40,-50,40,0,0,0
minkowski() {
    cube([20, 12, 3], center = true);
    sphere(r = 2, $fn = 20);
}
