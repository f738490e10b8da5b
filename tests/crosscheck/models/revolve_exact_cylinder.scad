// A rectangle on the axis revolved: the cylinder r = 3, h = 5. Faithful,
// its rings are OpenSCAD's cylinder's 128 points; exact, the vertical edge
// sweeps the wall, the level ones the caps, and the edge on the axis
// nothing, checked against the mesh within the tessellation's bound.
// camera: 9,-12,10,0,0,2.5
rotate_extrude($fn = 128) square([3, 5]);
