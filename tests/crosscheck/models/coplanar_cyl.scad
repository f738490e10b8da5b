// Faithful cylinders sharing planes: a tube whose bore shares both caps,
// and a cylinder minus its own upper half (coincident side planes).
// camera: 25,-32,28,6,0,5
difference() { cylinder(h = 10, r = 5, $fn = 8); cylinder(h = 10, r = 3, $fn = 8); }
translate([13, 0, 0]) difference() {
    cylinder(h = 10, r = 4, $fn = 10);
    translate([0, 0, 5]) cylinder(h = 10, r = 4, $fn = 10);
}
