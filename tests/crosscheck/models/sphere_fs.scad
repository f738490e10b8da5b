// $fs drives the count: 2 pi 3 / 0.5 = 37.7 -> 38 fragments.
// camera: 10,-12,8,0,0,0
sphere(r = 3, $fa = 1, $fs = 0.5);
