// A V-belt pulley: a revolved profile (hub, web, rim with a groove), a
// rounded lip on each side of the groove (circles revolved: tori), a bore
// and a set-screw hole, and a quarter cut away to show the section.
difference() {
    rotate_extrude($fn = 96) {
        polygon(points = [[4, -6], [8, -6], [8, -2], [16, -2], [16, -5], [22, -5],
                          [22, -4], [19, 0], [22, 4], [22, 5], [16, 5], [16, 2],
                          [8, 2], [8, 6], [4, 6]]);
        translate([22, 4.5]) circle(r = 0.8, $fn = 24);
        translate([22, -4.5]) circle(r = 0.8, $fn = 24);
    }
    translate([0, 0, -10]) cylinder(h = 20, r = 4, $fn = 48);
    rotate([0, 90, 0]) cylinder(h = 12, r = 1.5, $fn = 24);
    translate([0, 0, -10]) rotate([0, 0, 180]) cube([30, 30, 20]);
}
