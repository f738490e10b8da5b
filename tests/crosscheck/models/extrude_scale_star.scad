// A five-pointed star (a non-convex polygon) scaled to 0.3 at the top, a
// star scaled to a point and one scaled onto a segment ([1, 0]).
// camera: 25,-45,40,8,0,4
function star(r1, r2, n) =
    [for (i = [0 : 2 * n - 1]) let (a = 180 * i / n, r = i % 2 ? r2 : r1)
        [r * cos(a), r * sin(a)]];
linear_extrude(height = 8, scale = 0.3) polygon(star(6, 2.5, 5));
translate([14, 0, 0]) linear_extrude(height = 6, scale = 0) polygon(star(4, 2, 5));
translate([0, 14, 0]) linear_extrude(height = 5, scale = [1, 0]) circle(3, $fn = 24);
