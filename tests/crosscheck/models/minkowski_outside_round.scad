// Round-Anything's minkowskiOutsideRound (github.com/Irev-Dev/Round-Anything,
// MIT): the outside edges of an L-shaped part rounded by a minkowski of the
// difference of a box and the minkowski of the difference of a box and the
// part. Minkowski of a difference goes through CGAL's convex decomposition.
// camera: 40,-55,45,8,8,3
module minkowskiOutsideRound(r = 1, cubeSize = [40, 40, 40]) {
    minkowski() {
        difference() {
            cube(cubeSize - [0.1, 0.1, 0.1], center = true);
            minkowski() {
                difference() {
                    cube(cubeSize, center = true);
                    children();
                }
                sphere(r, $fn = 8);
            }
        }
        sphere(r, $fn = 8);
    }
}
minkowskiOutsideRound(2)
    union() {
        cube([20, 8, 6]);
        cube([8, 20, 6]);
    }
