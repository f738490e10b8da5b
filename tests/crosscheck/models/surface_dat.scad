// surface() of a .dat height map (surface_dat.dat beside this file).
// camera: 14,-12,16,2.5,2,1
// files: surface_dat.dat
scale([1, 1, 0.5]) surface(file = "surface_dat.dat", center = false);
