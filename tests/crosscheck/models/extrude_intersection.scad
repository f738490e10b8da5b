// linear_extrude of a square intersected with a circle (rounded corners),
// centred; checked against a 96-gon's mesh.
// camera: 20,-24,30,0,0,0
linear_extrude(height = 6, center = true) intersection() {
    square(10, center = true);
    circle(r = 6.5, $fn = 96);
}
