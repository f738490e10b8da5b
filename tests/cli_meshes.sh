# Bad meshes on the command line (docs/meshes.md): a polyhedron that is
# not closed, next to a cube. By default a warning at the polyhedron's
# position, exit 0, and the rest rendered: in exact mode the polyhedron
# too (by the parity rule), in faithful mode without it (OpenSCAD leaves it
# out, with its own message). With --strict, in either mode, the error,
# exit status 1 (2 for overlaps and compare), and no output written.
. "$(dirname "$0")/testlib.sh"

# The notch of tests/test_build_mesh.c with its last face turned the wrong
# way (inconsistently oriented), and a cube at x = 5.
cat >bad.csg <<'CSG'
group() {
    polyhedron(points = [[0, 0, 0], [2, 0, 0], [2, 2, 0], [0, 2, 0], [0, 0, 2], [2, 0, 2],
                         [2, 2, 2], [0, 2, 2], [1, 1, 1]],
               faces = [[0, 1, 2, 3], [4, 5, 1, 0], [5, 6, 2, 1], [6, 7, 3, 2], [7, 4, 0, 3],
                        [4, 8, 5], [5, 8, 6], [6, 8, 7], [7, 4, 8]]);
    multmatrix([[1, 0, 0, 5], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {
        cube(size = [1, 1, 1], center = false);
    }
}
CSG
edge="polyhedron is not consistently oriented (edge 4-8 runs the same way in two faces)"
exact_warning="bad.csg:2:5: warning: $edge; rendered by the parity rule (--strict makes it an error)"
faithful_warning="bad.csg:2:5: warning: $edge; left out, as OpenSCAD leaves it out (\"The given mesh is not closed! Unable to convert to CGAL_Nef_Polyhedron.\")"
strict_error="bad.csg:2:5: error: $edge"

# expect STATUS STDERR-LINE COMMAND...: the exit status and stderr's first line.
expect() {
    local want_rc=$1 want=$2
    shift 2
    check
    "$bin" "$@" >out.txt 2>err.txt
    local rc=$? got
    got=$(head -n 1 err.txt)
    if [ "$rc" != "$want_rc" ] || [ "$got" != "$want" ]; then
        fail "spancast $*: exit $rc (want $want_rc)"
        echo "    got  '$got'"
        echo "    want '$want'"
    fi
}

view=(--camera=12,-14,10,3,1,1 --imgsize=80,60 --threads=1)
expect 0 "$exact_warning" render bad.csg -o exact.png --mask=exact_mask.png "${view[@]}"
expect 0 "$faithful_warning" render bad.csg -o faithful.png --mask=faithful_mask.png \
    --faithful "${view[@]}"
# The rest is rendered: the notch (exact) and the cube (both).
expect 0 "$exact_warning" inside bad.csg --point=1,1,0.5 --point=1,1,1.5 --point=5.5,0.5,0.5
[ "$(tr '\n' ' ' <out.txt)" = "in out in " ] || fail "exact inside: $(tr '\n' ' ' <out.txt)"
expect 0 "$faithful_warning" inside bad.csg --faithful --point=1,1,0.5 --point=5.5,0.5,0.5
[ "$(tr '\n' ' ' <out.txt)" = "out in " ] || fail "faithful inside: $(tr '\n' ' ' <out.txt)"
# The two masks differ by the notch alone: the faithful one has fewer
# pixels set, and not none.
if [ -e exact_mask.png ] && [ -e faithful_mask.png ]; then
    check
    python3 - exact_mask.png faithful_mask.png <<'PY' || fail "masks: the notch is not the difference"
import struct, sys, zlib
def lit(path):
    data = open(path, 'rb').read()
    pos, idat, width = 8, b'', 0
    while pos < len(data):
        n, kind = struct.unpack('>I4s', data[pos:pos + 8])
        if kind == b'IHDR':
            width, _, depth, colour = struct.unpack('>IIBB', data[pos + 8:pos + 18])
            channels = {0: 1, 2: 3, 4: 2, 6: 4}[colour] * depth // 8
        if kind == b'IDAT':
            idat += data[pos + 8:pos + 8 + n]
        pos += 12 + n
    raw = zlib.decompress(idat)
    stride = width * channels + 1
    # count rows whose filtered bytes are not all zero: a coarse but
    # filter-proof test of "some pixels set" per row
    return sum(1 for r in range(len(raw) // stride) if any(raw[r * stride + 1:(r + 1) * stride]))
exact, faithful = lit(sys.argv[1]), lit(sys.argv[2])
sys.exit(0 if exact > faithful > 0 else 1)
PY
else
    fail "a render wrote no mask"
fi

# --strict: an error in both modes, for every command that loads a model;
# a failed render leaves an existing output alone.
printf 'keep' >keep.png
expect 1 "$strict_error" render bad.csg -o keep.png --strict "${view[@]}"
expect 1 "$strict_error" render bad.csg -o keep.png --strict --faithful "${view[@]}"
[ "$(cat keep.png)" = keep ] || fail "a failed render replaced keep.png"
expect 1 "$strict_error" info bad.csg --strict
expect 1 "$strict_error" measure bad.csg --strict -q
expect 2 "$strict_error" overlaps bad.csg --strict -q
expect 2 "$strict_error" compare bad.csg bad.csg --strict -q
expect 1 "$strict_error" inside bad.csg --strict --point=0,0,0
expect 1 "$strict_error" spans bad.csg --strict --ray=1,1,-1,0,0,1
# Without --strict those commands go on, with the warning.
expect 0 "$exact_warning" info bad.csg
expect 0 "$exact_warning" measure bad.csg -q
# batch: --strict on a job's line.
printf 'render bad.csg -o batch.png --imgsize=8,8 --strict\n' >jobs.txt
check
"$bin" batch jobs.txt >out.txt 2>err.txt && fail "batch with a --strict job that fails: exit 0"
# batch --strict passes it on to each job.
printf 'render bad.csg -o batch.png --imgsize=8,8\n' >jobs.txt
check
"$bin" batch jobs.txt >out.txt 2>err.txt || fail "batch without --strict: exit $?"
check
"$bin" batch jobs.txt --strict >out.txt 2>err.txt && fail "batch --strict: exit 0"
grep -q "$strict_error" out.txt err.txt || fail "batch --strict: no error shown"
# --help names the option.
check
"$bin" --help 2>&1 | grep -q -- "--strict" || fail "--help does not name --strict"

# A profile whose outlines touch at a point (two squares meeting at a
# corner) extrudes to a mesh that is closed as built, but OpenSCAD 2021.01's
# CGAL polyhedron builder merges the points by position, and the vertical
# edge at the corner then has four faces: "not closed", and the extrusion
# is left out of the difference (openscad -o x.stl prints that error, then
# "Current top level object is empty."). Alone it is drawn as it is, and
# exact mode takes the solid the profile bounds.
cat >pinch.csg <<'CSG'
difference() {
	linear_extrude(height = 2, center = false, convexity = 1, scale = [1, 1], $fn = 0, $fa = 12, $fs = 2) {
		square(size = [1, 1], center = false);
		multmatrix([[1, 0, 0, 1], [0, 1, 0, 1], [0, 0, 1, 0], [0, 0, 0, 1]]) {
			square(size = [1, 1], center = false);
		}
	}
	multmatrix([[1, 0, 0, 0.2], [0, 1, 0, 0.2], [0, 0, 1, -1], [0, 0, 0, 1]]) {
		cube(size = [0.3, 0.3, 0.3], center = false);
	}
}
CSG
pinch_warning='pinch.csg:2:2: warning: linear_extrude is not closed (edge (1, 1, 0)-(1, 1, 2) is used by 4 faces); left out, as OpenSCAD leaves it out ("The given mesh is not closed! Unable to convert to CGAL_Nef_Polyhedron.")'
points=(--point=0.8,0.8,1 --point=1.5,1.5,1)
expect 0 "$pinch_warning" inside pinch.csg --faithful "${points[@]}"
[ "$(tr '\n' ' ' <out.txt)" = "out out " ] || fail "faithful pinch: $(tr '\n' ' ' <out.txt)"
expect 0 "" inside pinch.csg "${points[@]}"
[ "$(tr '\n' ' ' <out.txt)" = "in in " ] || fail "exact pinch: $(tr '\n' ' ' <out.txt)"
sed -n '2,7p' pinch.csg >pinch-alone.csg
expect 0 "" inside pinch-alone.csg --faithful "${points[@]}"
[ "$(tr '\n' ' ' <out.txt)" = "in in " ] || fail "faithful pinch alone: $(tr '\n' ' ' <out.txt)"
expect 1 "pinch.csg:2:2: error: linear_extrude is not closed (edge (1, 1, 0)-(1, 1, 2) is used by 4 faces)" \
    inside pinch.csg --faithful --strict "${points[@]}"
if command -v openscad >/dev/null; then
    check
    openscad -o "$PWD/pinch_os.stl" pinch.csg >/dev/null 2>pinch_os.err
    grep -q '^ERROR: The given mesh is not closed! Unable to convert to CGAL_Nef_Polyhedron\.$' pinch_os.err &&
        grep -q '^Current top level object is empty\.$' pinch_os.err ||
        fail "openscad does not leave the pinched extrusion out: $(cat pinch_os.err)"
else
    fail "no openscad to check the pinched extrusion with"
fi

echo "$checks checks, $fails failed"
[ "$fails" = 0 ]
