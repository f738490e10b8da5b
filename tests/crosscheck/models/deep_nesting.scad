// 60 levels of nested transforms and booleans: every level moves, turns
// and stretches what follows; every 10th level adds a solid, every 15th
// level drills it.
// camera: 50,-60,40,0,3,14
module level(n) {
    if (n > 0) {
        if (n % 15 == 0) {
            difference() {
                translate([0.4, 0, 0.4]) rotate([0, 0, 6]) scale([1.01, 1, 1]) level(n - 1);
                translate([0, 0, 1]) cylinder(h = 8, r = 1, $fn = 8);
            }
        } else if (n % 10 == 0) {
            union() {
                cylinder(h = 2, r = 2, $fn = 8);
                translate([0.4, 0, 0.4]) rotate([0, 0, 6]) scale([1.01, 1, 1]) level(n - 1);
            }
        } else {
            translate([0.4, 0, 0.4]) rotate([0, 0, 6]) scale([1.01, 1, 1]) level(n - 1);
        }
    } else {
        cube(3, center = true);
    }
}
level(60);
