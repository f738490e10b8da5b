// Drums whose top caps are single non-planar faces of 5 to 9 points, far
// off any plane, so that the plane libtess2 projects a cap onto (the axis
// along which its points spread most) folds many of them: OpenSCAD 2021.01
// cuts those at the crossings, drops the triangles with the new points and
// mends the rest; a fan of the cap is another surface. Seeded, so the
// model is the same on every run.
// camera: 0,-60,55,0,0,2
function cap(n, seed) =
    let(r = rands(0, 1, 2 * n, seed))
    [for (i = [0 : n - 1]) let(a = 360 * i / n)
        [3 * cos(a), 3 * sin(a), 4 + 5 * (r[i] - 0.5) + 2 * r[n + i] * cos(2 * a)]];
module drum(n, seed) {
    top = cap(n, seed);
    bottom = [for (i = [0 : n - 1]) let(a = 360 * i / n) [3 * cos(a), 3 * sin(a), 0]];
    polyhedron(points = concat(bottom, top),
               faces = concat([[for (i = [0 : n - 1]) i]],
                              [[for (i = [n - 1 : -1 : 0]) n + i]],
                              [for (i = [0 : n - 1]) [i, n + i, n + (i + 1) % n, (i + 1) % n]]));
}
for (k = [0 : 24])
    translate([8 * (k % 5) - 16, 8 * floor(k / 5) - 16, 0])
        drum(5 + k % 5, 7 * k + 1);
