# AMF and 3MF files of several objects, as OpenSCAD 2021.01 imports them
# (import_amf.cc, import_3mf.cc): each object its own solid, the objects
# united (OpenSCAD: a CGAL union), in exact and faithful mode, through
# import() and as a model (`spancast inside part.amf`). A triangle soup of
# all objects fails each case below: an object wound inside out cancels
# another, an open object or a face two objects share spoils the others.
# 3MF: mesh objects once each; build items, their transforms and
# components are not read. Zipped AMF as OpenSCAD reads it with libzip:
# the entry named as the file, else the archive's only entry with
# OpenSCAD's warning, else a warning and an empty import (--strict: an
# error). What OpenSCAD prints was seen on openscad 2021.01.
#
# Run as: bash cli_import_objects.sh <path-to-spancast> <source-dir> <work-dir>
. "$(dirname "$0")/testlib.sh"
# lib3mf 1.8 leaves libzip's allocations behind on every 3MF read; under the
# sanitizers they are suppressed by library name (spancast's own are still
# reported), and the list of suppressions used is kept off stderr.
export LSAN_OPTIONS="suppressions=$src/tests/imports.lsan-suppressions:print_suppressions=0${LSAN_OPTIONS:+:$LSAN_OPTIONS}"
require_tools python3

# The files: cubes as objects, written by python3 (AMF as text, 3MF and
# zipped AMF as zip archives).
python3 - "$src/tests" <<'PY'
import sys, zipfile
sys.path.insert(0, sys.argv[1])
from meshfiles import amf, cube, mesh, package, threemf

# overlapping cubes [0, 4]^3 and [2, 6]^3, the second wound inside out
overlap = [cube((0, 0, 0), 4), cube((2, 2, 2), 4, inward=True)]
# cubes [0, 4]^3 and [4, 8] x [0, 4]^2, sharing the face x = 4
touching = [cube((0, 0, 0), 4), cube((4, 0, 0), 4)]
# a closed cube and, at x = 6, one without its last triangle
open_second = [cube((0, 0, 0), 4), cube((6, 0, 0), 4, drop=1)]
# a closed cube [0, 4]^3 and, overlapping it, [2, 6]^3 without its last
# triangle
open_overlap = [cube((0, 0, 0), 4), cube((2, 2, 2), 4, drop=1)]
# two objects, both open; one open object alone
all_open = [cube((0, 0, 0), 4, drop=1), cube((6, 0, 0), 4, drop=1)]
one_open = [cube((2, 2, 2), 4, drop=1)]
for name, objects in [('overlap', overlap), ('touching', touching), ('open', open_second),
                      ('open_overlap', open_overlap), ('all_open', all_open),
                      ('one_open', one_open)]:
    open(name + '.amf', 'w').write(amf(objects))
    threemf(name + '.3mf', objects)
# a mesh object placed by two build items (one moved), and used by a
# components object, which OpenSCAD imports as the object alone, once
a = cube((0, 0, 0), 4)
package('items.3mf', '<object id="1" type="model">' + mesh(*a) + '</object>'
        '<object id="3" type="model"><components><component objectid="1" '
        'transform="1 0 0 0 1 0 0 0 1 10 0 0"/></components></object>',
        '<item objectid="1" transform="1 0 0 0 1 0 0 0 1 0 20 0"/><item objectid="1"/>'
        '<item objectid="3"/>')
# zipped AMF: its entry named as the file (in a folder), another single
# entry, and two entries named otherwise
text = amf(overlap)
with zipfile.ZipFile('zipped.amf', 'w', zipfile.ZIP_DEFLATED) as z:
    z.writestr('parts/zipped.amf', text)
with zipfile.ZipFile('single.amf', 'w', zipfile.ZIP_DEFLATED) as z:
    z.writestr('overlap.amf', text)
with zipfile.ZipFile('two_entries.amf', 'w', zipfile.ZIP_DEFLATED) as z:
    z.writestr('a.amf', text)
    z.writestr('b.amf', text)
PY
[ -s items.3mf ] || fail "python3 did not write the files"

# inside_is MODEL WANT [OPTION...]: spancast inside at the points below
# says WANT (space-separated), with nothing on stderr.
points=(--point=1,1,1 --point=3,3,3 --point=5,5,5 --point=5,1,1 --point=7,1,1
        --point=1,5,1 --point=9,1,1)
inside_is() {
    local model=$1 want=$2
    shift 2
    check
    "$bin" inside "$model" "${points[@]}" "$@" >in.txt 2>err.txt ||
        fail "inside $model $*: exit $?: $(cat err.txt)"
    [ "$(tr '\n' ' ' <in.txt)" = "$want " ] ||
        fail "inside $model $*: $(tr '\n' ' ' <in.txt), want $want"
    [ -s err.txt ] && fail "inside $model $*: stderr $(cat err.txt)"
}

# Points: 1,1,1 in the first cube only; 3,3,3 in both of overlap; 5,5,5 in
# the second of overlap only; 5,1,1 and 7,1,1 in the second of touching;
# 1,5,1 and 9,1,1 in none.
for ext in amf 3mf; do
    for mode in "" --faithful; do
        inside_is overlap.$ext "in in in out out out out" $mode
        inside_is touching.$ext "in in out in in out out" $mode
        printf 'import(file = "overlap.%s");\n' $ext >overlap-$ext.csg
        inside_is overlap-$ext.csg "in in in out out out out" $mode
        # the union seen from outside: the faces inside the overlap are not hit
        check
        "$bin" spans overlap-$ext.csg --ray=3,3,-1,0,0,1 $mode >spans.txt 2>&1 ||
            fail "spans overlap-$ext.csg $mode: $(cat spans.txt)"
        grep -q ": 1 span$" spans.txt || fail "spans overlap-$ext.csg $mode: $(cat spans.txt)"
    done
    # an open object: its own warning; left out in faithful mode, drawn by
    # the parity rule in exact mode; the closed one stays
    edge="edge (10, 4, 0)-(10, 0, 4) is used by 1 face"
    printf 'import(file = "open.%s");\n' $ext >open-$ext.csg
    for mode in exact faithful; do
        check
        opt=()
        [ $mode = faithful ] && opt=(--faithful)
        "$bin" inside open-$ext.csg --point=1,1,1 --point=7,1,1 --point=5,1,1 "${opt[@]}" \
            >in.txt 2>err.txt || fail "inside open-$ext.csg $mode: $(cat err.txt)"
        want="in in out"
        rule="rendered by the parity rule (--strict makes it an error)"
        if [ $mode = faithful ]; then
            want="in out out"
            rule='left out, as OpenSCAD leaves it out ("The given mesh is not closed! Unable to convert to CGAL_Nef_Polyhedron.")'
        fi
        [ "$(tr '\n' ' ' <in.txt)" = "$want " ] ||
            fail "inside open-$ext.csg $mode: $(tr '\n' ' ' <in.txt), want $want"
        w="open-$ext.csg:1:15: warning: object 2 of the imported file is not closed ($edge); $rule"
        [ "$(cat err.txt)" = "$w" ] || fail "open-$ext.csg $mode: stderr '$(cat err.txt)', want '$w'"
    done
    check
    "$bin" inside open-$ext.csg --point=1,1,1 --strict >in.txt 2>err.txt &&
        fail "open-$ext.csg --strict: exit 0"
    w="open-$ext.csg:1:15: error: object 2 of the imported file is not closed ($edge)"
    [ "$(cat err.txt)" = "$w" ] || fail "open-$ext.csg --strict: '$(cat err.txt)', want '$w'"
done

# inside a boolean that CGAL evaluates (a hull of a difference), the
# objects are united there too: the hull reaches the second cube's far
# corner (OpenSCAD 2021.01's hull has the vertex 6,6,6)
for ext in amf 3mf; do
    printf 'hull() {\n\tdifference() {\n\t\timport(file = "overlap.%s");\n\t\tcube(1);\n\t}\n}\n' $ext >hull-$ext.csg
    for mode in "" --faithful; do
        check
        "$bin" inside hull-$ext.csg --point=5.9,5.9,5.9 --point=3,3,3 --point=6.1,6.1,6.1 \
            $mode >in.txt 2>err.txt || fail "inside hull-$ext.csg $mode: $(cat err.txt)"
        [ "$(tr '\n' ' ' <in.txt)" = "in in out " ] ||
            fail "inside hull-$ext.csg $mode: $(tr '\n' ' ' <in.txt), want in in out"
    done
done

# hull and projection outside CGAL booleans, which take the objects as one
# mesh: an open object is left out in both modes, as OpenSCAD 2021.01
# leaves it out of the objects' union (seen: the hull of open.amf has no
# point beyond x = 4, the projection of open_overlap.amf is the first
# square alone). Before, exact mode drew the joined mesh by the parity
# rule: the hull reached x = 10, and the projection lost the overlap and
# kept the open square.
left='left out, as OpenSCAD leaves it out ("The given mesh is not closed! Unable to convert to CGAL_Nef_Polyhedron.")'
for ext in amf 3mf; do
    printf 'hull() {\n\timport(file = "open.%s");\n}\n' $ext >hull-open-$ext.csg
    printf 'linear_extrude(height = 1) {\n\tprojection() {\n\t\timport(file = "open_overlap.%s");\n\t}\n}\n' \
        $ext >projection-open-$ext.csg
    for mode in "" --faithful; do
        check
        "$bin" inside hull-open-$ext.csg --point=1,1,1 --point=4.5,1,1 --point=7,1,1 \
            $mode >in.txt 2>err.txt || fail "inside hull-open-$ext.csg $mode: $(cat err.txt)"
        [ "$(tr '\n' ' ' <in.txt)" = "in out out " ] ||
            fail "inside hull-open-$ext.csg $mode: $(tr '\n' ' ' <in.txt), want in out out"
        w="hull-open-$ext.csg:2:16: warning: object 2 of the imported file is not closed (edge (10, 4, 0)-(10, 0, 4) is used by 1 face); $left"
        [ "$(cat err.txt)" = "$w" ] ||
            fail "hull-open-$ext.csg $mode: stderr '$(cat err.txt)', want '$w'"
        check
        "$bin" inside projection-open-$ext.csg --point=1,1,0.5 --point=3,3,0.5 \
            --point=5,5,0.5 $mode >in.txt 2>err.txt ||
            fail "inside projection-open-$ext.csg $mode: $(cat err.txt)"
        [ "$(tr '\n' ' ' <in.txt)" = "in in out " ] ||
            fail "inside projection-open-$ext.csg $mode: $(tr '\n' ' ' <in.txt), want in in out"
        w="projection-open-$ext.csg:3:17: warning: object 2 of the imported file is not closed (edge (6, 6, 2)-(6, 2, 6) is used by 1 face); $left"
        [ "$(cat err.txt)" = "$w" ] ||
            fail "projection-open-$ext.csg $mode: stderr '$(cat err.txt)', want '$w'"
    done
done

# one open object alone under projection: OpenSCAD 2021.01 projects the
# mesh it reads without asking that it be closed, and prints nothing (seen:
# the projection of one_open.3mf is the square [2, 6]^2, and openscad -o
# of projection-one-open-amf.csg prints no warning). So spancast projects
# it silently in both modes, and --strict has no warning to make an error
# (cli_open_mesh.sh has the cut, which leaves it out). Before, it was an
# error in every mode.
for ext in amf 3mf; do
    printf 'linear_extrude(height = 1) {\n\tprojection() {\n\t\timport(file = "one_open.%s");\n\t}\n}\n' \
        $ext >projection-one-open-$ext.csg
    for mode in "" --faithful --strict; do
        check
        "$bin" inside projection-one-open-$ext.csg --point=3,3,0.5 --point=5.9,2.1,0.5 \
            --point=1,3,0.5 $mode >in.txt 2>err.txt ||
            fail "inside projection-one-open-$ext.csg $mode: exit $?: $(cat err.txt)"
        [ "$(tr '\n' ' ' <in.txt)" = "in in out " ] ||
            fail "inside projection-one-open-$ext.csg $mode: $(tr '\n' ' ' <in.txt), want in in out"
        [ -s err.txt ] && fail "projection-one-open-$ext.csg $mode: stderr '$(cat err.txt)'"
    done
done

# the same under a boolean that CGAL evaluates (a hull of a difference):
# each object is its own Nef polyhedron, and an open one is left out, as
# OpenSCAD 2021.01 leaves it out (seen: its hull has no point beyond
# x = 4). Before, it was an error in both modes.
for ext in amf 3mf; do
    printf 'hull() {\n\tdifference() {\n\t\timport(file = "open.%s");\n\t\tcube(1);\n\t}\n}\n' $ext \
        >hull-difference-open-$ext.csg
    for mode in "" --faithful; do
        check
        "$bin" inside hull-difference-open-$ext.csg --point=0.5,0.5,0.5 --point=3.9,3.9,3.9 \
            --point=4.5,1,1 --point=0.2,0.2,0.2 $mode >in.txt 2>err.txt ||
            fail "inside hull-difference-open-$ext.csg $mode: $(cat err.txt)"
        [ "$(tr '\n' ' ' <in.txt)" = "in in out out " ] ||
            fail "inside hull-difference-open-$ext.csg $mode: $(tr '\n' ' ' <in.txt), want in in out out"
        w="hull-difference-open-$ext.csg:3:17: warning: object 2 of the imported file is not closed (edge (10, 4, 0)-(10, 0, 4) is used by 1 face); $left"
        [ "$(cat err.txt)" = "$w" ] ||
            fail "hull-difference-open-$ext.csg $mode: stderr '$(cat err.txt)', want '$w'"
    done
done

# A file whose every object is open. OpenSCAD 2021.01 prints "ERROR: The
# given mesh is not closed! Unable to convert to CGAL_Nef_Polyhedron."
# for each object and then crashes (SIGSEGV, exit status 139) in every use
# seen: alone, beside a cube, under hull, under projection, in a preview
# PNG. spancast gives each object's warning (an error with --strict) and
# goes on: the import is empty where OpenSCAD's objects are left out (in
# --faithful mode, under hull, projection and CGAL), drawn by the parity
# rule where exact mode draws an open object; nothing more is said of the
# empty hull or extrusion (it follows from the warnings), as after any
# import left out; the model's emptiness is still said.
for ext in amf 3mf; do
    e1="(edge (4, 4, 0)-(4, 0, 4) is used by 1 face)"
    e2="(edge (10, 4, 0)-(10, 0, 4) is used by 1 face)"
    parity="rendered by the parity rule (--strict makes it an error)"
    printf 'union() {\n\tcube(1);\n\timport(file = "all_open.%s");\n}\n' $ext >all-open-$ext.csg
    printf 'hull() {\n\timport(file = "all_open.%s");\n}\n' $ext >hull-all-open-$ext.csg
    printf 'linear_extrude(height = 1) {\n\tprojection() {\n\t\timport(file = "all_open.%s");\n\t}\n}\n' \
        $ext >projection-all-open-$ext.csg
    printf 'hull() {\n\tdifference() {\n\t\timport(file = "all_open.%s");\n\t\tcube(1);\n\t}\n}\n' $ext \
        >cgal-all-open-$ext.csg
    # case MODEL POSITION MODE RULE WANT [EMPTY]: spancast inside MODEL at
    # 0.5,0.5,0.5 and 2,2,0.5 (in the first object) in MODE says WANT; its
    # stderr is the two objects' warnings at POSITION with RULE, then the
    # model's emptiness when EMPTY is set
    case_of() {
        local model=$1 at=$2 mode=$3 rule=$4 want=$5 empty=${6:-}
        check
        "$bin" inside "$model" --point=0.5,0.5,0.5 --point=2,2,0.5 $mode >in.txt 2>err.txt ||
            fail "inside $model $mode: $(cat err.txt)"
        [ "$(tr '\n' ' ' <in.txt)" = "$want " ] ||
            fail "inside $model $mode: $(tr '\n' ' ' <in.txt), want $want"
        w="$model$at: warning: object 1 of the imported file is not closed $e1; $rule
$model$at: warning: object 2 of the imported file is not closed $e2; $rule"
        [ -n "$empty" ] && w="$w
$model: warning: the model is empty (nothing to render)"
        [ "$(cat err.txt)" = "$w" ] || fail "$model $mode: stderr '$(cat err.txt)', want '$w'"
        check
        "$bin" inside "$model" --point=0.5,0.5,0.5 --strict >in.txt 2>err.txt &&
            fail "$model --strict: exit 0"
        w="$model$at: error: object 1 of the imported file is not closed $e1"
        [ "$(cat err.txt)" = "$w" ] || fail "$model --strict: '$(cat err.txt)', want '$w'"
    }
    case_of all_open.$ext "" "" "$parity" "in in"
    case_of all_open.$ext "" --faithful "$left" "out out" empty
    case_of all-open-$ext.csg :3:16 "" "$parity" "in in"
    case_of all-open-$ext.csg :3:16 --faithful "$left" "in out"
    for mode in "" --faithful; do
        case_of hull-all-open-$ext.csg :2:16 "$mode" "$left" "out out" empty
        case_of projection-all-open-$ext.csg :3:17 "$mode" "$left" "out out" empty
        case_of cgal-all-open-$ext.csg :3:17 "$mode" "$left" "out out" empty
    done
done

# 3MF build items and components: the mesh object once, where it is
inside_is items.3mf "in in out out out out out"
check
"$bin" inside items.3mf --point=1,21,1 --point=11,1,1 >in.txt 2>&1
[ "$(tr '\n' ' ' <in.txt)" = "out out " ] || fail "items.3mf: $(cat in.txt)"

# zipped AMF
inside_is zipped.amf "in in in out out out out"
printf 'import(file = "single.amf");\n' >single.csg
check
"$bin" inside single.csg "${points[@]}" >in.txt 2>err.txt || fail "single.csg: $(cat err.txt)"
[ "$(tr '\n' ' ' <in.txt)" = "in in in out out out out " ] || fail "single.csg: $(cat in.txt)"
w="single.csg:1:15: warning: Can't read file 'single.amf' from zipped AMF 'single.amf'; trying to read single entry 'overlap.amf'"
[ "$(cat err.txt)" = "$w" ] || fail "single.csg: stderr '$(cat err.txt)', want '$w'"
printf 'union() {\n\tcube(1);\n\timport(file = "two_entries.amf");\n}\n' >two.csg
check
"$bin" inside two.csg --point=0.5,0.5,0.5 --point=3,3,3 >in.txt 2>err.txt ||
    fail "two.csg: $(cat err.txt)"
[ "$(tr '\n' ' ' <in.txt)" = "in out " ] || fail "two.csg: $(cat in.txt)"
w="two.csg:3:16: warning: import: two_entries.amf: can't read file 'two_entries.amf' from zipped AMF: none of its 2 entries is named 'two_entries.amf'; the import is empty, as OpenSCAD leaves it out (--strict makes it an error)"
[ "$(cat err.txt)" = "$w" ] || fail "two.csg: stderr '$(cat err.txt)', want '$w'"
check
"$bin" inside two.csg --point=0.5,0.5,0.5 --strict >in.txt 2>err.txt && fail "two.csg --strict: exit 0"
w="two.csg:3:16: error: import: two_entries.amf: can't read file 'two_entries.amf' from zipped AMF: none of its 2 entries is named 'two_entries.amf'"
[ "$(cat err.txt)" = "$w" ] || fail "two.csg --strict: '$(cat err.txt)', want '$w'"

echo "$checks checks, $fails failures"
[ "$fails" = 0 ]
