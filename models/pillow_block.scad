// A preview example: a pillow block (a split bearing housing) with a bronze
// bushing, for section views and edge drawings (README, "Preview renders").
// The housing is one solid drilled for the bushing and two bolts and
// grooved for grease; the bushing is a separate coloured part in the bore.
// Exported to pillow_block.csg with:
//   openscad -o "$PWD/pillow_block.csg" "$PWD/pillow_block.scad"

$fn = 72;

base = [90, 34, 12];
bore = 30;    // housing bore, the bushing's outside diameter
shaft = 20;   // the bushing's bore
axis_z = 34;  // height of the shaft axis

difference() {
    union() {
        translate([-base[0] / 2, -base[1] / 2, 0]) cube(base);
        // the boss around the bore, blended into the base by a block
        translate([0, 0, axis_z]) rotate([90, 0, 0])
            cylinder(d = 52, h = base[1], center = true);
        translate([-26, -base[1] / 2, 0]) cube([52, base[1], axis_z]);
    }
    // the bore and its chamfers
    translate([0, 0, axis_z]) rotate([90, 0, 0]) {
        cylinder(d = bore, h = base[1] + 2, center = true);
        translate([0, 0, base[1] / 2 - 2]) cylinder(d1 = bore, d2 = bore + 6, h = 3);
        translate([0, 0, -base[1] / 2 - 1]) cylinder(d1 = bore + 6, d2 = bore, h = 3);
    }
    // the grease hole from the top into the bore
    translate([0, 0, axis_z]) cylinder(d = 5, h = 40);
    // bolt holes with counterbores
    for (x = [-34, 34]) translate([x, 0, -1]) {
        cylinder(d = 9, h = base[2] + 2);
        translate([0, 0, base[2] - 3 + 1]) cylinder(d = 15, h = 4);
    }
    // a groove along the base's underside
    translate([-base[0] / 2 - 1, -4, -1]) cube([base[0] + 2, 8, 3]);
}

// the bronze bushing, flanged on the front
color([0.80, 0.50, 0.20]) translate([0, 0, axis_z]) rotate([90, 0, 0])
    difference() {
        union() {
            cylinder(d = bore, h = base[1], center = true);
            translate([0, 0, base[1] / 2 - 0.01]) cylinder(d = bore + 8, h = 3);
        }
        cylinder(d = shaft, h = base[1] + 10, center = true);
    }
