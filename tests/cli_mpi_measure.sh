# `mpirun -np N spancast measure|overlaps|compare ...`: every rank casts its
# run of each round's lines and the ranks exchange them, so the results are
# the single-process ones to the last printed digit (text and --json, 2 and
# 3 ranks, a model and a mesh); errors are reported once, by rank 0, with
# the single-process exit status.
#
# Run as: bash cli_mpi_measure.sh <path-to-spancast> <source-dir> <work-dir>
. "$(dirname "$0")/testlib.sh"
require_mpi

# A block drilled by a cylinder and cut by a sphere (curved surfaces, so the
# integration refines over many rounds), and the same with a wider hole.
drilled() {
    cat <<CSG
difference() {
  cube(size = [20, 20, 10]);
  cylinder(h = 30, r1 = $1, r2 = $1, center = true);
  multmatrix([[1, 0, 0, 14], [0, 1, 0, 12], [0, 0, 1, 5], [0, 0, 0, 1]]) {
    sphere(r = 5);
  }
}
CSG
}
drilled 4 >a.csg
drilled 4.2 >b.csg
# Three objects, two of them overlapping in a curved sliver.
cat >o.csg <<'CSG'
group() {
  sphere(r = 6);
  multmatrix([[1, 0, 0, 8], [0, 1, 0, 1], [0, 0, 1, 0], [0, 0, 0, 1]]) {
    cylinder(h = 12, r1 = 4, r2 = 3, center = true);
  }
  multmatrix([[1, 0, 0, 20], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {
    cube(size = [3, 3, 3]);
  }
}
CSG
cp "$src/models/knob.stl" knob.stl
cp "$src/models/knob_part.csg" knob.csg

# same EXPECTED-EXIT NAME ARGS...: the command alone, then on 2 and 3 ranks;
# stdout byte for byte and the exit status the same.
same() {
    local want=$1 name=$2
    shift 2
    check
    "$bin" "$@" >"$name-1.txt" 2>"$name-1.err"
    local rc=$?
    [ "$rc" = "$want" ] || fail "$name alone: exit $rc: $(tail -n 3 "$name-1.err")"
    [ -s "$name-1.txt" ] || fail "$name alone printed nothing"
    for np in 2 3; do
        check
        mpirun_test -np "$np" "$bin" "$@" >"$name-$np.txt" 2>"$name-$np.err"
        rc=$?
        [ "$rc" = "$want" ] ||
            fail "$name on $np ranks: exit $rc: $(tail -n 3 "$name-$np.err")"
        cmp -s "$name-1.txt" "$name-$np.txt" ||
            fail "$name on $np ranks differs: $(diff "$name-1.txt" "$name-$np.txt" | head -n 6)"
    done
}

same 0 measure measure a.csg -q --threads=1 --tolerance=1e-4
same 0 measure-json measure a.csg -q --json --density=7.85 --tolerance=1e-4
# Enough lines that every rank's run is many lines (the counts are cut in
# three unequal runs on most rounds).
grep -q '"lines": [1-9][0-9][0-9][0-9][0-9]' measure-json-1.txt ||
    fail "the measure cast too few lines to share: $(cat measure-json-1.txt)"
same 1 compare compare a.csg b.csg -q --json --imgsize=64,48
same 1 compare-text compare a.csg b.csg -q --tolerance=1e-5 --imgsize=32,24
same 1 overlaps overlaps o.csg -q --json
same 1 overlaps-text overlaps o.csg -q
# (the mesh is OpenSCAD's facets of the exact solid: "different")
same 1 compare-mesh compare knob.csg knob.stl -q --tolerance=1e-3 --imgsize=32,24
grep -q '"same": false' compare-1.txt || fail "compare: $(cat compare-1.txt)"
grep -q '"volume": {"value": 22\.7' overlaps-1.txt || fail "overlaps: $(cat overlaps-1.txt)"

# Errors: once, from rank 0, with the single-process status.
check
mpirun_test -np 2 "$bin" compare a.csg missing.stl -q >out.txt 2>err.txt
rc=$?
[ "$rc" = 2 ] || fail "a missing mesh on 2 ranks: exit $rc"
[ "$(grep -c "^spancast: error: cannot open 'missing.stl': No such file or directory$" err.txt)" = 1 ] ||
    fail "a missing mesh on 2 ranks: '$(cat err.txt)'"
check
printf 'union() {\n  cube(1)\n}\n' >bad.csg
mpirun_test -np 3 "$bin" measure bad.csg -q >out.txt 2>err.txt
rc=$?
[ "$rc" = 1 ] || fail "a bad model on 3 ranks: exit $rc"
[ "$(grep -c '^bad.csg:3:1: error:' err.txt)" = 1 ] ||
    fail "a bad model on 3 ranks: '$(cat err.txt)'"
[ -s out.txt ] && fail "a bad model on 3 ranks printed results: $(cat out.txt)"
# A bad command line, found before the ranks join the job (--max-memory is
# read first of all): still once, by rank 0.
check
mpirun_test -np 3 "$bin" measure a.csg --max-memory=bogus >out.txt 2>err.txt
rc=$?
[ "$rc" = 2 ] || fail "a bad --max-memory on 3 ranks: exit $rc"
[ "$(grep -c '^spancast: error: --max-memory expects a size' err.txt)" = 1 ] ||
    fail "a bad --max-memory on 3 ranks: '$(cat err.txt)'"
check
mpirun_test -np 2 "$bin" spans a.csg --bogus >out.txt 2>err.txt
[ "$(grep -c "^spancast: error: unknown option '--bogus'" err.txt)" = 1 ] ||
    fail "a command that does not share its work, on 2 ranks: '$(cat err.txt)'"

echo "$checks checks, $fails failures"
[ "$fails" = 0 ]
