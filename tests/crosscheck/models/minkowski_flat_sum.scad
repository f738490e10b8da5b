// minkowski() sums its children two at a time, as OpenSCAD 2021.01 does
// (applyMinkowski), and of each sum of two convex parts keeps the hull of
// the corners that are neither on a line nor in a plane with their
// neighbours: a sum that is flat keeps none, and is empty. So three cubes
// each flattened onto a segment along a different axis (OpenSCAD's own
// test, testdata/scad/3D/issues/issue1671.scad) sum to nothing: the first
// two make a flat square, which is dropped before the third could make
// it a cube. spancast drew the unit cube. A cube and a segment, whose sum
// is not flat, give a box; a flat square and a segment across it, a box.
// camera: 6,-9,7,2.5,0.5,0.8
minkowski() {
    scale([0, 0, 1]) cube(1);
    scale([0, 1, 0]) cube(1);
    scale([1, 0, 0]) cube(1);
}
translate([2, 0, 0]) minkowski() { cube(1); scale([0, 0, 1]) cube(1); }
translate([4, 0, 0]) minkowski() { scale([1, 1, 0]) cube(1); scale([0, 0, 1]) cube(1.5); }
