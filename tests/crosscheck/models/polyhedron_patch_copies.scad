// A closed surface made the way BOSL's Bezier patches make one: every
// face lists its own copies of its corners, so no two faces share a point
// number, and the mesh is closed only once equal points are merged, as
// OpenSCAD merges them (its grid of 2^-20). The faces are non-planar
// quads of a rounded box (a superellipsoid), with a bore through it.
// camera: 26,-30,22,0,0,0
n = 24;   // around
m = 12;   // pole to pole
e = 0.5;  // squareness
function sp(c, p) = sign(c) * pow(abs(c), p);
function pt(i, j) =
    let(u = 360 * i / n, v = -90 + 180 * j / m)
    [9 * sp(cos(v), e) * sp(cos(u), e), 7 * sp(cos(v), e) * sp(sin(u), e),
     6 * sp(sin(v), e)];
quads = [for (i = [0 : n - 1]) for (j = [0 : m - 1])
    [pt(i, j), pt(i, j + 1), pt(i + 1, j + 1), pt(i + 1, j)]];
difference() {
    polyhedron(points = [for (q = quads) for (p = q) p],
               faces = [for (k = [0 : len(quads) - 1]) [4 * k, 4 * k + 1, 4 * k + 2, 4 * k + 3]]);
    cylinder(r = 2, h = 20, center = true, $fn = 24);
}
