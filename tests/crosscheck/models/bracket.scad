// The default model, a machined bracket: countersunk holes, a slot,
// chamfers, a bored boss and gussets ($fn = 64), as a real part.
// camera: 120,-135,120,40,25,22
// spancast's default model: a machined mounting bracket.
// A chamfered base plate with countersunk bolt holes and a slot, an upright
// web with a bored, chamfered boss, two gussets and two round bosses.
// Exported to bracket.csg with:
//   openscad -o "$PWD/bracket.csg" "$PWD/bracket.scad"

$fn = 64;

plate = [80, 50, 8];
chamfer = 2;

// A box with its vertical and top edges chamfered: the cube minus
// 45-degree prisms centred on each edge.
module chamfered_plate(size, c) {
    w = c * sqrt(2);
    difference() {
        cube(size);
        for (x = [0, size[0]]) for (y = [0, size[1]])
            translate([x, y, size[2] / 2]) rotate([0, 0, 45])
                cube([w, w, size[2] + 2], center = true);
        for (y = [0, size[1]])
            translate([size[0] / 2, y, size[2]]) rotate([45, 0, 0])
                cube([size[0] + 2, w, w], center = true);
        for (x = [0, size[0]])
            translate([x, size[1] / 2, size[2]]) rotate([0, 45, 0])
                cube([w, size[1] + 2, w], center = true);
    }
}

module countersunk_hole(d, depth) {
    translate([0, 0, -1]) cylinder(d = d, h = depth + 2);
    translate([0, 0, depth - d / 2]) cylinder(d1 = d, d2 = 2 * d, h = d / 2 + 0.01);
}

// A right-triangle plate in the yz plane, thickness t along x: zero
// height at y = 0, full height at y = depth.
module gusset(t, depth, height) {
    intersection() {
        cube([t, depth, height]);
        translate([-1, 0, 0]) rotate([-atan(depth / height), 0, 0])
            cube([t + 2, 2 * depth, 2 * height]);
    }
}

difference() {
    union() {
        chamfered_plate(plate, chamfer);
        // upright web
        translate([22, 36, 0]) cube([36, 10, 42]);
        // boss on the web's front face
        translate([40, 36.01, 30]) rotate([90, 0, 0]) cylinder(d = 24, h = 12);
        // gussets beside the web
        for (x = [22, 53]) translate([x, 24, 0]) gusset(5, 12.01, 30);
        // round bosses on the plate
        for (x = [10, 70]) translate([x, 40, 0]) cylinder(d = 12, h = 12);
    }
    // bore through the boss, with a chamfered mouth
    translate([40, 50, 30]) rotate([90, 0, 0]) cylinder(d = 12, h = 40);
    translate([40, 23.99, 30]) rotate([-90, 0, 0]) cylinder(d1 = 16, d2 = 10, h = 3);
    // countersunk bolt holes
    for (x = [10, 70]) translate([x, 12, 0]) countersunk_hole(6, plate[2]);
    for (x = [10, 70]) translate([x, 40, 0]) countersunk_hole(5, 12);
    // slot through the plate
    translate([30, 9, -1]) cube([20, 6, 10]);
    for (x = [30, 50]) translate([x, 12, -1]) cylinder(d = 6, h = 10);
}
