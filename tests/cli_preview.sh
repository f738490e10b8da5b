# Preview renders end to end: colour schemes, lighting, view presets,
# sheets, sections and edges through the command line, every output
# format, crops; then, against OpenSCAD 2021.01 itself, every colour
# scheme: the background pixel must equal OpenSCAD's PNG export exactly,
# and a drilled box rendered with OpenSCAD's polygons (--faithful) and its
# lighting (--lighting=openscad) must equal its preview (F5) and render
# (F6) exports except for a few pixels along edges (rasterisation rules),
# within one 8-bit step (rounding). The OpenSCAD part is skipped (exit 77)
# when openscad 2021.01 or xvfb-run is missing or OpenSCAD cannot render
# offscreen.
#
# Run as: bash cli_preview.sh <path-to-spancast> <source-dir> <work-dir>
. "$(dirname "$0")/testlib.sh"
# Under the sanitizers the library suppresses fontconfig's one leak
# (build_text.c); the list of suppressions used is kept off stderr, which
# the text and font checks below read.
export LSAN_OPTIONS="print_suppressions=0${LSAN_OPTIONS:+:$LSAN_OPTIONS}"

require_tools oiiotool idiff iinfo

cat >drilled.csg <<'EOF'
difference() {
    cube(size = [20, 14, 10], center = true);
    cylinder($fn = 0, $fa = 12, $fs = 2, h = 12, r1 = 3, r2 = 3, center = true);
}
EOF

# pixel FILE X Y: the pixel's values as oiiotool prints them.
pixel() {
    oiiotool "$1" --cut "1x1+$2+$3" --printstats | grep 'Stats Min' | sed 's/.*Min: //'
}

# ---- command-line errors ----
check
out=$("$bin" render drilled.csg -o x.png --colorscheme=Nope 2>&1)
[ $? = 2 ] || fail "unknown scheme: exit status not 2"
echo "$out" | grep -q "^spancast: error: --colorscheme: unknown colour scheme 'Nope' (known: 'Cornfield', " ||
    fail "unknown scheme: message was: $out"
echo "$out" | grep -q "'Tomorrow Night'" || fail "unknown scheme: names not listed: $out"
[ -e x.png ] && fail "unknown scheme: wrote an image"

check
out=$("$bin" render drilled.csg -o x.png --view=edges,bogus 2>&1)
[ "$out" = "spancast: error: --view: unknown name 'bogus' (expected edges, axes, scales, crosshairs)" ] ||
    fail "--view: message was: $out"
# scales without axes draw nothing, as in OpenSCAD: said once, and the
# render goes on; with axes, or given in two options, no word
check
out=$("$bin" render drilled.csg -o x.png --imgsize=32,24 -q --view=scales 2>&1)
[ "$out" = "spancast: warning: --view=scales marks the axes, which are not drawn: add axes to --view" ] ||
    fail "--view=scales alone: message was: $out"
[ -s x.png ] || fail "--view=scales alone: no image"
check
out=$("$bin" render drilled.csg -o x.png --imgsize=32,24 -q --view=scales --view=axes 2>&1)
[ -z "$out" ] || fail "--view=scales --view=axes: message was: $out"
rm -f x.png
check
out=$("$bin" render drilled.csg -o x.png --section=0,0,0,1 2>&1)
echo "$out" | grep -q "^spancast: error: --section expects NX,NY,NZ,D with a non-zero normal" ||
    fail "--section: message was: $out"
check
out=$("$bin" render drilled.csg -o x.png --sheet=top,front --camera=1,2,3,0,0,0 2>&1)
[ "$out" = "spancast: error: --camera does not combine with --sheet" ] ||
    fail "--sheet with --camera: message was: $out"
check
out=$("$bin" render drilled.csg -o x.png --view-preset=up 2>&1)
echo "$out" | grep -q "^spancast: error: --view-preset: unknown name 'up' (expected top, bottom" ||
    fail "--view-preset: message was: $out"

# ---- the command line wins over the file's background() ----
check
cat >painted.csg <<'EOF'
background(color = [0, 0, 1]);
cube(size = [20, 14, 10], center = true);
EOF
"$bin" render painted.csg -o painted.png -q --imgsize=40,30 --colorscheme=Metallic ||
    fail "painted.csg did not render"
[ "$(pixel painted.png 0 0)" = "0.666667 0.666667 1.000000 (float)" ] ||
    fail "--colorscheme over background(): $(pixel painted.png 0 0)"

# ---- a preset is OpenSCAD's rotation framed like --viewall --autocenter ----
check
"$bin" render drilled.csg -o top.png -q --imgsize=80,60 --view-preset=top --view=edges &&
    "$bin" render drilled.csg -o top_camera.png -q --imgsize=80,60 \
        --camera=0,0,0,0,0,0,140 --viewall --autocenter --view=edges ||
    fail "preset renders failed"
idiff -fail 0 top.png top_camera.png >/dev/null || fail "--view-preset=top is not its camera"

# ---- every feature, every format, and a crop equals the whole ----
features=(--view=edges,axes,scales,crosshairs --section=1,1,0,3 --section-style=hatch
    --ao=4 --spp=4 --colorscheme=Sunset --sheet=front,top,right,diagonal --imgsize=64,48)
for ext in png exr tif; do
    check
    "$bin" render drilled.csg -o "whole.$ext" -q "${features[@]}" --mask=mask.png \
        --depth=depth.exr --normal=normal.exr --id=id.exr || fail "$ext: render failed"
    size=$(iinfo "whole.$ext" | grep -Eo '[0-9]+ x +[0-9]+' | tr -d ' ')
    [ "$size" = 128x96 ] || fail "$ext: a sheet of 4 tiles of 64x48 is $size"
done
check
"$bin" render drilled.csg -o crop.exr -q "${features[@]}" --region=37,20,101,75 \
    --mask=crop_mask.png || fail "crop render failed"
oiiotool whole.exr --cut 64x55+37+20 -o whole_cut.exr
oiiotool mask.png --cut 64x55+37+20 -o mask_cut.png
idiff -fail 0 crop.exr whole_cut.exr >/dev/null || fail "the crop's colour is not the whole's"
idiff -fail 0 crop_mask.png mask_cut.png >/dev/null || fail "the crop's mask is not the whole's"
check
"$bin" render drilled.csg -o one_thread.exr -q "${features[@]}" --threads=1 ||
    fail "one-thread render failed"
idiff -fail 0 one_thread.exr whole.exr >/dev/null || fail "one thread changes the image"

# ---- against OpenSCAD ----
require_tools openscad xvfb-run
openscad --version 2>&1 | grep -q '2021\.01' ||
    skip "the colours checked are OpenSCAD 2021.01's, not $(openscad --version 2>&1)"
cat >drilled.scad <<'EOF'
difference() { cube([20, 14, 10], center = true); cylinder(r = 3, h = 12, center = true); }
EOF
openscad_png() {
    timeout 300 xvfb-run -a -n 130 -s "-screen 0 1024x768x24" openscad "$@" >/dev/null 2>&1
}
openscad -o "$work/drilled_os.csg" drilled.scad >/dev/null 2>&1 || {
    echo "FAIL: openscad could not export drilled_os.csg"
    exit 1
}
openscad_png -o probe.png --imgsize=32,24 drilled.scad
[ -s probe.png ] || skip "openscad cannot render offscreen"

limit=5 # pixels of 160 x 120 that may differ along edges (1 seen)
# The scheme names, as spancast lists them.
names=$("$bin" render drilled.csg -o x.png --colorscheme=? 2>&1 | sed "s/.*(known: //; s/)$//")
count=0
while IFS= read -r name; do
    [ -n "$name" ] || continue
    count=$((count + 1))
    tag=$(echo "$name" | tr ' ' '_')
    for mode in preview render; do
        check
        if [ $mode = preview ]; then
            openscad_png -o "os_$tag.png" --imgsize=160,120 --colorscheme="$name" drilled.scad
            extra=(--preview)
        else
            openscad_png --render -o "os_$tag.png" --imgsize=160,120 --colorscheme="$name" \
                drilled.scad
            extra=()
        fi
        [ -s "os_$tag.png" ] || {
            fail "$name $mode: openscad wrote no image"
            continue
        }
        "$bin" render drilled_os.csg -o "sc_$tag.png" -q --imgsize=160,120 --faithful \
            --colorscheme="$name" --lighting=openscad "${extra[@]}" || {
            fail "$name $mode: spancast failed"
            continue
        }
        [ "$(pixel "os_$tag.png" 0 0)" = "$(pixel "sc_$tag.png" 0 0)" ] ||
            fail "$name: background $(pixel "sc_$tag.png" 0 0), OpenSCAD's $(pixel "os_$tag.png" 0 0)"
        report=$(idiff -fail 0.004 "os_$tag.png" "sc_$tag.png" 2>&1)
        differ=$(echo "$report" | grep -Eo '[0-9]+ pixels .* over 0\.004' | grep -Eo '^[0-9]+')
        differ=${differ:-0}
        [ "$differ" -le "$limit" ] ||
            fail "$name $mode: $differ pixels differ from OpenSCAD's by more than 1/255"
    done
done < <(echo "$names" | sed "s/', '/\n/g; s/^'//; s/'$//")
[ "$count" -ge 11 ] || fail "only $count colour schemes found (OpenSCAD ships 11)"

# ---- translucent parts against OpenSCAD's preview ----
# OpenSCAD 2021.01 draws a translucent lone object (a '#' or '%' part, a
# colour with alpha) rear faces first, then front faces; a product of
# several objects only where OpenCSG's depth pass keeps it; the '%' parts
# before the '#' parts, with depth writes. A '#' operand of a union with
# others is left out of the solid, and the highlight is the term where it
# stops (a difference whose first operand is '#'); a '#' on a '%' node,
# and the '#' and '%' children of a hull, are parts too. A '#' operand of
# a union with others inside a '%' is left out of the '%' part as out of
# the solid: red only, not red over grey. An intersection
# is framed by its operands' boxes. A render() is one mesh: in the colour
# from above it, the walls of holes cut inside it in the face colour, all
# of it in the cut-out colour where it is subtracted (with the convexity
# its shape needs, or OpenCSG's own image is wrong). A translucent
# render() is one lone object: its rear faces, and its front faces before
# the nearest rear one, which the depth test keeps. A '#' or '%' term that
# reaches a render() without meeting another operand is lost, as
# OpenSCAD's RenderNode collects none; one that a union inside it meets is
# drawn. A colour with a negative component (color(alpha = 0.5)) is not
# set, and its negative components are the face colour's. A mesh that is
# not closed is drawn, as OpenCSG takes any mesh, though --faithful leaves
# it out of the render's union. A polyhedron with a quad out of its plane,
# turned, in a union is drawn as written: OpenCSG splits the quad its own
# way, where the render splits it as CGAL takes it, after the turn. Each
# scene is converted by OpenSCAD and compared with its own preview image.
scenes=(
    'difference() { cube(20, center = true); #cylinder(r = 5, h = 30, center = true); }'
    'cube(5); %translate([8, 0, 0]) cube(5);'
    'color([1, 0, 0, 0.5]) cube(5); translate([8, 0, 0]) cube(5);'
    '%cube(5); %translate([0, 10, 0]) cube(5); translate([0, -12, 0]) sphere(3);'
    'difference() { color([0, 0, 1, 0.4]) cube(10, center = true); sphere(6); }'
    '#cylinder(r = 5, h = 10);'
    'cube(8); #difference() { translate([4, 4, 4]) cube(8); translate([8, 8, 0]) cylinder(r = 2, h = 20); }'
    'difference() { #cube(10); sphere(6); } translate([15, 0, 0]) cube(5);'
    'intersection() { #cube(10); sphere(7); } translate([15, 0, 0]) cube(5);'
    'translate([0, 0, 0]) { #cube(5); } sphere(2);'
    'cube(1); %translate([0, 8, 0]) #cube(4);'
    'rotate([0, 0, 90]) polyhedron(points = [[0, 0, 0], [6, 0, 0], [6, 4, 0], [0, 4, 0], [0, 0, 4], [6, 0, 3], [6, 4, 3], [0, 4, 3]], faces = [[0, 1, 2, 3], [4, 5, 1, 0], [7, 6, 5, 4], [5, 6, 2, 1], [6, 7, 3, 2], [7, 4, 0, 3]]); translate([2, 2, 0]) cube(1);'
    '%union() { cube(5); #translate([6, 0, 0]) cube(3); } sphere(2);'
    '#cube(5); #translate([8, 0, 0]) cube(5);'
    '%#cube(10);'
    'hull() { cube(5, center = true); %translate([20, 0, 0]) sphere(4, $fn = 20); }'
    'render() difference() { cube(10, center = true); cylinder(r = 3, h = 12, center = true); }'
    'render() color("red", 0.5) cube(10);'
    'color("blue") render() difference() { cube(10, center = true); color("red") sphere(6); }'
    'difference() { cube(12, center = true); render(convexity = 2) difference() { cylinder(r = 4, h = 14, center = true); cylinder(r = 2, h = 16, center = true); } }'
    'difference() { render(convexity = 2) difference() { cube(10, center = true); translate([0, 0, 5]) sphere(4); } translate([5, 5, 0]) cylinder(r = 3, h = 20, center = true); }'
    'color("green", 0.4) render() difference() { cube(10, center = true); sphere(6.5); }'
    '%render() difference() { cube(10, center = true); cylinder(r = 3, h = 20, center = true); } cube(4);'
    'render() #cube(10);'
    'render() translate([2, 0, 0]) #cube(5); sphere(2);'
    'render() %sphere(5); cube(3);'
    'render() { cube(4); %translate([6, 0, 0]) sphere(3); }'
    'render() union() { cube(4); %translate([6, 0, 0]) sphere(3); }'
    'cube(5); render() { #translate([8, 0, 0]) cube(4); translate([0, 8, 0]) cube(4); }'
    'color(alpha = 0.5) cube(10, center = true);'
    'color([1, 0, 0, -1]) color("blue") cube(10, center = true);'
    'linear_extrude(height = 3, scale = [0, 1]) difference() { square(2, center = true); square(1, center = true); } translate([4, 0, 0]) cube(1);'
)
# 2D objects in a 3D model (and 3D ones in a 2D model), which the render
# leaves out, are slabs 1 thick in the preview (1.1 where subtracted), as
# are a 2D model's objects moved out of its plane. With a given camera and
# with the default one, which frames a slab by its polygons' flat box, as
# OpenSCAD does. A 2D model is drawn so too: its leaves in their colours,
# the walls of a 2D difference in the cut-out colour.
slab_scenes=(
    'cube(5); translate([8, 0, 0]) square(4);'
    'rotate([90, 0, 0]) circle(3); translate([8, 0, 0]) cube(3);'
    'difference() { cube([10, 10, 10], center = true); translate([0, 0, 5]) square(4, center = true); }'
    'cube(3); %translate([6, 0, 0]) square(3); #translate([0, 6, 0]) circle(2);'
    'difference() { square(10); translate([5, 5, 0]) cube(3, center = true); }'
    'translate([0, 0, 5]) square(4); rotate([90, 0, 0]) square(3);'
    'color("red") square(10); color("blue") translate([16, 0]) circle(4);'
    'difference() { square(20, center = true); square(8, center = true); }'
)
# Meshes that are not closed: OpenSCAD draws one as it is where nothing
# hands it to CGAL (alone, or the one operand of an operation), in its
# render and its preview, in the face colour whichever way its faces
# wind; beside another object its render leaves it out, as CGAL cannot
# take it. An extrusion's 2D children are united by Clipper, not CGAL.
# Beside another object in the preview, the far wall seen through the
# box's opening is drawn, as OpenSCAD draws it: the line that enters the
# box through its opening crosses it once, and that crossing opens a span
# to the mesh's box (docs/meshes.md). A cube whose top face is listed
# twice (as OpenSCAD's issue1876 lists one) shows its top: the copies
# would cancel under parity, and are one face.
open_box='polyhedron(points = [[0, 0, 0], [10, 0, 0], [10, 10, 0], [0, 10, 0], [0, 0, 10], [10, 0, 10], [10, 10, 10], [0, 10, 10]], faces = [[0, 1, 2, 3], [0, 4, 5, 1], [1, 5, 6, 2], [2, 6, 7, 3], [3, 7, 4, 0]]);'
open_scenes=(
    "$open_box"
    'polyhedron(points = [[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]], faces = [[0, 4, 2], [0, 2, 5], [0, 3, 4], [0, 5, 3], [1, 2, 4], [1, 5, 2], [1, 3, 4], [1, 3, 5]]);'
    'linear_extrude(height = 3, scale = [0, 1]) difference() { square(2, center = true); square(1, center = true); }'
    "translate([0, 0, 5]) { $open_box }"
    "$open_box translate([15, 0, 0]) cube(4);"
    'linear_extrude(height = 3, scale = [0, 1]) { translate([-1.5, -1]) square([1, 2]); translate([0.5, -1]) square([1, 2]); }'
    'polyhedron(points = [[0, 0, 0], [10, 0, 0], [10, 10, 0], [0, 10, 0], [0, 0, 10], [10, 0, 10], [10, 10, 10], [0, 10, 10]], faces = [[0, 1, 2, 3], [4, 5, 1, 0], [7, 6, 5, 4], [5, 6, 2, 1], [6, 7, 3, 2], [7, 4, 0, 3], [7, 6, 5, 4]]);'
)
# the options of OpenSCAD's and spancast's images: the preview, or with
# --render OpenSCAD's render and spancast's in its colour scheme
os_mode=()
sc_mode=(--preview)
compare_scene() { # name, scene, then options of both
    local name=$1 scene=$2
    shift 2
    check
    echo "$scene" >"$name.scad"
    openscad -o "$name.csg" "$name.scad" >/dev/null 2>&1 || {
        fail "$name: openscad could not export it"
        return
    }
    openscad_png "${os_mode[@]}" -o "os_$name.png" --imgsize=160,120 "$@" "$name.scad"
    [ -s "os_$name.png" ] || {
        fail "$name: openscad wrote no image"
        return
    }
    "$bin" render "$name.csg" -o "sc_$name.png" -q --imgsize=160,120 --faithful \
        --lighting=openscad "${sc_mode[@]}" "$@" 2>/dev/null || {
        fail "$name: spancast failed"
        return
    }
    report=$(idiff -fail 0.004 "os_$name.png" "sc_$name.png" 2>&1)
    differ=$(echo "$report" | grep -Eo '[0-9]+ pixels .* over 0\.004' | grep -Eo '^[0-9]+')
    differ=${differ:-0}
    [ "$differ" -le "$limit" ] ||
        fail "$name ($scene): $differ pixels differ from OpenSCAD's by more than 1/255"
}
for k in "${!scenes[@]}"; do
    compare_scene "part$k" "${scenes[$k]}"
done
for k in "${!slab_scenes[@]}"; do
    compare_scene "slab$k" "${slab_scenes[$k]}" --camera=20,-30,25,4,2,0
    compare_scene "framed$k" "${slab_scenes[$k]}"
done
for k in "${!open_scenes[@]}"; do
    compare_scene "open$k" "${open_scenes[$k]}"
done
os_mode=(--render)
sc_mode=(--colorscheme=Cornfield)
for k in "${!open_scenes[@]}"; do
    compare_scene "open_render$k" "${open_scenes[$k]}"
done
# A 2D model in the render, as OpenSCAD's render draws a 2D result
# (CGALRenderer::draw): flat at z = 0, unlit in the scheme's 2D face
# colour, the outlines (the hole's too) 2 pixels wide in its 2D edge
# colour over it, framed by the flat box; at the default camera, at one
# that cuts the outlines at the image's right edge, and in a scheme of
# other 2D colours.
flat_scene='difference() { circle(10); square(8, center = true); } translate([12, 0]) polygon([[0, 0], [8, 2], [3, 9], [4, 3]]);'
compare_scene flat "$flat_scene"
compare_scene flat_cut "$flat_scene" --camera=20,-30,25,4,2,0
os_mode=(--render --colorscheme=Solarized)
sc_mode=(--colorscheme=Solarized)
compare_scene flat_solarized "$flat_scene"
# A font file the .scad uses (use <font.ttf>) is registered, as OpenSCAD
# registers it, so that text() draws it: MarVoSym, a symbol font no Debian
# package installs (tests/data/fonts), rendered from the .scad by both.
mkdir -p fonts && cp "$src/tests/data/fonts/marvosym.ttf" fonts/
printf 'use <fonts/marvosym.ttf>\ntext("0123 AB", font = "MarVoSym", size = 10);\n' >symbol.scad
check
openscad_png --render -o os_symbol.png --imgsize=160,120 symbol.scad
"$bin" render symbol.scad -o sc_symbol.png -q --imgsize=160,120 --faithful \
    --lighting=openscad --colorscheme=Cornfield 2>symbol_err.txt || fail "symbol.scad: spancast failed"
[ -s symbol_err.txt ] && fail "symbol.scad: $(cat symbol_err.txt)"
differ=$(idiff -fail 0.004 os_symbol.png sc_symbol.png 2>&1 |
    grep -Eo '[0-9]+ pixels .* over 0\.004' | grep -Eo '^[0-9]+')
[ "${differ:-0}" -le "$limit" ] ||
    fail "symbol.scad: $differ pixels differ from OpenSCAD's render"
# The folders of OPENSCAD_FONT_PATH hold fonts, as OpenSCAD's FontCache
# adds them: the same font found there, from a .csg that does not use it.
mkdir -p fontdir && cp "$src/tests/data/fonts/marvosym.ttf" fontdir/
printf 'text(text = "0123 AB", size = 10, font = "MarVoSym");\n' >symbol_path.csg
check
OPENSCAD_FONT_PATH="$PWD/nothere:$PWD/fontdir" openscad_png --render -o os_symbol_path.png \
    --imgsize=160,120 symbol_path.csg
OPENSCAD_FONT_PATH="$PWD/nothere:$PWD/fontdir" "$bin" render symbol_path.csg \
    -o sc_symbol_path.png -q --imgsize=160,120 --faithful --lighting=openscad \
    --colorscheme=Cornfield 2>symbol_path_err.txt || fail "symbol_path.csg: spancast failed"
[ -s symbol_path_err.txt ] && fail "symbol_path.csg: $(cat symbol_path_err.txt)"
differ=$(idiff -fail 0.004 os_symbol_path.png sc_symbol_path.png 2>&1 |
    grep -Eo '[0-9]+ pixels .* over 0\.004' | grep -Eo '^[0-9]+')
[ "${differ:-0}" -le "$limit" ] ||
    fail "symbol_path.csg: $differ pixels differ from OpenSCAD's render"
check
"$bin" render symbol_path.csg -o sc_symbol_nopath.png -q 2>symbol_nopath_err.txt
grep -q "font 'MarVoSym' was not found" symbol_nopath_err.txt ||
    fail "symbol_path.csg without OPENSCAD_FONT_PATH: $(cat symbol_nopath_err.txt)"

echo "$checks checks, $fails failures"
[ "$fails" = 0 ]
