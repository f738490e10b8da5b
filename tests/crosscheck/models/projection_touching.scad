// Faces lying in the cut plane, as OpenSCAD 2021.01 keeps them: a cube
// standing on z = 0 minus a block touching its bottom face from below
// (a square with a hole), and two cubes that meet only in z = 0
// (their common face), and a cylinder and an extruded polygon mirrored.
// camera: 20,-25,30,8,5,0.5
linear_extrude(1) projection(cut = true) {
    difference() { cube(10); translate([2, 2, -10]) cube([4, 4, 10]); }
    intersection() {
        translate([12, 0, -10]) cube(10);
        translate([14, 0, 0]) cube(10);
    }
    mirror([1, 0, 0]) translate([3, 5, 0]) rotate([0, 90, 0]) cylinder(h = 6, r = 2, center = true, $fn = 12);
    translate([0, 12, 0]) rotate([90, 0, 0]) linear_extrude(4, center = true) polygon([[0, -1], [5, -2], [3, 2]]);
}
