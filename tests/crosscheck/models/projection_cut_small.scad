// projection(cut = true) of a box 0.1 wide, extruded. OpenSCAD 2021.01
// snaps the box to its grid of 2^-20 where it makes the Nef polyhedron
// and hands the section on exactly (CGALUtils::project): the edge at
// 0.0999994 wide, not on Clipper's grid of 2^-16 (0.0999908).
// camera: 0.55,-0.55,0.6,0.35,-0.25,0.5
linear_extrude(1) projection(cut = true) translate([0.3, -0.3, -0.5]) cube([0.1, 0.1, 1]);
