// Polyhedra with a face out of its plane, rotated inside a union under
// hull(), a difference under minkowski() and a union under
// projection(cut = true). OpenSCAD 2021.01 moves their points by the
// transforms since the boolean (PolySet::transform) and makes its Nef
// polyhedra of them there: the first box is kept (as written, CGAL's
// check of its top fails and it is lost), and the others are split on
// the diagonal the rotation gives.
// camera: 40,-50,50,8,10,2
module box() polyhedron(
    points = [[0, 0, 0], [5.5, 0, 0], [5.5, 5.17, 0], [0, 5.17, 0],
              [0, 0, 7.31], [5.5, 0, 6.34], [5.5, 5.17, 7.31], [0, 5.17, 6.71]],
    faces = [[0, 1, 2, 3], [4, 5, 1, 0], [7, 6, 5, 4],
             [5, 6, 2, 1], [6, 7, 3, 2], [7, 4, 0, 3]]);
module box2() polyhedron(
    points = [[0, 0, 0], [6, 0, 0], [6, 4, 0], [0, 4, 0],
              [0, 0, 4], [6, 0, 3], [6, 4, 3], [0, 4, 3]],
    faces = [[0, 1, 2, 3], [4, 5, 1, 0], [7, 6, 5, 4],
             [5, 6, 2, 1], [6, 7, 3, 2], [7, 4, 0, 3]]);
hull() union() {
    rotate([0, 0, 90]) box();
    translate([3, 8, 0]) cube(1);
}
translate([20, 0, 0]) minkowski() {
    difference() {
        rotate([0, 0, 90]) box2();
        translate([-1, 1, -1]) cube(0.5);
    }
    cube(0.2);
}
translate([8, 20, 0]) linear_extrude(1) projection(cut = true)
    translate([0, 0, -3.5]) union() {
        rotate([0, 0, 90]) box2();
        translate([3, 3, 0]) cube(1);
    }
