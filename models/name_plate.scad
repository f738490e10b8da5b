// A name plate: a rounded plate with the name engraved 1 unit deep and a
// serif line of text standing on it. Text is extruded exactly (its
// quadratic curves, not polygons); with --faithful it is OpenSCAD's
// polygons.
difference() {
    union() {  // a rounded rectangle
        translate([-42, -12, 0]) cube([84, 24, 4]);
        translate([-38, -16, 0]) cube([76, 32, 4]);
        for (x = [-38, 38], y = [-12, 12]) translate([x, y, 0]) cylinder(r = 4, h = 4, $fn = 48);
    }
    translate([0, 2, 3]) linear_extrude(height = 2)
        text("spancast", size = 11, halign = "center", valign = "center");
}
translate([0, -10, 4]) linear_extrude(height = 1)
    text("exact text", size = 5, font = "Liberation Serif:style=Italic", halign = "center");
