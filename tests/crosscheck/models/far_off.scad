// Far from the origin: coordinates in the thousands, 6 digits in the .csg.
// camera: 1030,-1040,1025,1000.12,-1000.12,1000.12
translate([1000.123456, -1000.123456, 1000.123456]) difference() {
    cube(10, center = true);
    sphere(6.2, $fn = 30);
}
