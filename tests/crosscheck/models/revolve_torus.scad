// A torus ring: a circle off the axis revolved; the circle's own $fn
// gives the profile's polygon, the extrusion's the rings.
// camera: 24,-30,20,0,0,0
rotate_extrude($fn = 30) translate([7, 0]) circle(r = 2.5, $fn = 16);
