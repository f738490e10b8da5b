# Booleans inside hull() and minkowski(), and the booleans and minkowski
# sums a projection(cut = false) outlines, go through CGAL in the plugin
# spancast-cgal.so, loaded only when a model has one: --version, info and
# render of other models never load it (ld.so's own log), a hull of an
# intersection and a projection of a difference do, a broken plugin is an
# error that names it, two CGAL computations cut from GEB give OpenSCAD's
# solid, and memory running out inside CGAL is an error.
#
# Run as: bash cli_cgal.sh <path-to-spancast> <source-dir> <work-dir>
. "$(dirname "$0")/testlib.sh"

cat >plain.csg <<'CSG'
hull() { cube(2); multmatrix([[1, 0, 0, 5], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) { sphere(1, $fn = 8); } }
difference() { cube(10, center = true); sphere(6); }
minkowski() { cube(1); sphere(1, $fn = 8); }
linear_extrude(height = 1) { projection(cut = false) { union() { cube(3); sphere(2); } } }
linear_extrude(height = 1) { projection(cut = true) { difference() { cube(3, center = true); sphere(1); } } }
CSG
cat >proj.csg <<'CSG'
linear_extrude(height = 1) {
  projection(cut = false) {
    difference() { cube(10, center = true); cylinder(h = 30, r1 = 3, r2 = 3, center = true); }
  }
}
CSG
cat >bool.csg <<'CSG'
hull() {
  intersection() {
    cube(size = [10, 10, 10], center = true);
    cylinder(h = 20, r1 = 6, r2 = 6, center = true, $fn = 32, $fa = 12, $fs = 2);
  }
}
CSG

loaded() { cat "$1".* 2>/dev/null | grep -Eq 'file=[^ ]*spancast-cgal\.so'; }

check
LD_DEBUG=files LD_DEBUG_OUTPUT="$PWD/ld-version" "$bin" --version >/dev/null ||
    fail "--version failed"
loaded ld-version && fail "--version loaded spancast-cgal.so"
for cmd in info render; do
    check
    out=()
    [ "$cmd" = render ] && out=(-o plain.png --imgsize=32,24 -q)
    LD_DEBUG=files LD_DEBUG_OUTPUT="$PWD/ld-$cmd" "$bin" "$cmd" plain.csg "${out[@]}" \
        >/dev/null || fail "$cmd of a model without hull booleans failed"
    loaded "ld-$cmd" && fail "$cmd of a model without hull booleans loaded spancast-cgal.so"
    ! cat ld-"$cmd".* | grep -Eq 'file=[^ ]*lib(gmp|mpfr)' ||
        fail "$cmd of a model without hull booleans loaded GMP or MPFR"
done

check
LD_DEBUG=files LD_DEBUG_OUTPUT="$PWD/ld-bool" "$bin" info bool.csg >info.txt ||
    fail "info of a hull of an intersection failed: $(cat info.txt)"
loaded ld-bool || fail "a hull of an intersection did not load spancast-cgal.so"
check
LD_DEBUG=files LD_DEBUG_OUTPUT="$PWD/ld-proj" "$bin" info proj.csg >info.txt ||
    fail "info of a projection of a difference failed: $(cat info.txt)"
loaded ld-proj || fail "a projection of a difference did not load spancast-cgal.so"
# A plugin that lacks the entry points (another plugin under its name),
# beside a copy of the tool: an error naming it, a non-zero exit, no
# image.
check
mkdir broken
cp "$bin" broken/spancast
cp "$(dirname "$bin")/spancast-tiff.so" broken/spancast-cgal.so
if broken/spancast render bool.csg -o broken.png -q 2>err.txt; then
    fail "a broken plugin was not an error"
fi
grep -q "^bool.csg:2:3: error: hull: cannot load the CGAL plugin (spancast-cgal.so): it lacks spancast_nef_from_mesh$" err.txt ||
    fail "broken plugin message: $(cat err.txt)"
[ -e broken.png ] && fail "an image was written"
check
if broken/spancast render proj.csg -o broken.png -q 2>err.txt; then
    fail "a broken plugin was not an error for a projection"
fi
grep -q "^proj.csg:3:5: error: projection: cannot load the CGAL plugin (spancast-cgal.so): it lacks spancast_nef_from_mesh$" err.txt ||
    fail "broken plugin message for a projection: $(cat err.txt)"
[ -e broken.png ] && fail "an image was written for a projection"

# Two CGAL computations in one process, cut from OpenSCAD's GEB example
# (tests/data/geb_two_projections.csg): the outline of the extruded E,
# then that of the E and G intersected. The letters' caps went to CGAL as
# a fan per outline, which overlap; the Nef polyhedra built from them were
# not valid and the intersection crashed inside CGAL (SIGSEGV, every run).
# Both info and measure build it; the volume is OpenSCAD's own (its STL's,
# when openscad is here).
geb="$src/tests/data/geb_two_projections.csg"
check
"$bin" info "$geb" >info.txt 2>stderr.txt ||
    fail "info of two GEB projections failed (exit $?): $(cat stderr.txt)"
check
if "$bin" measure "$geb" >measure.txt 2>stderr.txt; then
    volume=$(awk '$1 == "volume" && $3 == "+-" { print $2, $4 }' measure.txt)
    if command -v openscad >/dev/null; then
        check
        openscad -o "$work/geb.stl" "$geb" >/dev/null 2>&1 ||
            fail "openscad could not render $geb"
        # the STL's volume: the divergence theorem over its triangles
        want=$(awk '$1 == "vertex" { p[n % 3] = $2 " " $3 " " $4; n++ }
            $1 == "vertex" && n % 3 == 0 { split(p[0], a); split(p[1], b); split(p[2], c)
                v += a[1] * (b[2] * c[3] - b[3] * c[2]) - a[2] * (b[1] * c[3] - b[3] * c[1])
                v += a[3] * (b[1] * c[2] - b[2] * c[1]) }
            END { printf "%.9g", v / 6 }' geb.stl)
        awk -v got="$volume" -v want="$want" 'BEGIN { split(got, g, " ")
            d = g[1] - want; if (d < 0) d = -d; exit !(want > 0 && d <= g[2] + 1e-6 * want) }' ||
            fail "two GEB projections: volume $volume, OpenSCAD's $want"
    else
        echo "note: openscad is not installed; the volume of the GEB projections is not compared"
    fi
else
    fail "measure of two GEB projections failed (exit $?): $(cat stderr.txt)"
fi

# Memory running out inside CGAL's exact arithmetic (GMP) is a clean
# error, not GMP's abort: a hull of a finely tessellated sphere cut by a
# cube takes about 140 MB. Under AddressSanitizer no memory limit can hold
# (cli_bounded.sh): the case is left out there.
cat >mem.csg <<'CSG'
hull() { difference() { sphere(r = 10, $fn = 120); cube(size = [30, 30, 30]); } }
CSG
"$bin" info plain.csg --max-memory=4G >/dev/null 2>stderr.txt
if grep -q "is below the" stderr.txt; then
    echo "note: $(cat stderr.txt); the --max-memory case is left out"
else
    check
    if "$bin" info mem.csg --max-memory=80M >/dev/null 2>stderr.txt; then
        fail "a hull boolean past --max-memory loaded"
    fi
    grep -Eq "^mem.csg:1:[0-9]+: error: out of memory \(the memory limit of 80.0 MiB is reached\)$" \
        stderr.txt || fail "past --max-memory: $(cat stderr.txt)"
fi

echo "$checks checks, $fails failures"
[ "$fails" = 0 ]
