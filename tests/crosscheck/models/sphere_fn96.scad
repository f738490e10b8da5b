// A large $fn; also checked in exact mode against this mesh.
// camera: 30,-45,30,0,0,0
// exact: sphere,10,96
sphere(r = 10, $fn = 96);
