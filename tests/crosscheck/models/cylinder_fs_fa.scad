// $fa and $fs together: min(360 / 5, 2 pi 8 / 1) = 50.3 -> 51 fragments.
// camera: 25,-30,20,0,0,2.5
cylinder(h = 5, r = 8, $fa = 5, $fs = 1);
