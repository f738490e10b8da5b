# Cross-check of the camera contract against OpenSCAD 2021.01 itself: the same
# boxes (exact in both programs) are rendered by `openscad -o x.png` and by
# `spancast render` under every camera form, and the silhouettes must agree
# except for a few pixels whose centres lie on an edge (rasterisation rules).
# Skipped (exit 77, reported as skipped) when openscad 2021.01 or xvfb-run
# is missing or OpenSCAD cannot render offscreen at all; once OpenSCAD has
# rendered, its failure on any view is a failure of the test.
#
# Run as: bash cli_openscad_camera.sh <path-to-spancast> <source-dir> <work-dir>
. "$(dirname "$0")/testlib.sh"

require_tools openscad xvfb-run oiiotool idiff
openscad --version 2>&1 | grep -q '2021\.01' ||
    skip "the conventions checked are OpenSCAD 2021.01's, not $(openscad --version 2>&1)"

cat >boxes.scad <<'EOF'
cube([20, 2, 2]);
cube([2, 10, 2]);
translate([-3, -4, 0]) cube([3, 3, 9]);
translate([5, 5, -6]) cube([4, 4, 4]);
EOF
openscad -o boxes.csg boxes.scad >/dev/null 2>&1 || {
    echo "FAIL: openscad could not export boxes.csg"
    exit 1
}

limit=5 # pixels of 320 x 240 that may differ along edges (1 seen)

# Whether OpenSCAD can render offscreen here at all (a machine without a
# working GL under Xvfb cannot): if not, nothing below can be checked.
timeout 300 xvfb-run -a -n 120 -s "-screen 0 1024x768x24" \
    openscad -o probe.png --imgsize=32,24 boxes.scad >probe.log 2>&1
[ -s probe.png ] || skip "openscad cannot render offscreen: $(tail -n 1 probe.log)"

# compare NAME OPTIONS...: the same options for both programs, on
# $model.scad (OpenSCAD, with os_extra last: its --render takes an optional
# argument, which would take the file) and $model.csg (spancast, with
# sc_extra too).
model=boxes
os_extra=()
sc_extra=()
compare() {
    local name=$1
    shift
    checks=$((checks + 1))
    timeout 300 xvfb-run -a -n 120 -s "-screen 0 1024x768x24" \
        openscad "$model.scad" -o "os_$name.png" --imgsize=320,240 "$@" "${os_extra[@]}" >/dev/null 2>&1
    if [ ! -s "os_$name.png" ]; then
        fail "$name: openscad wrote no image"
        return
    fi
    "$bin" render "$model.csg" -o "sc_$name.png" --mask="mask_$name.png" \
        --imgsize=320,240 -q "${sc_extra[@]}" "$@" || {
        echo "FAIL: $name: spancast failed"
        fails=$((fails + 1))
        return
    }
    # OpenSCAD's silhouette: every pixel that is not the #ffffe5 background
    oiiotool "os_$name.png" --absdiffc 1,1,0.898039 --chsum --mulc 200 \
        --clamp:min=0:max=1 -d uint8 -o "osmask_$name.png"
    local report count
    report=$(idiff -fail 0.5 "osmask_$name.png" "mask_$name.png" 2>&1)
    count=$(echo "$report" | grep -Eo '[0-9]+ pixels .* over 0\.5' | grep -Eo '^[0-9]+')
    count=${count:-0}
    if ! echo "$report" | grep -Eq 'PASS|pixels'; then
        echo "FAIL: $name: idiff: $report"
        fails=$((fails + 1))
    elif [ "$count" -gt "$limit" ]; then
        echo "FAIL: $name: $count pixels differ from OpenSCAD (limit $limit)"
        fails=$((fails + 1))
    fi
}

compare default
compare gimbal --camera=3,2,1,70,20,40,80
compare gimbal_ortho --camera=1,2,3,30,-50,160,60 --projection=o
compare top_turned --camera=0,0,0,0,0,30,90
compare bottom --camera=0,0,0,180,0,0,90
compare vector --camera=40,-50,30,5,2,1
compare vector_down --camera=5,2,60,5,2,0
compare vector_up --camera=5,2,-60,5,2,0
compare ortho --camera=3,2,1,70,20,40,80 --projection=o
compare viewall --camera=10,0,0,55,0,25,20 --viewall
compare viewall_autocenter --camera=10,0,0,55,0,25,20 --viewall --autocenter
compare autocenter_alone --camera=10,0,0,55,0,25,120 --autocenter
compare viewall_vector --camera=40,-50,30,5,2,1 --viewall --autocenter
compare viewall_wide --camera=1,2,3,120,10,200,50 --viewall

# The default camera frames the box of the mesh OpenSCAD computed, where
# the booleans cut parts of the boxes of what they were made of away
# (csg/bounds.h): a sphere drilled through, whose farthest points in y are
# corners of the hole's polygonal rim; a sphere with its top cut off; two
# rotated cones, whose boxes are their vertices' and not their rotated
# boxes'; and a sliver 0.01 thick, the intersection of two cubes, far
# to the left of a cube, which the box must keep. In faithful mode, as
# OpenSCAD's mesh, against OpenSCAD's render (its preview frames the
# boxes of its CSG products, as spancast's --preview does).
frames() { # NAME, then the scene on stdin
    cat >"$1.scad"
    openscad -o "$1.csg" "$1.scad" >/dev/null 2>&1 || {
        echo "FAIL: openscad could not export $1.csg"
        fails=$((fails + 1))
        return
    }
    model=$1
    compare "$1"
    compare "$1_viewall" --camera=10,0,0,70,0,140,20 --viewall --autocenter
}
os_extra=(--render)
sc_extra=(--faithful)
frames drilled <<'EOF'
difference() {
  sphere(r = 10);
  rotate([90, 0, 0]) cylinder(r = 6, h = 30, center = true);
}
EOF
frames capped <<'EOF'
difference() {
  sphere(r = 10);
  translate([-20, -20, 5]) cube(40);
}
EOF
frames cones <<'EOF'
translate([0, -40, 0]) rotate([90, 0, 45]) cylinder(r1 = 10, r2 = 0, h = 20);
rotate(v = [-1, 0, 0], a = 45) cylinder(r1 = 10, r2 = 0, h = 20);
EOF
# Parts that compete for an extreme inside a cut: the lowest point is the
# third cylinder's rim, which a search of the whole difference missed
# for the second's (42 pixels), and a random union of rotated, scaled
# spheres and cylinders with a rotated box cut from it (3,532 pixels).
frames tilted <<'EOF'
difference() {
  union() {
    cylinder(r = 1, h = 8, $fn = 10);
    translate([24, 0, 0]) rotate([0, 72, 0]) cylinder(r = 1, h = 8, $fn = 10);
    translate([27, 0, 0]) rotate([0, 81, 0]) cylinder(r = 1, h = 8, $fn = 10);
  }
  translate([0, 0, 6]) cube([40, 10, 10], center = true);
}
EOF
frames jumble <<'EOF'
difference() {
  union() {
    translate([1.5, -7.42, -1.47]) rotate([177.27, 139.13, 274.02]) scale([0.58, 0.7, 1.73]) sphere(2.37, $fn = 20);
    translate([-7.25, 3.16, -5.23]) rotate([89.73, 126.51, 116.06]) cylinder(r = 1.75, h = 5.8, $fn = 6);
    translate([-0.67, 4.6, -1.26]) rotate([266.69, 329.17, 190.72]) scale([1.91, 1.9, 2.33]) sphere(2.42, $fn = 10);
    translate([-7.27, -1.29, -1.58]) rotate([294.59, 61.95, 135.81]) cylinder(r1 = 2.76, r2 = 0.43, h = 3.69, center = true, $fn = 8);
  }
  translate([-6.36, -5.0, -4.57]) rotate([70.32, 123.41, 281.66]) cube([4.01, 1.93, 3.8], center = true);
}
EOF
frames sliver <<'EOF'
cube(2);
translate([-12, 12, 0]) intersection() {
  cube([10, 10, 10], center = true);
  translate([0, -9.99, -9.99]) cube([10, 10, 10], center = true);
}
EOF

echo "$checks views compared with OpenSCAD, $fails failed"
[ "$fails" = 0 ]
