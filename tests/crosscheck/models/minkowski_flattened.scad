// minkowski() with meshes under a singular transform. OpenSCAD 2021.01
// flattens a mesh's points (PolySet::transform) and sums the flat mesh:
// a cube with a flat square (a 3 x 3 x 1 box), a sphere with a sheet
// from a turned cylinder, and a cube with a flattened L-shaped
// polyhedron, which OpenSCAD finds convex (its faces are flat) and sums
// as the hull of its points, and a cube with a flattened box extrusion.
// camera: 5,-12,12,5,4,1
minkowski() { cube(1); translate([0, 0, 3]) scale([1, 1, 0]) cube(2); }
translate([6, 0, 0]) minkowski() {
    sphere(0.5, $fn = 8);
    rotate([30, 0, 0]) scale([1, 0, 1]) cylinder(r = 1, h = 2, $fn = 8);
}
translate([6, 6, 0]) minkowski() {
    cube(0.5);
    scale([1, 1, 0]) polyhedron(
        points = [[0, 0, 0], [4, 0, 0], [4, 1, 0], [1, 1, 0], [1, 4, 0], [0, 4, 0],
                  [0, 0, 2], [4, 0, 2], [4, 1, 2], [1, 1, 2], [1, 4, 2], [0, 4, 2]],
        faces = [[0, 1, 2, 3, 4, 5], [11, 10, 9, 8, 7, 6], [0, 6, 7, 1], [1, 7, 8, 2],
                 [2, 8, 9, 3], [3, 9, 10, 4], [4, 10, 11, 5], [5, 11, 6, 0]]);
}
translate([0, 6, 0]) minkowski() {
    cube(0.5);
    rotate([0, 0, 20]) scale([1, 1, 0]) linear_extrude(2) square([3, 1]);
}
