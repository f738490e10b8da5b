// resize() of 2D children in a 2D model (Polygon2d::resize): x to 20, y
// from auto (the x scale); a negative size is as 0 for the second one.
// camera: 5,-14,50,5,6,0
// 2d: flat
resize([20, 0], auto = true) {
    circle(r = 3, $fn = 20);
    translate([4, 0]) square([6, 2]);
}
translate([0, 12]) resize([-5, 6]) difference() {
    square([8, 4]);
    translate([2, 1]) circle(r = 1, $fn = 10);
}
