// A non-convex polyhedron: a five-pointed star prism whose top is a low
// pyramid, as one closed polyhedron, with a ball cut out of one point.
n = 5;
outer = 20; inner = 8; h = 6; apex = 12;
ring = [for (i = [0 : 2 * n - 1])
            let(r = i % 2 == 0 ? outer : inner, a = 90 + i * 180 / n)
                [r * cos(a), r * sin(a)]];
m = 2 * n;
points = concat([for (p = ring) [p[0], p[1], 0]],
                [for (p = ring) [p[0], p[1], h]],
                [[0, 0, 0], [0, 0, apex]]);
faces = concat([for (i = [0 : m - 1]) [i, (i + 1) % m, m + (i + 1) % m, m + i]],
               [for (i = [0 : m - 1]) [2 * m, (i + 1) % m, i]],
               [for (i = [0 : m - 1]) [2 * m + 1, m + i, m + (i + 1) % m]]);
difference() {
    polyhedron(points = points, faces = faces);
    translate([0, outer, h]) sphere(r = 5, $fn = 32);
}
