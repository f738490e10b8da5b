#!/usr/bin/env bash
# beamChain-2's exact render against OpenSCAD's mesh (exact-differs):
#   needles.sh BUILD_DIR WORKDIR W,H
# Round-Anything's beamChain with a start angle gives the second polygon
# two needles: it runs from point 150 out to 151 and back past 150 to 0,
# then back to 1, all on one line to within 1e-7 (at 150) and 4.5e-6 (at
# 1). Even-odd, they are two slivers of the polygon, walls at most 4.5e-6
# thick once extruded, which a ray crosses like any wall: the exact render
# draws them. OpenSCAD's clipper works on a grid of 2^-16 (1.5e-5), where
# they have no width, and drops them, as the faithful render does.
# Checks both halves of that: as written, the exact render differs from
# the mesh (check.sh's verdict "differs"); with points 151 and 0 taken
# out (the needles' tips), the exact render matches the mesh, so nothing
# else differs. Exits 0 when both hold.
set -uo pipefail
if (($# != 3)); then
    echo "usage: needles.sh BUILD_DIR WORKDIR W,H" >&2
    exit 2
fi
build=$1 work=$2 size=$3
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
model=$here/round-anything/examples/beamChain-2.csg
mkdir -p "$work"
work=$(cd "$work" && pwd)
status=0

bash "$here/check.sh" "$build" "$model" "$work/as-written" "$size" >"$work/as-written.row"
IFS=$'\t' read -r _ _ _ exact _ _ _ cgal _ verdict _ _ xverdict _ reason \
    <"$work/as-written.row"
if [[ $cgal != ok ]]; then
    echo "needles: OpenSCAD's CGAL render failed ($cgal); skipped" >&2
    exit 77
fi
if [[ $verdict != match || $xverdict != differs ]]; then
    echo "needles: as written: faithful $verdict, exact $xverdict (expected match, differs): $reason" >&2
    status=1
fi

# The tips: the polygon's first point and its last.
sed -e 's/polygon(points = \[\[-3.96527, 6.60879\], /polygon(points = [/' \
    -e 's/, \[3.96527, -6.60879\]\], paths/], paths/' "$model" >"$work/no-needles.csg"
removed=$(($(grep -o '3\.96527' "$model" | wc -l) - $(grep -o '3\.96527' "$work/no-needles.csg" | wc -l)))
if ((removed != 2)); then
    echo "needles: expected to take out 2 points, took out $removed" >&2
    exit 1
fi
bash "$here/check.sh" "$build" "$work/no-needles.csg" "$work/no-needles" "$size" \
    >"$work/no-needles.row"
IFS=$'\t' read -r _ _ _ _ _ _ _ _ _ verdict _ _ xverdict _ reason <"$work/no-needles.row"
if [[ $verdict != match || $xverdict != match ]]; then
    echo "needles: without the needles: faithful $verdict, exact $xverdict (expected match, match): $reason" >&2
    status=1
fi
exit $status
