#!/usr/bin/env bash
# One real model (see README.md here):
#   check.sh BUILD_DIR MODEL.csg WORKDIR W,H [CGAL_TIMEOUT [RENDER_TIMEOUT]]
# BUILD_DIR holds spancast and the cross-check's tools (refcast, compare,
# fitcam: tests/reference, tests/crosscheck, tests/real). Steps:
#   1. spancast info: leaf and node counts;
#   2. OpenSCAD's CGAL render of the .csg to a binary STL, with a time limit,
#      cached in BUILD_DIR/tests/real/cache under the .csg's checksum (the
#      outcome too: a timeout or OpenSCAD's error is not retried until the
#      .csg or the limit changes). A 2D model, which OpenSCAD renders but
#      will not write as an STL ("Current top level object is not a 3D
#      object"), is checked from here on as WORKDIR/extruded.csg: the whole
#      file under linear_extrude(height = 1), which OpenSCAD does write.
#      Its mesh is OpenSCAD's own 2D polygons extruded (binary STL floats),
#      the same outline its .svg or .dxf export would carry, without a
#      second file format and its rounding in between; the faithful render
#      is compared with it as any model's (the slab's silhouette is the
#      outline, its top face the depth). A model that imports by a
#      relative path would not find its file from WORKDIR: none does now;
#   3. spancast render in exact mode, then in --faithful mode, each with
#      mask and depth, on the camera fitcam frames from the STL (spancast's
#      default camera when there is no STL);
#   4. the cross-check of tests/crosscheck: refcast casts the same rays into
#      the STL and compare judges the faithful mask and depth against them
#      (faithful rules: at most 0.05 % mask mismatches, all on silhouettes;
#      relative depth error at most 1e-5);
#   5. the exact render against the same rays, within the chord-error bound
#      tests/crosscheck/chord.py derives from the .csg (compare's exact
#      rules; the faithful rules when the model has no curved leaf), or,
#      when no bound is derived, the reason.
# Writes WORKDIR/row, one tab-separated line: model, leaves, nodes, exact,
# exact seconds, faithful, faithful seconds, cgal, cgal seconds, verdict,
# mask mismatches, max depth error, exact verdict (match, MISMATCH,
# differs: a mismatch whose cause exact-differs gives, unbounded, kept
# (the faithful render leaves out a part OpenSCAD leaves out, which exact
# mode draws) or -),
# its max depth error over the bound, reason (the first
# failure's message; for a model that passes without an exact bound, why).
# Exits 0 when both renders succeed, the faithful cross-check matches and
# the exact one matches or has no bound, 1 otherwise, 2 on bad usage.
set -uo pipefail
if (($# < 4 || $# > 6)); then
    echo "usage: check.sh BUILD_DIR MODEL.csg WORKDIR W,H [CGAL_TIMEOUT [RENDER_TIMEOUT]]" >&2
    exit 2
fi
build=$(cd "$1" && pwd) csg=$2 work=$3 size=$4
cgal_limit=${5:-120} render_limit=${6:-120}
spancast=$build/spancast
refcast=$build/tests/reference/refcast
compare=$build/tests/crosscheck/crosscheck_compare
chord=$(cd "$(dirname "${BASH_SOURCE[0]}")/../crosscheck" && pwd)/chord.py
fitcam=$build/tests/real/fitcam
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
csg=$(cd "$(dirname "$csg")" && pwd)/$(basename "$csg")
model=${csg#"$here"/}
model=${model%.csg}
rm -rf "$work"
mkdir -p "$work"
work=$(cd "$work" && pwd)

now() { date +%s.%N; }
elapsed() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.2f", b - a }'; }
# The message of the first error line in a log, without its position prefix
# ("file:line:col: error: " or "spancast: error: ").
first_error() {
    grep -m 1 -E 'error|ERROR' "$1" | sed -e 's/^.*[Ee][Rr][Rr][Oo][Rr]: *//' | cut -c 1-160
}

# 1. Size of the tree.
leaves=- nodes=-
if "$spancast" info "$csg" >"$work/info.txt" 2>&1; then
    leaves=$(sed -n 's/^leaves: *\([0-9]*\).*/\1/p' "$work/info.txt")
    nodes=$(sed -n 's/^nodes: *\([0-9]*\).*/\1/p' "$work/info.txt")
    leaves=${leaves:--} nodes=${nodes:--}
fi

# 2. The reference mesh, cached: reference sets key, stl and cgal_status
# for the .csg at $csg.
cache=$build/tests/real/cache
mkdir -p "$cache"
reference() {
    key=$(sha256sum "$csg" | cut -c 1-32)
    stl=$cache/$key.stl
    if [[ ! -e "$cache/$key.status" ]] || { grep -q '^timeout' "$cache/$key.status" &&
        [[ "$(cat "$cache/$key.limit" 2>/dev/null)" != "$cgal_limit" ]]; }; then
        t0=$(now)
        timeout "$cgal_limit" openscad --export-format binstl -o "$stl.$$.tmp" "$csg" \
            >"$cache/$key.log" 2>&1
        rc=$?
        t1=$(now)
        if ((rc == 0)) && [[ -s "$stl.$$.tmp" ]]; then
            mv "$stl.$$.tmp" "$stl"
            echo ok >"$cache/$key.status"
        elif ((rc == 124)); then
            echo "timeout after ${cgal_limit} s" >"$cache/$key.status"
        else
            msg=$(grep -v -E '^ *(Rendering|Total|Geometry|Simple|Vertices|Halfedges|Edges|Halffacets|Facets|Volumes|Top level|CGAL|Compiling|Parsing)' \
                "$cache/$key.log" | tail -n 1)
            echo "error: ${msg:-OpenSCAD exit status $rc}" >"$cache/$key.status"
        fi
        rm -f "$stl.$$.tmp"
        elapsed "$t0" "$t1" >"$cache/$key.seconds"
        echo "$cgal_limit" >"$cache/$key.limit"
    fi
    cgal_status=$(cat "$cache/$key.status")
    cgal_seconds=$(cat "$cache/$key.seconds")
}
twod=
reference
if [[ $cgal_status == *"Current top level object is not a 3D object"* ]]; then
    {
        printf 'linear_extrude(height = 1, center = false, convexity = 1, scale = [1, 1], $fn = 0, $fa = 12, $fs = 2) {\n'
        cat "$csg"
        printf '\n}\n'
    } >"$work/extruded.csg"
    csg=$work/extruded.csg
    reference
    twod="2D: compared as its linear_extrude(height = 1)"
fi
cgal=ok
case $cgal_status in
ok) ;;
timeout*) cgal=timeout ;;
*) cgal=error ;;
esac

view=(--imgsize="$size")
if [[ $cgal == ok ]]; then
    camera=$("$fitcam" "$stl" 2>"$work/fitcam.log") || camera=
    [[ -n "$camera" ]] && view+=(--camera="$camera")
fi

# 3. spancast, exact and faithful. render LABEL [options]
render() {
    local label=$1 t0 t1 rc
    shift
    t0=$(now)
    timeout "$render_limit" "$spancast" render "$csg" "${view[@]}" -q \
        -o "$work/$label.png" "$@" 2>"$work/$label.log"
    rc=$?
    t1=$(now)
    eval "${label}_seconds=$(elapsed "$t0" "$t1") ${label}_rc=$rc"
    if ((rc == 0)); then
        eval "${label}=ok"
    elif ((rc == 124)); then
        eval "${label}=timeout"
        echo "error: spancast took more than ${render_limit} s" >>"$work/$label.log"
    else
        eval "${label}=FAIL"
    fi
}
render exact --mask="$work/exact_mask.png" --depth="$work/exact_depth.exr"
render faithful --faithful --mask="$work/faithful_mask.png" --depth="$work/faithful_depth.exr"

# 4. The cross-check, whenever the faithful render and the mesh exist.
verdict=- mismatches=- max_err=- reason= judged=
if [[ $faithful != ok ]]; then
    judged=$(first_error "$work/faithful.log")
    judged="faithful: ${judged:-spancast exit status $faithful_rc}"
elif [[ $cgal != ok ]]; then
    judged="CGAL $cgal_status"
elif [[ -z "${camera:-}" ]]; then
    judged="$(cat "$work/fitcam.log")"
elif ! "$refcast" "$stl" "${view[@]}" --mask="$work/ref_mask.png" \
    --depth="$work/ref_depth.exr" --cos="$work/ref_cos.exr" 2>"$work/refcast.log"; then
    judged="refcast: $(head -n 1 "$work/refcast.log")"
elif row=$("$compare" "$work/ref_mask.png" "$work/ref_depth.exr" \
    "$work/faithful_mask.png" "$work/faithful_depth.exr" 2>"$work/compare.log"); then
    verdict=match
    read -r _ mismatches _ max_err _ <<<"$row"
else
    verdict=MISMATCH
    read -r _ mismatches _ max_err _ <<<"$row"
    judged=$(grep -m 1 -E 'mismatches|tolerance' "$work/compare.log" ||
        head -n 1 "$work/compare.log")
fi
# 5. The exact cross-check, whenever the exact render and the reference
# images exist (refcast ran when the verdict is match or MISMATCH).
exact_verdict=- exact_err=- exact_judged= note=
if [[ $exact == ok && $verdict != - ]]; then
    bound=$(python3 "$chord" "$csg" 2>"$work/chord.log") || bound="none chord.py failed"
    exact_view=()
    [[ $bound == "0 0" ]] ||
        exact_view=(--exact="${bound/ /,}" --cos="$work/ref_cos.exr" --camera="$camera")
    # A part the faithful render leaves out, as OpenSCAD leaves it out (a
    # mesh CGAL does not take), exact mode draws unless it leaves it out
    # too (docs/meshes.md): the exact render is not OpenSCAD's mesh there.
    left_out=$(grep "; left out, as OpenSCAD leaves it out" "$work/faithful.log" |
        sed 's/: warning: .*//' | while read -r at; do
            grep -F "$at: warning: " "$work/exact.log" | grep -q "left out" || echo "$at"
        done | head -n 1)
    if [[ -n "$left_out" ]]; then
        exact_verdict=kept
        note="exact not checked: exact mode keeps what the faithful render leaves out as OpenSCAD does (${left_out##*/})"
    elif [[ $bound == none* ]]; then
        exact_verdict=unbounded
        note="exact not checked: ${bound#none }"
    elif row=$("$compare" "$work/ref_mask.png" "$work/ref_depth.exr" \
        "$work/exact_mask.png" "$work/exact_depth.exr" "${exact_view[@]}" \
        2>"$work/compare_exact.log"); then
        exact_verdict=match
        read -r _ _ _ exact_err _ <<<"$row"
    else
        exact_verdict=MISMATCH
        read -r _ _ _ exact_err _ <<<"$row"
        exact_judged="exact: $(grep -m 1 -E 'mismatches|tolerance' "$work/compare_exact.log" ||
            head -n 1 "$work/compare_exact.log")"
        # A difference whose cause is known and checked (exact-differs: the
        # model, a tab, the cause) is "differs", with the cause before
        # compare's complaint; it still fails.
        known=$(awk -F '\t' -v m="$model" '$1 == m { print $2 }' "$here/exact-differs")
        if [[ -n "$known" ]]; then
            exact_verdict=differs
            exact_judged="exact differs: $known (${exact_judged#exact: })"
        fi
    fi
fi
# The reason: the exact render's error first, else the cross-checks'.
if [[ $exact != ok ]]; then
    reason=$(first_error "$work/exact.log")
    [[ -n "$reason" ]] || reason="spancast exit status $exact_rc: $(tail -n 1 "$work/exact.log")"
else
    reason=${judged:-${exact_judged:-$note}}
fi
[[ -n "$twod" ]] && reason="$twod${reason:+; $reason}"
printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$model" "$leaves" \
    "$nodes" "$exact" "$exact_seconds" "$faithful" "$faithful_seconds" "$cgal" \
    "$cgal_seconds" "$verdict" "${mismatches:--}" "${max_err:--}" "$exact_verdict" \
    "${exact_err:--}" "$reason" | tee "$work/row"
[[ $verdict == match && $exact == ok && ($exact_verdict == match ||
    $exact_verdict == unbounded || $exact_verdict == kept) ]]
