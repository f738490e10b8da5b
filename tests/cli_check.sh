# The checking commands, `spancast measure`, `spancast overlaps` and
# `spancast compare`, end to end: every estimate against the analytic value
# it must hold within its printed error, exit statuses, JSON parsed by
# Python, results that do not depend on --threads, and the exact error
# messages. The comparison with an STL export needs OpenSCAD (the last
# part; skipped without it).
#
# Run as: bash cli_check.sh <path-to-spancast> <source-dir> <work-dir>
. "$(dirname "$0")/testlib.sh"
require_tools python3

# The README's models (docs/examples): a 10 mm cube drilled along z through
# (5, 5) with radius 2; the same with the hole moved 0.1 mm along x; a
# drilled plate with three bolts.
cp "$src/docs/examples/drilled.csg" "$src/docs/examples/moved.csg" \
    "$src/docs/examples/assembly.csg" . || fail "the README's models are missing"
cmp -s moved.csg <(sed 's/\[1, 0, 0, 5\], \[0, 1, 0, 5\]/[1, 0, 0, 5.1], [0, 1, 0, 5]/' drilled.csg) ||
    fail "moved.csg is not drilled.csg with the hole moved 0.1 mm"

# pycheck 'PYTHON' FILE: runs the Python statements with j = the JSON in
# FILE; a failed assert is a failure of this test. holds(e, x) says that
# the estimate e = {"value", "error"} holds x.
pycheck() {
    check
    if ! python3 -c "import json, math, sys
j = json.load(open(sys.argv[1]))
def holds(e, x):
    assert abs(e['value'] - x) <= e['error'], (e, x)
$1" "$2"; then
        fail "python check on $2: $1"
    fi
}

# run RC FILE ARGS...: runs spancast ARGS with stdout to FILE and expects
# exit status RC.
run() {
    local want=$1 out=$2
    shift 2
    check
    "$bin" "$@" >"$out" 2>err.txt
    local rc=$?
    [ "$rc" = "$want" ] || fail "spancast $*: exit $rc (want $want): $(cat err.txt)"
}

# ---- measure ----

run 0 measure.json measure drilled.csg --json -q
pycheck '
pi = math.pi
holds(j["volume"], 1000 - 40 * pi)
holds(j["area"], 600 - 8 * pi + 40 * pi)
for c in j["centroid"]:
    holds(c, 5)
mc, cube = 40 * pi, 1000 * 200 / 12
for e, x in zip(j["principal_moments"], [cube - mc * 112 / 12] * 2 + [cube - mc * 2]):
    holds(e, x)
assert j["volume"]["error"] < 3e-3 * 1000 and j["converged"], j["volume"]
for e in j["box_min"]:
    holds(e, 0)
for e in j["box_max"]:
    holds(e, 10)' measure.json
check
[ ! -s err.txt ] || fail "measure -q wrote to stderr: $(cat err.txt)"

run 0 measure.txt measure drilled.csg
check
grep -q '^volume  *874\.[0-9]* +- ' measure.txt || fail "measure text: $(cat measure.txt)"
check
grep -q '^spancast: measured drilled.csg in [0-9.]* s ([0-9]* threads)$' err.txt ||
    fail "measure summary line: $(cat err.txt)"
grep -q 'note' err.txt && fail "measure of a solid: a note: $(cat err.txt)"

# A 2D model is measured as the slab OpenSCAD's preview draws it (its
# render draws it flat), with a note that
# says so (also with -q: it explains the numbers); info says it too.
printf 'square(size = [10, 5]);\n' >flat.csg
run 0 flat.txt measure flat.csg -q
grep -q '^volume  *50 +- ' flat.txt || fail "2D measure: $(cat flat.txt)"
# its faces on the tree's box: hits rounded past it are on it, and no error
# bound is negative
grep -qx 'box min  *(0, 0, -0.5) +- (0, 0, 0)' flat.txt || fail "2D box: $(cat flat.txt)"
grep -q -- '+- (*-' flat.txt && fail "2D measure: a negative error bound: $(cat flat.txt)"
check
[ "$(cat err.txt)" = "spancast: note: flat.csg is a 2D model, measured as the slab OpenSCAD's preview draws it: 1 unit thick (z from -0.5 to 0.5), so its volume is its area" ] ||
    fail "2D measure: note '$(cat err.txt)'"
run 0 flat_info.txt info flat.csg
grep -qx "2D: drawn flat at z = 0, as OpenSCAD's render draws it; measured as the slab its preview draws: 1 unit thick (z from -0.5 to 0.5), so its volume is its area" flat_info.txt ||
    fail "2D info: $(cat flat_info.txt)"
# Past 1e6 across the slab is 1e-6 of the model's size thick: the note
# and info say how thick, and the volume is that times the area.
printf 'square(size = [1e7, 5e6]);\n' >flat_big.csg
run 0 flat_big.txt measure flat_big.csg -q
grep -q '^volume  *5e+14 +- ' flat_big.txt || fail "big 2D measure: $(cat flat_big.txt)"
check
[ "$(cat err.txt)" = "spancast: note: flat_big.csg is a 2D model, measured as the slab OpenSCAD's preview draws it: 10 thick (z from -5 to 5, 1e-6 of its size past 1e6 across), so its volume is 10 times its area" ] ||
    fail "big 2D measure: note '$(cat err.txt)'"
run 0 flat_big_info.txt info flat_big.csg
grep -q "its preview draws: 10 thick (z from -5 to 5," flat_big_info.txt ||
    fail "big 2D info: $(cat flat_big_info.txt)"
run 0 solid_info.txt info drilled.csg
grep -q '^2D' solid_info.txt && fail "info of a solid says 2D"

# Density scales mass and inertia; one thread or three give the same bytes.
run 0 dense.json measure drilled.csg --json -q --density=7.85e-3 --tolerance=1e-3 --threads=1
run 0 dense3.json measure drilled.csg --json -q --density=7.85e-3 --tolerance=1e-3 --threads=3
check
cmp -s dense.json dense3.json || fail "measure differs between 1 and 3 threads"
pycheck '
holds(j["mass"], 7.85e-3 * (1000 - 40 * math.pi))
assert abs(j["mass"]["value"] - 7.85e-3 * j["volume"]["value"]) < 1e-12 * j["mass"]["value"]' dense.json

# ---- overlaps ----

# Two boxes overlapping in [8, 10] x [7, 10] x [6, 10] (24 mm^3), and a
# third that shares the face x = 10 with the first and overlaps the second
# in [10, 13] x [7, 10] x [6, 10] (36 mm^3).
cat >boxes.csg <<'CSG'
group() {
  cube(size = [10, 10, 10]);
  multmatrix([[1, 0, 0, 8], [0, 1, 0, 7], [0, 0, 1, 6], [0, 0, 0, 1]]) {
    cube(size = [5, 5, 5]);
  }
  multmatrix([[1, 0, 0, 10], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {
    cube(size = [4, 10, 10]);
  }
}
CSG
run 1 boxes.json overlaps boxes.csg --json -q
pycheck '
o = j["overlaps"]
assert j["objects"] == 3 and len(o) == 2, j
assert (o[0]["a"]["index"], o[0]["b"]["index"]) == (1, 2), o[0]
assert (o[1]["a"]["index"], o[1]["b"]["index"]) == (2, 3), o[1]
assert (o[0]["a"]["line"], o[0]["a"]["column"], o[0]["b"]["line"]) == (2, 3, 3), o[0]
holds(o[0]["volume"], 24)
holds(o[1]["volume"], 36)
assert max(abs(a - b) for a, b in zip(o[0]["box_min"] + o[0]["box_max"], [8, 7, 6, 10, 10, 10])) < 1e-9, o[0]
assert j["above_min_volume"] == 2' boxes.json
# texthold FILE PREFIX X: FILE has a line that starts with PREFIX (a
# Python regular expression) and goes on "volume V +- E", where V holds X.
texthold() {
    check
    python3 -c "import re, sys
m = re.search('^' + sys.argv[2] + r'volume (\S+) \+- ([^,\s]+)', open(sys.argv[1]).read(), re.M)
assert m and abs(float(m.group(1)) - float(sys.argv[3])) <= float(m.group(2))" "$@" ||
        fail "no overlap line '$2' holding $3 in $1: $(cat "$1")"
}
run 1 boxes.txt overlaps boxes.csg -q
texthold boxes.txt 'overlap: boxes\.csg:2:3 \(cube, object 1\) and boxes\.csg:3:3 \(multmatrix, object 2\): ' 24
# Below --min-volume: listed, exit 0.
run 0 boxes-min.txt overlaps boxes.csg -q --min-volume=40

# Two cubes that only share a face.
cat >touching.csg <<'CSG'
cube(size = [10, 10, 10]);
multmatrix([[1, 0, 0, 10], [0, 1, 0, 2], [0, 0, 1, 3], [0, 0, 0, 1]]) {
  cube(size = [4, 4, 4]);
}
CSG
# no_overlaps MODEL N WHAT: overlaps finds N objects and no overlap.
no_overlaps() {
    run 0 "$1.txt" overlaps "$1" -q
    check
    [ "$(cat "$1.txt")" = "$(printf '%s top-level objects\nno overlaps' "$2")" ] ||
        fail "$3: $(cat "$1.txt")"
}
no_overlaps touching.csg 2 "touching cubes"

# Two pairs of wedges that meet on a diagonal face, one pair along each
# diagonal. The lines of a grid laid on the box the pair shares cross a
# face through opposite corners of that box, and lie in it; such a line is
# on the boundary of both wedges, so it must not count as inside both.
cat >wedges.csg <<'CSG'
group() {
  linear_extrude(height = 5, center = false, convexity = 1, scale = [1, 1], $fn = 0, $fa = 12, $fs = 2) {
    polygon(points = [[0, 0], [10, 0], [0, 10]], paths = undef, convexity = 1);
  }
  linear_extrude(height = 5, center = false, convexity = 1, scale = [1, 1], $fn = 0, $fa = 12, $fs = 2) {
    polygon(points = [[10, 0], [10, 10], [0, 10]], paths = undef, convexity = 1);
  }
  linear_extrude(height = 5, center = false, convexity = 1, scale = [1, 1], $fn = 0, $fa = 12, $fs = 2) {
    polygon(points = [[20, 0], [30, 0], [30, 10]], paths = undef, convexity = 1);
  }
  linear_extrude(height = 5, center = false, convexity = 1, scale = [1, 1], $fn = 0, $fa = 12, $fs = 2) {
    polygon(points = [[20, 0], [30, 10], [20, 10]], paths = undef, convexity = 1);
  }
}
CSG
no_overlaps wedges.csg 4 "wedges that meet on a diagonal"

# A thin overlap on the face of a thin plate: 0.01 x 100 x 1. The grid's
# box is widened beyond the plates' shared box, and its cells there must
# count only their part within: the lines of a cell in the margin all lie
# inside the plates, and counted the margin as overlap (1.039 +- 0.0053).
cat >thin.csg <<'CSG'
cube(size = [100, 100, 1]);
multmatrix([[1, 0, 0, 99.99], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {
  cube(size = [100, 100, 1]);
}
CSG
run 1 thin.json overlaps thin.csg --json -q
pycheck '
o = j["overlaps"]
assert len(o) == 1, o
holds(o[0]["volume"], 0.01 * 100 * 1)
assert o[0]["converged"], o[0]' thin.json
run 0 thin-min.txt overlaps thin.csg -q --min-volume=1.01

# A '!' in each of two objects: each object is built with the other
# disabled, so each is its own root (the first '!' outside the disabled
# parts, as with '*'). A root drops the transforms above it, so both are
# the cube at the origin and overlap wholly; were the first '!' kept while
# building the second object, that object would be empty.
cat >roots.csg <<'CSG'
group() {
  !cube(size = [10, 10, 10]);
  multmatrix([[1, 0, 0, 5], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {
    !cube(size = [10, 10, 10]);
  }
}
CSG
run 1 roots.json overlaps roots.csg --json -q
pycheck '
o = j["overlaps"]
assert j["objects"] == 2 and len(o) == 1, j
holds(o[0]["volume"], 1000)' roots.json

# A drilled plate (a module call: one group) with three bolts: one with
# clearance in its hole, one resting on the plate's top face, one 0.1 mm
# too thick for its hole, which overlaps the plate by pi (2.1^2 - 2^2) 5.
run 1 assembly.json overlaps assembly.csg --json -q --tolerance=1e-2
pycheck '
o = j["overlaps"]
assert j["objects"] == 4 and len(o) == 1, j
assert (o[0]["a"]["index"], o[0]["a"]["node"], o[0]["b"]["index"], o[0]["b"]["line"]) == (1, "group", 4, 19), o[0]
holds(o[0]["volume"], math.pi * (2.1 ** 2 - 4) * 5)
assert o[0]["volume"]["error"] < 2e-2 * o[0]["volume"]["value"], o[0]' assembly.json

# ---- compare ----

run 0 self.txt compare drilled.csg drilled.csg -q
check
tail -n 1 self.txt | grep -qx same || fail "compare with itself: $(cat self.txt)"

# Two empty models: the same, with nothing to integrate and nothing that
# fell short of the tolerance.
printf '' >empty.csg
run 0 empty.txt compare empty.csg empty.csg -q
check
tail -n 1 empty.txt | grep -qx same || fail "compare empty models: $(cat empty.txt)"
grep -q "not reached" empty.txt && fail "compare empty models: $(cat empty.txt)"

# A plate against the same plate 1e-6 higher: the difference is two sheets
# 1e-6 thick, 0.01 each, 2e-6 of the volume; the lines along x and y lie
# between them and see nothing, those along z cross them. The estimate is
# the largest of the axes', not their mean (a third: "same").
cat >plate.csg <<'CSG'
cube(size = [100, 100, 1]);
CSG
cat >plate-up.csg <<'CSG'
multmatrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 1e-06], [0, 0, 0, 1]]) {
  cube(size = [100, 100, 1]);
}
CSG
run 1 plate.json compare plate.csg plate-up.csg --json -q
pycheck '
holds(j["only_a"], 0.01)
holds(j["only_b"], 0.01)
assert not j["same"] and j["converged"], j' plate.json

# Differences known exactly, each wider than the lines' spacing: a ball of
# radius 0.05 moved clear of itself beside a unit cube (each difference is
# the ball), a unit cube against it chamfered by 0.05 along an edge (a
# wedge of 0.05^2 / 2), and the same turned. Each error bar must cover the
# exact volume.
ball() {
    printf 'union() { cube(size = [1, 1, 1]); multmatrix([[1, 0, 0, %s], [0, 1, 0, 0.5], [0, 0, 1, 1.3], [0, 0, 0, 1]]) { sphere(r = 0.05); } }\n' "$1"
}
ball 0.5 >ball1.csg
ball 0.2 >ball2.csg
run 1 ball.json compare ball1.csg ball2.csg --json -q --tolerance=1e-9
pycheck '
holds(j["only_a"], 4 / 3 * math.pi * 0.05 ** 3)
holds(j["only_b"], 4 / 3 * math.pi * 0.05 ** 3)' ball.json
turn='multmatrix([[0.6634139481689384, -0.47302145844036114, 0.5797694655894312, 0], [0.5566703992264194, 0.8297694655894313, 0.0400087565481419, 0], [-0.49999999999999994, 0.29619813272602386, 0.8137976813493738, 0], [0, 0, 0, 1]])'
cut='multmatrix([[1, 0, 0, 0.5], [0, 0.7071067811865476, -0.7071067811865476, 0], [0, 0.7071067811865476, 0.7071067811865476, 1], [0, 0, 0, 1]]) { cube(size = [3, 0.07071067811865477, 0.07071067811865477], center = true); }'
printf 'cube(size = [1, 1, 1]);\n' >box.csg
printf 'difference() { cube(size = [1, 1, 1]); %s }\n' "$cut" >chamfer.csg
printf '%s { cube(size = [1, 1, 1]); }\n' "$turn" >turned.csg
printf '%s { difference() { cube(size = [1, 1, 1]); %s } }\n' "$turn" "$cut" >chamfer-turned.csg
run 1 chamfer.json compare box.csg chamfer.csg --json -q --tolerance=1e-9
run 1 chamfer-turned.json compare turned.csg chamfer-turned.csg --json -q --tolerance=1e-9
for f in chamfer.json chamfer-turned.json; do
    pycheck '
holds(j["only_a"], 0.05 ** 2 / 2)
holds(j["only_b"], 0)' $f
done

# A prism with a face through opposite corners of its box against the STL
# OpenSCAD 2021.01 exports of it: the same solid, though the lines in the
# plane of that face meet the mesh on its triangles' edges.
cat >prism.csg <<'CSG'
linear_extrude(height = 1, center = true, convexity = 1, scale = [1, 1], $fn = 0, $fa = 12, $fs = 2) {
  polygon(points = [[0, 0], [10, 0], [0, 10]], paths = undef, convexity = 1);
}
CSG
python3 - <<'PY' || fail "writing prism.stl"
tris = [((0, 0, -.5), (0, 10, -.5), (10, 0, -.5)), ((10, 0, .5), (0, 10, .5), (0, 0, .5)),
        ((0, 0, -.5), (0, 10, .5), (0, 10, -.5)), ((0, 0, -.5), (0, 0, .5), (0, 10, .5)),
        ((10, 0, -.5), (0, 0, .5), (0, 0, -.5)), ((10, 0, -.5), (10, 0, .5), (0, 0, .5)),
        ((0, 10, -.5), (10, 0, .5), (10, 0, -.5)), ((0, 10, -.5), (0, 10, .5), (10, 0, .5))]
with open("prism.stl", "w") as f:
    f.write("solid OpenSCAD_Model\n")
    for t in tris:
        f.write("  facet normal 0 0 0\n    outer loop\n")
        for v in t:
            f.write("      vertex %g %g %g\n" % v)
        f.write("    endloop\n  endfacet\n")
    f.write("endsolid OpenSCAD_Model\n")
PY
run 0 prism.json compare prism.csg prism.stl --json -q
pycheck '
holds(j["only_a"], 0)
holds(j["only_b"], 0)
assert j["symmetric_difference"]["value"] <= 1e-6 * 50 and j["same"], j' prism.json

# A mesh written to 6 significant digits (as OpenSCAD's ASCII STL): a
# plate 0.1000005 thick as 0.100001. The volumes differ by 5e-6 of the
# volume, past the tolerance, and compare says so; rounding to 6 digits
# moves a point by up to 5e-6 on each axis (at 1), which accounts for it,
# and a note says that. The plate written with 17 digits has no note.
printf 'cube(size = [1, 1, 0.1000005], center = false);\n' >third.csg
python3 - <<'PY'
corners = [(x, y, z) for x in (0, 1) for y in (0, 1) for z in (0, 1)]
quads = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
for name, top in (("third6.stl", "0.100001"), ("third17.stl", repr(0.1000005))):
    with open(name, "w") as f:
        f.write("solid plate\n")
        for q in quads:
            for t in ((q[0], q[1], q[2]), (q[0], q[2], q[3])):
                f.write(" facet normal 0 0 0\n  outer loop\n")
                for i in t:
                    x, y, z = corners[i]
                    f.write("   vertex %d %d %s\n" % (x, y, top if z else "0"))
                f.write("  endloop\n endfacet\n")
        f.write("endsolid plate\n")
PY
run 1 third.json compare third.csg third6.stl --json -q
check
grep -q "^spancast: note: 'third6.stl' gives its coordinates to 6 significant digits: its surface may lie up to 8.7e-06 from the one it was written from" err.txt ||
    fail "compare third.csg third6.stl: no note of the rounding: $(cat err.txt)"
pycheck '
assert not j["same"], j
assert j["rounding"] >= j["symmetric_difference"]["value"] > 0, j' third.json
run 0 third17.txt compare third.csg third17.stl -q
check
[ -s err.txt ] && fail "compare third.csg third17.stl: $(cat err.txt)"

# The hole moved 0.1 mm: the symmetric difference is twice the circle less
# the lens two circles of radius 2 with centres 0.1 apart share, over the
# height 10.
run 1 moved.json compare drilled.csg moved.csg --json -q --diff=diff-
pycheck '
r, d = 2.0, 0.1
lens = 2 * r * r * math.acos(d / (2 * r)) - d / 2 * math.sqrt(4 * r * r - d * d)
holds(j["only_a"], 10 * (math.pi * r * r - lens))
holds(j["only_b"], 10 * (math.pi * r * r - lens))
holds(j["symmetric_difference"], 20 * (math.pi * r * r - lens))
assert not j["same"]
v = {x["view"]: x for x in j["views"]}
assert v["+x"]["mask_mismatch"] == 0 and v["diagonal"]["depth_mismatch"] > 0, v' moved.json
for view in px nx py ny pz nz diagonal; do
    check
    [ -s "diff-$view.png" ] || fail "compare --diff wrote no diff-$view.png"
done

# Errors: a bad option and a file that does not load exit 2.
expect() {
    local want_rc=$1 want_err=$2
    shift 2
    check
    "$bin" "$@" >out.txt 2>err.txt
    local rc=$?
    if [ "$rc" != "$want_rc" ] || [ "$(cat err.txt)" != "$want_err" ]; then
        fail "spancast $*: exit $rc (want $want_rc), stderr '$(cat err.txt)' (want '$want_err')"
    fi
    if [ -s out.txt ]; then
        fail "spancast $*: wrote to stdout on an error: $(cat out.txt)"
    fi
}
printf 'cube(1;\n' >bad.csg
expect 2 "spancast: error: --tolerance expects a relative error between 0 and 1" measure drilled.csg --tolerance=2
expect 2 "spancast: error: --density expects a positive number" measure drilled.csg --density=-1
expect 2 "spancast: error: option '--min-volume' does not apply to 'measure'" measure drilled.csg --min-volume=1
expect 2 "spancast: error: option '--density' does not apply to 'compare'" compare drilled.csg moved.csg --density=1
expect 2 "spancast: error: compare expects two models: A B" compare drilled.csg
expect 2 "spancast: error: unexpected argument 'x.csg'" measure drilled.csg x.csg
expect 1 "spancast: error: cannot open 'missing.csg': No such file or directory" measure missing.csg
expect 2 "spancast: error: cannot read 'missing.csg': No such file or directory" overlaps missing.csg
expect 2 "bad.csg:1:7: error: expected ')' (to close '(' at line 1)" overlaps bad.csg
expect 2 "spancast: error: cannot open 'missing.csg': No such file or directory" compare drilled.csg missing.csg
expect 2 "spancast: error: cannot open 'missing.stl': No such file or directory" compare drilled.csg missing.stl
expect 2 "spancast: error: cannot open 'missing.scad': No such file or directory" overlaps missing.scad

# ---- against OpenSCAD's STL export ----

command -v openscad >/dev/null || skip "openscad is not installed"
# The hole with 64 sides: the mesh's hole is the polygon inscribed in the
# circle, so the mesh has 10 (pi r^2 - 32 r^2 sin(2 pi / 64)) more volume
# and nothing less.
sed 's/r1 = 2, r2 = 2, center = false)/r1 = 2, r2 = 2, center = false, $fn = 64)/' \
    drilled.csg >drilled64.csg
openscad -o "$work/drilled64.stl" "$work/drilled64.csg" >openscad.log 2>&1 ||
    fail "openscad STL export: $(cat openscad.log)"
bound=$(python3 -c "import math; print(10 * (math.pi * 4 - 32 * 4 * math.sin(2 * math.pi / 64)) / (1000 - 40 * math.pi))")
# A third of the bound: different.
run 1 stl.json compare drilled64.csg drilled64.stl --json -q \
    --tolerance="$(python3 -c "print($bound / 3)")"
pycheck '
extra = 10 * (math.pi * 4 - 32 * 4 * math.sin(2 * math.pi / 64))
holds(j["only_b"], extra)
assert j["only_a"]["value"] < 1e-3 * extra, j["only_a"]
assert not j["same"]' stl.json
# Within the bound (and a fifth more for the hole's 6-digit numbers): the same.
run 0 stl.txt compare drilled64.csg drilled64.stl -q --tolerance="$(python3 -c "print($bound * 1.2)")"
check
tail -n 1 stl.txt | grep -qx same || fail "compare with the STL within its bound: $(cat stl.txt)"

# ---- overlaps of OpenSCAD source ----

# The boxes above written in OpenSCAD's language, one from a module: the
# same pairs and volumes; each object is placed on the source with the line
# of OpenSCAD's export it is on (the same lines as boxes.csg, which is that
# export's shape).
cat >boxes.scad <<'SCAD'
module box(at, size) translate(at) cube(size);
cube(10);
box([8, 7, 6], 5);
box([10, 0, 0], [4, 10, 10]);
SCAD
run 1 scad.json overlaps boxes.scad --json -q
pycheck '
o = j["overlaps"]
assert j["objects"] == 3 and len(o) == 2, j
assert [(p["a"]["index"], p["b"]["index"]) for p in o] == [(1, 2), (2, 3)], o
holds(o[0]["volume"], 24)
holds(o[1]["volume"], 36)' scad.json
run 1 scad.txt overlaps boxes.scad -q
texthold scad.txt "overlap: boxes\\.scad \\(line [0-9]* of OpenSCAD's export\\) \\(cube, object 1\\) and boxes\\.scad \\(line [0-9]* of OpenSCAD's export\\) \\(group, object 2\\): " 24
grep -q "csg" scad.txt && fail "overlaps of a .scad names a .csg: $(cat scad.txt)"
# A .csg in OpenSCAD's language is converted the same way, with the note.
cp boxes.scad language.csg
run 1 language.txt overlaps language.csg -q
check
grep -q "^overlap: language.csg (line [0-9]* of OpenSCAD's export) (cube, object 1)" language.txt ||
    fail "overlaps of a language .csg: $(cat language.txt)"
grep -q "language.csg: note: uses OpenSCAD's language beyond its CSG export (line 1); converting it with openscad" err.txt ||
    fail "no note for the language .csg: $(cat err.txt)"
printf 'cube(5);\ncube(10;\n' >broken.scad
run 2 broken.txt overlaps broken.scad
grep -q "^broken.scad:2:[0-9]*: error: " err.txt || fail "overlaps of a broken .scad: $(cat err.txt)"

echo "$checks checks, $fails failures"
[ "$fails" = 0 ]
