// import of an SVG drawing (import_svg.svg beside this file): a rounded
// rect, cubic and quadratic Beziers with a hole, an elliptical arc, a
// circle, a rotated ellipse, a group with translate and scale holding a
// polygon, a stroked polyline and line, smooth curves, a viewBox scaled
// to a page in millimetres; extruded as drawn and again centred at 96 dpi.
// camera: 15,-70,90,15,10,2
// files: import_svg.svg
linear_extrude(height = 3) import("import_svg.svg");
translate([0, 0, 3]) linear_extrude(height = 1) import("import_svg.svg", center = true, dpi = 96);
