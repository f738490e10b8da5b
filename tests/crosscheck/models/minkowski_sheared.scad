// Minkowski sums of a cube and an L-shaped prism under a shear, which is
// not convex: OpenSCAD 2021.01 decomposes the prism into convex parts
// where the shear has moved its points (CGAL's convex decomposition
// depends on the frame) and sums each part. Each sum matched OpenSCAD
// only once the parts were found there, one in faithful mode and one in
// exact mode.
// camera: 30,-30,30,6,3,2
module l() polyhedron(
    points = [[0, 0, 0], [4.69, 0, 0], [4.69, 1.48, 0], [1.48, 1.48, 0],
              [1.48, 5.72, 0], [0, 5.72, 0], [0, 0, 3.99], [4.69, 0, 3.99],
              [4.69, 1.48, 3.99], [1.48, 1.48, 3.99], [1.48, 5.72, 3.99],
              [0, 5.72, 3.99]],
    faces = [[0, 1, 2, 3, 4, 5], [11, 10, 9, 8, 7, 6], [0, 6, 7, 1],
             [1, 7, 8, 2], [2, 8, 9, 3], [3, 9, 10, 4], [4, 10, 11, 5],
             [5, 11, 6, 0]]);
minkowski() {
    multmatrix([[1, -0.22, 0.21, -1.49], [0.16, 1, -0.15, -0.09],
                [0, -0.03, 1, 0], [0, 0, 0, 1]]) l();
    cube(1.16, center = true);
}
translate([12, 0, 0]) minkowski() {
    multmatrix([[1, -0.16, -0.24, -1.49], [-0.06, 1, -0.21, -0.09],
                [-0.26, -0.06, 1, 0], [0, 0, 0, 1]]) l();
    cube(1.16, center = true);
}
