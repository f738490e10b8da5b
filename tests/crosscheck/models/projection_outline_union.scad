// projection(cut = false) of the union of a rotated cube and a sphere,
// extruded: the outline of what is seen from above, down-facing faces
// included (OpenSCAD unites every face's projection).
// camera: 25,-35,40,4,0,1
linear_extrude(2) projection() union() {
    rotate([0, 0, 45]) rotate([30, 20, 0]) cube(10, center = true);
    translate([8, 0, 3]) sphere(5);
}
