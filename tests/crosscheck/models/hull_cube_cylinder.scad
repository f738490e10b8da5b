// The hull of a cube and a rotated cylinder beside it.
// camera: 40,-60,45,8,0,5
hull() {
    cube([6, 6, 6], center = true);
    translate([18, 0, 8]) rotate([30, 0, 0]) cylinder(h = 6, r1 = 5, r2 = 3, center = true, $fn = 30);
}
