// linear_extrude of text("spancast") in the default font (Liberation Sans,
// 10 units, OpenSCAD's 4 points per curve), seen from the front and above.
// camera: 27,-58,72,27,2,1
linear_extrude(height = 3) text("spancast");
