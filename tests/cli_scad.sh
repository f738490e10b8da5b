# `spancast render model.scad`: conversion through OpenSCAD. The knob model
# (an imported STL, drilled) renders from its .scad exactly as from its
# .csg (relative imports resolve beside the source), the temporary
# directory is gone afterwards, a source OpenSCAD rejects gives OpenSCAD's
# last message, and without openscad in PATH the error says so. The
# conversion part is skipped (exit 77, reported as skipped) when openscad
# is missing; the missing-OpenSCAD message is checked either way.
#
# Run as: bash cli_scad.sh <path-to-spancast> <source-dir> <work-dir>
. "$(dirname "$0")/testlib.sh"
mkdir -p "$work/tmp"

# No OpenSCAD: a PATH without it.
printf 'cube(1);\n' >cube.scad
PATH=/nonexistent "$bin" render cube.scad -o none.png -q 2>err.txt
rc=$?
want="spancast: error: cannot convert 'cube.scad': OpenSCAD is not installed ('openscad' was not found in PATH)"
[ "$rc" = 1 ] || fail "without openscad: exit $rc (want 1)"
[ "$(cat err.txt)" = "$want" ] || fail "without openscad: got '$(cat err.txt)'"
[ -e none.png ] && fail "without openscad: an image was written"

require_tools openscad

export TMPDIR="$work/tmp"
"$bin" render "$src/models/knob_part.scad" -o scad.png --imgsize=96,96 --threads=1 -q ||
    fail "knob_part.scad did not render"
"$bin" render "$src/models/knob_part.csg" -o csg.png --imgsize=96,96 --threads=1 -q ||
    fail "knob_part.csg did not render"
cmp -s scad.png csg.png || fail "knob_part: .scad and .csg renders differ"
[ -z "$(ls -A "$work/tmp")" ] || fail "temporary files left: $(ls -A "$work/tmp")"

# fails_with MODEL MESSAGE: rendering MODEL exits 1 with MESSAGE alone on
# stderr and writes no image.
fails_with() {
    "$bin" render "$1" -o "$1.png" -q 2>err.txt
    local rc=$?
    [ "$rc" = 1 ] || fail "$1: exit $rc (want 1)"
    [ "$(cat err.txt)" = "$2" ] || fail "$1: got '$(cat err.txt)'"
    [ -e "$1.png" ] && fail "$1: an image was written"
}

printf 'cube(;\n' >bad.scad
fails_with bad.scad "bad.scad:1:1: error: Parser error: syntax error"

# OpenSCAD's first error at its own position: in an included file, a lexer
# error before the parser's, and from another directory a path relative to
# it (OpenSCAD 2021.01 gives no column); never the temporary file's name.
mkdir -p sub
printf 'size = 3;\n\nmodule part() {\n  cube(size)\n}\n}\n' >sub/part.scad
printf '// uses sub/part.scad\ninclude <sub/part.scad>\npart();\n' >main.scad
fails_with main.scad "sub/part.scad:5:1: error: Parser error: syntax error"
printf 'cube(1);\nname = "open;\n' >string.scad
(cd sub && "$bin" render ../string.scad -o ../string.png -q 2>../err.txt)
case "$(cat err.txt)" in
"../string.scad:"*": error: Parser error: Unterminated string") ;;
*) fail "string.scad: got '$(cat err.txt)'" ;;
esac
grep -q "spancast-\|\.csg" err.txt && fail "string.scad: a temporary name: $(cat err.txt)"
[ -e string.png ] && fail "string.scad: an image was written"
[ -z "$(ls -A "$work/tmp")" ] || fail "temporary files left after a failure"

# An error inside the converted model names the .csg beside the source.
printf 'import("open.stl");\n' >open.scad
printf 'solid o\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid o\n' >open.stl
"$bin" render open.scad -o open.png -q 2>err.txt
want="$work/open.csg:1:15: error: imported mesh is not closed (edge (0, 0, 0)-(0, 1, 0) is used by 1 face)"
[ "$(cat err.txt)" = "$want" ] || fail "open.scad: got '$(cat err.txt)'"
[ -e open.csg ] && fail "open.scad: a .csg was left beside the source"

if [ "$fails" != 0 ]; then
    echo "$fails failure(s)"
    exit 1
fi
echo "cli_scad: all checks passed"
