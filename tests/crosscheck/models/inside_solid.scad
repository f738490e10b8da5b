// Seen from inside the solid: the eye is inside a sphere, so every ray
// starts inside and meets the surface where it leaves.
// camera: 1,-2,0.5,3,4,2
sphere(10, $fn = 20);
