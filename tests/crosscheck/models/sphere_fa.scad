// $fa drives the count: 360 / 20 = 18 fragments.
// camera: 60,-80,50,0,0,0
sphere(r = 20, $fa = 20, $fs = 0.1);
