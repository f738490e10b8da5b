# OpenSCAD 2021.01's leniency, end to end: what OpenSCAD leaves out with a
# warning, spancast leaves out with the same warning, at the node, and
# renders the rest with exit 0; the result is checked against the model
# written without what was left out (spancast compare: volumes, masks and
# depths from seven views). A 2D model is drawn flat at z = 0 in its 2D
# face colour in the render. A lossy --mask format gets a warning.
# Children of the other dimension, left out of an operation with their
# own warnings first, are cli_lenient_dims.sh's.
#
# Run as: bash cli_lenient.sh <path-to-spancast> <source-dir> <work-dir>
. "$(dirname "$0")/testlib.sh"
require_tools oiiotool

# pixel IMAGE X Y: the 8-bit values of one pixel ("R G B").
pixel() {
    oiiotool "$1" --cut "1x1+$2+$3" -d uint8 -o px.png &&
        oiiotool --dumpdata px.png | sed -n 's/^ *Pixel (0, 0): \([0-9 ]*\) (.*/\1/p'
}

# The first object decides, as in OpenSCAD: a file that starts with a 2D
# object is a 2D model, its 3D objects left out.
printf 'square(size = [10, 4], center = false);\ncube(size = [3, 3, 3], center = false);\n' >first2d.csg
printf 'polygon(points = [[0, 0], [10, 0], [10, 4], [0, 4]]);\n' >flat_ref.csg
warns first2d.csg "first2d.csg:2:1: warning: Mixing 2D and 3D objects is not supported
first2d.csg:2:1: warning: Ignoring 3D child object for 2D operation"
same first2d.csg flat_ref.csg

# The same inside a boolean that OpenSCAD evaluates with CGAL (the mesh a
# projection takes): the 2D child is the empty operand, so it subtracts
# nothing, and the warnings are OpenSCAD's.
cat >nefmix.csg <<'M'
projection(cut = false) {
	difference() {
		cube(size = [10, 10, 10], center = false);
		square(size = [3, 3], center = false);
		multmatrix([[1, 0, 0, 2], [0, 1, 0, 2], [0, 0, 1, -1], [0, 0, 0, 1]]) {
			cube(size = [2, 2, 20], center = false);
		}
	}
}
M
cat >nefmix_ref.csg <<'M'
projection(cut = false) {
	difference() {
		cube(size = [10, 10, 10], center = false);
		multmatrix([[1, 0, 0, 2], [0, 1, 0, 2], [0, 0, 1, -1], [0, 0, 0, 1]]) {
			cube(size = [2, 2, 20], center = false);
		}
	}
}
M
warns nefmix.csg "nefmix.csg:4:3: warning: Mixing 2D and 3D objects is not supported
nefmix.csg:4:3: warning: Ignoring 2D child object for 3D operation"
same nefmix.csg nefmix_ref.csg
# and it empties an intersection
sed 's/difference/intersection/' nefmix.csg >nefmeet.csg
warns nefmeet.csg "nefmeet.csg:4:3: warning: Mixing 2D and 3D objects is not supported
nefmeet.csg:4:3: warning: Ignoring 2D child object for 3D operation
nefmeet.csg:1:1: warning: the 2D model has no area
nefmeet.csg: warning: the model is empty (nothing to render)"

# A difference that cuts everything away: OpenSCAD 2021.01's render says
# "Current top level object is empty." (openscad -o x.stl); spancast's
# tree is not empty, but no ray of the search for the solid's box meets
# it, which it says in both modes. One that leaves a part keeps quiet.
cat >cutaway.csg <<'M'
difference() {
	cube(size = [5, 5, 5], center = false);
	multmatrix([[1, 0, 0, -1], [0, 1, 0, -1], [0, 0, 1, -1], [0, 0, 0, 1]]) {
		cube(size = [10, 10, 10], center = false);
	}
}
M
cutaway="cutaway.csg: warning: no ray of a search across the model's box meets the solid: its operations leave it empty, or nearly"
warns cutaway.csg "$cutaway"
warns cutaway.csg "$cutaway" --faithful
sed 's/size = \[10, 10, 10\]/size = [10, 10, 5.5]/' cutaway.csg >cutpart.csg
warns cutpart.csg ""
# A slab 0.001 thick left at the bottom is met only by the lines along z:
# no warning, and the frame is the slab's (its other sides the tree's).
sed 's/\[0, 0, 1, -1\]/[0, 0, 1, 0.001]/' cutaway.csg >cutslab.csg
warns cutslab.csg ""
check
"$bin" info cutslab.csg >info.txt 2>&1
grep -q '^frame:  \[0, 0, 0\] to \[5, 5, 0.001\] ' info.txt ||
    fail "cutslab.csg: $(grep frame info.txt)"
if command -v openscad >/dev/null; then
    check
    openscad -o "$PWD/cutaway_os.stl" cutaway.csg >/dev/null 2>cutaway_os.err
    grep -q '^Current top level object is empty\.$' cutaway_os.err ||
        fail "openscad does not find the cut-away model empty: $(cat cutaway_os.err)"
fi

# ---- a 2D model: flat at z = 0 in the render, in colour, mask and depth ----
# (the slab 1 thick about z = 0 that OpenSCAD's preview draws is what
# measure and the preview see: cli_check.sh, cli_preview.sh)
printf 'square(size = [10, 4], center = false);\n' >flat.csg
warns flat.csg ""
same flat.csg flat_ref.csg
# A 2D model past 1e6 across is a slab 1e-6 of its width or height thick
# (the larger), so that the slab the render finds its plane in stays far
# above the rays' tolerance (1e-9 of the extent): a rectangle 1e12 across,
# seen from above, fills the middle of the image, where a slab 1 thick had
# no area.
printf 'square(size = [1e12, 4e11], center = false);\n' >flat_big.csg
printf 'polygon(points = [[0, 0], [1e12, 0], [1e12, 4e11], [0, 4e11]]);\n' >flat_big_ref.csg
for mode in "" --faithful; do
    # shellcheck disable=SC2086
    { warns flat_big.csg "" $mode; same flat_big.csg flat_big_ref.csg $mode; }
    check
    # shellcheck disable=SC2086
    "$bin" render flat_big.csg -o big.png --mask=big_mask.png --imgsize=80,60 \
        --camera=5e11,2e11,2e12,5e11,2e11,0 -q $mode &&
        [ "$(pixel big_mask.png 40 30)" = 255 ] ||
        fail "flat_big.csg $mode: mask '$(pixel big_mask.png 40 30)' at the centre"
done
# A projection alone is a 2D model too: its section drawn flat.
printf 'projection(cut = true) { multmatrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, -1], [0, 0, 0, 1]]) { cube(size = [10, 4, 2], center = false); } }\n' >projected.csg
warns projected.csg ""
same projected.csg flat_ref.csg
check
"$bin" render flat.csg -o flat.png --imgsize=80,60 --camera=5,2,50,5,2,0 -q &&
    [ "$(pixel flat.png 40 30)" = "0 191 153" ] ||
    fail "2D model in the render: pixel '$(pixel flat.png 40 30)', want CGAL_FACE_2D_COLOR 0 191 153"
# The preview draws it as any slab: lit, in the preview's face colour.
check
"$bin" render flat.csg -o flat_preview.png --preview --imgsize=80,60 \
    --camera=5,2,50,5,2,0 -q &&
    printf 'linear_extrude(height = 1, center = true) { square(size = [10, 4]); }\n' >slab_ref.csg &&
    "$bin" render slab_ref.csg -o slab_preview.png --preview --imgsize=80,60 \
        --camera=5,2,50,5,2,0 -q &&
    [ "$(pixel flat_preview.png 40 30)" = "$(pixel slab_preview.png 40 30)" ] &&
    [ "$(pixel flat_preview.png 40 30)" != "0 191 153" ] ||
    fail "2D model in the preview: '$(pixel flat_preview.png 40 30)', want '$(pixel slab_preview.png 40 30)'"

# Against OpenSCAD itself, where it can draw offscreen: its render and its
# preview of the same 2D model, centre pixel for centre pixel (the preview
# with OpenSCAD's lighting).
if command -v openscad >/dev/null && command -v xvfb-run >/dev/null &&
    openscad --version 2>&1 | grep -q '2021\.01'; then
    printf 'square([10, 4]);\n' >flat.scad
    for mode in render preview; do
        timeout 300 xvfb-run -a -n 110 -s "-screen 0 1024x768x24" \
            openscad --$mode -o "os_$mode.png" --imgsize=80,60 --camera=5,2,50,5,2,0 \
            flat.scad >/dev/null 2>&1
    done
    if [ -s os_render.png ] && [ -s os_preview.png ]; then
        check
        [ "$(pixel os_render.png 40 30)" = "$(pixel flat.png 40 30)" ] ||
            fail "render: OpenSCAD '$(pixel os_render.png 40 30)', spancast '$(pixel flat.png 40 30)'"
        check
        "$bin" render flat.csg -o flat_os.png --preview --lighting=openscad --imgsize=80,60 \
            --camera=5,2,50,5,2,0 -q &&
            [ "$(pixel os_preview.png 40 30)" = "$(pixel flat_os.png 40 30)" ] ||
            fail "preview: OpenSCAD '$(pixel os_preview.png 40 30)', spancast '$(pixel flat_os.png 40 30)'"
    elif [ "${SPANCAST_NO_SKIP:-0}" = 1 ]; then
        fail "openscad cannot draw offscreen here, so the 2D model is not compared with it"
    fi
elif [ "${SPANCAST_NO_SKIP:-0}" = 1 ]; then
    fail "no openscad 2021.01 and xvfb-run to compare the 2D model with"
fi

# ---- import() of a file that does not open: empty, the rest rendered ----
printf 'cube(size = [1, 1, 1], center = false);\nimport(file = "missing.stl");\n' >import.csg
printf 'cube(size = [1, 1, 1], center = false);\n' >cube_ref.csg
warns import.csg "import.csg:2:15: warning: Can't open import file 'missing.stl': No such file or directory; the import is empty, as OpenSCAD leaves it out (--strict makes it an error)"
same import.csg cube_ref.csg
cat >dxf.csg <<'M'
linear_extrude(height = 3) {
	square(size = [10, 6], center = false);
	import(file = "missing.dxf");
}
M
printf 'linear_extrude(height = 3) { square(size = [10, 6], center = false); }\n' >extrude_ref.csg
warns dxf.csg "dxf.csg:3:2: warning: Can't open DXF file 'missing.dxf': No such file or directory; the import is empty, as OpenSCAD leaves it out (--strict makes it an error)"
same dxf.csg extrude_ref.csg
printf 'linear_extrude(height = 3) {\n\tsquare(size = [10, 6], center = false);\n\timport(file = "missing.svg");\n}\n' >svg.csg
warns svg.csg "svg.csg:3:2: warning: Can't open SVG file 'missing.svg': No such file or directory; the import is empty, as OpenSCAD leaves it out (--strict makes it an error)"
same svg.csg extrude_ref.csg

# An SVG at dpi = inf, as OpenSCAD writes it into a .csg (dpi = 1/0 in the
# .scad), is no error: a length without unit is 0 mm (import_svg.cc's
# to_mm), so a page with a viewBox scales to nothing, and one without keeps
# its user units, at a height of 0 (openscad -o x.stl: an empty model, and
# the rectangle at x 10 to 40, y -30 to -10).
for box in 'viewBox="0 0 100 50"' ''; do
    name=dpi_inf${box:+_box}
    printf '<svg xmlns="http://www.w3.org/2000/svg" width="100" height="50" %s><rect x="10" y="10" width="30" height="20"/></svg>\n' "$box" >$name.svg
    printf 'linear_extrude(height = 1) {\n\timport(file = "%s.svg", layer = "", origin = [0, 0], center = false, dpi = inf, scale = 1, convexity = 1, $fn = 0, $fa = 12, $fs = 2, timestamp = 0);\n}\n' $name >$name.csg
done
warns dpi_inf_box.csg "dpi_inf_box.csg:1:1: warning: linear_extrude without height or area is empty
dpi_inf_box.csg: warning: the model is empty (nothing to render)"
warns dpi_inf.csg ""
printf 'linear_extrude(height = 1) { multmatrix([[1, 0, 0, 10], [0, 1, 0, -30], [0, 0, 1, 0], [0, 0, 0, 1]]) { square(size = [30, 20], center = false); } }\n' >dpi_inf_ref.csg
same dpi_inf.csg dpi_inf_ref.csg

# A polygon outline with a coordinate past Clipper's range (2^62 over
# OpenSCAD's 2^16 scale: about 7.04e13, and past the conversion's range,
# 1e20, as well) is refused by OpenSCAD's clipper, and that outline and
# those after it are left out (openscad -o x.stl prints exactly this
# warning, and draws the rest). A path of fewer than three points after
# Clipper drops its trailing repeats is not tested.
ext1='linear_extrude(height = 1)'
unit="$ext1 square(size = [1, 1], center = false);"
range_case() {
    printf '%s polygon(points = %s, paths = %s, convexity = 1);\n%s\n' "$ext1" "$2" "$3" "$unit" >"$1.csg"
}
range_case range_one '[[0, 0], [1e14, 0], [0, 1e14]]' undef
range_case range_last '[[2, 0], [3, 0], [2, 1], [10, 10], [1e14, 10], [10, 11]]' '[[0, 1, 2], [3, 4, 5]]'
range_case range_first '[[2, 0], [3, 0], [2, 1], [10, 10], [1e14, 10], [10, 11]]' '[[3, 4, 5], [0, 1, 2]]'
range_case range_far '[[0, 0], [-1e20, 0], [0, 1]]' undef
range_case range_repeat '[[0, 0], [0, 0], [7.1e13, 0]]' undef
# a nan passes OpenSCAD's conversion of the point (an inf does not) and
# fails the clipper's range check in the same way (openscad prints the
# same warning for polygon(points = [[2, 0], [3, 0], [0 / 0, 1]]))
range_case range_nan '[[2, 0], [3, 0], [2, 1], [10, 10], [nan, 10], [10, 11]]' '[[0, 1, 2], [3, 4, 5]]'
printf '%s\n' "$unit" >range_unit_ref.csg
printf '%s polygon(points = [[2, 0], [3, 0], [2, 1]], paths = undef, convexity = 1);\n%s\n' "$ext1" "$unit" >range_last_ref.csg
range_said='warning: Range check failed for polygon. skipping (the outline and those after it, as OpenSCAD leaves them out; --strict makes it an error)'
for mode in "" --faithful; do
    # shellcheck disable=SC2086
    {
        for f in range_one range_last range_first range_far range_repeat range_nan; do
            warns $f.csg "$f.csg:1:28: $range_said" $mode
        done
        refuses range_one.csg "range_one.csg:1:28: error: polygon: coordinates out of the clipper's range" $mode
        same range_one.csg range_unit_ref.csg $mode
        same range_first.csg range_unit_ref.csg $mode
        same range_far.csg range_unit_ref.csg $mode
        same range_repeat.csg range_unit_ref.csg $mode
        same range_last.csg range_last_ref.csg $mode
        same range_nan.csg range_last_ref.csg $mode
    }
done
# A square past the range is drawn where OpenSCAD draws it without its
# clipper, but turned over (a mirror) OpenSCAD sanitizes it again and its
# clipper refuses it, and a union of two stops on Clipper's exception: the
# exact extrusion, which reads squares without a clipper, follows OpenSCAD
# there too.
printf '%s { multmatrix([[-1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) { square(size = [1e14, 1e14], center = false); } }\n%s\n' "$ext1" "$unit" >range_mirror.csg
printf '%s { union() { square(size = [1e14, 1e14], center = false); circle(r = 1e14); } }\n' "$ext1" >range_union.csg
printf 'linear_extrude(height = 1e12) { multmatrix([[1, 0, 0, 5e13], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) { circle(r = 3e13); } }\n' >range_circle.csg
printf 'rotate_extrude() { union() { square(size = [1e14, 1e14], center = false); square(size = [1, 1e14], center = false); } }\n' >range_revolve_union.csg
printf 'rotate_extrude() { square(size = [1e14, 1e14], center = false); }\n' >range_revolve.csg
for mode in "" --faithful; do
    # shellcheck disable=SC2086
    {
        warns range_mirror.csg "range_mirror.csg:1:30: warning: Range check failed for polygon. skipping (outline 1 of the shape and those after it, as OpenSCAD leaves them out; --strict makes it an error)" $mode
        same range_mirror.csg range_unit_ref.csg $mode
        refuses range_union.csg "range_union.csg:1:30: error: union: coordinates out of range (limit is 7.03687e+13)" $mode
        warns range_circle.csg "" $mode
        refuses range_revolve_union.csg "range_revolve_union.csg:1:20: error: union: coordinates out of range (limit is 7.03687e+13)" $mode
        warns range_revolve.csg "" $mode
    }
done
# the same inside hull, minkowski and projection (OpenSCAD: hull() {
# import("missing.stl"); cube(1); } is the cube, with the warning)
printf 'hull() {\n\timport(file = "missing.stl");\n\tcube(size = [1, 1, 1], center = false);\n}\n' >hull-missing.csg
printf 'minkowski() {\n\timport(file = "missing.stl");\n\tcube(size = [1, 1, 1], center = false);\n}\n' >mink-missing.csg
printf 'linear_extrude(height = 1) {\n\tprojection(cut = false) {\n\t\timport(file = "missing.stl");\n\t\tcube(size = [1, 1, 1], center = false);\n\t}\n}\n' >proj-missing.csg
printf 'linear_extrude(height = 1) {\n\tsquare(size = [1, 1], center = false);\n}\n' >square_ref.csg
warns hull-missing.csg "hull-missing.csg:2:16: warning: Can't open import file 'missing.stl': No such file or directory; the import is empty, as OpenSCAD leaves it out (--strict makes it an error)"
same hull-missing.csg cube_ref.csg
warns mink-missing.csg "mink-missing.csg:2:16: warning: Can't open import file 'missing.stl': No such file or directory; the import is empty, as OpenSCAD leaves it out (--strict makes it an error)"
same mink-missing.csg cube_ref.csg
warns proj-missing.csg "proj-missing.csg:3:17: warning: Can't open import file 'missing.stl': No such file or directory; the import is empty, as OpenSCAD leaves it out (--strict makes it an error)"
same proj-missing.csg square_ref.csg
# --strict: a file that cannot be opened is the error, in both modes
# (exit 1, no image)
for case in "import.csg:2:15: error: Can't open import file 'missing.stl'" \
    "dxf.csg:3:2: error: Can't open DXF file 'missing.dxf'" \
    "svg.csg:3:2: error: Can't open SVG file 'missing.svg'" \
    "hull-missing.csg:2:16: error: Can't open import file 'missing.stl'" \
    "mink-missing.csg:2:16: error: Can't open import file 'missing.stl'" \
    "proj-missing.csg:3:17: error: Can't open import file 'missing.stl'"; do
    model=${case%%:*}
    for mode in "" --faithful; do
        check
        rm -f strict.png
        "$bin" render "$model" -o strict.png -q --strict $mode 2>err.txt &&
            fail "$model --strict $mode: exit 0"
        [ "$(cat err.txt)" = "$case: No such file or directory" ] ||
            fail "$model --strict $mode: $(cat err.txt)"
        [ -e strict.png ] && fail "$model --strict $mode: an image was written"
    done
done
# against_openscad MODEL: MODEL is "same" in --faithful as openscad's
# binary STL of it, where openscad is installed.
against_openscad() {
    command -v openscad >/dev/null || return 0
    check
    openscad -o "$PWD/os_$1.stl" --export-format binstl "$1" >/dev/null 2>&1 ||
        fail "openscad did not render $1"
    same "$1" "os_$1.stl" --faithful
}

# A malformed DXF drawing is read as OpenSCAD 2021.01 reads it, with its
# warnings at the drawing's lines: a value that is not a number skipped
# (line 8), a CIRCLE without its centre left out with the next LINE's
# values read as its own (line 48: the circle is drawn at (20, 3)), and a
# blank line that ends the reading (line 65: the LINE after it is not
# drawn). --strict makes the first the error.
printf '0\nSECTION\n2\nENTITIES\n0\nLINE\n10\n1d1\n10\n0\n20\n0\n11\n10\n21\n0\n0\nLINE\n10\n10\n20\n0\n11\n10\n21\n6\n0\nLINE\n10\n10\n20\n6\n11\n0\n21\n6\n0\nLINE\n10\n0\n20\n6\n11\n0\n21\n0\n0\nCIRCLE\n40\n2\n0\nLINE\n10\n20\n20\n3\n11\n30\n21\n30\n0\nENDSEC\n0\nEOF\n\n0\nSECTION\n2\nENTITIES\n0\nLINE\n10\n0\n20\n0\n11\n50\n21\n50\n0\nEOF\n' >bad.dxf
printf 'linear_extrude(height = 3) {\n\timport(file = "bad.dxf");\n}\n' >bad_dxf.csg
bad_dxf="bad.dxf:8:1: warning: Illegal value '1d1' (group code 10): OpenSCAD skips it (--strict makes it an error)
bad.dxf:48:1: warning: Not enough input values for LINE: OpenSCAD leaves out the CIRCLE that lacks them, and reads the values after it as more of it (--strict makes it an error)
bad.dxf:65:1: warning: Illegal ID '': OpenSCAD reads no further in the DXF file (--strict makes it an error)"
warns bad_dxf.csg "$bad_dxf"
warns bad_dxf.csg "$bad_dxf" --faithful
refuses bad_dxf.csg "bad.dxf:8:1: error: Illegal value '1d1' (group code 10): OpenSCAD skips it"
against_openscad bad_dxf.csg
# nan and inf are numbers (an ARC whose segment count is not a number draws
# nothing); a last code that is not an integer ends the drawing silently,
# as does text in CR-only line ends
printf '0\nSECTION\n2\nENTITIES\n0\nLWPOLYLINE\n70\n1\n10\n0\n20\n0\n10\n8\n20\n0\n10\n8\n20\n5\n0\nARC\n10\n0\n20\n0\n40\nINF\n50\nnan\n51\n90\n0\nENDSEC\n0\nEOF\ngarbage\n' >nan.dxf
printf 'linear_extrude(height = 3) {\n\timport(file = "nan.dxf");\n}\n' >nan_dxf.csg
warns nan_dxf.csg ""
printf 'linear_extrude(height = 3) { polygon(points = [[0, 0], [8, 0], [8, 5]]); }\n' >nan_ref.csg
same nan_dxf.csg nan_ref.csg --faithful
against_openscad nan_dxf.csg

# left_out MODEL REF AT MESH KIND WHY: in both modes MODEL warns at AT that
# MESH is not a valid KIND file (WHY) and leaves it out, renders as REF,
# and is that error with --strict.
left_out() {
    local model=$1 ref=$2 at=$3 mesh=$4 kind=$5 why=$6 mode
    for mode in "" --faithful; do
        # shellcheck disable=SC2086
        warns "$model" "$model:$at: warning: import: '$mesh' is not a valid $kind file ($why); the import is empty, as OpenSCAD leaves it out (--strict makes it an error)" $mode
        # shellcheck disable=SC2086
        same "$model" "$ref" $mode
        # shellcheck disable=SC2086
        refuses "$model" "$model:$at: error: import: '$mesh' is not a valid $kind file ($why)" $mode
    done
}

# A file with a line OpenSCAD 2021.01's STL reader cannot parse, or a
# vertex line after a triangle's third, or an OFF file CGAL's reader stops
# in: OpenSCAD logs its error, imports nothing, and renders the rest; as
# the model itself it is an error at the file's line. A line with two
# words after "vertex" it passes over, and the triangle with it.
printf 'solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0\n' >faceless.stl
printf 'solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0x\n' >bad.stl
printf 'solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nvertex 0 0 1\n' >extra.stl
printf 'OFF\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n' >short.off
printf 'cube(size = [1, 2, 3]);\n' >rest_ref.csg
for mesh in faceless.stl bad.stl extra.stl short.off; do
    printf 'import(file = "%s");\ncube(size = [1, 2, 3]);\n' $mesh >import_$mesh.csg
    case $mesh in
    faceless.stl) want="import_$mesh.csg:1:1: warning: import without faces is empty" ;;
    bad.stl) why="line 6: can't parse vertex line 'vertex 0 1 0x'" ;;
    extra.stl) why="line 7: extra vertex line 'vertex 0 0 1'" ;;
    short.off) why="line 5: the file ends before point 4 of 4" ;;
    esac
    kind=STL
    [ $mesh = short.off ] && kind=OFF
    against_openscad import_$mesh.csg
    if [ $mesh = faceless.stl ]; then
        for mode in "" --faithful; do
            warns import_$mesh.csg "$want" $mode
            same import_$mesh.csg rest_ref.csg $mode
        done
        continue
    fi
    left_out import_$mesh.csg rest_ref.csg 1:15 $mesh $kind "$why"
    check
    "$bin" render $mesh -o bad.png -q 2>err.txt && fail "$mesh rendered as the model"
    at="$mesh:$(echo "$why" | sed 's/^line \([0-9]*\):.*/\1/'):1: "
    [ "$(cat err.txt)" = "${at}error: import: '$PWD/$mesh' is not a valid $kind file ($why)" ] ||
        fail "$mesh as the model: $(cat err.txt)"
    [ -e bad.png ] && fail "$mesh as the model: an image was written"
done

# A corner that is nan or inf: OpenSCAD 2021.01 reads it, and leaves the
# mesh out of its union with the rest ("The given mesh is not closed!"):
# the warning, and the rest rendered.
python3 -c '
import struct
P = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
F = [(0, 2, 1), (0, 1, 3), (1, 2, 3), (0, 3, 2)]
for bad in ("nan", "inf"):
    with open("corner_%s.stl" % bad, "w") as f:
        f.write("solid t\n")
        for k, face in enumerate(F):
            f.write(" facet normal 0 0 0\n  outer loop\n")
            for i in face:
                p = ("%s" % bad, 1, 0) if (k, i) == (3, 2) else P[i]
                f.write("   vertex %s %s %s\n" % p)
            f.write("  endloop\n endfacet\n")
        f.write("endsolid t\n")
d = bytes(80) + struct.pack("<I", 4)
for k, face in enumerate(F):
    d += struct.pack("<3f", 0, 0, 0)
    for i in face:
        d += struct.pack("<3f", *((float("nan"), 1, 0) if (k, i) == (3, 2) else P[i]))
    d += bytes(2)
open("corner_binary.stl", "wb").write(d)'
printf 'multmatrix([[1, 0, 0, 5], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {\n\tcube(size = [1, 1, 1], center = false);\n}\n' >corner_ref.csg
for mesh in corner_nan.stl corner_inf.stl corner_binary.stl; do
    printf 'union() {\n\timport(file = "%s");\n\tmultmatrix([[1, 0, 0, 5], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {\n\t\tcube(size = [1, 1, 1], center = false);\n\t}\n}\n' $mesh >import_$mesh.csg
    why="line 27: a corner is not finite"
    [ $mesh = corner_binary.stl ] && why="a corner is not finite"
    left_out import_$mesh.csg corner_ref.csg 2:16 $mesh STL "$why"
    against_openscad import_$mesh.csg
    # under a minkowski, OpenSCAD's CGAL finds the mesh it read not
    # closed, and the whole minkowski is empty
    printf 'union() {\n\tminkowski() {\n\t\timport(file = "%s");\n\t\tcube(size = [0.5, 0.5, 0.5], center = false);\n\t}\n\tmultmatrix([[1, 0, 0, 5], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {\n\t\tcube(size = [1, 1, 1], center = false);\n\t}\n}\n' $mesh >mink_$mesh.csg
    for mode in "" --faithful; do
        check
        "$bin" inside mink_$mesh.csg $mode --point=1.2,0.2,0.2 --point=5.5,0.5,0.5 >in.txt 2>err.txt ||
            fail "mink_$mesh.csg $mode: exit $?: $(cat err.txt)"
        [ "$(tr '\n' ' ' <in.txt)" = "out in " ] || fail "mink_$mesh.csg $mode: $(tr '\n' ' ' <in.txt)"
        [ "$(cat err.txt)" = "mink_$mesh.csg:3:17: warning: imported mesh is not closed (a corner is not finite); the minkowski is empty, as OpenSCAD leaves it out (\"The given mesh is not closed! Unable to convert to CGAL_Nef_Polyhedron.\")" ] ||
            fail "mink_$mesh.csg $mode: $(cat err.txt)"
    done
    against_openscad mink_$mesh.csg
done

# An OFF file's numbers as CGAL 5's reader takes them (OpenSCAD 2021.01's
# import): the point count starts with a digit and the counts are ints
# ("in >> n"); each point and face is a line of its own, its numbers as
# the stream's num_get<double> extracts them, so "1.0.5" is 1.0 then .5,
# "1-2" is 1 then -2, and "0x1", "1e", "++1" and "1e400" end the line's
# numbers; a face's count and indices are truncated. Each tetrahedron
# below is read (a point in it is inside) or CGAL stops in it and nothing
# is imported, as openscad shows (checked with --faithful against its
# STL of the same model where it is installed).
off_v="0 0 0
1 0 0
0 1 0
0 0 1"
off_f="3 0 2 1
3 0 1 3
3 1 2 3
3 0 3 2"
off_case() { # NAME HEADER COUNTS POINTS FACES
    printf '%s\n%s\n%s\n%s\n' "$2" "$3" "$4" "$5" >"cg_$1.off"
}
off_case plain OFF "4 4 0" "$off_v" "$off_f"
off_case face_plus OFF "4 +4 0" "$off_v" "$off_f"
off_case same_line "OFF 4 4 0" "" "$off_v" "$off_f"
off_case dims "nOFF
3" "4 4 0" "$off_v" "$off_f"
off_case glued OFF "4 4 0" "0 0 0
1.0.5 0 0
0 1 0
0 0 1" "$off_f"
off_case minus_glued OFF "4 4 0" "0 0 0
1-2 0 0
0 1 0
0 0 1" "$off_f"
off_case truncated OFF "4 4 0" "$off_v" "3.7 0 2.9 1
3 0 1 3
3 1 2 3
3 0 3 2"
off_case index_truncated OFF "4 4 0" "$off_v" "3 -0.5 2 1
3 0 1 3
3 1 2 3
3 0 3 2"
off_case count_double OFF "4.0 4 0" "$off_v" "$off_f"
off_case count_comment OFF "4
# the face count is not on this line
4 0" "$off_v" "$off_f"
off_case count_plus OFF "+4 4 0" "$off_v" "$off_f"
off_case count_hex OFF "0x4 4 0" "$off_v" "$off_f"
off_case no_edges OFF "4 4" "$off_v" "$off_f"
# SKEL has no edge count: an OFF file's edge count is its first point's
off_case skel SKEL "4 4" "$off_v" "$off_f"
off_case skel_4 4SKEL "4 4" "0 0 0 1
1 0 0 1
0 1 0 2
0 0 1 1" "$off_f"
off_case skel_edges SKEL "4 4 0" "$off_v" "$off_f"
for bad in 0x1 1e ++1 1e400 1abc; do
    off_case "point_$bad" OFF "4 4 0" "0 0 0
$bad 0 0
0 1 0
0 0 1" "$off_f"
done
off_case split OFF "4 4 0" "0 0 0
1 0
0
0 1 0
0 0 1" "$off_f"
for off in cg_*.off; do
    name=${off%.off}
    printf 'union() {\n\timport(file = "%s");\n\tmultmatrix([[1, 0, 0, 5], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {\n\t\tcube(size = [1, 1, 1], center = false);\n\t}\n}\n' "$off" >"$name.csg"
    case $name in
    cg_plain | cg_face_plus | cg_same_line | cg_dims | cg_glued | cg_minus_glued | cg_truncated | cg_index_truncated | cg_skel | cg_skel_4) want="in" ;;
    *) want="out" ;;
    esac
    check
    "$bin" inside "$name.csg" --point=0.1,0.1,0.1 --point=5.5,0.5,0.5 >in.txt 2>err.txt ||
        fail "$name: exit $?: $(cat err.txt)"
    [ "$(tr '\n' ' ' <in.txt)" = "$want in " ] || fail "$name: $(tr '\n' ' ' <in.txt), want $want in"
    if [ $want = in ]; then
        [ -s err.txt ] && fail "$name: $(cat err.txt)"
    else
        grep -q "warning: import: '$off' is not a valid OFF file (line [0-9]*: .*); the import is empty" err.txt ||
            fail "$name: $(cat err.txt)"
    fi
    against_openscad "$name.csg"
done
# "1.0.5 0 0" is the point (1, 0.5, 0): the tetrahedron's corner moved
check
"$bin" inside cg_glued.csg --point=0.8,0.45,0.05 --point=0.1,0.02,0.02 >in.txt 2>&1
[ "$(tr '\n' ' ' <in.txt)" = "in out " ] || fail "cg_glued: $(tr '\n' ' ' <in.txt)"
# import_error OFF WHY: a model importing OFF is refused with the OFF
# reader's error WHY (where openscad aborts), and writes no image.
import_error() {
    local model=${1%.off}.csg
    printf 'import(file = "%s");\n' "$1" >"$model"
    check
    "$bin" render "$model" -o bad.png -q 2>err.txt && fail "$model rendered"
    [ "$(cat err.txt)" = "$model:1:15: error: import: '$1' is not a valid OFF file ($2)" ] ||
        fail "$model: $(cat err.txt)"
}
# where CGAL's builder is left open (an index missing from a face's line,
# or out of range), openscad aborts: an error at the face's line; also
# where the count is more than the file's points (CGAL reads the indices
# first, and finds one missing)
for face in "3 0 2\n1" "5 0 2 1" "-3 0 2 1"; do
    printf "OFF\n4 4 0\n%s\n$face\n3 0 1 3\n3 1 2 3\n3 0 3 2\n" "$off_v" >cg_missing.off
    import_error cg_missing.off "line 7: face 1 has fewer indices than its point count"
done
# the count's read stops at the comment line, which CGAL's int read does
# not pass
check
"$bin" render cg_count_comment.off -o bad.png -q 2>err.txt && fail "cg_count_comment.off rendered"
grep -q "^cg_count_comment.off:3:1: error: .*(line 3: the face count is not a number)$" err.txt ||
    fail "cg_count_comment.off: $(cat err.txt)"
# comment lines count as lines
printf 'OFF\n# c\n4 4 0\n# c\n0 0 0\n1 0 0\n0 1 0\n0 0 x\n%s\n' "$off_f" >cg_comments.off
check
"$bin" render cg_comments.off -o bad.png -q 2>err.txt && fail "cg_comments.off rendered"
grep -q "^cg_comments.off:8:1: error: .*(line 8: point 4 has fewer than 3 numbers)$" err.txt ||
    fail "cg_comments.off: $(cat err.txt)"
# a 4OFF point with w = 0 makes CGAL divide by zero, and openscad aborts
printf '4OFF\n4 4 0\n0 0 0 1\n1 0 0 0\n0 1 0 1\n0 0 1 1\n%s\n' "$off_f" >cg_w0.off
import_error cg_w0.off "line 4: point 2 is not finite"

# Binary OFF ("OFF BINARY"), as CGAL's reader takes it: big-endian counts,
# each point's floats (then a normal, NOFF; a colour's count and floats,
# COFF), each face's count, indices, and colour count and floats. A file
# it stops in is left out; one where openscad aborts (an index out of
# range or missing, a point that is not finite) is an error.
python3 -c '
import struct
P = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
F = [(0, 2, 1), (0, 1, 3), (1, 2, 3), (0, 3, 2)]
def off(name, kw="OFF", pts=P, faces=F, after=lambda i: b"", colour=struct.pack(">i", 0), cut=None, w=None):
    d = (kw + " BINARY\n").encode() + struct.pack(">3i", len(pts), len(faces), 0)
    for i, p in enumerate(pts):
        d += struct.pack(">3f", *p) + (struct.pack(">f", w[i]) if w else b"") + after(i)
    for f in faces:
        d += struct.pack(">i", len(f)) + b"".join(struct.pack(">i", x) for x in f) + colour
    open("bin_" + name + ".off", "wb").write(d[:cut] if cut else d)
off("plain")
off("colour", "COFF", after=lambda i: struct.pack(">i3f", 3, 1, 0, 0), colour=struct.pack(">i4f", 4, 1, 1, 1, 1))
off("normal", "NOFF", after=lambda i: struct.pack(">3f", 0, 0, 1))
off("w", "4OFF", pts=[(0, 0, 0), (2, 0, 0), (0, 2, 0), (0, 0, 2)], w=[1, 2, 2, 2])
off("cut", cut=60)
off("nocolour", colour=b"")
off("badcolour", colour=struct.pack(">i", 7))
off("twopoints", faces=[(0, 2), (0, 1, 3), (1, 2, 3), (0, 3, 2)])
off("index", faces=[(0, 2, 1), (0, 1, 9), (1, 2, 3), (0, 3, 2)])
off("nan", pts=[(0, 0, 0), (float("nan"), 0, 0), (0, 1, 0), (0, 0, 1)])
off("cutface", cut=138)
'
for off in bin_*.off; do
    name=${off%.off}
    printf 'union() {\n\timport(file = "%s");\n\tmultmatrix([[1, 0, 0, 5], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {\n\t\tcube(size = [1, 1, 1], center = false);\n\t}\n}\n' "$off" >"$name.csg"
    case $name in
    bin_plain | bin_colour | bin_normal | bin_w) want=in ;;
    bin_cut) want="byte 59: the file ends in point 4 of 4" ;;
    bin_nocolour) want="byte 135: the file ends before face 3 of 4" ;;
    bin_badcolour) want="byte 91: face 1 has a colour of 7 numbers (0 to 4)" ;;
    bin_twopoints) want="byte 75: face 1 has fewer than 3 points" ;;
    bin_index) want="error: byte 107: a point index of face 2 is out of range" ;;
    bin_nan) want="error: byte 47: point 2 is not finite" ;;
    bin_cutface) want="error: byte 135: face 4 has fewer indices than its point count" ;;
    esac
    check
    case $want in
    in)
        "$bin" inside "$name.csg" --point=0.1,0.1,0.1 --point=5.5,0.5,0.5 >in.txt 2>err.txt ||
            fail "$name: exit $?: $(cat err.txt)"
        [ "$(tr '\n' ' ' <in.txt)" = "in in " ] || fail "$name: $(tr '\n' ' ' <in.txt)"
        [ -s err.txt ] && fail "$name: $(cat err.txt)"
        against_openscad "$name.csg"
        ;;
    error:*)
        "$bin" render "$name.csg" -o bad.png -q 2>err.txt && fail "$name rendered"
        [ "$(cat err.txt)" = "$name.csg:2:16: error: import: '$off' is not a valid OFF file (${want#error: })" ] ||
            fail "$name: $(cat err.txt)"
        ;;
    *)
        left_out "$name.csg" corner_ref.csg 2:16 "$off" OFF "$want"
        against_openscad "$name.csg"
        ;;
    esac
done
# The quoted line is shown as printable ASCII: a terminal's escape
# sequence in the file does not reach the terminal.
printf 'solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 \033[31m\n' >esc.stl
printf 'import(file = "esc.stl");\ncube(size = [1, 2, 3]);\n' >import_esc.csg
warns import_esc.csg "import_esc.csg:1:15: warning: import: 'esc.stl' is not a valid STL file (line 6: can't parse vertex line 'vertex 0 1 \\x1b[31m'); the import is empty, as OpenSCAD leaves it out (--strict makes it an error)"
# a file that is neither binary nor ASCII STL (empty, another format):
# OpenSCAD 2021.01 imports nothing from it, silently, and renders the
# rest; as the model itself it is an error
: >empty.stl
printf 'import(file = "empty.stl");\ncube(size = [1, 2, 3]);\n' >empty_import.csg
printf 'cube(size = [1, 2, 3]);\n' >empty_ref.csg
why="neither binary STL (its size does not match its triangle count) nor ASCII STL (it does not start with 'solid')"
warns empty_import.csg "empty_import.csg:1:15: warning: import: 'empty.stl' is not a valid STL file ($why); the import is empty, as OpenSCAD leaves it out (--strict makes it an error)"
same empty_import.csg empty_ref.csg
refuses empty_import.csg "empty_import.csg:1:15: error: import: 'empty.stl' is not a valid STL file ($why)"
check
"$bin" render empty.stl -o empty.png -q 2>err.txt && fail "an empty STL model rendered"
[ "$(cat err.txt)" = "empty.stl: error: import: '$PWD/empty.stl' is not a valid STL file ($why)" ] ||
    fail "empty STL model: $(cat err.txt)"
[ -e empty.png ] && fail "empty STL model: an image was written"

# ---- resize() with a negative size: as 0 ----
cat >resize.csg <<'M'
resize(newsize = [10, -20, 0], auto = [0, 0, 1]) {
	multmatrix([[1, 0, 0, 1], [0, 1, 0, 2], [0, 0, 1, 3], [0, 0, 0, 1]]) {
		cube(size = [5, 5, 5], center = false);
	}
}
M
# OpenSCAD's mesh: x 2..12, y 2..7 (kept), z 6..16 (auto)
printf 'multmatrix([[1, 0, 0, 2], [0, 1, 0, 2], [0, 0, 1, 6], [0, 0, 0, 1]]) { cube(size = [10, 5, 10]); }\n' >resize_ref.csg
warns resize.csg ""
same resize.csg resize_ref.csg

# ---- a boolean's negative size mirrors it, measured on its CGAL result ----
# OpenSCAD resizes a CGAL Nef polyhedron by newsize / size, so a negative
# size mirrors; the box is the result's (x 0..2), not the first child's.
cat >mirror.csg <<'M'
resize(newsize = [-10, 0, 0], auto = [0, 0, 0]) {
	difference() {
		cube(size = [4, 4, 4], center = false);
		multmatrix([[1, 0, 0, 2], [0, 1, 0, -1], [0, 0, 1, -1], [0, 0, 0, 1]]) {
			cube(size = [3, 6, 6], center = false);
		}
	}
}
M
printf 'multmatrix([[1, 0, 0, -10], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) { cube(size = [10, 4, 4]); }\n' >mirror_ref.csg
warns mirror.csg ""
same mirror.csg mirror_ref.csg
warns mirror.csg "" --faithful
same mirror.csg mirror_ref.csg

# ---- 2D children of a 3D resize and hull: ignored with OpenSCAD's warnings ----
cat >resize2d.csg <<'M'
resize(newsize = [10, 0, 0], auto = [0, 0, 0]) {
	cube(size = [5, 5, 5], center = false);
	square(size = [20, 20], center = false);
}
M
printf 'cube(size = [10, 5, 5]);\n' >resize2d_ref.csg
warns resize2d.csg "resize2d.csg:3:2: warning: Mixing 2D and 3D objects is not supported
resize2d.csg:3:2: warning: Ignoring 2D child object for 3D operation"
same resize2d.csg resize2d_ref.csg
cat >hull2d.csg <<'M'
hull() {
	cube(size = [2, 2, 2], center = false);
	square(size = [20, 20], center = false);
	multmatrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 4], [0, 0, 0, 1]]) {
		cube(size = [2, 2, 2], center = false);
		circle(r = 9);
	}
}
M
printf 'cube(size = [2, 2, 6]);\n' >hull2d_ref.csg
warns hull2d.csg "hull2d.csg:6:3: warning: Mixing 2D and 3D objects is not supported
hull2d.csg:6:3: warning: Ignoring 2D child object for 3D operation
hull2d.csg:3:2: warning: Mixing 2D and 3D objects is not supported
hull2d.csg:3:2: warning: Ignoring 2D child object for 3D operation"
same hull2d.csg hull2d_ref.csg
# their arguments are still checked: a size OpenSCAD cannot convert is
# warned of first (openscad -o x.stl on the same file prints these)
printf 'resize(newsize = [10, 0, 0]) { cube(size = 5); square(size = "big"); }\n' >bad2d.csg
printf 'resize(newsize = [10, 0, 0]) { cube(size = 5); }\n' >bad2d_ref.csg
warns bad2d.csg 'bad2d.csg:1:62: warning: Unable to convert square(size="big", ...) parameter to a number or a vec2 of numbers
bad2d.csg:1:48: warning: Mixing 2D and 3D objects is not supported
bad2d.csg:1:48: warning: Ignoring 2D child object for 3D operation'
same bad2d.csg bad2d_ref.csg
refuses bad2d.csg 'bad2d.csg:1:62: error: Unable to convert square(size="big", ...) parameter to a number or a vec2 of numbers'

# ---- 2D hull, minkowski and resize in a 2D model: drawn flat ----
printf 'hull() { square(size = [1, 4]); multmatrix([[1, 0, 0, 9], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) { square(size = [1, 4]); } }\n' >hull_flat.csg
warns hull_flat.csg ""
same hull_flat.csg flat_ref.csg
printf 'minkowski() { square(size = [8, 2]); square(size = [2, 2]); }\n' >minkowski_flat.csg
warns minkowski_flat.csg ""
same minkowski_flat.csg flat_ref.csg
printf 'resize(newsize = [10, 0, 0], auto = [0, 1, 0]) { square(size = [5, 2]); }\n' >resize_flat.csg
warns resize_flat.csg ""
same resize_flat.csg flat_ref.csg
# a negative size is as 0 for a 2D shape: y keeps its size
printf 'resize(newsize = [10, -1, 0]) { square(size = [5, 4]); }\n' >resize_neg_flat.csg
warns resize_neg_flat.csg ""
same resize_neg_flat.csg flat_ref.csg
# a 3D child there is ignored with OpenSCAD's warnings
printf 'hull() { square(size = [1, 4]); cube(size = 30); multmatrix([[1, 0, 0, 9], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) { square(size = [1, 4]); } }\n' >hull_mixed.csg
warns hull_mixed.csg "hull_mixed.csg:1:33: warning: Mixing 2D and 3D objects is not supported
hull_mixed.csg:1:33: warning: Ignoring 3D child object for 2D operation"
same hull_mixed.csg flat_ref.csg

# ---- 2D imports outside an extrusion: 2D by their extension, as OpenSCAD ----
# a drawing 10 x 4 from the origin (SVG: millimetres, y down; DXF: a
# closed polyline)
printf '<svg xmlns="http://www.w3.org/2000/svg" width="10mm" height="4mm" viewBox="0 0 10 4"><rect x="0" y="0" width="10" height="4"/></svg>\n' >rect.svg
printf '0\nSECTION\n2\nENTITIES\n0\nLWPOLYLINE\n8\n0\n90\n4\n70\n1\n10\n0\n20\n0\n10\n10\n20\n0\n10\n10\n20\n4\n10\n0\n20\n4\n0\nENDSEC\n0\nEOF\n' >rect.dxf
printf 'import(file = "rect.svg");\n' >svg_flat.csg
warns svg_flat.csg ""
same svg_flat.csg flat_ref.csg
printf 'multmatrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) { import(file = "rect.dxf"); }\n' >dxf_flat.csg
warns dxf_flat.csg ""
same dxf_flat.csg flat_ref.csg
# under 2D booleans, offset, hull, minkowski and resize
printf 'difference() { import(file = "rect.svg"); multmatrix([[1, 0, 0, 2], [0, 1, 0, 1], [0, 0, 1, 0], [0, 0, 0, 1]]) { square(size = [3, 2]); } }\n' >svg_cut.csg
printf 'difference() { square(size = [10, 4]); multmatrix([[1, 0, 0, 2], [0, 1, 0, 1], [0, 0, 1, 0], [0, 0, 0, 1]]) { square(size = [3, 2]); } }\n' >svg_cut_ref.csg
warns svg_cut.csg ""
same svg_cut.csg svg_cut_ref.csg
printf 'offset(delta = 1) { import(file = "rect.dxf"); }\n' >dxf_offset.csg
printf 'offset(delta = 1) { square(size = [10, 4]); }\n' >dxf_offset_ref.csg
warns dxf_offset.csg ""
same dxf_offset.csg dxf_offset_ref.csg
printf 'hull() { import(file = "rect.svg"); multmatrix([[1, 0, 0, 0], [0, 1, 0, 9], [0, 0, 1, 0], [0, 0, 0, 1]]) { square(size = [1, 1]); } }\n' >svg_hull.csg
printf 'hull() { square(size = [10, 4]); multmatrix([[1, 0, 0, 0], [0, 1, 0, 9], [0, 0, 1, 0], [0, 0, 0, 1]]) { square(size = [1, 1]); } }\n' >svg_hull_ref.csg
warns svg_hull.csg ""
same svg_hull.csg svg_hull_ref.csg
printf 'minkowski() { import(file = "rect.dxf"); square(size = [2, 2]); }\n' >dxf_minkowski.csg
printf 'square(size = [12, 6]);\n' >dxf_minkowski_ref.csg
warns dxf_minkowski.csg ""
same dxf_minkowski.csg dxf_minkowski_ref.csg
printf 'resize(newsize = [20, 0, 0], auto = [0, 1, 0]) { import(file = "rect.svg"); }\n' >svg_resize.csg
printf 'square(size = [20, 8]);\n' >svg_resize_ref.csg
warns svg_resize.csg ""
same svg_resize.csg svg_resize_ref.csg
# in a 3D tree: ignored with OpenSCAD's warnings
printf 'union() {\n\tcube(size = [1, 1, 1]);\n\timport(file = "rect.svg");\n}\n' >svg_mixed.csg
warns svg_mixed.csg "svg_mixed.csg:3:2: warning: Mixing 2D and 3D objects is not supported
svg_mixed.csg:3:2: warning: Ignoring 2D child object for 3D operation"
same svg_mixed.csg cube_ref.csg
printf 'hull() {\n\tcube(size = [1, 1, 1]);\n\timport(file = "rect.dxf");\n}\n' >dxf_hull3d.csg
warns dxf_hull3d.csg "dxf_hull3d.csg:3:2: warning: Mixing 2D and 3D objects is not supported
dxf_hull3d.csg:3:2: warning: Ignoring 2D child object for 3D operation"
same dxf_hull3d.csg cube_ref.csg

# ---- a 2D child of a hull inside projection: ignored, as OpenSCAD ----
printf 'projection(cut = false) {\n\thull() {\n\t\tcube(size = [3, 3, 3]);\n\t\tsquare(size = [20, 20]);\n\t\timport(file = "rect.svg");\n\t}\n}\n' >proj_hull2d.csg
printf 'projection(cut = false) { cube(size = [3, 3, 3]); }\n' >proj_hull2d_ref.csg
warns proj_hull2d.csg "proj_hull2d.csg:4:3: warning: Mixing 2D and 3D objects is not supported
proj_hull2d.csg:4:3: warning: Ignoring 2D child object for 3D operation
proj_hull2d.csg:5:3: warning: Ignoring 2D child object for 3D operation"
same proj_hull2d.csg proj_hull2d_ref.csg

# ---- a malformed SVG or AMF: OpenSCAD logs an error and renders the rest ----
printf '<svg width="10mm" height="10mm">\n  <path d="M 1 1 L 5 1 L 5 5 z">\n</svg>\n' >bad.svg
printf '<?xml version="1.0"?>\n<amf>\n <object id="0"><mesh>\n  <vertices><vertex><coordinates><x>1,5</x><y>0</y><z>0</z></coordinates></vertex></vertices>\n </mesh></object>\n</amf>\n' >bad.amf
printf 'union() {\n\tcube(size = [1, 1, 1]);\n\tlinear_extrude(height = 1) import(file = "bad.svg");\n\timport(file = "bad.amf");\n}\n' >bad_files.csg
# After the import's warning, the empty extrusion or 2D model is not warned
# of again: OpenSCAD 2021.01 prints only the import's error (and "Current
# top level object is empty.", spancast's "the model is empty").
warns bad_files.csg "bad_files.csg:3:43: warning: import: bad.svg:4: Premature end of data in tag svg line 1; the import is empty, as OpenSCAD leaves it out (--strict makes it an error)
bad_files.csg:4:16: warning: import: bad.amf:4: '1,5' is not a number; the import is empty, as OpenSCAD leaves it out (--strict makes it an error)"
same bad_files.csg cube_ref.csg
printf 'import(file = "bad.svg");\n' >bad_flat.csg
warns bad_flat.csg "bad_flat.csg:1:15: warning: import: bad.svg:4: Premature end of data in tag svg line 1; the import is empty, as OpenSCAD leaves it out (--strict makes it an error)
bad_flat.csg: warning: the model is empty (nothing to render)"
printf 'union() {\n\tcube(size = [1, 1, 1]);\n\trotate_extrude() import(file = "bad.svg");\n\tlinear_extrude(height = 1) import(file = "missing.svg");\n}\n' >bad_revolve.csg
warns bad_revolve.csg "bad_revolve.csg:3:33: warning: import: bad.svg:4: Premature end of data in tag svg line 1; the import is empty, as OpenSCAD leaves it out (--strict makes it an error)
bad_revolve.csg:4:29: warning: Can't open SVG file 'missing.svg': No such file or directory; the import is empty, as OpenSCAD leaves it out (--strict makes it an error)"
same bad_revolve.csg cube_ref.csg
# an import of an extension no reader takes: OpenSCAD's "Unsupported file
# format", and in a 2D operation its "Ignoring 3D child object" too
printf 'union() {\n\tcube(size = [1, 1, 1]);\n\timport(file = "x.obj");\n\tlinear_extrude(height = 1) import(file = "x.obj");\n}\n' >obj.csg
warns obj.csg "obj.csg:3:16: warning: Unsupported file format while trying to import file '\"x.obj\"' (import() reads .stl, .off, .amf, .3mf, .dxf and .svg files); the import is empty, as OpenSCAD leaves it out (--strict makes it an error)
obj.csg:4:43: warning: Unsupported file format while trying to import file '\"x.obj\"' (import() reads .stl, .off, .amf, .3mf, .dxf and .svg files); the import is empty, as OpenSCAD leaves it out (--strict makes it an error)
obj.csg:4:29: warning: Ignoring 3D child object for 2D operation"
same obj.csg cube_ref.csg
check
"$bin" render obj.csg -o strict.png -q --strict 2>err.txt && fail "obj.csg --strict: exit 0"
[ "$(cat err.txt)" = "obj.csg:3:16: error: Unsupported file format while trying to import file '\"x.obj\"' (import() reads .stl, .off, .amf, .3mf, .dxf and .svg files)" ] ||
    fail "obj.csg --strict: $(cat err.txt)"
# an extrusion empty for its own reason is still warned of
printf 'union() {\n\tcube(size = [1, 1, 1]);\n\tlinear_extrude(height = 1) square(size = [0, 0]);\n}\n' >zero_extrude.csg
warns zero_extrude.csg "zero_extrude.csg:3:2: warning: linear_extrude without height or area is empty"
printf 'import(file = "bad.amf");\n' >bad_amf.csg
check
"$bin" render bad_amf.csg -o strict.png -q --strict 2>err.txt && fail "bad_amf.csg --strict: exit 0"
[ "$(cat err.txt)" = "bad_amf.csg:1:15: error: import: bad.amf:4: '1,5' is not a number" ] ||
    fail "bad_amf.csg --strict: $(cat err.txt)"
# --strict: the error, exit 1, no image
for model in bad_files.csg bad_flat.csg; do
    check
    rm -f strict.png
    "$bin" render "$model" -o strict.png -q --strict 2>err.txt && fail "$model --strict: exit 0"
    grep -q ": error: import: bad.svg:4: Premature end of data in tag svg line 1$" err.txt ||
        fail "$model --strict: $(cat err.txt)"
    [ -e strict.png ] && fail "$model --strict: an image was written"
done

# ---- a size that is not finite: a .scad's 1/0, which OpenSCAD's export
# writes as inf (0/0 as nan) ----
# OpenSCAD 2021.01 draws nothing for text() of such a size, or an offset()
# by such an amount, and no warning: its own STL of this file is the cube
# alone (12 triangles), and so is spancast's model, in both modes.
# (offset(r = -1/0) aborts OpenSCAD 2021.01 with an uncaught exception;
# spancast draws nothing for it either: test_twod.)
printf 'cube(1);\nlinear_extrude(height = 1) text("a", size = 1/0);\nlinear_extrude(height = 1) offset(r = 1/0) square(5);\nlinear_extrude(height = 1) offset(delta = 0/0) square(5);\n' >nonfinite.scad
check
openscad -o nonfinite_os.stl nonfinite.scad >/dev/null 2>&1 || fail "openscad -o nonfinite_os.stl: exit $?"
[ "$(grep -c 'facet normal' nonfinite_os.stl)" = 12 ] ||
    fail "OpenSCAD's STL of nonfinite.scad is not the cube alone"
for mode in "" --faithful; do
    same nonfinite.scad cube_ref.csg $mode
done
# A DXF drawing at no finite place: an origin of 1/0 or 0/0 is not
# converted, with OpenSCAD's warning, and the drawing is empty; so is one
# scaled by 1/0 or 0/0, without a word (the export writes linear_extrude's
# own scale of 1/0 as the default). OpenSCAD's STL of such a file is the
# cube alone, and so is spancast's model. (OpenSCAD's clipper may also say
# "Range check failed for polygon. skipping", depending on how its DXF
# reader joined the outlines there: not for this drawing.)
printf 'cube(1);
linear_extrude(height = 1) import(file = "rect.dxf", origin = [1/0, 0]);
linear_extrude(height = 1) import(file = "rect.dxf", origin = [0, 0/0]);
linear_extrude(height = 1) import(file = "rect.dxf", scale = 1/0);
linear_extrude(height = 1) import(file = "rect.dxf", scale = 0/0);
rotate_extrude(file = "rect.dxf", origin = [-1/0, 0]);
' >far_dxf.scad
check
openscad -o far_dxf_os.stl far_dxf.scad >/dev/null 2>far_dxf_os.err ||
    fail "openscad -o far_dxf_os.stl: exit $?"
[ "$(grep -c 'facet normal' far_dxf_os.stl)" = 12 ] ||
    fail "OpenSCAD's STL of far_dxf.scad is not the cube alone"
[ "$(grep -c '^WARNING: ' far_dxf_os.err)" = 3 ] ||
    fail "OpenSCAD's warnings of far_dxf.scad: $(cat far_dxf_os.err)"
for mode in "" --faithful; do
    same far_dxf.scad cube_ref.csg $mode
done
cat >far_dxf.csg <<'M'
cube(size = [1, 1, 1], center = false);
linear_extrude(height = 1) {
	import(file = "rect.dxf", origin = [inf, 0], scale = 1);
}
linear_extrude(height = 1) {
	import(file = "rect.dxf", origin = [0, 0], scale = nan);
}
M
warns far_dxf.csg "far_dxf.csg:3:37: warning: linear_extrude(..., origin=[inf, 0]) could not be converted
far_dxf.csg:2:1: warning: linear_extrude without height or area is empty
far_dxf.csg:5:1: warning: linear_extrude without height or area is empty"
same far_dxf.csg cube_ref.csg
# A spacing of 1/0 or 0/0 puts every glyph after the first at no finite
# place: OpenSCAD draws the first glyph alone (its SVG of "abc" so spaced
# is byte for byte its SVG of "a"), and so does spancast.
printf 'text("abc", spacing = 1/0);\n' >spacing_inf.scad
printf 'text("abc", spacing = 0/0);\n' >spacing_nan.scad
printf 'text("a");\n' >spacing_one.scad
for f in spacing_inf spacing_nan spacing_one; do
    openscad -o "${f}_os.svg" "$f.scad" >/dev/null 2>&1 || fail "openscad -o ${f}_os.svg: exit $?"
done
cmp -s spacing_inf_os.svg spacing_one_os.svg || fail "OpenSCAD draws more than one glyph at spacing 1/0"
cmp -s spacing_nan_os.svg spacing_one_os.svg || fail "OpenSCAD draws more than one glyph at spacing 0/0"
for mode in "" --faithful; do
    same spacing_inf.scad spacing_one.scad $mode
    same spacing_nan.scad spacing_one.scad $mode
done

# ---- surface(): a file that cannot be opened or read, an illegal value ----
# OpenSCAD 2021.01 (openscad -o x.stl x.scad) warns "The file '...'
# couldn't be opened.", "Can't read PNG image '...'" or "Illegal value in
# '...'" and renders the rest; a file without a PNG signature is read as
# .dat, and of a .dat file the values before the illegal one are kept.
# --strict makes each warning the error (exit 1, no image).
left_out="; the surface is empty, as OpenSCAD leaves it out (--strict makes it an error)"
stopped="; the rest of the file is ignored, as OpenSCAD stops reading there (--strict makes it an error)"
printf 'not a png\n' >notpng.png
printf '\211PNG\r\n\032\n\0\0\0\0' >broken.png
printf '1 2 3\n4 x 6\n7 8 9\n' >illegal.dat
printf '1 2 3\n4\n' >kept.dat
printf 'union() {\n\tcube(size = [1, 1, 1]);\n\tsurface(file = "missing.png");\n\tsurface(file = "notpng.png");\n}\n' >surface_empty.csg
printf 'union() {\n\tcube(size = [1, 1, 1]);\n\tsurface(file = "broken.png");\n}\n' >surface_broken.csg
printf 'surface(file = "illegal.dat", center = false, invert = false);\n' >surface_illegal.csg
printf 'surface(file = "kept.dat", center = false, invert = false);\n' >surface_kept.csg
for mode in "" --faithful; do
    warns surface_empty.csg "surface_empty.csg:3:17: warning: surface: the file 'missing.png' couldn't be opened: No such file or directory$left_out
surface_empty.csg:4:17: warning: surface: illegal value in 'notpng.png' line 1: 'not' is not a number$stopped" $mode
    # shellcheck disable=SC2086
    same surface_empty.csg cube_ref.csg $mode
    check
    "$bin" render surface_broken.csg -o out.png --imgsize=64,48 -q $mode 2>err.txt ||
        fail "surface_broken.csg $mode: exit $?: $(cat err.txt)"
    case $(cat err.txt) in
    "surface_broken.csg:3:17: warning: surface: can't read PNG image 'broken.png': "*"$left_out") ;;
    *) fail "surface_broken.csg $mode: stderr '$(cat err.txt)'" ;;
    esac
    # shellcheck disable=SC2086
    same surface_broken.csg cube_ref.csg $mode
    warns surface_illegal.csg "surface_illegal.csg:1:16: warning: surface: illegal value in 'illegal.dat' line 2: 'x' is not a number$stopped" $mode
    # shellcheck disable=SC2086
    same surface_illegal.csg surface_kept.csg $mode
    for model in surface_empty.csg surface_broken.csg surface_illegal.csg; do
        check
        rm -f strict.png
        "$bin" render "$model" -o strict.png -q --strict $mode 2>err.txt &&
            fail "$model --strict $mode: exit 0"
        case $model in
        surface_empty.csg) want="surface_empty.csg:3:17: error: surface: the file 'missing.png' couldn't be opened: No such file or directory" ;;
        surface_broken.csg) want="surface_broken.csg:3:17: error: surface: can't read PNG image 'broken.png': *" ;;
        *) want="surface_illegal.csg:1:16: error: surface: illegal value in 'illegal.dat' line 2: 'x' is not a number" ;;
        esac
        # shellcheck disable=SC2053 # want is a pattern for the PNG reader's reason
        [[ "$(cat err.txt)" == $want ]] || fail "$model --strict $mode: '$(cat err.txt)', want '$want'"
        [ -e strict.png ] && fail "$model --strict $mode: an image was written"
    done
done
# an illegal value on a last line without its newline: OpenSCAD 2021.01
# warns only when its stream is not at the end, so it keeps the same
# values silently (the same 34 facets as with the newline), also with
# --strict here, as there is no warning to make an error
printf '1 2 3\n4 5 6\n7 x 9' >unterminated.dat
printf '1 2 3\n4 5 6\n7\n' >unterminated_kept.dat
printf 'surface(file = "unterminated.dat", center = false, invert = false);\n' >surface_unterminated.csg
printf 'surface(file = "unterminated_kept.dat", center = false, invert = false);\n' >surface_unterminated_kept.csg
for mode in "" --faithful --strict; do
    warns surface_unterminated.csg "" $mode
    # shellcheck disable=SC2086
    same surface_unterminated.csg surface_unterminated_kept.csg $mode
done

# ---- polyhedron faces as OpenSCAD reads them ----
# OpenSCAD 2021.01 leaves a point index out of range out of its face with
# "Point index 7 is out of bounds (from faces[3][3])", in a hull or a
# projection as anywhere: here the tetrahedron keeps its four faces.
tetra='polyhedron(points = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], faces = [[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2, 7]], convexity = 1);'
tetra_ref='polyhedron(points = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], faces = [[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]], convexity = 1);'
printf '%s\n' "$tetra" >tetra_bad.csg
printf 'hull() {\n\t%s\n}\n' "$tetra" >tetra_hull.csg
printf 'linear_extrude(height = 1) {\n\tprojection(cut = false) {\n\t\t%s\n\t}\n}\n' "$tetra" >tetra_projection.csg
printf '%s\n' "$tetra_ref" >tetra_ref.csg
printf 'linear_extrude(height = 1) {\n\tprojection(cut = false) {\n\t\t%s\n\t}\n}\n' "$tetra_ref" >tetra_projection_ref.csg
for mode in "" --faithful; do
    # shellcheck disable=SC2086
    {
        warns tetra_bad.csg "tetra_bad.csg:1:119: warning: Point index 7 is out of bounds (from faces[3][3])" $mode
        same tetra_bad.csg tetra_ref.csg $mode
        warns tetra_hull.csg "tetra_hull.csg:2:120: warning: Point index 7 is out of bounds (from faces[3][3])" $mode
        same tetra_hull.csg tetra_ref.csg $mode
        warns tetra_projection.csg "tetra_projection.csg:3:121: warning: Point index 7 is out of bounds (from faces[3][3])" $mode
        same tetra_projection.csg tetra_projection_ref.csg $mode
    }
done
check
"$bin" render tetra_hull.csg -o strict.png -q --strict 2>err.txt && fail "tetra_hull.csg --strict: exit 0"
[ "$(cat err.txt)" = "tetra_hull.csg:2:120: error: polyhedron face 3: point index 7 is out of range (4 points)" ] ||
    fail "tetra_hull.csg --strict: $(cat err.txt)"

# ---- malformed polyhedron and polygon points, faces and paths ----
# OpenSCAD 2021.01 reads a point only where a face reads it: the first it
# cannot convert is its error "Unable to convert points[3] = [0, 0, "a"]
# to a vec3 of numbers", and the polyhedron keeps the faces before it
# (here one triangle, not closed: left out of the CGAL union with the
# cube, so --faithful renders the cube alone, and exact mode draws the
# triangle by the parity rule). A polygon point it cannot convert empties
# the polygon. A face or path that is not a vector is an empty one, faces
# that are not a vector none, paths that are not a vector none (all the
# points). A face left with fewer than 3 points (the one the bad point
# stops, or an empty one) is OpenSCAD's "PolySet has degenerate polygons",
# as its preview says it (its render says it only of a polyhedron that is
# not in a boolean); a path of fewer than 3 points is read silently.
# --strict makes each warning the error.
shift3='multmatrix([[1, 0, 0, 3], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]])'
tetra_faces='[[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]]'
printf 'polyhedron(points = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, "a"]], faces = %s, convexity = 1);\n%s {\n\tcube(size = [1, 1, 1], center = false);\n}\n' \
    "$tetra_faces" "$shift3" >bad_point.csg
printf '%s {\n\tcube(size = [1, 1, 1], center = false);\n}\n' "$shift3" >shifted_cube.csg
printf 'polyhedron(points = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1], "x"], faces = [[0, 1, 2], 7, [0, 3, 1], [0, 2, 3], [1, 3, 2], []], convexity = 1);\n%s {\n\tcube(size = [1, 1, 1], center = false);\n}\n' \
    "$shift3" >bad_face.csg
printf 'polyhedron(points = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], faces = %s, convexity = 1);\n%s {\n\tcube(size = [1, 1, 1], center = false);\n}\n' \
    "$tetra_faces" "$shift3" >bad_face_ref.csg
square_shift='multmatrix([[1, 0, 0, 3], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {
	square(size = [1, 1], center = false);
}'
printf 'polygon(points = [[0, 0], [1, 0], [0, 1], [1, "a"]], paths = [[0, 1, 2]], convexity = 1);\n%s\n' "$square_shift" >bad_polygon.csg
printf '%s\n' "$square_shift" >bad_polygon_ref.csg
printf 'polygon(points = [[0, 0], [1, 0], [0, 1], [1, 1]], paths = [[0, 1, 2], 5], convexity = 1);\n%s\n' "$square_shift" >bad_path.csg
printf 'polygon(points = [[0, 0], [1, 0], [0, 1], [1, 1]], paths = [[0, 1, 2]], convexity = 1);\n%s\n' "$square_shift" >bad_path_ref.csg
printf 'polygon(points = [[0, 0], [1, 0], [0, 1]], paths = 5, convexity = 1);\n%s\n' "$square_shift" >bad_paths.csg
printf 'polygon(points = [[0, 0], [1, 0], [0, 1]], convexity = 1);\n%s\n' "$square_shift" >bad_paths_ref.csg
unable_vec3='bad_point.csg:1:55: warning: Unable to convert points[3] = [0, 0, "a"] to a vec3 of numbers; the polyhedron keeps the faces before it, as OpenSCAD does (--strict makes it an error)
bad_point.csg:1:89: warning: PolySet has degenerate polygons (faces[1] has fewer than 3 points; left out, as OpenSCAD leaves it out)'
warns bad_point.csg "$unable_vec3
bad_point.csg:1:1: warning: polyhedron is not closed (edge 0-1 is used by 1 face); rendered by the parity rule (--strict makes it an error)"
warns bad_point.csg "$unable_vec3
bad_point.csg:1:1: warning: polyhedron is not closed (edge 0-1 is used by 1 face); left out, as OpenSCAD leaves it out (\"The given mesh is not closed! Unable to convert to CGAL_Nef_Polyhedron.\")" --faithful
same bad_point.csg shifted_cube.csg --faithful
for mode in "" --faithful; do
    # shellcheck disable=SC2086
    {
        warns bad_face.csg "bad_face.csg:1:92: warning: PolySet has degenerate polygons (faces[1] and 1 more have fewer than 3 points; left out, as OpenSCAD leaves them out)" $mode
        same bad_face.csg bad_face_ref.csg $mode
        warns bad_polygon.csg "bad_polygon.csg:1:43: warning: Unable to convert points[3] = [1, \"a\"] to a vec2 of numbers; the polygon is empty, as OpenSCAD leaves it out (--strict makes it an error)" $mode
        same bad_polygon.csg bad_polygon_ref.csg $mode
        warns bad_path.csg "" $mode
        same bad_path.csg bad_path_ref.csg $mode
        warns bad_paths.csg "" $mode
        same bad_paths.csg bad_paths_ref.csg $mode
    }
done
for mode in "" --faithful; do
    for pair in "bad_point.csg|bad_point.csg:1:55: error: wrong type for argument 'points' of 'polyhedron' (expected a vector of [x, y, z] points)" \
        "bad_polygon.csg|bad_polygon.csg:1:43: error: wrong type for argument 'points' of 'polygon' (expected a vector of [x, y] points)"; do
        model=${pair%%|*}
        check
        rm -f strict.png
        # shellcheck disable=SC2086
        "$bin" render "$model" -o strict.png -q --strict $mode 2>err.txt &&
            fail "$model --strict $mode: exit 0"
        [ "$(cat err.txt)" = "${pair#*|}" ] || fail "$model --strict $mode: $(cat err.txt)"
        [ -e strict.png ] && fail "$model --strict $mode: an image was written"
    done
done

# ---- a bad polygon that a 3D operation ignores ----
# OpenSCAD 2021.01 (openscad -o /abs/x.stl x.csg) prints a polygon's error
# "Unable to convert points[2] = [1, "a"] to a vec2 of numbers" also where
# a 3D operation ignores the polygon, before "Ignoring 2D child object for
# 3D operation", and no "Mixing 2D and 3D objects": the polygon is empty.
printf 'union() {\n\tcube(size = [1, 1, 1], center = false);\n\tpolygon(points = [[0, 0], [1, 0], [1, "a"]]);\n}\n' >empty2d_bad.csg
for mode in "" --faithful; do
    # shellcheck disable=SC2086
    {
        warns empty2d_bad.csg 'empty2d_bad.csg:3:36: warning: Unable to convert points[2] = [1, "a"] to a vec2 of numbers; the polygon is empty, as OpenSCAD leaves it out (--strict makes it an error)
empty2d_bad.csg:3:2: warning: Ignoring 2D child object for 3D operation' $mode
        same empty2d_bad.csg cube_ref.csg $mode
        check
        "$bin" render empty2d_bad.csg -o strict.png -q --strict $mode 2>err.txt &&
            fail "empty2d_bad.csg --strict $mode: exit 0"
        [ "$(cat err.txt)" = "empty2d_bad.csg:3:36: error: wrong type for argument 'points' of 'polygon' (expected a vector of [x, y] points)" ] ||
            fail "empty2d_bad.csg --strict $mode: $(cat err.txt)"
    }
done

# OpenSCAD 2021.01 says that an operation mixes 2D and 3D objects at its
# first ignored 2D child that is not empty (isValidDim), before every
# "Ignoring": not for square(0) nor for a polygon emptied by a bad point;
# the same in a hull, in a boolean CGAL evaluates for it, and in a hull
# inside projection (openscad -o /abs/x.stl x.csg prints exactly these).
cube1='cube(size = [1, 1, 1], center = false);'
bad2d='polygon(points = [[0, 0], [1, 0], [1, "a"]]);'
printf 'union() {\n\t%s\n\tsquare(size = [0, 0], center = false);\n}\n' "$cube1" >e_zero.csg
printf 'union() {\n\t%s\n\t%s\n\tsquare(size = [1, 1], center = false);\n}\n' "$cube1" "$bad2d" >e_then.csg
printf 'hull() {\n\t%s\n\t%s\n}\n' "$cube1" "$bad2d" >e_hull.csg
printf 'hull() {\n\t%s\n\t%s\n\tsquare(size = [1, 1], center = false);\n}\n' "$cube1" "$bad2d" >e_hull_then.csg
printf 'hull() {\n\tintersection() {\n\t\t%s\n\t\t%s\n\t}\n}\n' "$cube1" "$bad2d" >e_nef.csg
printf 'linear_extrude(height = 1) {\n\tprojection(cut = false) {\n\t\thull() {\n\t\t\t%s\n\t\t\t%s\n\t\t}\n\t}\n}\n' "$cube1" "$bad2d" >e_proj_hull.csg
printf 'linear_extrude(height = 1) {\n\tprojection(cut = false) {\n\t\t%s\n\t}\n}\n' "$cube1" >e_proj_hull_ref.csg
for mode in "" --faithful; do
    # shellcheck disable=SC2086
    {
        warns e_zero.csg "e_zero.csg:3:2: warning: Ignoring 2D child object for 3D operation" $mode
        same e_zero.csg cube_ref.csg $mode
        warns e_then.csg "$(unable e_then.csg 3 36)
e_then.csg:4:2: warning: Mixing 2D and 3D objects is not supported
e_then.csg:3:2: warning: Ignoring 2D child object for 3D operation
e_then.csg:4:2: warning: Ignoring 2D child object for 3D operation" $mode
        same e_then.csg cube_ref.csg $mode
        warns e_hull.csg "$(unable e_hull.csg 3 36)
e_hull.csg:3:2: warning: Ignoring 2D child object for 3D operation" $mode
        same e_hull.csg cube_ref.csg $mode
        warns e_hull_then.csg "$(unable e_hull_then.csg 3 36)
e_hull_then.csg:4:2: warning: Mixing 2D and 3D objects is not supported
e_hull_then.csg:3:2: warning: Ignoring 2D child object for 3D operation
e_hull_then.csg:4:2: warning: Ignoring 2D child object for 3D operation" $mode
        same e_hull_then.csg cube_ref.csg $mode
        warns e_nef.csg "$(unable e_nef.csg 4 37)
e_nef.csg:4:3: warning: Ignoring 2D child object for 3D operation
e_nef.csg: warning: the model is empty (nothing to render)" $mode
        warns e_proj_hull.csg "$(unable e_proj_hull.csg 5 38)
e_proj_hull.csg:5:4: warning: Ignoring 2D child object for 3D operation" $mode
        same e_proj_hull.csg e_proj_hull_ref.csg $mode
    }
done

# The same polygon as a 2D child of projection, which leaves it out:
# OpenSCAD 2021.01 still prints its error (and, for a direct child of
# projection without cut, nothing else); --strict makes it the error.
printf 'linear_extrude(height = 1) {\n\tprojection(cut = false) {\n\t\tcube(size = [1, 1, 1], center = false);\n\t\tpolygon(points = [[0, 0], [1, 0], [1, "a"]]);\n\t}\n}\n' >proj_bad2d.csg
printf 'linear_extrude(height = 1) {\n\tprojection(cut = false) {\n\t\tcube(size = [1, 1, 1], center = false);\n\t}\n}\n' >proj_bad2d_ref.csg
for mode in "" --faithful; do
    # shellcheck disable=SC2086
    {
        warns proj_bad2d.csg 'proj_bad2d.csg:4:37: warning: Unable to convert points[2] = [1, "a"] to a vec2 of numbers; the polygon is empty, as OpenSCAD leaves it out (--strict makes it an error)' $mode
        same proj_bad2d.csg proj_bad2d_ref.csg $mode
        check
        "$bin" render proj_bad2d.csg -o strict.png -q --strict $mode 2>err.txt &&
            fail "proj_bad2d.csg --strict $mode: exit 0"
        [ "$(cat err.txt)" = "proj_bad2d.csg:4:37: error: wrong type for argument 'points' of 'polygon' (expected a vector of [x, y] points)" ] ||
            fail "proj_bad2d.csg --strict $mode: $(cat err.txt)"
    }
done

# ---- multmatrix with nan or inf: OpenSCAD removes the object ----
# OpenSCAD 2021.01 exports multmatrix([[0/0, ...]]) and [[1/0, ...]] with
# nan and inf; rendering the .scad (openscad -o x.stl) it warns
# "Transformation matrix contains Not-a-Number and/or Infinity - removing
# object." and renders the rest. --strict makes it the error.
cat >not_finite.csg <<'M'
multmatrix([[nan, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {
	cube(size = [1, 1, 1], center = false);
}
cube(size = [1, 1, 1], center = false);
difference() {
	cube(size = [1, 1, 1], center = false);
	multmatrix([[1, 0, 0, -inf], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {
		sphere(r = 0.5, $fn = 8, $fa = 12, $fs = 2);
	}
}
M
removed="warning: Transformation matrix contains Not-a-Number and/or Infinity - removing object."
for mode in "" --faithful; do
    warns not_finite.csg "not_finite.csg:1:1: $removed
not_finite.csg:7:2: $removed" $mode
    # shellcheck disable=SC2086
    same not_finite.csg cube_ref.csg $mode
    check
    rm -f strict.png
    "$bin" render not_finite.csg -o strict.png -q --strict $mode 2>err.txt &&
        fail "not_finite.csg --strict $mode: exit 0"
    [ "$(cat err.txt)" = "not_finite.csg:1:1: error: multmatrix: matrix entries must be finite" ] ||
        fail "not_finite.csg --strict $mode: $(cat err.txt)"
    [ -e strict.png ] && fail "not_finite.csg --strict $mode: an image was written"
done

# A transform of 2D geometry whose xy part is singular: OpenSCAD 2021.01
# removes the object with "Scaling a 2D object with 0 - removing object"
# (Polygon2d::transform), in a profile and in a 2D model alike.
cat >flat2d.csg <<'M'
cube(size = [1, 1, 1], center = false);
linear_extrude(height = 1, center = false, convexity = 1, scale = [1, 1], $fn = 0, $fa = 12, $fs = 2) {
	multmatrix([[1, 0, 0, 0], [0, 0, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {
		square(size = [5, 2], center = false);
	}
}
M
cat >flat2d_only.csg <<'M'
multmatrix([[0, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {
	square(size = [5, 5], center = false);
}
square(size = [1, 1], center = false);
M
scaling="warning: Scaling a 2D object with 0 - removing object"
for mode in "" --faithful; do
    warns flat2d.csg "flat2d.csg:3:2: $scaling
flat2d.csg:2:1: warning: linear_extrude without height or area is empty" $mode
    warns flat2d_only.csg "flat2d_only.csg:1:1: $scaling" $mode
done
if command -v openscad >/dev/null; then
    for m in flat2d flat2d_only; do
        check
        openscad -o "$PWD/${m}_os.stl" $m.csg >/dev/null 2>${m}_os.err
        grep -q "^WARNING: Scaling a 2D object with 0 - removing object$" ${m}_os.err ||
            fail "openscad on $m.csg: $(cat ${m}_os.err)"
    done
fi

# projection(cut = true) of a solid that z = 0 misses: OpenSCAD 2021.01
# warns "Projection() failed." (CGALUtils::project); of a difference that
# is empty, it says nothing.
cat >pj_miss.csg <<'M'
cube(size = [1, 1, 1], center = false);
linear_extrude(height = 1, center = false, convexity = 1, scale = [1, 1], $fn = 0, $fa = 12, $fs = 2) {
	projection(cut = true, convexity = 0) {
		multmatrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 10], [0, 0, 0, 1]]) {
			cube(size = [1, 1, 1], center = false);
		}
	}
}
linear_extrude(height = 1, center = false, convexity = 1, scale = [1, 1], $fn = 0, $fa = 12, $fs = 2) {
	projection(cut = true, convexity = 0) {
		difference() {
			cube(size = [1, 1, 1], center = false);
			cube(size = [2, 2, 2], center = false);
		}
	}
}
M
for mode in "" --faithful; do
    warns pj_miss.csg "pj_miss.csg:3:2: warning: Projection() failed.
pj_miss.csg:2:1: warning: linear_extrude without height or area is empty
pj_miss.csg:9:1: warning: linear_extrude without height or area is empty" $mode
done
if command -v openscad >/dev/null; then
    check
    openscad -o "$PWD/pj_miss_os.stl" pj_miss.csg >/dev/null 2>pj_miss_os.err
    [ "$(grep -c '^WARNING: Projection() failed\.$' pj_miss_os.err)" = 1 ] ||
        fail "openscad on pj_miss.csg: $(cat pj_miss_os.err)"
fi

# The same wherever the multmatrix stands: under hull, minkowski, a hull of
# a difference (CGAL), projection, the extrusions, and in a 2D model. Each
# warns once (OpenSCAD: once) and is the model without that subtree.
nan_block='multmatrix([[nan, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) { multmatrix([[1, 0, 0, 5], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {'
inf_block='multmatrix([[1, 0, 0, inf], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) { multmatrix([[1, 0, 0, 5], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {'
# name | the model's first part | the removed subtree's leaf | the model's end
while IFS='|' read -r name head leaf tail; do
    printf '%s\n\t%s %s } }\n%s\n' "$head" "$nan_block" "$leaf" "$tail" >"nf_$name.csg"
    printf '%s\n%s\n' "$head" "$tail" >"nf_${name}_ref.csg"
    for mode in "" --faithful; do
        warns "nf_$name.csg" "nf_$name.csg:2:2: $removed" $mode
        # shellcheck disable=SC2086
        same "nf_$name.csg" "nf_${name}_ref.csg" $mode
    done
    check
    "$bin" render "nf_$name.csg" -o strict.png -q --strict 2>err.txt &&
        fail "nf_$name.csg --strict: exit 0"
    [ "$(cat err.txt)" = "nf_$name.csg:2:2: error: multmatrix: matrix entries must be finite" ] ||
        fail "nf_$name.csg --strict: $(cat err.txt)"
done <<'L'
hull|hull() { cube(size = [1, 1, 1], center = false);|cube(size = [1, 1, 1], center = false);|}
minkowski|minkowski() { cube(size = [1, 1, 1], center = false);|sphere(r = 1, $fn = 8, $fa = 12, $fs = 2);|}
cgal|hull() { difference() { cube(size = [2, 2, 2], center = false);|cube(size = [1, 1, 1], center = false);|} }
projection|projection(cut = false) { cube(size = [1, 1, 1], center = false);|cube(size = [1, 1, 1], center = false);|}
cut|projection(cut = true) { hull() { cube(size = [1, 1, 1], center = true);|cube(size = [1, 1, 1], center = false);|} }
extrude|linear_extrude(height = 1) { square(size = [1, 1], center = false);|square(size = [1, 1], center = false);|}
revolve|rotate_extrude($fn = 8) { multmatrix([[1, 0, 0, 2], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) { square(size = [1, 1], center = false); }|square(size = [1, 1], center = false);|}
L
# The removed object has no dimension, as OpenSCAD's removed object is no
# geometry: a 2D one in a 3D operation, or a 3D one in a 2D operation, is
# not warned of as mixed or ignored, nor decides a file's dimension.
printf 'union() {\n\tcube(size = [1, 1, 1], center = false);\n\t%s square(size = [1, 1], center = false); } }\n}\n' "$nan_block" >nf_mixed.csg
printf 'linear_extrude(height = 1) {\n\tsquare(size = [1, 1], center = false);\n\t%s cube(size = [1, 1, 1], center = false); } }\n}\n' "$nan_block" >nf_mixed_flat.csg
printf 'linear_extrude(height = 1) { square(size = [1, 1], center = false); }\n' >nf_mixed_flat_ref.csg
printf '%s square(size = [1, 1], center = false); } }\ncube(size = [1, 1, 1], center = false);\n' "$nan_block" >nf_first.csg
printf 'rotate_extrude($fn = 8) {\n\tmultmatrix([[1, 0, 0, 2], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) { square(size = [1, 1], center = false); }\n\t%s cube(size = [1, 1, 1], center = false); } }\n}\n' "$nan_block" >nf_mixed_revolve.csg
printf 'rotate_extrude($fn = 8) { multmatrix([[1, 0, 0, 2], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) { square(size = [1, 1], center = false); } }\n' >nf_mixed_revolve_ref.csg
for mode in "" --faithful; do
    warns nf_mixed.csg "nf_mixed.csg:3:2: $removed" $mode
    warns nf_mixed_flat.csg "nf_mixed_flat.csg:3:2: $removed" $mode
    warns nf_first.csg "nf_first.csg:1:1: $removed" $mode
    warns nf_mixed_revolve.csg "nf_mixed_revolve.csg:3:2: $removed" $mode
    for pair in nf_mixed.csg:cube_ref.csg nf_mixed_flat.csg:nf_mixed_flat_ref.csg \
        nf_first.csg:cube_ref.csg nf_mixed_revolve.csg:nf_mixed_revolve_ref.csg; do
        # shellcheck disable=SC2086
        same "${pair%%:*}" "${pair#*:}" $mode
    done
done
# OpenSCAD evaluates the removed object's children before it removes it:
# their own warnings come first (a polygon's point, a 2D union with a 3D
# child), then the removal; the removed object does not check its own
# children's dimensions (no word of the 2D ones in a 3D multmatrix). In a
# 2D operation (an extrusion) the same, in both modes. --strict: the first
# of them is the error.
cat >nf_warn.csg <<'M'
union() {
	cube(size = [1, 1, 1], center = false);
	multmatrix([[nan, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {
		cube(size = [1, 1, 1], center = false);
		polygon(points = [[0, 0], [1, 0], [1, "a"]]);
		square(size = [1, 1], center = false);
		linear_extrude(height = 1) { union() { square(size = [1, 1], center = false); cube(size = [1, 1, 1], center = false); } }
	}
}
M
cat >nf_warn_flat.csg <<'M'
linear_extrude(height = 1) {
	square(size = [1, 1], center = false);
	multmatrix([[nan, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {
		polygon(points = [[0, 0], [1, 0], [1, "a"]]);
		cube(size = [1, 1, 1], center = false);
		union() { square(size = [1, 1], center = false); cube(size = [1, 1, 1], center = false); }
	}
}
M
printf 'linear_extrude(height = 1) { square(size = [1, 1], center = false); }\n' >nf_warn_flat_ref.csg
for mode in "" --faithful; do
    warns nf_warn.csg 'nf_warn.csg:5:37: warning: Unable to convert points[2] = [1, "a"] to a vec2 of numbers; the polygon is empty, as OpenSCAD leaves it out (--strict makes it an error)
nf_warn.csg:7:81: warning: Mixing 2D and 3D objects is not supported
nf_warn.csg:7:81: warning: Ignoring 3D child object for 2D operation
nf_warn.csg:3:2: '"$removed" $mode
    warns nf_warn_flat.csg 'nf_warn_flat.csg:4:37: warning: Unable to convert points[2] = [1, "a"] to a vec2 of numbers; the polygon is empty, as OpenSCAD leaves it out (--strict makes it an error)
nf_warn_flat.csg:6:52: warning: Mixing 2D and 3D objects is not supported
nf_warn_flat.csg:6:52: warning: Ignoring 3D child object for 2D operation
nf_warn_flat.csg:3:2: '"$removed" $mode
    # shellcheck disable=SC2086
    same nf_warn.csg cube_ref.csg $mode
    # shellcheck disable=SC2086
    same nf_warn_flat.csg nf_warn_flat_ref.csg $mode
    for model in nf_warn.csg:5 nf_warn_flat.csg:4; do
        check
        # shellcheck disable=SC2086
        "$bin" render "${model%%:*}" -o strict.png -q --strict $mode 2>err.txt &&
            fail "$model --strict $mode: exit 0"
        [ "$(cat err.txt)" = "${model%%:*}:${model#*:}:37: error: wrong type for argument 'points' of 'polygon' (expected a vector of [x, y] points)" ] ||
            fail "$model --strict $mode: $(cat err.txt)"
    done
done
# a 2D model: the first object decides, the removed one is no object
printf 'square(size = [1, 1], center = false);\n%s square(size = [1, 1], center = false); } }\n' "$inf_block" >nf_flat.csg
printf 'square(size = [1, 1], center = false);\n' >nf_flat_ref.csg
for mode in "" --faithful; do
    warns nf_flat.csg "nf_flat.csg:2:1: $removed" $mode
    # shellcheck disable=SC2086
    same nf_flat.csg nf_flat_ref.csg $mode
done

# ---- arguments that are no parameter ----
# OpenSCAD 2021.01 warns of a call's arguments as it instantiates the tree,
# before any geometry: a name that is no parameter, a name given twice,
# positional arguments past the last; not under '*', and silently for the
# timestamp its own export writes. Then, for a primitive: children (not
# instantiated, so not warned of in turn), $fs below 0.01, a radius given
# with its diameter, a cylinder's r with r2; for a colour: a name it does
# not know, components out of range (not alpha; c = 5 silently). spancast
# gives the same warnings in the same order: compared here with what
# openscad prints for the same file (openscad -o x.csg evaluates no
# geometry), message and line. The model renders as it does without them
# (the $fn that multmatrix passes down to its sphere included); --strict
# refuses it at the first.
cat >args.csg <<'M'
union() {
	cube(size = [2, 2, 2], centre = true);
	multmatrix([[1, 0, 0, 4], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]], 2) sphere(r = 1, r = 2);
	%cylinder(h = 1, r = 1, convexity = 2);
	*cube(zz = 1);
	linear_extrude(height = 1, v = [0, 0, 1], timestamp = 0) square(size = 1, center = true, size = 3);
	import(file = "args_part.stl", timestamp = 0, id = 1);
	multmatrix([[1, 0, 0, 0], [0, 1, 0, 6], [0, 0, 1, 0], [0, 0, 0, 1]]) sphere(r = 1, d = 3, $fs = 0.001);
	cylinder(h = 1, r = 1, r2 = 2);
	multmatrix([[1, 0, 0, 30], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]], $fn = 6) sphere(r = 10);
	multmatrix([[1, 0, 0, -10], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) cube(size = 1) sphere(r = 5, zz = 1);
	color("nosuchcolour") multmatrix([[1, 0, 0, 0], [0, 1, 0, -10], [0, 0, 1, 0], [0, 0, 0, 1]]) cube(size = 1);
	color([1.25, 0, -0.5], alpha = 7) multmatrix([[1, 0, 0, 0], [0, 1, 0, -14], [0, 0, 1, 0], [0, 0, 0, 1]]) cube(size = 1);
	color(5) multmatrix([[1, 0, 0, 0], [0, 1, 0, -18], [0, 0, 1, 0], [0, 0, 0, 1]]) cube(size = 1);
}
M
cat >args_ref.csg <<'M'
union() {
	cube(size = [2, 2, 2]);
	multmatrix([[1, 0, 0, 4], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) sphere(r = 2);
	%cylinder(h = 1, r = 1);
	linear_extrude(height = 1) square(size = 3, center = true);
	import(file = "args_part.stl");
	multmatrix([[1, 0, 0, 0], [0, 1, 0, 6], [0, 0, 1, 0], [0, 0, 0, 1]]) sphere(r = 1.5, $fs = 0.01);
	cylinder(h = 1, r1 = 1, r2 = 2);
	multmatrix([[1, 0, 0, 30], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) sphere(r = 10, $fn = 6);
	multmatrix([[1, 0, 0, -10], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) cube(size = 1);
	multmatrix([[1, 0, 0, 0], [0, 1, 0, -10], [0, 0, 1, 0], [0, 0, 0, 1]]) cube(size = 1);
	multmatrix([[1, 0, 0, 0], [0, 1, 0, -14], [0, 0, 1, 0], [0, 0, 0, 1]]) cube(size = 1);
	multmatrix([[1, 0, 0, 0], [0, 1, 0, -18], [0, 0, 1, 0], [0, 0, 0, 1]]) cube(size = 1);
}
M
printf 'solid t\nfacet normal 0 0 -1\nouter loop\nvertex 0 0 -3\nvertex 0 1 -3\nvertex 1 0 -3\nendloop\nendfacet\nfacet normal 0 -1 0\nouter loop\nvertex 0 0 -3\nvertex 1 0 -3\nvertex 0 0 -2\nendloop\nendfacet\nfacet normal -1 0 0\nouter loop\nvertex 0 0 -3\nvertex 0 0 -2\nvertex 0 1 -3\nendloop\nendfacet\nfacet normal 1 1 1\nouter loop\nvertex 1 0 -3\nvertex 0 1 -3\nvertex 0 0 -2\nendloop\nendfacet\nendsolid t\n' >args_part.stl
check
openscad -o args_os.csg args.csg 2>os_args.err || fail "openscad -o args_os.csg args.csg: exit $?"
# "WARNING: M in file args.csg, line N" and "args.csg:N:C: warning: M" as "N: M";
# OpenSCAD warns of timestamp, which spancast takes silently (params.h)
sed -n 's/^WARNING: \(.*\) in file args\.csg, line \([0-9]*\)$/\2: \1/p' os_args.err |
    grep -v 'variable timestamp' >os_args.txt
[ "$(wc -l <os_args.txt)" = 14 ] || fail "openscad's warnings: $(cat os_args.err)"
for mode in "" --faithful; do
    # shellcheck disable=SC2086
    {
        check
        "$bin" render args.csg -o out.png --imgsize=64,48 -q $mode 2>err.txt ||
            fail "args.csg $mode: exit $?: $(cat err.txt)"
        sed -n 's/^args\.csg:\([0-9]*\):[0-9]*: warning: \(.*\)$/\1: \2/p' err.txt >sc_args.txt
        cmp -s os_args.txt sc_args.txt ||
            fail "args.csg $mode: spancast warns '$(cat err.txt)', openscad '$(cat os_args.txt)'"
        [ "$(wc -l <err.txt)" = 14 ] || fail "args.csg $mode: other messages: $(cat err.txt)"
        same args.csg args_ref.csg $mode
        refuses args.csg "args.csg:2:25: error: variable centre not specified as parameter" $mode
    }
done

# ---- arguments of the wrong kind ----
# OpenSCAD 2021.01 takes an argument of its modules that is of the wrong
# kind as the parameter's default: with a warning for the size of a cube
# or square, silently for the rest (radii, heights, center, scale, twist,
# slices, angle, cut, offset's r and delta, text's, resize's entries, a
# matrix that is no matrix); a $fs or $fa that is not a number is 0,
# which a primitive clamps with its warning, also where it is passed
# down. spancast does the same: its warnings are compared with what
# openscad prints for the same file, message and line, and the model with
# OpenSCAD's export of it, which writes the values OpenSCAD settled on.
# --strict refuses it at the first warning. (spancast's own nodes keep
# their errors: tests/bad-input.)
cat >types.csg <<'M'
union() {
	cube(size = "a");
	multmatrix([[1, 0, 0, 3], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) cube([1, 2], center = 1);
	multmatrix([[1, 0, 0, 6], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) sphere(r = "a", $fs = "b", $fa = true, $fn = [3]);
	multmatrix([[1, 0, 0, 9], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) cylinder(h = "a", r = 2, r1 = [1], d2 = true, center = "yes");
	multmatrix([[1, 0, 0, 14], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) cylinder(h = 3, r = undef, d = 2, d1 = "x");
	multmatrix([[1, 0, 0, 0], [0, 1, 0, 5], [0, 0, 1, 0], [0, 0, 0, 1]], $fs = "x") sphere(r = 2, d = [1]);
	multmatrix([[1, 0, 0, 0], [0, 1, 0, 9], [0, 0, 1, 0], [0, 0, 0, 1]]) cube(
		[1, true, 3]);
	multmatrix("m") resize(newsize = [2, "a", 3], auto = [1, "a", 0]) multmatrix([[1, 0, 0, 0], [0, 1, 0, -6], [0, 0, 1, 0], [0, 0, 0, 1]]) cube(size = [1, 2, 4]);
	linear_extrude(height = [1], scale = "b", twist = "t", slices = true, center = 1, convexity = "c") {
		multmatrix([[1, 0, 0, 0], [0, 1, 0, -12], [0, 0, 1, 0], [0, 0, 0, 1]]) circle(r = "a", d = [2]);
		multmatrix([[1, 0, 0, 4], [0, 1, 0, -12], [0, 0, 1, 0], [0, 0, 0, 1]]) square(size = [1, 2, 3], center = 1);
		offset(r = "a", delta = 0.5, chamfer = 1) multmatrix([[1, 0, 0, 8], [0, 1, 0, -12], [0, 0, 1, 0], [0, 0, 0, 1]]) square(size = 1);
		projection(cut = "yes", convexity = "x") multmatrix([[1, 0, 0, 12], [0, 1, 0, -12], [0, 0, 1, 0], [0, 0, 0, 1]]) cube(size = 2);
		text(5, size = "a");
	}
	multmatrix([[1, 0, 0, 0], [0, 1, 0, 20], [0, 0, 1, 0], [0, 0, 0, 1]]) rotate_extrude(angle = "a", convexity = "b", $fa = "c", $fn = 8) multmatrix([[1, 0, 0, 2], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) square(size = "q");
}
M
# like_openscad MODEL COUNT [REFUSAL]: OpenSCAD's export of MODEL warns
# COUNT times; spancast's render warns the same, at the same lines, and
# nothing else, exact and --faithful, and renders what OpenSCAD exports;
# with REFUSAL, --strict stops at that error.
like_openscad() {
    local model=$1 count=$2 refusal=${3:-} stem=${1%.csg} mode
    check
    openscad -o "$PWD/${stem}_os.csg" "$model" 2>os_types.err ||
        fail "openscad -o ${stem}_os.csg $model: exit $?"
    sed -n "s/^WARNING: \(.*\) in file ${stem}\.csg, line \([0-9]*\)\$/\2: \1/p" os_types.err \
        >os_types.txt
    [ "$(wc -l <os_types.txt)" = "$count" ] || fail "openscad's warnings: $(cat os_types.err)"
    for mode in "" --faithful; do
        # shellcheck disable=SC2086
        {
            check
            "$bin" render "$model" -o out.png --imgsize=64,48 -q $mode 2>err.txt ||
                fail "$model $mode: exit $?: $(cat err.txt)"
            sed -n "s/^${stem}\.csg:\([0-9]*\):[0-9]*: warning: \(.*\)\$/\1: \2/p" err.txt \
                >sc_types.txt
            cmp -s os_types.txt sc_types.txt ||
                fail "$model $mode: spancast warns '$(cat err.txt)', openscad '$(cat os_types.txt)'"
            [ "$(wc -l <err.txt)" = "$count" ] || fail "$model $mode: other messages: $(cat err.txt)"
            same "$model" "${stem}_os.csg" $mode
            [ -z "$refusal" ] || refuses "$model" "$refusal" $mode
        }
    done
}
like_openscad types.csg 9 'types.csg:2:14: error: Unable to convert cube(size="a", ...) parameter to a number or a vec3 of numbers'

# The same for what names a file and where a drawing goes (import,
# surface, the extrusions' origin): a file name or layer that is not a
# string is its text, center and invert true only when true, and an
# origin that is not [x, y] (with it, linear_extrude's scale) is warned
# of as OpenSCAD warns; args_part.stl is the tetrahedron above.
printf '1 2 3\n2 3 1\n0 1 2\n' >types.dat
cat >types_import.csg <<'M'
union() {
	import(file = "args_part.stl", origin = "a", convexity = [1]);
	multmatrix([[1, 0, 0, 5], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) linear_extrude(height = 2, origin = [0, 0], scale = [1, "a"]) square(size = 1);
	multmatrix([[1, 0, 0, 10], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) linear_extrude(height = 2, origin = [0, 0]) square(size = 1);
	multmatrix([[1, 0, 0, -8], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) surface(file = "types.dat", center = "a", invert = 1, convexity = "c");
	multmatrix([[1, 0, 0, 0], [0, 1, 0, 6], [0, 0, 1, 0], [0, 0, 0, 1]]) linear_extrude(file = 5, height = 1) square(size = 2);
}
M
like_openscad types_import.csg 3

# ---- a lossy mask ----
warns cube_ref.csg "spancast: warning: --mask=m.jpg: JPEG is lossy, so the mask is no longer exactly 0 and 255 at the model's edges (.png, .tif and .exr are exact)" --mask=m.jpg
check
[ -s m.jpg ] || fail "the JPEG mask was not written"
warns cube_ref.csg "" --mask=m.png

echo "$checks checks, $fails failed"
[ "$fails" = 0 ]
