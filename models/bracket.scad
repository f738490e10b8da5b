// spancast's default model: a machined mounting bracket.
// A chamfered base plate with four countersunk bolt holes, an upright web
// with a bored boss, a slot, and a chamfered rib. Exported to bracket.csg
// with: openscad -o "$PWD/bracket.csg" "$PWD/bracket.scad"

$fn = 64;

plate = [80, 50, 8];
chamfer = 2;

// A box with its four vertical edges and top edges chamfered: the cube
// minus 45-degree prisms along each edge.
module chamfered_plate(size, c) {
    difference() {
        cube(size);
        for (x = [0, size[0]]) for (y = [0, size[1]])
            translate([x, y, -1]) rotate([0, 0, 45])
                cube([c * sqrt(2), c * sqrt(2), size[2] + 2], center = true);
        for (y = [0, size[1]])
            translate([-1, y, size[2]]) rotate([45, 0, 0])
                cube([size[0] + 2, c * sqrt(2), c * sqrt(2)], center = true);
        for (x = [0, size[0]])
            translate([x, -1, size[2]]) rotate([0, 45, 0])
                cube([c * sqrt(2), size[1] + 2, c * sqrt(2)], center = true);
    }
}

module countersunk_hole(d, depth) {
    translate([0, 0, -1]) cylinder(d = d, h = depth + 2);
    translate([0, 0, depth - d / 2]) cylinder(d1 = d, d2 = 2 * d, h = d / 2 + 0.01);
}

difference() {
    union() {
        chamfered_plate(plate, chamfer);
        // upright web
        translate([25, 30, 0]) cube([30, 10, 40]);
        // boss on the web
        translate([40, 30, 30]) rotate([-90, 0, 0]) cylinder(d = 22, h = 16);
        // rib between plate and web
        intersection() {
            translate([37, 8, 0]) cube([6, 22, 30]);
            translate([40, 30, 8]) rotate([0, 90, 0])
                cylinder(r = 22, h = 10, center = true);
        }
        // round bosses on the plate
        for (x = [10, 70]) translate([x, 40, 0]) cylinder(d = 12, h = 12);
    }
    // bore through the boss, with a chamfered mouth
    translate([40, 20, 30]) rotate([-90, 0, 0]) cylinder(d = 12, h = 40);
    translate([40, 45.01, 30]) rotate([90, 0, 0]) cylinder(d1 = 16, d2 = 10, h = 3);
    // countersunk bolt holes
    for (x = [10, 70]) translate([x, 12, 0]) countersunk_hole(6, plate[2]);
    for (x = [10, 70]) translate([x, 40, 0]) countersunk_hole(5, 12);
    // slot through the plate
    slot();
}

module slot() {
    translate([30, 4, -1]) cube([20, 6, 10]);
    for (x = [30, 50]) translate([x, 7, -1]) cylinder(d = 6, h = 10);
}
