# The import readers go through plugins loaded on first use: spancast-xml.so
# (libxml2 with ICU, and libzip for zipped AMF) and spancast-3mf.so (lib3mf,
# which brings its own libzip). The tool links none of those libraries
# (ldd), and ld.so's own log shows that a render of a model without such
# imports, or with an STL import, loads neither plugin nor any of them; an
# AMF import (plain or zipped) loads the XML plugin with libxml2 and libzip
# and not the 3MF plugin; a 3MF import the 3MF plugin and not the XML one.
#
# Run as: bash cli_lazy_imports.sh <path-to-spancast> <source-dir> <work-dir>
. "$(dirname "$0")/testlib.sh"
export LSAN_OPTIONS="suppressions=$src/tests/imports.lsan-suppressions:print_suppressions=0${LSAN_OPTIONS:+:$LSAN_OPTIONS}"
require_tools ldd python3

heavy='(spancast-xml\.so|spancast-3mf\.so|libxml2|libicu|libzip|lib3MF)'
check
ldd "$bin" >ldd.txt 2>&1 || fail "ldd $bin: $(cat ldd.txt)"
grep -Eq "$heavy" ldd.txt && fail "spancast links $(grep -Eo "$heavy[^ ]*" ldd.txt | tr '\n' ' ')"

# The same tetrahedron as STL, AMF, zipped AMF and 3MF.
python3 - "$src/tests" <<'PY'
import sys, zipfile
sys.path.insert(0, sys.argv[1])
from meshfiles import amf, threemf
v = [(0, 0, 0), (2, 0, 0), (0, 2, 0), (0, 0, 2)]
t = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]
with open('tet.stl', 'w') as f:
    f.write('solid tet\n')
    for a, b, c in t:
        f.write(' facet normal 0 0 0\n  outer loop\n')
        for i in (a, b, c):
            f.write('   vertex %g %g %g\n' % v[i])
        f.write('  endloop\n endfacet\n')
    f.write('endsolid tet\n')
open('tet.amf', 'w').write(amf([(v, t)]))
with zipfile.ZipFile('zipped.amf', 'w', zipfile.ZIP_DEFLATED) as z:
    z.writestr('zipped.amf', amf([(v, t)]))
threemf('tet.3mf', [(v, t)])
PY
printf 'difference() { cube(10, center = true); sphere(6); }\n' >plain.csg

# loads LOG PATTERN: did the run that wrote LOG.* load a file matching PATTERN?
loads() { cat "$1".* 2>/dev/null | grep -Eq "file=[^ ]*$2"; }
# run NAME MODEL: renders MODEL to a PNG with ld.so's log in ld-NAME.*
run() {
    check
    LD_DEBUG=files LD_DEBUG_OUTPUT="$PWD/ld-$1" "$bin" render "$2" -o "$1.png" \
        --imgsize=32,24 -q >out.txt 2>&1 || fail "render $2 failed: $(cat out.txt)"
    [ -s "$1.png" ] || fail "no image of $2"
}

run plain plain.csg
run stl tet.stl
for name in plain stl; do
    ! loads "ld-$name" "$heavy" ||
        fail "$name loaded $(cat ld-"$name".* | grep -Eo "$heavy[^ ]*" | sort -u | tr '\n' ' ')"
done
for name in tet zipped; do
    run $name $name.amf
    loads ld-$name 'spancast-xml\.so' || fail "$name.amf did not load spancast-xml.so"
    loads ld-$name 'libxml2' || fail "$name.amf did not load libxml2"
    loads ld-$name 'libzip' || fail "$name.amf did not load libzip"
    loads ld-$name 'spancast-3mf\.so' && fail "$name.amf loaded spancast-3mf.so"
done
run threemf tet.3mf
loads ld-threemf 'spancast-3mf\.so' || fail "tet.3mf did not load spancast-3mf.so"
loads ld-threemf 'spancast-xml\.so' && fail "tet.3mf loaded spancast-xml.so"

echo "$checks checks, $fails failures"
[ "$fails" = 0 ]
