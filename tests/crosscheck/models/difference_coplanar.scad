// Differences whose tools are flush with the faces they cut: a through
// pocket with coplanar top and bottom, and a half-height slab removed.
// camera: 28,-34,30,8,5,5
difference() {
    cube(10);
    translate([2, 2, 0]) cube([6, 6, 10]);
}
translate([14, 0, 0]) difference() {
    cube(10);
    cube([10, 10, 5]);
}
