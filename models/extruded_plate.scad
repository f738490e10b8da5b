// An L-shaped plate extruded from a 2D profile with a slot (a polygon with
// two paths), a rounded boss (a circle) and two drilled holes.
difference() {
    union() {
        linear_extrude(height = 4)
            polygon(points = [[0, 0], [40, 0], [40, 10], [12, 10], [12, 30], [0, 30],
                              [3, 14], [9, 14], [9, 26], [3, 26]],
                    paths = [[0, 1, 2, 3, 4, 5], [6, 7, 8, 9]]);
        translate([32, 5, 0]) linear_extrude(height = 8) circle(r = 4, $fn = 40);
    }
    translate([32, 5, -1]) cylinder(r = 1.5, h = 10, $fn = 24);
    translate([20, 5, -1]) cylinder(r = 2, h = 6, $fn = 24);
}
