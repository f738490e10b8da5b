// A large $fn; also checked in exact mode against this mesh.
// camera: 20,-24,16,0,0,5
cylinder(h = 10, r = 5, $fn = 128);
