// A rounded box: the hull of eight spheres at a box's corners ($fn = 24).
// camera: 60,-70,50,0,0,0
$fn = 24;
hull() {
    for (x = [-15, 15], y = [-10, 10], z = [-5, 5])
        translate([x, y, z]) sphere(r = 4);
}
