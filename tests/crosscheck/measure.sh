#!/usr/bin/env bash
# One model of the measure cross-check (see CMakeLists.txt here):
#   measure.sh SPANCAST MESHMEASURE MODEL.scad WORKDIR
# OpenSCAD writes MODEL.csg and, from that .csg, the STL mesh; CGAL's
# Polygon_mesh_processing::volume and ::area on the mesh (meshmeasure) are
# the reference for `spancast measure --faithful`, which casts the same
# polygons, to a relative tolerance of 1e-3 (faceted models have many
# edges seen along the axes, where 1e-4 costs minutes: docs/measure.md).
# Each estimate must hold the reference within its own error
# bound plus what the STL's float32 vertices can move it: a vertex moves
# by at most 2^-24 of its largest coordinate c, so the volume by at most
# that times the area, and the area by at most twice that over the area
# over the smallest edge; 1e-6 of each value covers both for these models
# (all of size about 1 to 100, edges of at least 0.01). Prints one row:
#   name volume +- error reference | area +- error reference | seconds
set -euo pipefail
spancast=$1 meshmeasure=$2 model=$3 work=$4
name=$(basename "$model" .scad)
rm -rf "$work"
mkdir -p "$work"
work=$(cd "$work" && pwd)
cp "$model" "$work/$name.scad"
for file in $(sed -n 's|^// files: *||p' "$model" | head -n 1); do
    cp "$(dirname "$model")/$file" "$work/"
done
openscad -o "$work/$name.csg" "$work/$name.scad" >"$work/openscad.log" 2>&1 ||
    { cat "$work/openscad.log" >&2; exit 1; }
openscad --export-format binstl -o "$work/$name.stl" "$work/$name.csg" \
    >>"$work/openscad.log" 2>&1 || { cat "$work/openscad.log" >&2; exit 1; }
reference=$("$meshmeasure" "$work/$name.stl")
start=$(date +%s.%N)
"$spancast" measure "$work/$name.csg" --faithful --tolerance=1e-3 --json -q \
    >"$work/measure.json"
end=$(date +%s.%N)
python3 - "$work/measure.json" "$reference" "$name" "$start" "$end" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
volume, area = (float(x) for x in sys.argv[2].split())
name, seconds = sys.argv[3], float(sys.argv[5]) - float(sys.argv[4])
ok = True
row = [name]
for key, ref in (("volume", volume), ("area", area)):
    e = j[key]
    off = abs(e["value"] - ref)
    holds = off <= e["error"] + 1e-6 * abs(ref)
    ok &= holds
    row.append("%s %.10g +- %.2g cgal %.10g off %.2g (%.2g relative)%s" % (
        key, e["value"], e["error"], ref, off, off / abs(ref) if ref else 0,
        "" if holds else " OUTSIDE THE BOUND"))
row.append("%.2f s" % seconds)
print(" | ".join(row))
sys.exit(0 if ok else 1)
PY
