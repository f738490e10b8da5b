# `spancast render model.scad`: conversion through OpenSCAD. The knob model
# (an imported STL, drilled) renders from its .scad exactly as from its
# .csg (relative imports resolve beside the source), the temporary
# directory is gone afterwards, a source OpenSCAD rejects gives OpenSCAD's
# last message, and without openscad in PATH the error says so. The
# conversion part is skipped (exit 77, reported as skipped) when openscad
# is missing; the missing-OpenSCAD message is checked either way. A .csg
# beyond OpenSCAD's CSG export is converted the same way, with a note; -D
# passes through to OpenSCAD in every command and under mpirun.
#
# Run as: bash cli_scad.sh <path-to-spancast> <source-dir> <work-dir>
. "$(dirname "$0")/testlib.sh"
# Under the sanitizers the library suppresses fontconfig's one leak
# (build_text.c); the list of suppressions used is kept off stderr, which
# the text and font checks below read.
export LSAN_OPTIONS="print_suppressions=0${LSAN_OPTIONS:+:$LSAN_OPTIONS}"
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

# fails_with MODEL MESSAGE [OPTION]: rendering MODEL (with OPTION) exits 1
# with MESSAGE alone on stderr and writes no image.
fails_with() {
    "$bin" render "$1" -o "$1.png" -q ${3:+"$3"} 2>err.txt
    local rc=$?
    [ "$rc" = 1 ] || fail "$1: exit $rc (want 1)"
    [ "$(cat err.txt)" = "$2" ] || fail "$1: got '$(cat err.txt)'"
    [ -e "$1.png" ] && fail "$1: an image was written"
}

printf 'cube(;\n' >bad.scad
fails_with bad.scad "bad.scad:1:1: error: Parser error: syntax error"
# An error at the end of the source: OpenSCAD puts it on the line it
# appends (two past the end); it is the source's last line.
printf 'cube(5);\ntranslate([1, 2, 3]) sphere(2)\ncube(3)\n' >unended.scad
fails_with unended.scad "unended.scad:3:1: error: Parser error: syntax error at the end of the file"
printf 'cube(5);\nsphere(2)' >unended2.scad
fails_with unended2.scad "unended2.scad:2:1: error: Parser error: syntax error at the end of the file"

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
"../string.scad:2:1: error: Parser error: Unterminated string at the end of the file") ;;
*) fail "string.scad: got '$(cat err.txt)'" ;;
esac
grep -q "spancast-\|\.csg" err.txt && fail "string.scad: a temporary name: $(cat err.txt)"
[ -e string.png ] && fail "string.scad: an image was written"
[ -z "$(ls -A "$work/tmp")" ] || fail "temporary files left after a failure"

# An error inside the converted model names the .scad as the user gave it,
# with the line of OpenSCAD's export; never a .csg that does not exist.
printf 'import("open.stl");\n' >open.scad
printf 'solid o\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid o\n' >open.stl
fails_with open.scad "open.scad: error: imported mesh is not closed (edge (0, 0, 0)-(1, 0, 0) is used by 1 face) (line 1 of OpenSCAD's export)" --strict
[ -e open.csg ] && fail "open.scad: a .csg was left beside the source"
printf '\nresize([5, 5]) union() { square(1); square(1e14); }\n' >proj.scad
want="proj.scad: error: union: coordinates out of range (limit is 7.03687e+13) (line 2 of OpenSCAD's export)"
fails_with proj.scad "$want"
for cmd in info measure; do
    "$bin" $cmd proj.scad -q >/dev/null 2>err.txt
    rc=$?
    [ "$rc" = 1 ] || fail "$cmd proj.scad: exit $rc (want 1)"
    [ "$(cat err.txt)" = "$want" ] || fail "$cmd proj.scad: got '$(cat err.txt)'"
done

# OpenSCAD 2021.01 exits 0 after these errors and leaves the part out; its
# ERROR line fails the render all the same.
printf 'cube(1);\nassert(false, "boom");\n' >assert.scad
fails_with assert.scad "assert.scad:2:1: error: Assertion 'false' failed: \"boom\""
printf 'use <bad.scad>\ncube(1);\n' >usebad.scad
fails_with usebad.scad "bad.scad:1:1: error: Parser error: syntax error"

# warns_with MODEL MESSAGES: rendering MODEL exits 0, writes the image, and
# prints exactly MESSAGES on stderr.
warns_with() {
    rm -f "$1.png"
    "$bin" render "$1" -o "$1.png" -q 2>err.txt
    local rc=$?
    [ "$rc" = 0 ] || fail "$1: exit $rc (want 0)"
    [ "$(cat err.txt)" = "$2" ] || fail "$1: got '$(cat err.txt)'"
    [ -e "$1.png" ] || fail "$1: no image was written"
}
# Lines that end in CRLF: OpenSCAD 2021.01 counts a CRLF as one line in
# its parser's errors but as two in its other messages; both are put on
# the line an editor shows, in the source, in a library it uses and past
# its end on a -D setting.
printf 'cube(1);\r\ncube(1);\r\n\r\ncube(1) cube(;\r\n' >crlf_bad.scad
fails_with crlf_bad.scad "crlf_bad.scad:4:1: error: Parser error: syntax error"
printf 'cube(1);\r\n\r\ncube(1);\r\nassert(false);\r\n' >crlf_assert.scad
fails_with crlf_assert.scad "crlf_assert.scad:4:1: error: Assertion 'false' failed"
printf 'module w() {\r\n  cube(1);\r\n  sphere(foo = 1);\r\n}\r\n' >crlf_lib.scad
printf 'use <crlf_lib.scad>\r\n\r\ncube(bar = 1);\r\nw();\r\n' >crlf_warn.scad
warns_with crlf_warn.scad "crlf_warn.scad:3:1: warning: variable bar not specified as parameter
crlf_lib.scad:3:1: warning: variable foo not specified as parameter"
printf 'cube(x);\r\ncube(1);\r\n' >crlf_define.scad
"$bin" render crlf_define.scad -o crlf_define.png -q -D 'x=foo' 2>err.txt ||
    fail "crlf_define.scad: failed: $(cat err.txt)"
[ "$(cat err.txt)" = "<command-line>: warning: -D 'x=foo': Ignoring unknown variable 'foo'" ] ||
    fail "crlf_define.scad: got '$(cat err.txt)'"
# echo() output, as OpenSCAD prints it.
printf 'echo("hello", 42);\ncube(1);\necho(size = 3);\n' >echo.scad
warns_with echo.scad 'ECHO: "hello", 42
ECHO: size = 3'
# A string's line breaks, as OpenSCAD prints them: the message goes on
# after them, in echo() and in an assert()'s message, whose position
# follows them.
printf 'echo("a\\nb");\necho(x = "c\\nd", 1);\ncube(1);\n' >echo_lines.scad
warns_with echo_lines.scad 'ECHO: "a
b"
ECHO: x = "c
d", 1'
printf 'cube(1);\nassert(false, "one\\ntwo");\n' >assert_lines.scad
fails_with assert_lines.scad 'assert_lines.scad:2:1: error: Assertion '"'false'"' failed: "one
two"'
printf 'include <nope.scad>\ncube(1);\n' >noinc.scad
warns_with noinc.scad "noinc.scad: warning: Can't open include file 'nope.scad'."
# OpenSCAD's notes of a deprecated form are warnings too.
printf 'module m() child(0);\nm() cube(1);\n' >deprecated.scad
warns_with deprecated.scad "deprecated.scad: warning: child() will be removed in future releases. Use children() instead."
printf 'cube(1);\nfoo();\n' >unknown.scad
warns_with unknown.scad "unknown.scad:2:1: warning: Ignoring unknown module 'foo'"
# A use <font.ttf> of a file that is not there: OpenSCAD logs an error,
# goes on with fontconfig's match for the font's name and renders the
# model, so spancast warns and renders (with --strict, OpenSCAD's first
# warning is the error).
printf 'use <nofont.ttf>\ntext("Ab", font = "Liberation Sans");\n' >nofont.scad
warns_with nofont.scad "nofont.scad: warning: Can't open library 'nofont.ttf'.
nofont.scad: warning: Can't read font with path 'nofont.ttf'"
rm -f nofont.scad.png
fails_with nofont.scad "nofont.scad: error: Can't open library 'nofont.ttf'." --strict

# An empty model warns (the render goes on, as OpenSCAD's image export).
printf 'foo();\n' >onlyunknown.scad
warns_with onlyunknown.scad "onlyunknown.scad:1:1: warning: Ignoring unknown module 'foo'
onlyunknown.scad: warning: the model is empty (nothing to render)"
printf '// nothing\n' >empty.scad
warns_with empty.scad "empty.scad: warning: the model is empty (nothing to render)"
printf 'group();\n' >empty.csg
warns_with empty.csg "empty.csg: warning: the model is empty (nothing to render)"
[ -z "$(ls -A "$work/tmp")" ] || fail "temporary files left: $(ls -A "$work/tmp")"

# OpenSCAD gives the warnings of the arguments as it converts; the export's
# own (an alpha it folds into the colour, a component it warned of, the
# timestamp of an import) are not given again.
printf 'color([1.5, 0, 0]) sphere(3);\ncolor("red", alpha = 3) cube(1);\ncube(2, centre = true);\n' >args.scad
warns_with args.scad "args.scad:1:1: warning: color() expects numbers between 0.0 and 1.0. Value of 1.5 is out of range
args.scad:3:1: warning: variable centre not specified as parameter"
# With --strict the first of them is the error, as OpenSCAD's --hardwarnings
# makes it, in every command; nothing is written.
rm -f args.scad.png
fails_with args.scad "args.scad:1:1: error: color() expects numbers between 0.0 and 1.0. Value of 1.5 is out of range" --strict
"$bin" measure args.scad --strict -q >m.txt 2>err.txt
rc=$?
[ "$rc" = 1 ] || fail "measure --strict args.scad: exit $rc (want 1)"
grep -q "^args.scad:1:1: error: color() expects" err.txt || fail "measure --strict args.scad: $(cat err.txt)"
# OpenSCAD names the source in its warnings relative to the source's
# folder; spancast names it as the user did.
mkdir -p elsewhere
(cd elsewhere && "$bin" info ../unknown.scad >/dev/null 2>../err.txt) ||
    fail "info ../unknown.scad failed"
[ "$(cat err.txt)" = "../unknown.scad:2:1: warning: Ignoring unknown module 'foo'" ] ||
    fail "info ../unknown.scad: got '$(cat err.txt)'"
# A use'd library's warnings (and a library that one uses, beside it):
# OpenSCAD names their files relative to the source's folder too (from
# elsewhere/, "lib/sub/x.scad"); spancast names them from the working
# directory, where the user can open them, as OpenSCAD's parser errors
# already are.
mkdir -p lib/sub
printf 'use <y.scad>\nmodule m() { sphere(r = 1, d = 2); n(); }\n' >lib/sub/x.scad
printf 'module n() { cylinder(r = 1, d = 2, h = 1); }\n' >lib/sub/y.scad
printf 'use <lib/sub/x.scad>\nm();\n' >uselib.scad
(cd elsewhere && openscad -o ../uselib_os.csg ../uselib.scad >/dev/null 2>../os_err.txt) ||
    fail "openscad -o uselib_os.csg: exit $?"
grep -q "^WARNING: .* in file lib/sub/x.scad, line 2$" os_err.txt ||
    fail "OpenSCAD's warnings of uselib.scad: $(cat os_err.txt)"
(cd elsewhere && "$bin" info ../uselib.scad >/dev/null 2>../err.txt) ||
    fail "info ../uselib.scad failed"
[ "$(cat err.txt)" = "../lib/sub/x.scad:2:1: warning: Ignoring radius variable 'r' as diameter 'd' is defined too.
../lib/sub/y.scad:1:1: warning: Ignoring radius variable 'r' as diameter 'd' is defined too." ] ||
    fail "info ../uselib.scad: got '$(cat err.txt)'"
# OpenSCAD names a use'd library by its argument warnings relative to the
# library's own folder ("w.scad"): the library the source reaches, not a
# file of that name beside the source.
printf 'module lw() { cube(1, 2, 3); }\n' >lib/sub/w.scad
printf 'cube(5);\n' >w.scad
printf 'use <lib/sub/w.scad>\nlw();\n' >usew.scad
openscad -o usew_os.csg usew.scad >/dev/null 2>os_err.txt || fail "openscad -o usew_os.csg: exit $?"
grep -q "^WARNING: Too many unnamed arguments supplied in file w.scad, line 1$" os_err.txt ||
    fail "OpenSCAD's warnings of usew.scad: $(cat os_err.txt)"
"$bin" info usew.scad >/dev/null 2>err.txt || fail "info usew.scad failed"
[ "$(cat err.txt)" = "lib/sub/w.scad:1:1: warning: Too many unnamed arguments supplied" ] ||
    fail "info usew.scad: got '$(cat err.txt)'"
# A library OpenSCAD finds in an OPENSCADPATH folder, not beside the
# source: its warnings name that library, not a file of its name beside
# the source, nor a path that does not exist.
mkdir -p libpath/pw
printf 'module pw() { cube(1, 2, 3); }\n' >libpath/pw/w.scad
printf 'use <pw/w.scad>\npw();\n' >usepw.scad
OPENSCADPATH="$PWD/none:$PWD/libpath" openscad -o usepw_os.csg usepw.scad >/dev/null 2>os_err.txt ||
    fail "openscad -o usepw_os.csg: exit $?"
grep -q "^WARNING: Too many unnamed arguments supplied in file w.scad, line 1$" os_err.txt ||
    fail "OpenSCAD's warnings of usepw.scad: $(cat os_err.txt)"
OPENSCADPATH="$PWD/none:$PWD/libpath" "$bin" info usepw.scad >/dev/null 2>err.txt ||
    fail "info usepw.scad failed"
[ "$(cat err.txt)" = "$PWD/libpath/pw/w.scad:1:1: warning: Too many unnamed arguments supplied" ] ||
    fail "info usepw.scad: got '$(cat err.txt)'"

# Warnings at the converted text are put on the source, as its errors are.
printf 'cube(1);\nscale([1, 1, 0]) cube(1);\n' >flat.scad
warns_with flat.scad "flat.scad: warning: singular transform: subtree is empty (line 2 of OpenSCAD's export)"

# A .csg that uses more of OpenSCAD's language is converted like a .scad,
# with a note, and renders as the CSG OpenSCAD exports for it.
printf 'group() {\n  size = 2;\n  multmatrix([[1, 0, 0, 1], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) cube(size);\n}\n' >vars.csg
printf 'group() {\n  multmatrix([[1, 0, 0, 1], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {\n    cube(size = [2, 2, 2], center = false);\n  }\n}\n' >vars-plain.csg
note="vars.csg: note: uses OpenSCAD's language beyond its CSG export (line 2); converting it with openscad"
warns_with vars.csg "$note"
mv vars.csg.png vars.png
"$bin" render vars-plain.csg -o plain.png -q || fail "vars-plain.csg did not render"
cmp -s vars.png plain.png || fail "vars.csg: differs from its CSG export"
printf 'module part(s) { cube(s); }\nfor (i = [0 : 2]) translate([3 * i, 0, 0]) part(1 + i);\n' >loops.csg
warns_with loops.csg "loops.csg: note: uses OpenSCAD's language beyond its CSG export (line 1); converting it with openscad"
"$bin" info loops.csg 2>/dev/null | grep -q 'bounds: \[0, 0, 0\] to \[9, 3, 3\]' ||
    fail "loops.csg: bounds $("$bin" info loops.csg 2>&1)"
# OpenSCAD 2021.01's deprecated modules and intersection_for are
# language too: its export writes the import, extrusion or intersection
# they make, with its DEPRECATED line as a warning.
printf 'solid t\n' >dep.stl
for t in "0 0 0  0 2 0  2 0 0" "0 0 0  2 0 0  0 0 2" "0 0 0  0 0 2  0 2 0" "2 0 0  0 2 0  0 0 2"; do
    printf ' facet normal 0 0 0\n  outer loop\n' >>dep.stl
    for v in 0 3 6; do
        set -- $t
        shift $v
        printf '   vertex %s %s %s\n' "$1" "$2" "$3" >>dep.stl
    done
    printf '  endloop\n endfacet\n' >>dep.stl
done
printf 'endsolid t\n' >>dep.stl
printf 'group() {\n  import_stl("dep.stl");\n}\n' >dep.csg
warns_with dep.csg "dep.csg: note: uses OpenSCAD's language beyond its CSG export (line 2); converting it with openscad
dep.csg:2:1: warning: The import_stl() module will be removed in future releases. Use import() instead."
"$bin" info dep.csg 2>/dev/null | grep -q 'bounds: \[0, 0, 0\] to \[2, 2, 2\]' ||
    fail "dep.csg: bounds $("$bin" info dep.csg 2>&1)"
printf 'intersection_for(i = [0, 1]) multmatrix([[1, 0, 0, i], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) cube(2);\n' >ifor.csg
warns_with ifor.csg "ifor.csg: note: uses OpenSCAD's language beyond its CSG export (line 1); converting it with openscad"
"$bin" info ifor.csg 2>/dev/null | grep -q 'bounds: \[1, 0, 0\] to \[2, 2, 2\]' ||
    fail "ifor.csg: bounds $("$bin" info ifor.csg 2>&1)"
# OpenSCAD's own error, at its position, after the note; an error in the
# converted text names the .csg, with the export's line.
printf 'cube(1);\nx = ;\n' >badlang.csg
fails_with badlang.csg "badlang.csg: note: uses OpenSCAD's language beyond its CSG export (line 2); converting it with openscad
badlang.csg:2:1: error: Parser error: syntax error"
printf 'd = 1e14;\nresize([5, 5]) union() { square(1); square(d); }\n' >projlang.csg
fails_with projlang.csg "projlang.csg: note: uses OpenSCAD's language beyond its CSG export (line 1); converting it with openscad
projlang.csg: error: union: coordinates out of range (limit is 7.03687e+13) (line 2 of OpenSCAD's export)"
[ -z "$(ls -A "$work/tmp")" ] || fail "temporary files left: $(ls -A "$work/tmp")"

# -D NAME=VALUE passes through to OpenSCAD, as OpenSCAD's -D: in order (the
# last wins), as one word or two, for every command that converts.
printf 'size = 1;\nh = 1;\ncube([size, size, h]);\n' >d.scad
bounds() { "$bin" info "$@" 2>&1 | sed -n 's/^bounds: *//p'; }
[ "$(bounds d.scad -D size=3)" = "[0, 0, 0] to [3, 3, 1]" ] || fail "-D size=3: $(bounds d.scad -D size=3)"
[ "$(bounds -Dsize=4 d.scad -D h=2)" = "[0, 0, 0] to [4, 4, 2]" ] ||
    fail "-Dsize=4 -D h=2: $(bounds -Dsize=4 d.scad -D h=2)"
[ "$(bounds d.scad -D size=3 -D size=5)" = "[0, 0, 0] to [5, 5, 1]" ] || fail "-D: the last does not win"
[ "$(bounds d.scad -D 'size=2+1')" = "[0, 0, 0] to [3, 3, 1]" ] || fail "-D with an expression"
printf 'cube([size, size, 1]);\nsize = 1;\n' >dcsg.csg
[ "$(bounds dcsg.csg -D size=6 | tail -1)" = "[0, 0, 0] to [6, 6, 1]" ] || fail "-D on a converted .csg"
"$bin" measure d.scad -D size=2 --json -q >m.txt || fail "measure -D failed"
grep -q '"volume": {"value": 4' m.txt || fail "measure -D: $(cat m.txt)"
"$bin" render d.scad -D size=2 -o d2.png -q && "$bin" render d.scad -o d1.png -q ||
    fail "render -D failed"
cmp -s d1.png d2.png && fail "render -D: the same image with and without -D"
"$bin" compare d.scad "$work/d.scad" -D size=2 --imgsize=40,30 -q >/dev/null 2>&1 ||
    fail "compare -D: the model differs from itself"
printf 'render d.scad -o b1.png -q\n' >jobs.txt
"$bin" batch jobs.txt -D size=2 >/dev/null 2>&1 || fail "batch -D failed"
cmp -s b1.png d2.png || fail "batch -D: the job did not get -D"
# $preview is false as OpenSCAD renders (F6, or an export of a mesh) and
# true as it previews: OpenSCAD's own export to .csg would say true. A -D
# of it wins.
printf 'if ($preview) cube([1, 2, 3]); else cube([4, 5, 6]);\n' >pv.scad
[ "$(bounds pv.scad)" = "[0, 0, 0] to [4, 5, 6]" ] || fail "\$preview in a render: $(bounds pv.scad)"
[ "$(bounds pv.scad -D '$preview=true')" = "[0, 0, 0] to [1, 2, 3]" ] ||
    fail "-D \$preview=true: $(bounds pv.scad -D '$preview=true')"
printf 'cube([1, 2, 3]);\n' >pv_small.csg
"$bin" render pv.scad --preview -o pv_preview.png -q --imgsize=80,60 &&
    "$bin" render pv_small.csg --preview -o pv_small.png -q --imgsize=80,60 ||
    fail "render --preview of pv.scad failed"
cmp -s pv_preview.png pv_small.png || fail "\$preview in the preview: not the small cube"
# -D for a file spancast reads itself has no effect, and says so.
printf 'cube(1);\n' >plain.csg
"$bin" info plain.csg -D size=2 >/dev/null 2>err.txt || fail "info plain.csg -D failed"
[ "$(cat err.txt)" = "plain.csg: warning: -D is passed to OpenSCAD, which does not convert this file" ] ||
    fail "plain.csg -D: got '$(cat err.txt)'"
for bad in "-D" "-D size" "-D =2"; do
    "$bin" info d.scad $bad >/dev/null 2>err.txt
    rc=$?
    [ "$rc" = 2 ] || fail "info d.scad $bad: exit $rc (want 2)"
    case "$(cat err.txt)" in
    "spancast: error: -D expects NAME=VALUE, as OpenSCAD's -D"*) ;;
    *) fail "info d.scad $bad: got '$(cat err.txt)'" ;;
    esac
done
# OpenSCAD reads the -D settings after the source's end; what it says of
# one is said of the setting on the command line.
"$bin" info d.scad -D 'size=' >/dev/null 2>err.txt
rc=$?
[ "$rc" = 1 ] || fail "info d.scad -D 'size=': exit $rc (want 1)"
[ "$(cat err.txt)" = "<command-line>: error: -D 'size=': Parser error: syntax error" ] ||
    fail "info d.scad -D 'size=': got '$(cat err.txt)'"
"$bin" info d.scad -D h=1 -D 'other=nothing' >/dev/null 2>err.txt ||
    fail "info d.scad -D 'other=nothing' failed"
[ "$(cat err.txt)" = "<command-line>: warning: -D 'other=nothing': Ignoring unknown variable 'nothing'" ] ||
    fail "info d.scad -D 'other=nothing': got '$(cat err.txt)'"
# OpenSCAD appends the settings to each use'd library too, and says so for
# each time it evaluates one, past the library's end: said once, of the
# setting.
printf 'module peg() cylinder(h = 1, r = 1);\nfunction gap() = 8;\n' >lib.scad
printf 'use <lib.scad>\nfor (i = [0:4]) translate([i * gap(), 0, 0]) peg();\n' >uses.scad
"$bin" info uses.scad -D 'other=nothing' >/dev/null 2>err.txt ||
    fail "info uses.scad -D 'other=nothing' failed"
[ "$(cat err.txt)" = "<command-line>: warning: -D 'other=nothing': Ignoring unknown variable 'nothing'" ] ||
    fail "info uses.scad -D 'other=nothing': got '$(cat err.txt)'"
[ -z "$(ls -A "$work/tmp")" ] || fail "temporary files left: $(ls -A "$work/tmp")"

# spancast-mpi converts once: -D reaches it, the .csg beyond the export is
# converted, and an error in the converted text names the source.
if command -v mpirun >/dev/null && [ -x "$(dirname "$bin")/spancast-mpi" ]; then
    export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
    mpirun_test -np 2 "$bin" render d.scad -D size=2 -o np2.png -q >out.txt 2>&1 ||
        fail "mpirun -D: $(tail -n 5 out.txt)"
    cmp -s np2.png d2.png || fail "mpirun -D: the image differs"
    mpirun_test -np 2 "$bin" render vars.csg -o np2.png -q >out.txt 2>&1 ||
        fail "mpirun vars.csg: $(tail -n 5 out.txt)"
    cmp -s np2.png plain.png || fail "mpirun vars.csg: the image differs"
    grep -qF "$note" out.txt || fail "mpirun vars.csg: no note: $(cat out.txt)"
    mpirun_test -np 2 "$bin" render proj.scad -o np2.png -q >out.txt 2>&1
    grep -qF "$want" out.txt ||
        fail "mpirun proj.scad: $(cat out.txt)"
    grep -q "\.csg" out.txt && fail "mpirun proj.scad: names a .csg: $(cat out.txt)"
    mpirun_test -np 2 "$bin" render args.scad --strict -o np2s.png -q >out.txt 2>&1 &&
        fail "mpirun --strict args.scad: exit 0"
    grep -q "^args.scad:1:1: error: color() expects" out.txt ||
        fail "mpirun --strict args.scad: $(cat out.txt)"
    [ -e np2s.png ] && fail "mpirun --strict args.scad: an image was written"
fi

if [ "$fails" != 0 ]; then
    echo "$fails failure(s)"
    exit 1
fi
echo "cli_scad: all checks passed"
