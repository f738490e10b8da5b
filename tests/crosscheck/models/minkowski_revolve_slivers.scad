// A rotate_extrude of a kite (a ring, not convex) summed with a cube: CGAL's
// convex decomposition of the ring gives parts whose corners include nearly
// collinear triples, so their sums' hulls have sliver faces, whose rounded
// normals point anywhere; a sliver's plane must not cut its part.
// camera: 20,-24,18,0,0,0
minkowski() {
    rotate_extrude($fn = 10) translate([3, 0])
        polygon([[1.5, 0], [0, 4.53], [-2.38, 0], [0, -4.78]]);
    cube(0.5);
}
