// resize() of curved leaves where OpenSCAD's polygons stand for them in
// both modes (inside hull and projection): the scale comes from the
// polygons' box, as OpenSCAD resizes its mesh, not from the exact
// sphere's, which is wider than a sphere of $fn = 6 and gave a smaller
// hull and projection in exact mode.
// camera: 14,-22,20,4,0,1
hull() {
    resize([3.68, 7.5, 3.71]) sphere(r = 2.73, $fn = 6);
    translate([6, 0, 0]) cube(1);
}
translate([0, 10, 0]) linear_extrude(1)
    projection() resize([3.68, 7.5, 3.71]) sphere(r = 2.73, $fn = 6);
translate([8, 10, 0]) linear_extrude(1) projection() hull() {
    resize([3.38, 0, 5.42], auto = true) sphere(r = 1.16, $fn = 8);
    translate([2, 0, 0]) cube(1);
}
