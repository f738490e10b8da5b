// A twisted prism whose cross-section is a wavy heptagon: its two caps
// are non-planar heptagons and its sides non-planar hexagons, each
// spanning two layers. OpenSCAD 2021.01 splits every face of more than
// three points with libtess2's constrained Delaunay triangulation; a fan
// about each face's first point is a different surface. A notch is cut
// so that OpenSCAD takes it through CGAL.
// camera: 22,-26,30,0,0,5
k = 7;      // points round a layer
l = 8;      // layers (even: side faces span two)
function pt(i, j) =
    let(a = 360 * j / k + 9 * i, r = 5 + 0.8 * cos(3 * a + 40 * i),
        z = 1.5 * i + 0.9 * sin(2 * a + 30 * i) + (i == 0 ? -0.6 * cos(a) : 0))
    [r * cos(a), r * sin(a), z];
function at(i, j) = i * k + j % k;
difference() {
    polyhedron(points = [for (i = [0 : l]) for (j = [0 : k - 1]) pt(i, j)],
               faces = concat(
                   [[for (j = [0 : k - 1]) at(0, j)]],
                   [[for (j = [k - 1 : -1 : 0]) at(l, j)]],
                   [for (i = [0 : 2 : l - 1]) for (j = [0 : k - 1])
                       [at(i, j), at(i + 1, j), at(i + 2, j),
                        at(i + 2, j + 1), at(i + 1, j + 1), at(i, j + 1)]]));
    translate([2, -1, 8]) cube([6, 2, 10]);
}
