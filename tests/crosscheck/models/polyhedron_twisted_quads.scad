// A twisted ring of non-planar quads (a torus whose tube cross-section is
// an ellipse turning as it goes round, as in a knot or a twisted band),
// with a slot cut out so that OpenSCAD takes it through CGAL. OpenSCAD
// 2021.01 splits each quad along the diagonal libtess2's constrained
// Delaunay triangulation picks; splitting every quad along the same
// diagonal puts the surface off by up to a few 1e-3 of its size.
// camera: 30,-40,32,0,0,0
n = 48;     // segments round the ring
m = 10;     // points round the tube
function pt(i, j) =
    let(u = 360 * i / n, v = 360 * j / m + 3 * u,
        r = 10 + 3 * cos(v), z = 1.6 * sin(v) + 0.9 * cos(v + 2 * u))
    [r * cos(u), r * sin(u) * 0.8, z];
difference() {
    polyhedron(points = [for (i = [0 : n - 1]) for (j = [0 : m - 1]) pt(i, j)],
               faces = [for (i = [0 : n - 1]) for (j = [0 : m - 1])
                   [i * m + j, ((i + 1) % n) * m + j, ((i + 1) % n) * m + (j + 1) % m,
                    i * m + (j + 1) % m]]);
    translate([6, -2, -5]) cube([10, 4, 10]);
}
