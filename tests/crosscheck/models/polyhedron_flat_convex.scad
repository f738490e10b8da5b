// A polyhedron whose points all lie in one plane (a pyramid with its apex
// in its base, from OpenSCAD's own test builtin-invalid-range-test.scad)
// beside a pyramid. OpenSCAD 2021.01 finds the flat one convex
// (is_approximately_convex: no fold turns inward) and makes its Nef
// polyhedron from CGAL's convex hull of its points, which has no volume;
// the union of the two is the pyramid. spancast built the flat one with
// CGAL's polyhedron builder, as a mesh that is not convex, and CGAL's
// union with it failed, leaving the model empty.
// camera: 0,-30,25,0,0,0
module pyramid(h)
    polyhedron(points = [[10, 10, 0], [10, -10, 0], [-10, -10, 0], [-10, 10, 0], [0, 0, h]],
               faces = [[0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4], [1, 0, 3], [2, 1, 3]]);
pyramid(1);
pyramid(0);
