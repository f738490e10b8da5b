// A large $fn; also checked in exact mode against this mesh.
// camera: 30,-45,30,0,0,0
sphere(r = 10, $fn = 96);
