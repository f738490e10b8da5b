// A preview example: OpenSCAD's modifiers and colour alpha as its preview
// (F5) shows them (README, "Preview renders"; docs/preview.md).
// A flanged hub: the '#' marks the bore and one bolt hole, so the bore's
// subtracted cylinder shows translucent red where it was cut; the bolt
// hole's is one of four in a for(), a union, which OpenSCAD's preview
// leaves a '#' operand out of, so that hole is drilled in the render only,
// and the preview shows its cylinder red over the flange; the '%'
// shaft is a mating part drawn translucent grey, not part of the solid; the
// guard over the flange is coloured with alpha 0.4, so the hub shows
// through it. Exported to preview.csg with:
//   openscad -o "$PWD/preview.csg" "$PWD/preview.scad"

$fn = 64;

flange = 70;   // flange diameter
hub = 34;      // hub diameter
bore = 16;
bolts = 4;
bolt_circle = 52;

difference() {
    union() {
        cylinder(d = flange, h = 8);
        cylinder(d = hub, h = 30);
    }
    // the bore, highlighted
    #translate([0, 0, -5]) cylinder(d = bore, h = 40);
    // the bolt holes, the one in front highlighted
    for (k = [0 : bolts - 1])
        rotate([0, 0, k * 360 / bolts + 45])
            translate([bolt_circle / 2, 0, -1])
                if (k == 2) #cylinder(d = 7, h = 10);
                else cylinder(d = 7, h = 10);
}

// the shaft it takes: not part of the model, drawn for reference
%translate([0, 0, -30]) cylinder(d = bore, h = 90);

// a translucent guard over half the flange
color("SteelBlue", 0.4)
    translate([0, 0, 8]) intersection() {
        difference() {
            cylinder(d = flange, h = 14);
            translate([0, 0, -1]) cylinder(d = flange - 6, h = 13);
        }
        translate([0, -flange / 2, 0]) cube([flange / 2, flange, 14]);
    }
