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
# A hull takes the pinched extrusion's corners, as OpenSCAD's does.
printf 'hull() {\n%s\n}\n' "$(cat pinch-alone.csg)" >pinch-hull.csg
expect 0 "" inside pinch-hull.csg --faithful --point=1.2,0.5,1 --point=3,0.5,1
[ "$(tr '\n' ' ' <out.txt)" = "in out " ] || fail "hull of the pinch: $(tr '\n' ' ' <out.txt)"
# A render() of one child takes its mesh as it is (OpenSCAD's RenderNode
# unites its children as a group does: one is no CGAL operation); a
# minkowski() makes a Nef polyhedron of each operand, and OpenSCAD's is
# empty when one is not closed.
printf 'render(convexity = 1) {\n%s\n}\n' "$(cat pinch-alone.csg)" >pinch-render.csg
expect 0 "" inside pinch-render.csg --faithful --point=0.5,0.5,1
[ "$(cat out.txt)" = in ] || fail "render() of the pinch: $(cat out.txt)"
printf 'minkowski(convexity = 0) {\n%s\n\tcube(size = [0.1, 0.1, 0.1], center = false);\n}\n' \
    "$(cat pinch-alone.csg)" >pinch-minkowski.csg
expect 0 'pinch-minkowski.csg:2:2: warning: linear_extrude is not closed (edge (1, 1, 0)-(1, 1, 2) is used by 4 faces); left out, as OpenSCAD leaves it out ("The given mesh is not closed! Unable to convert to CGAL_Nef_Polyhedron.")' \
    inside pinch-minkowski.csg --faithful --point=0.5,0.5,1 --point=0.05,0.05,0.05
[ "$(tr '\n' ' ' <out.txt)" = "out out " ] || fail "minkowski of the pinch: $(tr '\n' ' ' <out.txt)"
if command -v openscad >/dev/null; then
    for m in pinch-render pinch-minkowski; do
        check
        openscad -o "$PWD/${m}_os.stl" $m.csg >/dev/null 2>${m}_os.err
    done
    grep -q 'not closed' pinch-render_os.err && fail "openscad: $(cat pinch-render_os.err)"
    grep -q '^Current top level object is empty\.$' pinch-minkowski_os.err ||
        fail "openscad does not empty the minkowski: $(cat pinch-minkowski_os.err)"
fi
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

# linear_extrude scaled to 0 at its top (OpenSCAD 2021.01's own test
# models, linear_extrude-scale-zero-tests.scad, each beside a cube so that
# OpenSCAD unites them with CGAL): whether OpenSCAD leaves the extrusion
# out ("not closed") depends on its own mesh, whose top is a point or a
# segment, and not on the one spancast draws, which splits the walls over
# the segment's points. A profile with a hole scaled to a point makes two
# fans of faces at the apex, which CGAL's polyhedron builder does not take;
# the same profile scaled onto a segment is closed. Each case: spancast
# leaves it out with a warning exactly when openscad prints its error.
if command -v openscad >/dev/null; then
    shapes=(
        'difference() {
		square(size = [2, 2], center = true);
		square(size = [1, 1], center = true);
	}'
        'multmatrix([[1, 0, 0, 1], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {
		square(size = [1, 1], center = true);
	}
	multmatrix([[1, 0, 0, -1], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {
		square(size = [1, 1], center = true);
	}'
        'difference() {
		square(size = [2, 2], center = true);
		multmatrix([[1, 0, 0, -0.5], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {
			square(size = [1, 1], center = true);
		}
	}')
    left_out=0 kept=0
    for k in 0 1 2; do
        for args in 'scale = [0, 1]' 'scale = [1, 0]' 'scale = [0, 0]' \
            'twist = 180, scale = [0, 1]' 'twist = 180, scale = [1, 0]' \
            'twist = 180, scale = [0, 0]'; do
            printf 'union() {\n\tlinear_extrude(height = 3, center = false, convexity = 1, slices = 20, %s) {\n\t%s\n\t}\n\tmultmatrix([[1, 0, 0, 100], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {\n\t\tcube(size = [0.1, 0.1, 0.1], center = false);\n\t}\n}\n' \
                "$args" "${shapes[$k]}" >zero.csg
            check
            openscad -o "$PWD/zero_os.stl" zero.csg >/dev/null 2>zero_os.err
            "$bin" info zero.csg --faithful >/dev/null 2>zero.err
            os=$(grep -c 'ERROR: The given mesh is not closed' zero_os.err)
            sc=$(grep -c 'linear_extrude is not closed.*left out, as OpenSCAD leaves it out' zero.err)
            if [ "$os" != "$sc" ]; then
                fail "shape $k, $args: openscad's errors $os, spancast's warnings $sc"
                cat zero.err
            fi
            [ "$os" = 0 ] && kept=$((kept + 1)) || left_out=$((left_out + 1))
        done
    done
    echo "scale 0: $left_out left out, $kept kept"
    # both outcomes are among the cases
    [ "$left_out" -gt 0 ] && [ "$kept" -gt 0 ] ||
        fail "scale 0: $left_out left out, $kept kept; the cases no longer tell the rules apart"
else
    fail "no openscad to compare the extrusions scaled to 0 with"
fi

# A polyhedron of two tetrahedra that meet only at a point: every edge has
# two faces, but the faces at that point make two fans, which CGAL's
# polyhedron builder does not take (openscad -o x.stl: "not closed", then
# an empty model), so faithful mode leaves it out of the difference; exact
# mode draws both solids.
cat >fans.csg <<'CSG'
difference() {
	polyhedron(points = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1], [-1, 0, 0], [0, -1, 0], [0, 0, -1]], faces = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3], [0, 4, 5], [0, 6, 4], [0, 5, 6], [4, 6, 5]], convexity = 1);
	multmatrix([[1, 0, 0, 5], [0, 1, 0, 5], [0, 0, 1, 5], [0, 0, 0, 1]]) {
		cube(size = [0.1, 0.1, 0.1], center = false);
	}
}
CSG
points=(--point=0.2,0.2,0.2 --point=-0.2,-0.2,-0.2)
expect 0 "fans.csg:2:2: warning: polyhedron is not closed (a face meets point 0 where the faces before it close, and CGAL's builder skips it); left out, as OpenSCAD leaves it out (\"The given mesh is not closed! Unable to convert to CGAL_Nef_Polyhedron.\")" \
    inside fans.csg --faithful "${points[@]}"
[ "$(tr '\n' ' ' <out.txt)" = "out out " ] || fail "faithful fans: $(tr '\n' ' ' <out.txt)"
expect 0 "" inside fans.csg "${points[@]}"
[ "$(tr '\n' ' ' <out.txt)" = "in in " ] || fail "exact fans: $(tr '\n' ' ' <out.txt)"
# A cut needs the polyhedron's Nef polyhedron, in both modes: left out.
cat >fans-cut.csg <<'CSG'
linear_extrude(height = 1, center = false, convexity = 1, scale = [1, 1], $fn = 0, $fa = 12, $fs = 2) {
	projection(cut = true, convexity = 0) {
		multmatrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0.3], [0, 0, 0, 1]]) {
			polyhedron(points = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1], [-1, 0, 0], [0, -1, 0], [0, 0, -1]], faces = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3], [0, 4, 5], [0, 6, 4], [0, 5, 6], [4, 6, 5]], convexity = 1);
		}
	}
}
CSG
for mode in faithful exact; do
    flags=()
    [ $mode = faithful ] && flags=(--faithful)
    expect 0 "fans-cut.csg:4:4: warning: polyhedron is not closed (a face meets point 0 where the faces before it close, and CGAL's builder skips it); left out, as OpenSCAD leaves it out (\"The given mesh is not closed! Unable to convert to CGAL_Nef_Polyhedron.\")" \
        inside fans-cut.csg "${flags[@]}" --point=-0.1,-0.1,0.5
    [ "$(cat out.txt)" = out ] || fail "cut of the fans ($mode): $(cat out.txt)"
done
if command -v openscad >/dev/null; then
    check
    openscad -o "$PWD/fans-cut_os.stl" fans-cut.csg >/dev/null 2>fans-cut_os.err
    grep -q '^ERROR: The given mesh is not closed' fans-cut_os.err ||
        fail "openscad cuts the polyhedron of two fans: $(cat fans-cut_os.err)"
    check
    openscad -o "$PWD/fans_os.stl" fans.csg >/dev/null 2>fans_os.err
    grep -q '^ERROR: The given mesh is not closed! Unable to convert to CGAL_Nef_Polyhedron\.$' fans_os.err ||
        fail "openscad does not leave the polyhedron of two fans out: $(cat fans_os.err)"
fi

# CGAL's polyhedron builder takes a mesh face by face, in order, and skips
# a face that passes through a point twice, runs an edge the way a face
# taken runs it, or meets a point whose faces already close; what it took
# must then leave no edge with one face ("not closed") and no point off
# every face taken ("invalid"). OpenSCAD tessellates an extrusion's caps,
# which splits a cap's edge at a point of that cap lying on it (the sides
# keep the edge whole); CGAL's OFF reader builds without the test, and a
# face it cannot take rolls the whole file back; a minkowski() of one
# solid is that solid as it is. Each case is judged against openscad's own
# verdict on the same file: an error, or none.
far='multmatrix([[1, 0, 0, 100], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) cube(size = [0.1, 0.1, 0.1], center = false);'
cube_pts='[[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]]'
cube_faces='[0, 1, 2, 3], [4, 5, 1, 0], [7, 6, 5, 4], [5, 6, 2, 1], [6, 7, 3, 2], [7, 4, 0, 3]'
cat >twice.csg <<CSG
difference() {
	polyhedron(points = $cube_pts, faces = [$cube_faces, [0, 1, 2, 3]], convexity = 1);
	$far
}
CSG
cat >twice-rev.csg <<CSG
difference() {
	polyhedron(points = $cube_pts, faces = [$cube_faces, [3, 2, 1, 0]], convexity = 1);
	$far
}
CSG
cat >tets-edge.csg <<CSG
difference() {
	polyhedron(points = [[0, 0, 0], [0, 0, 1], [1, 0, 0], [0, 1, 0], [-1, 0, 0], [0, -1, 0]], faces = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3], [0, 1, 4], [0, 5, 1], [0, 4, 5], [1, 5, 4]], convexity = 1);
	$far
}
CSG
cat >tee.csg <<CSG
difference() {
	linear_extrude(height = 1, center = false, convexity = 1, scale = [1, 1], \$fn = 0, \$fa = 12, \$fs = 2) polygon(points = [[0, 0], [1, 1], [0, 2], [1, 3], [0, 4]], paths = undef, convexity = 1);
	$far
}
CSG
cat >tee-revolve.csg <<CSG
difference() {
	rotate_extrude(angle = 180, convexity = 1, \$fn = 12, \$fa = 12, \$fs = 2) polygon(points = [[0, 0], [1, 1], [0, 2], [1, 3], [0, 4]], paths = undef, convexity = 1);
	$far
}
CSG
cat >hole-touch.csg <<CSG
difference() {
	linear_extrude(height = 1, center = false, convexity = 1, scale = [1, 1], \$fn = 0, \$fa = 12, \$fs = 2) polygon(points = [[0, 0], [4, 0], [4, 4], [0, 4], [2, 0], [3, 1], [1, 1]], paths = [[0, 1, 2, 3], [4, 5, 6]], convexity = 1);
	$far
}
CSG
cat >mink-one.csg <<CSG
minkowski(convexity = 0) {
	linear_extrude(height = 1, center = false, convexity = 1, scale = [1, 1], \$fn = 0, \$fa = 12, \$fs = 2) {
		square(size = [1, 1], center = false);
		multmatrix([[1, 0, 0, 1], [0, 1, 0, 1], [0, 0, 1, 0], [0, 0, 0, 1]]) square(size = [1, 1], center = false);
	}
}
CSG
# The same pinched prism as an operand of an intersection, under hull()
# and under projection() (extruded): OpenSCAD's CGAL takes no Nef
# polyhedron of it, so the intersection is empty, and so are the hull and
# the projection, which took the cube alone, without a warning.
pinched_in_cube='intersection() {
		linear_extrude(height = 1, center = false, convexity = 1, scale = [1, 1], $fn = 0, $fa = 12, $fs = 2) {
			square(size = [1, 1], center = false);
			multmatrix([[1, 0, 0, 1], [0, 1, 0, 1], [0, 0, 1, 0], [0, 0, 0, 1]]) square(size = [1, 1], center = false);
		}
		cube(size = [2, 2, 2], center = false);
	}'
cat >hull-pinched.csg <<CSG
hull() {
	$pinched_in_cube
}
CSG
cat >projection-pinched.csg <<CSG
linear_extrude(height = 1, center = false, convexity = 1, scale = [1, 1], \$fn = 0, \$fa = 12, \$fs = 2) {
projection(cut = false, convexity = 0) {
	$pinched_in_cube
}
}
CSG
cat >mink-one-cut.csg <<CSG
difference() {
	minkowski(convexity = 0) {
		linear_extrude(height = 1, center = false, convexity = 1, scale = [1, 1], \$fn = 0, \$fa = 12, \$fs = 2) {
			square(size = [1, 1], center = false);
			multmatrix([[1, 0, 0, 1], [0, 1, 0, 1], [0, 0, 1, 0], [0, 0, 0, 1]]) square(size = [1, 1], center = false);
		}
	}
	$far
}
CSG
cat >hull-mink.csg <<CSG
hull() {
	minkowski(convexity = 0) {
		linear_extrude(height = 1, center = false, convexity = 1, scale = [1, 1], \$fn = 0, \$fa = 12, \$fs = 2) {
			square(size = [1, 1], center = false);
			multmatrix([[1, 0, 0, 1], [0, 1, 0, 1], [0, 0, 1, 0], [0, 0, 0, 1]]) square(size = [1, 1], center = false);
		}
	}
}
CSG
l_pts='[[0, 0, 0], [2, 0, 0], [2, 1, 0], [1, 1, 0], [1, 2, 0], [0, 2, 0], [0, 0, 1], [2, 0, 1], [2, 1, 1], [1, 1, 1], [1, 2, 1], [0, 2, 1]]'
l_sides='[11, 10, 9, 8, 7, 6], [6, 7, 1, 0], [7, 8, 2, 1], [8, 9, 3, 2], [9, 10, 4, 3], [10, 11, 5, 4], [11, 6, 0, 5]'
cat >spike.csg <<CSG
difference() {
	polyhedron(points = $l_pts, faces = [[0, 1, 2, 3, 0, 3, 4, 5], $l_sides], convexity = 1);
	$far
}
CSG
cat >spike-convex.csg <<CSG
difference() {
	polyhedron(points = [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]], faces = [[0, 1, 2, 0, 2, 3], [4, 5, 1, 0], [7, 6, 5, 4], [5, 6, 2, 1], [6, 7, 3, 2], [7, 4, 0, 3]], convexity = 1);
	$far
}
CSG
cat >opposite.csg <<CSG
difference() {
	polyhedron(points = [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1], [3, 0, 0], [4, 0, 0], [4, 1, 0], [3, 1, 0], [3, 0, 1], [4, 0, 1], [4, 1, 1], [3, 1, 1]], faces = [[0, 1, 2, 3], [4, 5, 1, 0], [7, 6, 5, 4], [5, 6, 2, 1], [6, 7, 3, 2], [7, 4, 0, 3], [11, 10, 9, 8], [8, 9, 13, 12], [12, 13, 14, 15], [9, 10, 14, 13], [10, 11, 15, 14], [11, 8, 12, 15]], convexity = 1);
	$far
}
CSG
# A square with a triangular hole at its corner, scaled to a point: the
# hole's walls and the square's meet along the edge from (0, 0, 0) to
# the apex. OpenSCAD appends the bottom cap before the walls, so CGAL's
# builder skips walls there and leaves borders ("not closed"); with the
# walls first it would skip the cap and leave a point unused ("invalid").
cat >hole-corner.csg <<CSG
difference() {
	linear_extrude(height = 3, center = false, convexity = 1, scale = [0, 0], \$fn = 0, \$fa = 12, \$fs = 2) {
		polygon(points = [[0, 0], [10, 0], [10, 10], [0, 10], [0, 0], [3, 1], [1, 3]], paths = [[0, 1, 2, 3], [4, 5, 6]], convexity = 1);
	}
	$far
}
CSG
# Cubes with a face out of its plane. OpenSCAD builds CGAL's Nef
# polyhedron from the faces as they are; CGAL checks each face's points
# against its plane, corner by corner, and OpenSCAD triangulates and tries
# again only when the first check to fail is the one for the point after
# the corner. With CGAL 5, where another check fails first (here, at the
# last face about the first corner CGAL meets out of a plane), the solid is
# lost. The first is OpenSCAD's own test model polyhedron-nonplanar-tests'
# second cube (which it also finds not convex: its side folds inward
# between the triangles it makes of it); the second is tried again.
cube_faces='[[3, 2, 1, 0], [7, 6, 5, 4], [0, 1, 6, 7], [1, 2, 5, 6], [2, 3, 4, 5], [3, 0, 7, 4]]'
cat >plane-lost.csg <<CSG
difference() {
	polyhedron(points = [[0, 0, 1], [1, 0.2, 1], [1, 1, 1], [0, 1, 1], [0, 1, 0], [1, 1, 0], [1, 0, 0], [0, 0, 0]], faces = $cube_faces, convexity = 1);
	$far
}
CSG
cat >plane-kept.csg <<CSG
difference() {
	polyhedron(points = [[-0.2, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1], [0, 1, 0], [1, 1, 0], [1, 0, 0], [0, 0, 0]], faces = $cube_faces, convexity = 1);
	$far
}
CSG
# A box with its top out of its plane, in a union: as written, OpenSCAD
# finds it not convex and CGAL's check fails at point 4 (the solid is
# lost); rotated or mirrored, OpenSCAD moves its points first
# (PolySet::transform), its tessellation splits the top on the other
# diagonal, it is convex and kept.
box_points='[[0, 0, 0], [5.5, 0, 0], [5.5, 5.17, 0], [0, 5.17, 0], [0, 0, 7.31], [5.5, 0, 6.34], [5.5, 5.17, 7.31], [0, 5.17, 6.71]]'
box_faces='[[0, 1, 2, 3], [4, 5, 1, 0], [7, 6, 5, 4], [5, 6, 2, 1], [6, 7, 3, 2], [7, 4, 0, 3]]'
for moved in "lost group()" \
    "turned multmatrix([[0, -1, 0, 0], [1, 0, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]])" \
    "mirrored multmatrix([[1, 0, 0, 0], [0, -1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]])"; do
    cat >"box-${moved%% *}.csg" <<CSG
union() {
	${moved#* } {
		polyhedron(points = $box_points, faces = $box_faces, convexity = 1);
	}
	$far
}
CSG
done
# The box as written beside a child that is no solid, which OpenSCAD's
# union leaves out (applyToChildren3D's actual children): an empty cube, a
# 2D square, and operations whose geometry is empty: a group of an empty
# cube, a difference whose first child is one, an extrusion of an empty
# square, a revolution of a circle of no radius. The union has one solid,
# which it passes on as it is: no CGAL operation takes the box, and it is
# drawn.
for other in "empty cube(size = [0, 1, 1], center = false);" \
    "2d square(size = [1, 1], center = false);" \
    "group group() { cube(size = [0, 1, 1], center = false); }" \
    "diff difference() { cube(size = [1, 0, 1], center = false); cube(size = [1, 1, 1], center = false); }" \
    "extrude linear_extrude(height = 1, center = false, convexity = 1, scale = [1, 1], \$fn = 0, \$fa = 12, \$fs = 2) { square(size = [0, 1], center = false); }" \
    "revolve rotate_extrude(angle = 360, convexity = 1, \$fn = 0, \$fa = 12, \$fs = 2) { group() { circle(r = 0); } }"; do
    cat >"box-${other%% *}.csg" <<CSG
union() {
	polyhedron(points = $box_points, faces = $box_faces, convexity = 1);
	${other#* }
}
CSG
done
# A cube a tenth wide at x = 0.3 in a difference: OpenSCAD snaps its
# corners to its grid of 2^-20 where the translation puts them, before
# CGAL takes them, so the box runs from trunc(0.3 * 2^20) / 2^20 =
# 0.29999924 to 0.39999962, and up to 0.09999943.
cat >snapped.csg <<CSG
difference() {
	multmatrix([[1, 0, 0, 0.3], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {
		cube(size = [0.1, 0.1, 0.1], center = false);
	}
	$far
}
CSG
# The same cube in a difference under hull(): OpenSCAD makes a Nef
# polyhedron of the difference's operands, and the hull is empty. (A
# minkowski() of it alone takes it as convex, on its whole faces.)
cat >plane-hull.csg <<CSG
hull() {
	difference() {
		polyhedron(points = [[0, 0, 1], [1, 0.2, 1], [1, 1, 1], [0, 1, 1], [0, 1, 0], [1, 1, 0], [1, 0, 0], [0, 0, 0]], faces = $cube_faces, convexity = 1);
		$far
	}
}
CSG
cat >plane-mink.csg <<CSG
minkowski() {
	polyhedron(points = [[0, 0, 1], [1, 0.2, 1], [1, 1, 1], [0, 1, 1], [0, 1, 0], [1, 1, 0], [1, 0, 0], [0, 0, 0]], faces = $cube_faces, convexity = 1);
	cube(size = [0.1, 0.1, 0.1], center = false);
}
CSG
# An L-shaped prism of quads with one corner lowered, as an OFF file (its
# faces turned outward, which OpenSCAD hands to CGAL back to front).
printf 'OFF\n12 10 0\n0 0 0\n2 0 0\n2 1 0\n1 1 0\n1 2 0\n0 2 0\n0 0 1\n2 0 1\n2 1 1\n1 1 1\n1 2 1\n0 2 0.7\n4 3 2 1 0\n4 5 4 3 0\n4 7 8 9 6\n4 9 10 11 6\n4 0 1 7 6\n4 1 2 8 7\n4 2 3 9 8\n4 3 4 10 9\n4 4 5 11 10\n4 5 0 6 11\n' >plane.off
cat >plane-off.csg <<CSG
difference() {
	import(file = "plane.off", layer = "", origin = [0, 0], scale = 1, convexity = 1, \$fn = 0, \$fa = 12, \$fs = 2, timestamp = 0);
	$far
}
CSG
cat >mink-dup.csg <<CSG
minkowski(convexity = 0) {
	polyhedron(points = $l_pts, faces = [[0, 1, 2, 3, 4, 5], $l_sides, [2, 3, 9, 8]], convexity = 1);
	cube(size = [0.1, 0.1, 0.1], center = false);
}
CSG
# The L as an STL file (each face fanned from a point that sees all of it,
# turned outward as STL's are), its first triangle given twice: CGAL's
# builder skips the second copy, and OpenSCAD's minkowski takes the rest.
python3 - "$l_pts" "[[0, 1, 2, 3, 4, 5], [6, 11, 10, 9, 8, 7], ${l_sides#*], }]" <<'PY' >dup.stl
import json, sys
pts, faces = json.loads(sys.argv[1]), json.loads(sys.argv[2])
tris = [(f[0], f[i + 1], f[i]) for f in faces for i in range(1, len(f) - 1)]
print('solid dup')
for t in tris + tris[:1]:
    print(' facet normal 0 0 0\n  outer loop')
    for i in t:
        print('   vertex %g %g %g' % tuple(pts[i]))
    print('  endloop\n endfacet')
print('endsolid dup')
PY
cat >mink-dup-stl.csg <<CSG
minkowski(convexity = 0) {
	import(file = "dup.stl", layer = "", origin = [0, 0], scale = 1, convexity = 1, \$fn = 0, \$fa = 12, \$fs = 2, timestamp = 0);
	cube(size = [0.1, 0.1, 0.1], center = false);
}
CSG
printf 'OFF\n8 7 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n4 0 1 2 3\n4 4 5 1 0\n4 7 6 5 4\n4 5 6 2 1\n4 6 7 3 2\n4 7 4 0 3\n4 0 1 2 3\n' >twice.off
cat >off-twice.csg <<CSG
difference() {
	import(file = "twice.off", layer = "", origin = [0, 0], scale = 1, convexity = 1, \$fn = 0, \$fa = 12, \$fs = 2, timestamp = 0);
	$far
}
CSG
# A face whose first point comes again at its end: CGAL's builder takes
# it on the tetrahedron (and OpenSCAD draws it), and on the cube one of
# its assertions fails (OpenSCAD stops).
printf 'OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n4 0 2 1 0\n3 0 1 3\n3 1 2 3\n3 0 3 2\n' >ends.off
printf 'OFF\n8 6 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n5 6 2 3 7 6\n4 3 0 4 7\n' >stops.off
for off in ends stops; do
    sed "s/twice.off/$off.off/" off-twice.csg >off-$off.csg
done

# file, points, faithful answers, first line of the faithful stderr, what
# openscad prints (a pattern, or "" for no ERROR line)
not_closed='The given mesh is not closed! Unable to convert to CGAL_Nef_Polyhedron.'
assertion='CGAL error in CGAL_Nef_polyhedron3(): CGAL ERROR: assertion violation!'
builder_cases=(
    "twice.csg|0.5,0.5,0.5|in||"
    "twice-rev.csg|0.5,0.5,0.5|in||"
    "tets-edge.csg|0.1,0.1,0.3|out|tets-edge.csg:2:2: warning: polyhedron is invalid (no face CGAL takes uses point 4); left out, as OpenSCAD leaves it out (\"The given mesh is invalid! Unable to convert to CGAL_Nef_Polyhedron.\")|^ERROR: The given mesh is invalid"
    "tee.csg|0.3,1,0.5|out|tee.csg:2:2: warning: linear_extrude is not closed (its cap's edge (0, 4, 0)-(0, 0, 0) passes through its point (0, 2, 0), where OpenSCAD's tessellation splits the cap but not the side); left out, as OpenSCAD leaves it out (\"$not_closed\")|^ERROR: The given mesh is not closed"
    "tee-revolve.csg|0.1,0.1,0.3|out|tee-revolve.csg:2:2: warning: rotate_extrude is not closed (its cap's edge (0, 0, 4)-(0, 0, 0) passes through its point (0, 0, 2), where OpenSCAD's tessellation splits the cap but not the side); left out, as OpenSCAD leaves it out (\"$not_closed\")|^ERROR: The given mesh is not closed"
    "hole-touch.csg|3.5,3.5,0.5|out|hole-touch.csg:2:2: warning: linear_extrude is not closed (its cap's edge (0, 0, 0)-(4, 0, 0) passes through its point (2, 0, 0), where OpenSCAD's tessellation splits the cap but not the side); left out, as OpenSCAD leaves it out (\"$not_closed\")|^ERROR: The given mesh is not closed"
    "mink-one.csg|1.5,1.5,0.5|in||"
    "hull-mink.csg|1.2,0.5,0.5|in||"
    "spike.csg|0.5,0.5,0.5|out|spike.csg:2:2: warning: polyhedron is not closed (a face passes through point 0 twice, and CGAL's builder skips it); left out, as OpenSCAD leaves it out (\"$not_closed\")|^ERROR: The given mesh is not closed"
    "spike-convex.csg|0.5,0.5,0.5|in||"
    "mink-dup.csg|1.5,1.05,1.05|in||"
    "plane-lost.csg|0.5,0.5,0.5|out|plane-lost.csg:2:2: warning: polyhedron has a face out of its plane at point 1 (CGAL's assertion ss_circle.has_on(sp_0) fails there, and OpenSCAD does not triangulate and try again); left out, as OpenSCAD leaves it out (\"$assertion\")|^ERROR: $assertion"
    "plane-kept.csg|0.5,0.5,0.5|in||"
    "box-lost.csg|2.5,2.5,1|out|box-lost.csg:3:3: warning: polyhedron has a face out of its plane at point 4 (CGAL's assertion ss_circle.has_on(sp_0) fails there, and OpenSCAD does not triangulate and try again); left out, as OpenSCAD leaves it out (\"$assertion\")|^ERROR: $assertion"
    "box-turned.csg|-2.5,2.5,1|in||"
    "box-mirrored.csg|2.5,-2.5,1|in||"
    "snapped.csg|0.2999995,0.05,0.05|in||"
    "snapped.csg|0.3999998,0.05,0.05|out||"
    "snapped.csg|0.35,0.05,0.0999997|out||"
    "snapped.csg|0.35,0.05,0.0999993|in||"
    "box-empty.csg|2.5,2.5,1|in|box-empty.csg:3:2: warning: cube with a zero, negative or non-finite size is empty|"
    "box-2d.csg|2.5,2.5,1|in|box-2d.csg:3:2: warning: Mixing 2D and 3D objects is not supported|"
    "box-group.csg|2.5,2.5,1|in|box-group.csg:3:12: warning: cube with a zero, negative or non-finite size is empty|"
    "box-diff.csg|2.5,2.5,1|in|box-diff.csg:3:17: warning: cube with a zero, negative or non-finite size is empty|"
    "box-extrude.csg|2.5,2.5,1|in|box-extrude.csg:3:2: warning: linear_extrude without height or area is empty|"
    "box-revolve.csg|2.5,2.5,1|in|box-revolve.csg:3:2: warning: rotate_extrude without area is empty|"
    "plane-hull.csg|0.5,0.5,0.5|out|plane-hull.csg:3:3: warning: polyhedron has a face out of its plane at point 1 (CGAL's assertion ss_circle.has_on(sp_0) fails there, and OpenSCAD does not triangulate and try again); left out, as OpenSCAD leaves it out (\"$assertion\")|^ERROR: $assertion"
    "plane-mink.csg|0.95,0.1,0.5|in||"
    "plane-off.csg|0.5,0.5,0.5|out|plane-off.csg:2:16: warning: imported mesh has a face out of its plane at (0, 0, 1) (CGAL's assertion ss_circle.has_on(sp_0) fails there, and OpenSCAD does not triangulate and try again); left out, as OpenSCAD leaves it out (\"$assertion\")|^ERROR: $assertion"
    "hole-corner.csg|5,5,0.5|out|hole-corner.csg:2:2: warning: linear_extrude is not closed (edge (0, 0, 0)-(0, 0, 3) is used by 4 faces); left out, as OpenSCAD leaves it out (\"$not_closed\")|^ERROR: The given mesh is not closed"
    "mink-dup-stl.csg|1.5,1.05,1.05|in||"
    "opposite.csg|0.5,0.5,0.5|in||"
    "opposite.csg|3.5,0.5,0.5|in||"
    "hull-pinched.csg|1.5,0.5,0.5|out|hull-pinched.csg:3:3: warning: linear_extrude is not closed (edge (1, 1, 0)-(1, 1, 1) is used by 4 faces); left out, as OpenSCAD leaves it out (\"$not_closed\")|^ERROR: The given mesh is not closed"
    "projection-pinched.csg|1.5,0.5,0.5|out|projection-pinched.csg:4:3: warning: linear_extrude is not closed (edge (1, 1, 0)-(1, 1, 1) is used by 4 faces); left out, as OpenSCAD leaves it out (\"$not_closed\")|^ERROR: The given mesh is not closed"
    "mink-one-cut.csg|1.5,1.5,0.5|out|mink-one-cut.csg:3:3: warning: linear_extrude is not closed (edge (1, 1, 0)-(1, 1, 1) is used by 4 faces); left out, as OpenSCAD leaves it out (\"$not_closed\")|^ERROR: The given mesh is not closed"
    "off-twice.csg|0.5,0.5,0.5|out|off-twice.csg:2:16: warning: import: 'twice.off' is not a mesh CGAL's OFF reader takes (line 17: face 7: CGAL's builder says \"facet 6 shares a halfedge from vertex 0 to vertex 1 with facet 0\"); the import is empty, as OpenSCAD reads nothing from it (--strict makes it an error)|input error: facet 6 shares a halfedge"
    "off-ends.csg|0.1,0.1,0.1|in||"
)
for case in "${builder_cases[@]}"; do
    IFS='|' read -r file point want warning openscad_says <<<"$case"
    expect 0 "$warning" inside "$file" --faithful --point="$point"
    [ "$(cat out.txt)" = "$want" ] || fail "$file (faithful) at $point: $(cat out.txt), want $want"
    command -v openscad >/dev/null || continue
    check
    openscad -o "$PWD/${file%.csg}_os.stl" "$file" >/dev/null 2>"${file%.csg}_os.err"
    if [ -n "$openscad_says" ]; then
        grep -q "$openscad_says" "${file%.csg}_os.err" ||
            fail "openscad on $file: $(cat "${file%.csg}_os.err")"
    elif grep -q '^ERROR' "${file%.csg}_os.err" || [ ! -s "${file%.csg}_os.stl" ]; then
        fail "openscad on $file: $(cat "${file%.csg}_os.err")"
    fi
done
# A minkowski() of an L-shaped prism whose quads are out of their planes:
# OpenSCAD's Nef polyhedron of it (not convex) is made of the triangles
# its tessellation makes, on the diagonals it chooses, and so must be the
# solid spancast splits into convex parts.
cat >mink-plane.csg <<'CSG'
minkowski(convexity = 0) {
	polyhedron(points = [[0, 0, 0], [2, 0, 0], [2, 0.95, 0], [1, 1, 0], [1, 2, 0], [0, 2, 0], [0, 0, 1], [2, 0, 1], [2.05, 1, 1], [1, 1, 1], [1, 2, 1], [0, 2, 1]], faces = [[0, 1, 2, 3], [0, 3, 4, 5], [6, 9, 8, 7], [6, 11, 10, 9], [6, 7, 1, 0], [7, 8, 2, 1], [8, 9, 3, 2], [9, 10, 4, 3], [10, 11, 5, 4], [11, 6, 0, 5]], convexity = 1);
	cube(size = [0.1, 0.1, 0.1], center = false);
}
CSG
if command -v openscad >/dev/null; then
    check
    # binary STL: the ASCII export's 6 digits move its points by up to
    # 5e-6
    openscad -o "$PWD/mink-plane_os.stl" --export-format binstl mink-plane.csg \
        >/dev/null 2>mink-plane_os.err
    "$bin" compare mink-plane.csg mink-plane_os.stl --faithful >out.txt 2>err.txt ||
        fail "mink-plane.csg is not openscad's solid: $(tail -n 9 out.txt)"
else
    fail "no openscad to check the minkowski of quads out of their planes with"
fi
# The two cubes of opposite winding in one polyhedron are both solid, as
# CGAL's Nef polyhedron of it keeps both (openscad's mesh reaches x = 4),
# in exact mode too; the spike (a face through a point twice, which a
# null ear hides) is drawn where nothing hands it to CGAL.
if command -v openscad >/dev/null; then
    check
    grep -q 'vertex 4 ' opposite_os.stl || fail "openscad drops the second cube of opposite.csg"
fi
expect 0 "" inside opposite.csg --point=0.5,0.5,0.5 --point=3.5,0.5,0.5 --point=2,0.5,0.5
[ "$(tr '\n' ' ' <out.txt)" = "in in out " ] || fail "opposite.csg (exact): $(tr '\n' ' ' <out.txt)"
expect 0 "" inside spike.csg --point=0.5,0.5,0.5
[ "$(cat out.txt)" = in ] || fail "spike.csg (exact): $(cat out.txt)"
# --strict makes the OFF reader's refusal the error; exact mode draws the
# file by the parity rule.
expect 1 "off-twice.csg:2:16: error: import: 'twice.off' is not a mesh CGAL's OFF reader takes (line 17: face 7: CGAL's builder says \"facet 6 shares a halfedge from vertex 0 to vertex 1 with facet 0\")" \
    inside off-twice.csg --faithful --strict --point=0.5,0.5,0.5
expect 0 "off-twice.csg:2:16: warning: imported mesh is not closed (edge (0, 0, 0)-(1, 0, 0) is used by 3 faces); rendered by the parity rule (--strict makes it an error)" \
    inside off-twice.csg --point=0.5,0.5,0.5
[ "$(cat out.txt)" = in ] || fail "off-twice.csg (exact): $(cat out.txt)"
# where CGAL's assertion fails, openscad stops: an error in --faithful
expect 1 "off-stops.csg:2:16: error: import: 'stops.off' is not a mesh CGAL's OFF reader takes (line 15: face 5: CGAL's assertion prev->is_border() fails, where OpenSCAD stops)" \
    inside off-stops.csg --faithful --point=0.5,0.5,0.5
if command -v openscad >/dev/null; then
    check
    # (in a shell of its own, which says "Aborted" where no one reads it)
    (
        openscad -o "$PWD/off-stops_os.stl" off-stops.csg >/dev/null 2>off-stops_os.err
        exit $?
    ) 2>/dev/null && fail "openscad rendered off-stops.csg"
    grep -q "prev->is_border()" off-stops_os.err || fail "openscad on off-stops.csg: $(cat off-stops_os.err)"
fi

# A minkowski() whose operand CGAL's convex decomposition fails on (a loft
# from a triangle to a square, its quads out of their planes): OpenSCAD's
# own sum and its fallback, CGAL's minkowski_sum_3, both throw, and it
# keeps the sum so far, with an error in its log but an STL written. The
# first child as it is (the decomposition of the first or the second
# fails), else the sum of the children before the one that failed; a hull
# of such a minkowski hulls what it keeps.
loft='polyhedron(points = [[7, 0, 0], [4.37524, 1.51486, 0], [1.75047, 3.02973, 0], [-0.874293, 4.54459, 0], [-3.49906, 6.05946, 0], [-3.5, 3.03054, 0], [-3.5, 8.88178e-16, 0], [-3.5, -3.03054, 0], [-3.49906, -6.05946, 0], [-0.874293, -4.54459, 0], [1.75047, -3.02973, 0], [4.37524, -1.51486, 0], [0.5, -3, 4], [1.18762, -2.24257, 4], [1.87524, -1.48514, 4], [2.56285, -0.727704, 4], [1.25047, 2.02973, 4], [1.25, 2.51527, 4], [1.25, 3, 4], [-0.75, 1.48473, 4], [-2.74953, -0.0297278, 4], [-3.43715, 0.727704, 4], [-2.12476, -0.514864, 4], [-0.812382, -1.75743, 4], [-6, -6, 8], [-2, -6, 8], [2, -6, 8], [6, -6, 8], [6, -2, 8], [6, 2, 8], [6, 6, 8], [2, 6, 8], [-2, 6, 8], [-6, 6, 8], [-6, 2, 8], [-6, -2, 8]], faces = [[0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11], [35, 34, 33, 32, 31, 30, 29, 28, 27, 26, 25, 24], [12, 13, 1, 0], [13, 14, 2, 1], [14, 15, 3, 2], [15, 16, 4, 3], [16, 17, 5, 4], [17, 18, 6, 5], [18, 19, 7, 6], [19, 20, 8, 7], [20, 21, 9, 8], [21, 22, 10, 9], [22, 23, 11, 10], [23, 12, 0, 11], [24, 25, 13, 12], [25, 26, 14, 13], [26, 27, 15, 14], [27, 28, 16, 15], [28, 29, 17, 16], [29, 30, 18, 17], [30, 31, 19, 18], [31, 32, 20, 19], [32, 33, 21, 20], [33, 34, 22, 21], [34, 35, 23, 22], [35, 24, 12, 23]], convexity = 1);'
cat >mink-fail.csg <<CSG
minkowski(convexity = 0) {
	$loft
	cube(size = [0.1, 0.1, 0.1], center = false);
}
CSG
cat >mink-fail-third.csg <<CSG
minkowski(convexity = 0) {
	cube(size = [1, 1, 1], center = false);
	sphere(\$fn = 8, \$fa = 12, \$fs = 2, r = 1);
	$loft
}
CSG
cat >mink-fail-hull.csg <<CSG
hull() {
	minkowski(convexity = 0) {
		$loft
		cube(size = [0.1, 0.1, 0.1], center = false);
	}
}
CSG
failed="minkowski: CGAL failed on 'polyhedron': CGAL ERROR: assertion violation!"
# inside m, and inside the sum but not m (x is at most 7 in m)
expect 0 "mink-fail.csg:2:2: warning: $failed" inside mink-fail.csg --faithful \
    --point=0,0,2 --point=7.05,0.05,0.05
[ "$(tr '\n' ' ' <out.txt)" = "in out " ] || fail "mink-fail.csg: $(tr '\n' ' ' <out.txt)"
grep -q 'the result is its first child alone, as OpenSCAD keeps it' err.txt ||
    fail "mink-fail.csg: $(cat err.txt)"
expect 0 "mink-fail.csg:2:2: warning: $failed" inside mink-fail.csg --point=7.05,0.05,0.05
[ "$(cat out.txt)" = out ] || fail "mink-fail.csg (exact): $(cat out.txt)"
expect 1 "mink-fail.csg:2:2: error: $failed" inside mink-fail.csg --faithful --strict \
    --point=0,0,2
expect 0 "mink-fail-third.csg:4:2: warning: $failed" inside mink-fail-third.csg \
    --faithful --point=-0.9,0.5,0.5
[ "$(cat out.txt)" = in ] || fail "mink-fail-third.csg: $(cat out.txt)"
grep -q 'the result is the sum of the children before it' err.txt ||
    fail "mink-fail-third.csg: $(cat err.txt)"
for m in mink-fail mink-fail-third mink-fail-hull; do
    command -v openscad >/dev/null || {
        fail "no openscad to check $m.csg with"
        continue
    }
    check
    openscad -o "$PWD/${m}_os.stl" --export-format binstl $m.csg >/dev/null 2>${m}_os.err
    grep -q '^ERROR: CGAL error in CGALUtils::applyBinaryOperator UNKNOWN' ${m}_os.err ||
        fail "openscad on $m.csg: $(cat ${m}_os.err)"
    "$bin" compare $m.csg ${m}_os.stl --faithful >out.txt 2>err.txt ||
        fail "$m.csg is not openscad's solid: $(tail -n 9 out.txt)"
done

# OpenSCAD's minkowski puts each mesh operand on its 2^-20 grid, each
# coordinate towards zero, in the minkowski's own frame; at unit scale
# that moves the solid by 1.6e-6 of its volume (CGAL's exact volumes).
# Two children, three (the sum of the first two is put on the grid too),
# under a transform, under a hull, in a difference.
sphere8='sphere($fn = 8, $fa = 12, $fs = 2, r = 1);'
cube1='cube(size = [1, 1, 1], center = false);'
printf 'minkowski(convexity = 0) {\n\t%s\n\t%s\n}\n' "$cube1" "$sphere8" >grid-two.csg
printf 'minkowski(convexity = 0) {\n\t%s\n\t%s\n\tcylinder($fn = 6, $fa = 12, $fs = 2, h = 0.7, r1 = 0.3, r2 = 0.3, center = false);\n}\n' "$cube1" "$sphere8" >grid-three.csg
printf 'multmatrix([[0.8660254037844387, -0.5, 0, 0.3], [0.5, 0.8660254037844387, 0, -0.2], [0, 0, 1, 0.1], [0, 0, 0, 1]]) {\n\tminkowski(convexity = 0) {\n\t\tmultmatrix([[1, 0, 0, -0.3], [0, 1, 0, 0.45], [0, 0, 1, 0], [0, 0, 0, 1]]) %s\n\t\t%s\n\t}\n}\n' "$cube1" "$sphere8" >grid-turned.csg
printf 'hull() {\n\tminkowski(convexity = 0) {\n\t\t%s\n\t\t%s\n\t}\n\tmultmatrix([[1, 0, 0, 3], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) cube(size = [0.5, 0.5, 0.5], center = false);\n}\n' "$cube1" "$sphere8" >grid-hull.csg
printf 'difference() {\n\tminkowski(convexity = 0) {\n\t\t%s\n\t\t%s\n\t}\n\tcube(size = [1, 1, 5], center = true);\n}\n' "$cube1" "$sphere8" >grid-cut.csg
for m in grid-two grid-three grid-turned grid-hull grid-cut; do
    command -v openscad >/dev/null || {
        fail "no openscad to check $m.csg with"
        continue
    }
    check
    openscad -o "$PWD/${m}_os.stl" --export-format binstl $m.csg >/dev/null 2>&1 ||
        fail "openscad on $m.csg failed"
    "$bin" compare $m.csg ${m}_os.stl --faithful >out.txt 2>err.txt ||
        fail "$m.csg is not openscad's solid: $(tail -n 9 out.txt)"
done

# OpenSCAD snaps a mesh's points to its 2^-20 grid only where it makes a
# Nef polyhedron of it: an STL cube of side 0.1 alone keeps its corners
# (openscad's export of it writes 0.1), in a difference they snap to
# 0.0999994 (the faithful bounds say which).
python3 - <<'PY'
corners = [(x, y, z) for x in (0, 0.1) for y in (0, 0.1) for z in (0, 0.1)]
quads = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
with open("tenth.stl", "w") as f:
    f.write("solid tenth\n")
    for q in quads:
        for t in ((q[0], q[1], q[2]), (q[0], q[2], q[3])):
            f.write(" facet normal 0 0 0\n  outer loop\n")
            for i in t:
                f.write("   vertex %r %r %r\n" % corners[i])
            f.write("  endloop\n endfacet\n")
    f.write("endsolid tenth\n")
PY
tenth='import(file = "tenth.stl", layer = "", origin = [0, 0], scale = 1, convexity = 1, $fn = 0, $fa = 12, $fs = 2, timestamp = 0);'
printf '%s\n' "$tenth" >tenth.csg
printf 'difference() {\n\t%s\n\t%s\n}\n' "$tenth" "$far" >tenth-cut.csg
for m in tenth:0.1 tenth-cut:0.0999994; do
    check
    got=$("$bin" info ${m%%:*}.csg --faithful 2>&1 | sed -n 's/^bounds: *//p')
    [ "$got" = "[0, 0, 0] to [${m#*:}, ${m#*:}, ${m#*:}]" ] || fail "${m%%:*}.csg (faithful): bounds $got"
done
if command -v openscad >/dev/null; then
    check
    openscad -o "$PWD/tenth_os.stl" tenth.csg >/dev/null 2>&1
    grep -q 'vertex 0.1 ' tenth_os.stl || fail "openscad snaps tenth.stl alone: $(grep -m1 vertex tenth_os.stl)"
fi

echo "$checks checks, $fails failed"
[ "$fails" = 0 ]
