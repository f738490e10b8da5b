// The twisted ring of polyhedron_twisted_quads.scad (a torus whose tube
// cross-section is an ellipse turning as it goes round, knot-like), with
// its quads joined in pairs along the ring: every face is a non-planar
// hexagon. OpenSCAD 2021.01 splits each with libtess2's constrained
// Delaunay triangulation; a fan about the first point of each face is a
// different surface. A slot is cut out so that OpenSCAD takes it through
// CGAL.
// camera: 30,-40,32,0,0,0
n = 48;     // segments round the ring (even: faces span two)
m = 10;     // points round the tube
function pt(i, j) =
    let(u = 360 * i / n, v = 360 * j / m + u,
        r = 10 + 3 * cos(v), z = 1.6 * sin(v) + 0.9 * cos(v + 2 * u))
    [r * cos(u), r * sin(u) * 0.8, z];
function at(i, j) = (i % n) * m + j % m;
difference() {
    polyhedron(points = [for (i = [0 : n - 1]) for (j = [0 : m - 1]) pt(i, j)],
               faces = [for (i = [0 : 2 : n - 1]) for (j = [0 : m - 1])
                   [at(i, j), at(i + 1, j), at(i + 2, j),
                    at(i + 2, j + 1), at(i + 1, j + 1), at(i, j + 1)]]);
    translate([6, -2, -5]) cube([10, 4, 10]);
}
