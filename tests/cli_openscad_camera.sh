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

# compare NAME OPTIONS...: the same options for both programs.
compare() {
    local name=$1
    shift
    checks=$((checks + 1))
    timeout 300 xvfb-run -a -n 120 -s "-screen 0 1024x768x24" \
        openscad -o "os_$name.png" --imgsize=320,240 "$@" boxes.scad >/dev/null 2>&1
    if [ ! -s "os_$name.png" ]; then
        fail "$name: openscad wrote no image"
        return
    fi
    "$bin" render boxes.csg -o "sc_$name.png" --mask="mask_$name.png" \
        --imgsize=320,240 -q "$@" || {
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

echo "$checks views compared with OpenSCAD, $fails failed"
[ "$fails" = 0 ]
