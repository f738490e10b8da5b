// Centred text with a larger $fn (9 points per curve), a serif font with
// kerning ("AV") and holes ("Bo"), extruded about z = 0.
// camera: 3,-42,52,0,0,0
linear_extrude(height = 2, center = true)
    text("AVBo@", size = 8, font = "Liberation Serif", halign = "center",
         valign = "center", $fn = 64);
