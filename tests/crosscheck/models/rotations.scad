// The intersection of cubes rotated by 45 degrees (0.707107 in the .csg).
// camera: 18,-22,15,0,0,0
intersection() {
    cube(10, center = true);
    rotate([45, 0, 0]) cube(10, center = true);
    rotate([0, 0, 45]) cube(10, center = true);
}
