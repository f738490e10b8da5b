# The input forms every command takes as MODEL, without OpenSCAD:
# hand-written .csg in OpenSCAD's grammar (a node with one child and no
# braces, bare blocks, empty statements, modifiers in front of children)
# renders byte for byte as the braced model; a mesh (.stl, ASCII and
# binary, .off, .amf, .3mf) is the model that imports it, in render, info, measure,
# overlaps, compare, spans, inside, batch and under mpirun; bad input gets
# its position and exit 1. (tests/cli_scad.sh checks what needs OpenSCAD:
# .csg files beyond its CSG export, -D.)
#
# Run as: bash cli_input.sh <path-to-spancast> <source-dir> <work-dir>
. "$(dirname "$0")/testlib.sh"
# lib3mf 1.8 leaves libzip's allocations behind on every 3MF read; under the
# sanitizers they are suppressed by library name (spancast's own are still
# reported), and the list of suppressions used is kept off stderr.
export LSAN_OPTIONS="suppressions=$src/tests/imports.lsan-suppressions:print_suppressions=0${LSAN_OPTIONS:+:$LSAN_OPTIONS}"
opts=(--imgsize=80,60 --threads=1 -q)

# same_render A B: A and B render to identical colour, mask and depth.
same_render() {
    check
    "$bin" render "$1" -o a.png --mask=a-mask.png --depth=a-depth.exr "${opts[@]}" \
        2>a.err || fail "$1 did not render: $(cat a.err)"
    "$bin" render "$2" -o b.png --mask=b-mask.png --depth=b-depth.exr "${opts[@]}" \
        2>b.err || fail "$2 did not render: $(cat b.err)"
    for out in .png -mask.png -depth.exr; do
        cmp -s "a$out" "b$out" || fail "$1 and $2: a$out and b$out differ"
    done
    rm -f a.png a-mask.png a-depth.exr b.png b-mask.png b-depth.exr
}

# ---- item 6: OpenSCAD's grammar without braces ----

m='[[1, 0, 0, 2], [0, 0.707107, -0.707107, 0], [0, 0.707107, 0.707107, 0], [0, 0, 0, 1]]'
printf 'multmatrix(%s) cube(1);\n' "$m" >one.csg
printf 'multmatrix(%s) {\n\tcube(1);\n}\n' "$m" >one-braced.csg
same_render one.csg one-braced.csg

printf 'color("red", 0.5) sphere(5);\n' >color.csg
printf 'color("red", 0.5) {\n\tsphere(5);\n}\n' >color-braced.csg
same_render color.csg color-braced.csg

# Nested, in a difference, with modifiers in front of child statements,
# bare blocks and empty statements.
cat >nested.csg <<EOF
difference() {
    multmatrix($m) color([0, 0, 1, 1]) cube(2, center = true);;
    { multmatrix([[1, 0, 0, 2], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]])
        cylinder(h = 4, r1 = 0.5, r2 = 0.5, center = true); }
    *sphere(3);
    ;
}
%multmatrix([[1, 0, 0, -3], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) sphere(1);
{}
EOF
cat >nested-braced.csg <<EOF
difference() {
    multmatrix($m) {
        color([0, 0, 1, 1]) {
            cube(2, center = true);
        }
    }
    multmatrix([[1, 0, 0, 2], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {
        cylinder(h = 4, r1 = 0.5, r2 = 0.5, center = true);
    }
    *sphere(3);
}
%multmatrix([[1, 0, 0, -3], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {
    sphere(1);
}
EOF
same_render nested.csg nested-braced.csg
check
"$bin" info nested.csg | tail -n +2 >a.txt
"$bin" info nested-braced.csg | tail -n +2 >b.txt
cmp -s a.txt b.txt || fail "info: nested.csg and nested-braced.csg differ: $(diff a.txt b.txt)"
opts_preview=(--preview)
"$bin" render nested.csg -o a.png "${opts[@]}" "${opts_preview[@]}" &&
    "$bin" render nested-braced.csg -o b.png "${opts[@]}" "${opts_preview[@]}" &&
    cmp -s a.png b.png || fail "--preview: nested.csg and nested-braced.csg differ"

# fails_with MODEL STATUS MESSAGE: info MODEL exits STATUS with MESSAGE
# alone on stderr.
fails_with() {
    check
    "$bin" info "$1" >/dev/null 2>err.txt
    local rc=$?
    [ "$rc" = "$2" ] || fail "$1: exit $rc (want $2)"
    [ "$(cat err.txt)" = "$3" ] || fail "$1: got '$(cat err.txt)', want '$3'"
}
printf 'multmatrix(%s)\n' "$m" >open-child.csg
fails_with open-child.csg 1 \
    "open-child.csg:2:1: error: expected ';', '{' or a child node after node 'multmatrix'"
printf 'group() {\n  multmatrix([]) }\n' >brace-child.csg
fails_with brace-child.csg 1 \
    "brace-child.csg:2:18: error: expected ';', '{' or a child node after node 'multmatrix'"
printf '{\n  cube(1);\n' >open-block.csg
fails_with open-block.csg 1 "open-block.csg:3:1: error: expected '}' (to close '{' at line 1)"
printf '#{ cube(1); }\n' >modifier-block.csg
fails_with modifier-block.csg 1 "modifier-block.csg:1:2: error: expected a node name before '{'"
# OpenSCAD ignores the children of a leaf, with a warning; so does spancast.
printf 'cube(1) sphere(2);\n' >leaf-child.csg
check
"$bin" info leaf-child.csg >/dev/null 2>err.txt || fail "leaf-child.csg did not load"
[ "$(cat err.txt)" = "leaf-child.csg:1:1: warning: module cube() does not support child modules" ] ||
    fail "leaf-child.csg: got '$(cat err.txt)'"

# OpenSCAD's language beyond the CSG export, without OpenSCAD: the note,
# then the missing OpenSCAD's error; nothing written.
printf 'cube(1);\nsize = 2;\ncube(size);\n' >language.csg
check
PATH=/nonexistent "$bin" render language.csg -o language.png -q 2>err.txt
rc=$?
want="language.csg: note: uses OpenSCAD's language beyond its CSG export (line 2); converting it with openscad
spancast: error: cannot convert 'language.csg': OpenSCAD is not installed ('openscad' was not found in PATH)"
[ "$rc" = 1 ] || fail "language.csg without openscad: exit $rc (want 1)"
[ "$(cat err.txt)" = "$want" ] || fail "language.csg without openscad: got '$(cat err.txt)'"
[ -e language.png ] && fail "language.csg without openscad: an image was written"

# ---- item 8: meshes as models ----

# A tetrahedron with corners (0,0,0), (2,0,0), (0,2,0), (0,0,2), outward.
tris=("0 0 0  0 2 0  2 0 0" "0 0 0  2 0 0  0 0 2" "0 0 0  0 0 2  0 2 0" "2 0 0  0 2 0  0 0 2")
{
    echo "solid tet"
    for t in "${tris[@]}"; do
        set -- $t
        printf ' facet normal 0 0 0\n  outer loop\n'
        printf '   vertex %s %s %s\n   vertex %s %s %s\n   vertex %s %s %s\n' "$@"
        printf '  endloop\n endfacet\n'
    done
    echo "endsolid tet"
} >tet.stl
# Binary: an 80-byte header, the count, and per triangle a normal, three
# corners (little-endian float32: 0 is 00000000, 2 is 00000040) and two
# attribute bytes.
f32() { [ "$1" = 0 ] && printf '\x00\x00\x00\x00' || printf '\x00\x00\x00\x40'; }
{
    printf '%80s' "binary tet"
    printf '\x04\x00\x00\x00'
    for t in "${tris[@]}"; do
        set -- $t
        f32 0; f32 0; f32 0
        for c in "$@"; do f32 "$c"; done
        printf '\x00\x00'
    done
} >tet-binary.stl
[ "$(stat -c %s tet-binary.stl)" = 284 ] || fail "tet-binary.stl has $(stat -c %s tet-binary.stl) bytes"
printf 'OFF\n4 4 0\n0 0 0\n2 0 0\n0 2 0\n0 0 2\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n' >tet.off
cp tet.stl TET-UPPER.STL
# AMF (one object) and 3MF (a zip holding one object), the same corners
# and triangles.
{
    printf '<?xml version="1.0" encoding="UTF-8"?>\n<amf unit="millimeter">\n'
    printf ' <object id="0"><mesh><vertices>\n'
    for v in "0 0 0" "2 0 0" "0 2 0" "0 0 2"; do
        set -- $v
        printf '  <vertex><coordinates><x>%s</x><y>%s</y><z>%s</z></coordinates></vertex>\n' "$@"
    done
    printf ' </vertices><volume>\n'
    for t in "0 2 1" "0 1 3" "0 3 2" "1 2 3"; do
        set -- $t
        printf '  <triangle><v1>%s</v1><v2>%s</v2><v3>%s</v3></triangle>\n' "$@"
    done
    printf ' </volume></mesh></object>\n</amf>\n'
} >tet.amf
python3 - "$src/tests" <<'PY'
import sys
sys.path.insert(0, sys.argv[1])
from meshfiles import threemf
threemf('tet.3mf', [([(0, 0, 0), (2, 0, 0), (0, 2, 0), (0, 0, 2)],
                     [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)])])
PY

for mesh in tet.stl tet-binary.stl tet.off TET-UPPER.STL tet.amf tet.3mf; do
    printf 'import(file = "%s");\n' "$mesh" >"import-$mesh.csg"
    same_render "$mesh" "import-$mesh.csg"
    for cmd in info measure overlaps; do
        check
        "$bin" $cmd "$mesh" -q 2>err.txt | tail -n +2 >a.txt
        [ "${PIPESTATUS[0]}" = 0 ] || fail "$cmd $mesh: exit ${PIPESTATUS[0]}: $(cat err.txt)"
        [ -s err.txt ] && fail "$cmd $mesh: stderr '$(cat err.txt)'"
        "$bin" $cmd "import-$mesh.csg" -q 2>/dev/null | tail -n +2 >b.txt
        cmp -s a.txt b.txt || fail "$cmd $mesh: differs from the import: $(diff a.txt b.txt)"
    done
    check
    "$bin" compare "$mesh" "import-$mesh.csg" --imgsize=40,30 -q >out.txt 2>&1 ||
        fail "compare $mesh import-$mesh.csg: $(cat out.txt)"
    check
    "$bin" inside "$mesh" --point=0.25,0.25,0.25 --point=2,2,2 >a.txt 2>&1 ||
        fail "inside $mesh: $(cat a.txt)"
    "$bin" inside "import-$mesh.csg" --point=0.25,0.25,0.25 --point=2,2,2 >b.txt 2>&1
    cmp -s a.txt b.txt || fail "inside $mesh: differs from the import"
    check
    # The same spans; each leaf is named by the file it was loaded from,
    # the mesh's without a position (it is the whole file), the import's
    # at the import.
    "$bin" spans "$mesh" --ray=0.3,0.3,-1,0,0,1 2>&1 | sed "s/@$mesh /@X /g" >a.txt
    "$bin" spans "import-$mesh.csg" --ray=0.3,0.3,-1,0,0,1 2>&1 |
        sed "s/@import-$mesh.csg:1:1 /@X /g" >b.txt
    grep -q "1 span" a.txt || fail "spans $mesh: $(cat a.txt)"
    cmp -s a.txt b.txt || fail "spans $mesh: differs from the import: $(diff a.txt b.txt)"
done
check
"$bin" measure tet.stl --json -q >a.txt || fail "measure tet.stl --json failed"
grep -q '"volume": {"value": 1.33333' a.txt || fail "measure tet.stl: the volume is not 4/3: $(cat a.txt)"

# batch: a mesh job.
printf 'render tet.stl -o batch.png --imgsize=80,60 --threads=1 -q\n' >jobs.txt
check
"$bin" batch jobs.txt >out.txt 2>&1 || fail "batch: $(cat out.txt)"
"$bin" render tet.stl -o one.png "${opts[@]}"
cmp -s batch.png one.png || fail "batch: the mesh job's image differs"

# A bad mesh: the error is the mesh file's, exit 1, nothing written.
printf 'solid bad\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex 1 0 0\n   vertex x 1 0\n' >bad.stl
check
"$bin" render bad.stl -o bad.png -q 2>err.txt
rc=$?
[ "$rc" = 1 ] || fail "bad.stl: exit $rc (want 1)"
want="bad.stl:6:1: error: import: '$work/bad.stl' is not a valid STL file (line 6: can't parse vertex line 'vertex x 1 0')"
[ "$(cat err.txt)" = "$want" ] || fail "bad.stl: got '$(cat err.txt)'"
[ -e bad.png ] && fail "bad.stl: an image was written"
printf 'OFF\n3 1 0\n0 0 0\n1 0 0\n' >bad.off
check
"$bin" info bad.off >/dev/null 2>err.txt
rc=$?
[ "$rc" = 1 ] || fail "bad.off: exit $rc (want 1)"
want_off="bad.off:4:1: error: import: '$work/bad.off' is not a valid OFF file (line 4: the file ends before point 3 of 3)"
[ "$(cat err.txt)" = "$want_off" ] || fail "bad.off: got '$(cat err.txt)'"
# on the file's first line too; a warning about the mesh as a whole has no
# position (it is not at a line)
printf 'OFF x\n' >bad1.off
check
"$bin" info bad1.off >/dev/null 2>err.txt && fail "bad1.off: exit 0"
want_off="bad1.off:1:1: error: import: '$work/bad1.off' is not a valid OFF file (line 1: the point count is not a number)"
[ "$(cat err.txt)" = "$want_off" ] || fail "bad1.off: got '$(cat err.txt)'"
# a count past an int, and a file that ends before its counts, say so
printf 'OFF\n4 3000000000 0\n' >big.off
printf 'OFF\n4 4\n' >short.off
for off in big short; do
    case $off in
    big) why="line 2: the face count is past the largest int" ;;
    short) why="line 2: the file ends before the edge count" ;;
    esac
    check
    "$bin" info $off.off >/dev/null 2>err.txt && fail "$off.off: exit 0"
    [ "$(cat err.txt)" = "$off.off:2:1: error: import: '$work/$off.off' is not a valid OFF file ($why)" ] ||
        fail "$off.off: got '$(cat err.txt)'"
done
# an AMF file's error is at its line too, as an STL or OFF file's
printf '<?xml version="1.0"?>\n<amf>\n<object id="0">\n<mesh><vertices><vertex><coordinates><x>1,5</x><y>0</y><z>0</z></coordinates></vertex></vertices></mesh>\n</object>\n</amf>\n' >bad.amf
check
"$bin" info bad.amf >/dev/null 2>err.txt && fail "bad.amf: exit 0"
[ "$(cat err.txt)" = "bad.amf:4:1: error: import: $work/bad.amf:4: '1,5' is not a number" ] ||
    fail "bad.amf: got '$(cat err.txt)'"
printf 'OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n' >open.off
check
"$bin" info open.off >/dev/null 2>err.txt || fail "open.off: exit $?"
[ "$(head -n 1 err.txt)" = "open.off: warning: imported mesh is not closed (edge (0, 0, 0)-(1, 0, 0) is used by 1 face); rendered by the parity rule (--strict makes it an error)" ] ||
    fail "open.off: got '$(cat err.txt)'"
fails_with missing.stl 1 "spancast: error: cannot open 'missing.stl': No such file or directory"
# OFF's variants, as CGAL's OFF reader (OpenSCAD's import) takes them: a
# colour (COFF), a normal (NOFF) or a homogeneous coordinate (4OFF) after
# each point, on the point's line; the same tetrahedron as tet.off.
off_faces='3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n'
printf "COFF\n4 4 6\n0 0 0 255 0 0 255\n2 0 0 255 0 0 255\n0 2 0 0.5 0.5 0.5 1\n0 0 2 1 1 1 1\n$off_faces" >tet-c.off
printf "NOFF\n4 4 6\n0 0 0 0 0 1\n2 0 0 0 0 1\n0 2 0 0 0 1\n0 0 2 0 0 1\n$off_faces" >tet-n.off
printf "4OFF\n4 4 6\n0 0 0 2\n4 0 0 2\n0 4 0 2\n0 0 1 0.5\n$off_faces" >tet-4.off
printf "CNOFF\n# the point's colour after its normal\n4 4 6\n0 0 0 0 0 1 1 0 0\n2 0 0 0 0 1 1 0 0\n0 2 0 0 0 1 1 0 0\n0 0 2 0 0 1 1 0 0\n$off_faces" >tet-cn.off
"$bin" info tet.off 2>&1 | grep '^bounds' >a.txt
for mesh in tet-c.off tet-n.off tet-4.off tet-cn.off; do
    check
    "$bin" info $mesh 2>err.txt | grep '^bounds' >b.txt
    [ -s err.txt ] && fail "$mesh: stderr '$(cat err.txt)'"
    cmp -s a.txt b.txt || fail "$mesh: $(cat b.txt), want $(cat a.txt)"
    command -v openscad >/dev/null || continue
    check
    printf 'import(file = "%s");\n' $mesh >import-$mesh.csg
    openscad -o "$PWD/$mesh.stl" --export-format binstl import-$mesh.csg >/dev/null 2>&1
    "$bin" compare $mesh $mesh.stl --faithful >out.txt 2>&1 ||
        fail "$mesh is not openscad's import: $(tail -n 9 out.txt)"
done
printf 'OFF BINARY\n' >binary.off
fails_with binary.off 1 "binary.off: error: import: '$work/binary.off' is not a valid OFF file (byte 11: the file ends before its counts)"

# ---- spancast-mpi: the same inputs, converted or read once by rank 0 ----
if command -v mpirun >/dev/null && [ -x "$(dirname "$bin")/spancast-mpi" ]; then
    export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
    for model in tet.stl tet-binary.stl tet.off nested.csg; do
        check
        "$bin" render "$model" -o one.png "${opts[@]}"
        mpirun_test -np 2 "$bin" render "$model" -o np2.png "${opts[@]}" >out.txt 2>&1 ||
            fail "mpirun $model: $(tail -n 5 out.txt)"
        cmp -s one.png np2.png || fail "mpirun $model: the image differs"
    done
    check
    mpirun_test -np 2 "$bin" render bad.stl -o bad.png -q >out.txt 2>&1
    grep -qF "$want" out.txt || fail "mpirun bad.stl: got '$(cat out.txt)'"
    [ "$(grep -c "error" out.txt)" = 1 ] || fail "mpirun bad.stl: not one error: $(cat out.txt)"
fi

# An output whose extension names no format spancast writes is a bad
# command line (exit 2, as --help says), refused before the model is read:
# the model here does not exist.
check
"$bin" render no-such-model.csg -o out.xyz -q 2>err.txt
rc=$?
[ "$rc" = 2 ] || fail "-o out.xyz: exit $rc (want 2)"
[ "$(cat err.txt)" = "spancast: error: cannot write 'out.xyz': unknown image format" ] ||
    fail "-o out.xyz: got '$(cat err.txt)'"
[ -e out.xyz ] && fail "-o out.xyz: a file was written"

if [ "$fails" != 0 ]; then
    echo "$fails failure(s) in $checks checks"
    exit 1
fi
echo "cli_input: all $checks checks passed"
