// Thin walls: a box 0.1 thick and a plate 0.05 thick.
// camera: 30,-35,30,10,10,3
difference() {
    cube([20, 20, 8]);
    translate([0.1, 0.1, 0.1]) cube([19.8, 19.8, 8]);
}
translate([5, 25, 0]) cube([10, 10, 0.05]);
