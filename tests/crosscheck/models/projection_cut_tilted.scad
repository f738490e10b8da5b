// projection(cut = true) of a tilted cube with a spherical cavity, cut
// below its centre, extruded: the section is a square band with a hole
// (OpenSCAD's polygons of the sphere, cut by the plane).
// camera: 20,-30,35,0,0,1.5
linear_extrude(3) projection(cut = true) translate([0, 0, -1]) rotate([30, 0, 0])
    difference() { cube(10, center = true); sphere(6); }
