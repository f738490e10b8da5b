// rotate_extrude's last side, a profile with a hole at 10 degrees (and at
// -10), turned to face the projection: OpenSCAD projects the side's
// triangles, which leave the hole open, and a short sweep does not cover
// it. Its outline and hole lie in a plane of no constant x, y or z, and
// are taken together as the one face the builder made of them.
// camera: 4,-10,20,4,3,0
linear_extrude(1) {
    projection() rotate([90, 0, 0]) rotate([0, 0, -10])
        rotate_extrude(angle = 10, $fn = 36)
            translate([3, 0]) difference() { square(2); translate([0.5, 0.5]) square(1); }
    translate([0, 4]) projection() rotate([-90, 0, 0]) rotate([0, 0, 10])
        rotate_extrude(angle = -10, $fn = 36)
            translate([3, 0]) difference() { square(2); translate([0.5, 0.5]) square(1); }
}
