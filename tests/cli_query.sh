# The query commands, `spancast spans` and `spancast inside`, end to end:
# text and JSON output (JSON parsed by Python), a number round-tripping
# through JSON, --pixel against the depth `render --depth` writes at that
# pixel, ray and point files, and the exact error messages.
#
# Run as: bash cli_query.sh <path-to-spancast> <source-dir> <work-dir>
. "$(dirname "$0")/testlib.sh"
require_tools python3

# The sphere of radius 3 at (3, 0, 5); its node is at line 2, column 3.
cat >sphere.csg <<'CSG'
multmatrix([[1, 0, 0, 3], [0, 1, 0, 0], [0, 0, 1, 5], [0, 0, 0, 1]]) {
  sphere(r = 3);
}
CSG
# A 10 mm cube drilled along z through (5, 5) with radius 2.
cat >drilled.csg <<'CSG'
difference() {
  cube(size = [10, 10, 10], center = false);
  multmatrix([[1, 0, 0, 5], [0, 1, 0, 5], [0, 0, 1, -1], [0, 0, 0, 1]]) {
    cylinder(h = 12, r1 = 2, r2 = 2, center = false);
  }
}
CSG

# pycheck 'PYTHON' FILE: runs the Python statements with j = the JSON in
# FILE; a failed assert is a failure of this test.
pycheck() {
    check
    if ! python3 -c "import json, math, sys
j = json.load(open(sys.argv[1]))
$1" "$2"; then
        fail "python check on $2: $1"
    fi
}

# The worked example. 21 t^2 - 60 t + 35 = 0 (|o + t d - c|^2 = 9 with
# o - c = (-2, -2, -6)): t = (30 -+ sqrt(165)) / 21, distance
# 2 sqrt(55 / 7).
check
if ! "$bin" spans sphere.csg --ray=1,-2,-1,1,2,4 >worked.txt 2>err.txt; then
    fail "spans on the worked example: $(cat err.txt)"
fi
check
grep -q '^ray 1: origin (1, -2, -1) direction (1, 2, 4), t >= 0: 1 span$' worked.txt ||
    fail "worked example header: $(cat worked.txt)"
check
grep -q "in t=0.81689368.* sphere#0@sphere.csg:2:3 normal .*; out t=2.04024917.* sphere#0@sphere.csg:2:3 normal .*; distance 5.6061191" worked.txt ||
    fail "worked example span: $(cat worked.txt)"

"$bin" spans sphere.csg --ray=1,-2,-1,1,2,4 --json >worked.json || fail "spans --json"
pycheck '
s = j["rays"][0]["spans"]
assert len(s) == 1, s
t0, t1 = (30 - math.sqrt(165)) / 21, (30 + math.sqrt(165)) / 21
assert abs(s[0]["in"]["t"] - t0) < 1e-12 and abs(s[0]["out"]["t"] - t1) < 1e-12
assert abs(s[0]["distance"] - 2 * math.sqrt(55 / 7)) < 1e-12
e = s[0]["in"]
assert (e["leaf"], e["kind"], e["file"], e["line"], e["column"], e["subtracted"]) == \
    (0, "sphere", "sphere.csg", 2, 3, False), e
p = [1 + t0, -2 + 2 * t0, -1 + 4 * t0]
assert all(abs(a - b) < 1e-12 for a, b in zip(e["point"], p))
n = [(p[0] - 3) / 3, p[1] / 3, (p[2] - 5) / 3]
assert all(abs(a - b) < 1e-9 for a, b in zip(e["normal"], n))
' worked.json

# Round trip: every number in the JSON is printed with 17 significant
# digits, so the t read back is the double that was computed, and feeding
# the entry point back as a ray origin gives t = 0 at that same point.
pycheck '
t = j["rays"][0]["spans"][0]["in"]["t"]
assert float(repr(t)) == t
open("t.txt", "w").write(repr(t))
p = j["rays"][0]["spans"][0]["in"]["point"]
open("p.txt", "w").write(",".join(repr(v) for v in p))
' worked.json
check
grep -q "\"t\": $(cat t.txt)[,}]" worked.json || fail "t does not round-trip: $(cat t.txt)"
"$bin" spans sphere.csg --ray="$(cat p.txt),1,2,4" --json >again.json || fail "spans again"
pycheck '
s = j["rays"][0]["spans"][0]
assert abs(s["in"]["t"]) < 1e-9 and abs(s["distance"] - 2 * math.sqrt(55 / 7)) < 1e-9, s
' again.json

# The subtracted surface: x = -1 + 2 t is in the solid for x in [0, 3] and
# [7, 10]; the ends at the hole are the cylinder's, flagged subtracted, with
# normals into the hole.
"$bin" spans drilled.csg --ray=-1,5,5,2,0,0 --json >drilled.json || fail "spans drilled"
pycheck '
s = j["rays"][0]["spans"]
assert [(x["in"]["t"], x["out"]["t"]) for x in s] == [(0.5, 2), (4, 5.5)], s
a, b = s[0]["out"], s[1]["in"]
assert a["kind"] == b["kind"] == "cylinder" and a["subtracted"] and b["subtracted"]
assert (a["line"], a["column"]) == (4, 5)
assert a["normal"] == [1, 0, 0] and b["normal"] == [-1, 0, 0], (a, b)
assert not s[0]["in"]["subtracted"] and s[0]["in"]["normal"] == [-1, 0, 0]
' drilled.json
"$bin" spans drilled.csg --ray=-1,5,5,2,0,0 >drilled.txt
check
grep -q 'out t=2 (3, 5, 5) cylinder#1@drilled.csg:4:5 normal (1, 0, 0) subtracted;' drilled.txt ||
    fail "text of a subtracted end: $(cat drilled.txt)"

# --both-ways: from inside the sphere, t >= 0 starts at the origin (on no
# surface); the whole line adds the entry behind it.
"$bin" spans sphere.csg --ray=3,0,5,0,0,2 >fwd.txt
"$bin" spans sphere.csg --ray=3,0,5,0,0,2 --both-ways >both.txt
check
grep -q '^  in t=0 (3, 0, 5) (ray start); out t=1.5 (3, 0, 8) .*; distance 3$' fwd.txt ||
    fail "ray from inside: $(cat fwd.txt)"
check
grep -q '^  in t=-1.5 (3, 0, 2) sphere#0.*; out t=1.5 .*; distance 6$' both.txt ||
    fail "--both-ways: $(cat both.txt)"

# A rays file, with a comment and a blank line; commas or spaces.
printf '# origin direction\n1 -2 -1 1 2 4\n\n3,0,20,0,0,1\n' >rays.txt
"$bin" spans sphere.csg --rays=rays.txt --json >file.json || fail "--rays"
pycheck '
r = j["rays"]
assert len(r) == 2 and len(r[0]["spans"]) == 1 and r[1]["spans"] == [], r
' file.json

# --pixel: the ray render shoots through that pixel's centre, so its first
# span's t |d| is the depth render writes there (a float). The pixel at the
# image centre and one near the edge of the model.
if python3 -c 'import OpenEXR' 2>/dev/null || command -v oiiotool >/dev/null; then
    "$bin" render drilled.csg -o d.png --depth=d.exr --imgsize=64,48 -q ||
        fail "render --depth"
    for px in 32,24 20,30; do
        "$bin" spans drilled.csg --pixel=$px --imgsize=64,48 --json >px.json ||
            fail "--pixel=$px"
        i=${px%,*} j=${px#*,}
        if command -v oiiotool >/dev/null; then
            depth=$(oiiotool d.exr --cut "1x1+$i+$j" --printinfo:stats=1 2>&1 |
                sed -n 's/.*Constant Color: \([^ ]*\).*/\1/p')
        else
            depth=$(python3 -c "import OpenEXR, array
f = OpenEXR.InputFile('d.exr'); h = f.header()['dataWindow']
w = h.max.x - h.min.x + 1; c = list(f.header()['channels'])[0]
print(array.array('f', f.channel(c))[$j * w + $i])")
        fi
        pycheck "
r = j['rays'][0]
assert r['pixel'] == [$i, $j]
d = math.sqrt(sum(v * v for v in r['direction']))
depth = float('$depth')
assert r['spans'], 'the pixel should see the model'
got = r['spans'][0]['in']['t'] * d
assert abs(got - depth) <= 1e-5 * depth, (got, depth)
" px.json
    done
else
    echo "note: no EXR reader; --pixel checked against the API test only"
fi

# inside: points in, out and on, from the command line and a file.
"$bin" inside drilled.csg --point=1,1,1 --point=5,5,5 --point=0,5,5 --point=3,5,5 \
    --point=20,0,0 >inside.txt || fail "inside"
check
[ "$(tr '\n' ' ' <inside.txt)" = "in out on on out " ] ||
    fail "inside: $(cat inside.txt)"
printf '1 1 1\n# a comment\n5,5,5\n10 10 10\n' >points.txt
"$bin" inside drilled.csg --points=points.txt --json >inside.json || fail "inside --json"
pycheck '
assert [p["where"] for p in j["points"]] == ["in", "out", "on"], j
assert j["points"][0]["point"] == [1, 1, 1]
' inside.json

# Errors: usage 2 with spancast's message, a bad line as FILE:LINE, a
# model that does not load 1.
expect() {
    local want_rc=$1 want_err=$2
    shift 2
    check
    "$bin" "$@" >out.txt 2>err.txt
    local rc=$?
    if [ "$rc" != "$want_rc" ] || [ "$(cat err.txt)" != "$want_err" ]; then
        fail "spancast $*: exit $rc (want $want_rc), stderr '$(cat err.txt)' (want '$want_err')"
    fi
    if [ "$want_rc" != 0 ] && [ -s out.txt ]; then
        fail "spancast $*: wrote to stdout on an error: $(cat out.txt)"
    fi
}
printf '1 2 3 4 5\n' >short.txt
printf '1 2 3 0 0 0\n' >zero.txt
printf '1 2 x\n' >word.txt
printf 'cube(1;\n' >bad.csg
expect 2 "spancast: error: no ray to query (give --ray, --rays or --pixel)" spans sphere.csg
expect 2 "spancast: error: no point to query (give --point or --points)" inside sphere.csg
expect 2 "spancast: error: missing input file" spans --ray=0,0,0,1,0,0
expect 2 "spancast: error: --ray expects 6 numbers: OX,OY,OZ,DX,DY,DZ" spans sphere.csg --ray=1,2,3
expect 2 "spancast: error: --ray expects 6 numbers: OX,OY,OZ,DX,DY,DZ" spans sphere.csg --ray=1,2,3,4,5,nan
expect 2 "spancast: error: --ray direction must not be zero" spans sphere.csg --ray=1,2,3,0,0,0
expect 2 "spancast: error: --pixel expects I,J: a column and a row, integers >= 0" spans sphere.csg --pixel=1.5,2
expect 2 "spancast: error: pixel 800,0 is outside the 800x600 image" spans sphere.csg --pixel=800,0
expect 2 "spancast: error: --fov expects an angle in degrees between 0 and 180" spans sphere.csg --pixel=1,1 --fov=200
expect 2 "spancast: error: camera eye and centre are the same point" spans sphere.csg --pixel=1,1 --camera=1,1,1,1,1,1
expect 2 "spancast: error: --point expects 3 numbers: X,Y,Z" inside sphere.csg --point=1,2
expect 2 "spancast: error: option '--point' does not apply to 'spans'" spans sphere.csg --point=1,2,3
expect 2 "spancast: error: option '--camera' does not apply to 'inside'" inside sphere.csg --camera=0,0,0,1,1,1
expect 2 "spancast: error: option '--json' takes no value" inside sphere.csg --json=yes
expect 2 "spancast: error: option '--ray' expects a value" spans sphere.csg --ray
expect 2 "spancast: error: unknown option '--frobnicate'" spans sphere.csg --frobnicate
expect 2 "spancast: error: cannot open 'missing.txt': No such file or directory" spans sphere.csg --rays=missing.txt
expect 2 "short.txt:1: error: expected 6 numbers (origin, direction), got 5" spans sphere.csg --rays=short.txt
expect 2 "zero.txt:1: error: ray direction must not be zero" spans sphere.csg --rays=zero.txt
expect 2 "word.txt:1: error: 'x' is not a finite number" inside sphere.csg --points=word.txt
expect 2 "short.txt:1: error: expected 3 numbers (x, y, z), got 5" inside sphere.csg --points=short.txt
expect 1 "spancast: error: cannot open 'missing.csg': No such file or directory" spans missing.csg --ray=0,0,0,1,0,0
expect 1 "bad.csg:1:7: error: expected ')' (to close '(' at line 1)" inside bad.csg --point=0,0,0

# inside on the edges and corners of a mesh: every axis line through such a
# point lies in a face or along an edge, where the mesh counts no crossing
# (they were all "out"); an oblique line crosses there.
python3 - <<'PY' || fail "writing cube.stl"
c = [(x, y, z) for x in (0, 10) for y in (0, 10) for z in (0, 10)]
quads = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
with open("cube.stl", "w") as f:
    f.write("solid cube\n")
    for a, b, d, e in quads:
        for t in ((a, b, d), (a, d, e)):
            f.write("facet normal 0 0 0\nouter loop\n")
            for i in t:
                f.write("vertex %g %g %g\n" % c[i])
            f.write("endloop\nendfacet\n")
    f.write("endsolid cube\n")
PY
check
"$bin" inside cube.stl --point=10,10,5 --point=5,10,10 --point=0,10,10 --point=10,10,10 \
    --point=0,0,0 --point=5,5,10 --point=5,5,5 --point=10.001,10,5 >cube.txt 2>err.txt ||
    fail "inside cube.stl: $(cat err.txt)"
[ "$(tr '\n' ' ' <cube.txt)" = "on on on on on on in out " ] ||
    fail "inside on a mesh's edges and corners: $(tr '\n' ' ' <cube.txt)"

# ---- a model OpenSCAD converts ----

# Positions in OpenSCAD's export are put on the source with the export's
# line, as messages are: never the export's own name, which is no file of
# the user's (here a .csg of the same name beside the source is another
# model).
command -v openscad >/dev/null || skip "openscad is not installed"
printf 'difference() { cube([30, 20, 10]); translate([10, -1, 5]) cube([30, 22, 10]); }\n' >step.scad
printf 'sphere(1);\n' >step.csg
check
"$bin" spans step.scad --ray=-1,5,7,1,0,0 >step.txt 2>err.txt || fail "spans step.scad: $(cat err.txt)"
grep -q "in t=1 (0, 5, 7) box#0@step.scad (line [0-9]* of OpenSCAD's export) normal (-1, 0, 0); out t=11 (10, 5, 7) box#1@step.scad (line [0-9]* of OpenSCAD's export) normal (1, 0, 0) subtracted; distance 10" step.txt ||
    fail "spans of a .scad: $(cat step.txt)"
grep -q "csg" step.txt && fail "spans of a .scad names a .csg: $(cat step.txt)"
"$bin" spans step.scad --ray=-1,5,7,1,0,0 --json >step.json 2>err.txt || fail "spans --json step.scad: $(cat err.txt)"
pycheck '
e = j["rays"][0]["spans"][0]["in"]
assert e["file"] == "step.scad" and e["line"] is None and e["column"] is None, e
assert e["export_line"] > 0 and e["kind"] == "box", e' step.json

echo "$checks checks, $fails failures"
[ "$fails" = 0 ]
