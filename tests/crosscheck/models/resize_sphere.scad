// resize of a sphere to an ellipsoid, the z size from auto.
// camera: 40,-45,35,0,0,0
resize([30, 12, 0], auto = [false, false, true]) sphere(r = 5, $fn = 30);
