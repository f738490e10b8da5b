#!/usr/bin/env bash
# One model of the cross-check suite (see CMakeLists.txt here):
#   run.sh SPANCAST REFCAST COMPARE MODEL.scad WORKDIR W,H
# OpenSCAD writes MODEL.csg (spancast's input) and, from that .csg itself,
# the binary STL mesh (the reference), so both sides start from the same
# 6-digit numbers. spancast --faithful and refcast render mask and depth on
# the camera the model names in its comments, and so does spancast in its
# default, exact mode, judged against the same mesh within the bound that
# chord.py derives from the .csg (the tessellation's chord error; 0 when the
# model has no curved leaf, and then by the faithful rules), or a row saying
# why the model has no such bound:
#   // camera: EX,EY,EZ,CX,CY,CZ       (required)
#   // projection: o                   (optional; default perspective)
#   // faithful: skip REASON           (optional: no faithful row, for
#                                       models faithful mode cannot build yet)
#   // files: NAME...                  (optional: files beside the model,
#                                       meshes it imports, height maps, copied
#                                       with it so relative paths resolve)
#   // openscad: empty                 (optional: OpenSCAD's render of the
#                                       model is empty, as its log says,
#                                       "Current top level object is
#                                       empty.", and it writes no mesh; the
#                                       reference is then the empty mesh. A
#                                       model that says so and gets a mesh
#                                       fails)
#   // 2d: flat                        (optional: a 2D model, which
#                                       spancast's render draws flat at
#                                       z = 0; the reference mesh is
#                                       OpenSCAD's 2D result of the .csg
#                                       extruded 1e-5 thick about z = 0,
#                                       which shows its top within 5e-6)
# compare judges each pair and prints its row; the rows also go to
# WORKDIR/rows, which tests/crosscheck/report gathers. Exits non-zero when
# any check fails.
set -euo pipefail
spancast=$1 refcast=$2 compare=$3 model=$4 work=$5 size=$6
# lib3mf's own leak when it reads a 3MF (import_3mf), told to
# LeakSanitizer under the sanitizers (tests/imports.lsan-suppressions).
export LSAN_OPTIONS="suppressions=$(cd "$(dirname "$0")/.." && pwd)/imports.lsan-suppressions:print_suppressions=0${LSAN_OPTIONS:+:$LSAN_OPTIONS}"
name=$(basename "$model" .scad)
rm -rf "$work"
mkdir -p "$work"
work=$(cd "$work" && pwd)

setting() { sed -n "s|^// $1: *||p" "$model" | head -n 1; }
camera=$(setting camera)
projection=$(setting projection)
faithful=$(setting faithful)
[[ -n "$camera" ]] || { echo "$model: no '// camera:' line" >&2; exit 2; }
view=(--camera="$camera" --imgsize="$size" --projection="${projection:-p}")

now() { date +%s.%N; }
elapsed() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.2f", b - a }'; }

cp "$model" "$work/$name.scad"
# Files the model reads (import, surface), named by `// files: NAME ...`.
for file in $(setting files); do
    cp "$(dirname "$model")/$file" "$work/"
done
openscad -o "$work/$name.csg" "$work/$name.scad" >"$work/openscad.log" 2>&1 ||
    { cat "$work/openscad.log" >&2; exit 1; }
mesh_input=$work/$name.csg
if [[ "$(setting 2d)" == flat ]]; then
    mesh_input=$work/${name}_flat.csg
    { echo "linear_extrude(height = 1e-5, center = true) {"; cat "$work/$name.csg"; echo "}"; } \
        >"$mesh_input"
fi
t0=$(now)
if [[ "$(setting openscad)" == empty ]]; then
    if openscad --export-format binstl -o "$work/$name.stl" "$mesh_input" \
        >>"$work/openscad.log" 2>&1; then
        echo "$model: OpenSCAD rendered a mesh, where the model says it is empty" >&2
        exit 1
    fi
    grep -qx 'Current top level object is empty.' "$work/openscad.log" ||
        { cat "$work/openscad.log" >&2; exit 1; }
    # the empty binary STL: its header and no triangles
    head -c 84 /dev/zero >"$work/$name.stl"
else
    openscad --export-format binstl -o "$work/$name.stl" "$mesh_input" \
        >>"$work/openscad.log" 2>&1 || { cat "$work/openscad.log" >&2; exit 1; }
fi
t1=$(now)
mesh_time=$(elapsed "$t0" "$t1")
"$refcast" "$work/$name.stl" "${view[@]}" --mask="$work/ref_mask.png" \
    --depth="$work/ref_depth.exr" --cos="$work/ref_cos.exr"
bound=$(python3 "$(dirname "${BASH_SOURCE[0]}")/chord.py" "$work/$name.csg")

status=0
: >"$work/rows"
# check LABEL [--faithful] [compare options]: render with spancast, compare.
check() {
    local label=$1 mode=$2
    shift 2
    local row seconds
    "$spancast" render "$work/$name.csg" $mode "${view[@]}" -o "$work/$label.png" \
        --mask="$work/${label}_mask.png" --depth="$work/${label}_depth.exr" \
        2>"$work/$label.log" || { cat "$work/$label.log" >&2; exit 1; }
    # spancast's summary line: load, render and write, in seconds.
    seconds=$(sed -n 's/^spancast: wrote .* in \([0-9.]*\) s$/\1/p' "$work/$label.log")
    if row=$("$compare" "$work/ref_mask.png" "$work/ref_depth.exr" \
        "$work/${label}_mask.png" "$work/${label}_depth.exr" "$@"); then
        result=pass
    else
        result=FAIL
        status=1
    fi
    echo "$label $row $mesh_time ${seconds:-?} $result" | tee -a "$work/rows"
}
if [[ "$faithful" == skip* ]]; then
    echo "$name: no faithful row (${faithful#skip })"
else
    check "$name" --faithful
fi
case $bound in
none*)
    echo "$name.exact - - - - - $mesh_time - not exact-checked: ${bound#none }" |
        tee -a "$work/rows"
    ;;
"0 0") check "$name.exact" "" ;;
*)
    check "$name.exact" "" --exact="${bound/ /,}" --cos="$work/ref_cos.exr" \
        --camera="$camera" --projection="${projection:-p}"
    ;;
esac
exit $status
