// Unions with coincident faces: two cubes sharing a face, a cylinder
// standing on the top face, a cube overlapping on a shared plane.
// camera: 25,-30,25,5,5,5
union() {
    cube([10, 10, 5]);
    translate([0, 0, 5]) cube([10, 10, 5]);
    translate([5, 5, 10]) cylinder(h = 3, r = 3, $fn = 12);
    translate([10, 0, 0]) cube([4, 10, 10]);
}
