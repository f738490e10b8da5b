# `spancast bench accuracy` end to end on a tiny grid (2 x 2 rays, so it
# runs in about a second): the CSV has its header and one row per scene,
# method and tolerance with the documented columns; the default method
# gets every hit right at the tolerances that see the thinnest scene; the
# plot is a PNG; bad command lines exit 2; a failed run leaves no file.
# (Timing is reported, never asserted.)
#
# Run as: bash cli_bench.sh <path-to-spancast> <source-dir> <work-dir>
. "$(dirname "$0")/testlib.sh"
require_tools gnuplot

"$bin" bench accuracy --csv acc.csv --rays 2 2>stderr.txt
rc=$?
[ "$rc" = 0 ] || fail "bench exited $rc: $(cat stderr.txt)"
[ "$(head -1 acc.csv)" = "scene,method,tolerance,rays,mean_abs_error,max_abs_error,wrong_hits,seconds" ] ||
    fail "header: $(head -1 acc.csv)"
# 7 scenes x 3 methods x 4 tolerances
[ "$(tail -n +2 acc.csv | wc -l)" = 84 ] || fail "rows: $(tail -n +2 acc.csv | wc -l)"
for scene in sphere torus triple_root high_freq steep_exp minmax_kink thin_shell; do
    for method in interval lipschitz march; do
        n=$(grep -c "^$scene,$method," acc.csv)
        [ "$n" = 4 ] || fail "$scene $method: $n rows"
    done
done
awk -F, 'NR > 1 && (NF != 8 || $4 != 4) { bad++ } END { exit bad > 0 }' acc.csv ||
    fail "malformed rows"
# interval bisection: no wrong hit and errors at rounding level wherever
# the tolerance (<= 1e-3) is below the thinnest feature (the 0.004 shell)
awk -F, 'NR > 1 && $2 == "interval" && $3 <= 0.001 && ($7 != 0 || $6 > 1e-12) { bad++ }
    END { exit bad > 0 }' acc.csv || fail "interval rows: $(grep interval acc.csv)"

"$bin" bench accuracy --csv acc2.csv --plot acc.png --rays 1 2>/dev/null ||
    fail "bench with --plot failed"
[ "$(head -c 8 acc.png | od -An -c | tr -d ' ')" = "211PNG\r\n032\n" ] ||
    fail "acc.png is not a PNG"
ls ./*.tmp* >/dev/null 2>&1 && fail "temporary files left behind"

"$bin" bench accuracy --rays 2 2>err.txt
[ $? = 2 ] || fail "missing --csv should exit 2"
grep -qx "spancast: error: missing --csv FILE" err.txt || fail "message: $(cat err.txt)"
"$bin" bench speed --csv x.csv 2>err.txt
[ $? = 2 ] || fail "unknown benchmark should exit 2"
grep -qx "spancast: error: unknown benchmark (expected 'bench accuracy' or 'bench stability')" err.txt ||
    fail "message: $(cat err.txt)"
"$bin" bench accuracy --csv x.csv --rays 0 2>err.txt
[ $? = 2 ] || fail "--rays 0 should exit 2"
[ -e x.csv ] && fail "x.csv written by a failed run"
"$bin" bench accuracy --csv no/such/dir/x.csv --rays 1 2>err.txt
[ $? = 1 ] || fail "unwritable CSV should exit 1"

[ "$fails" = 0 ] || exit 1
echo "cli_bench: all checks passed"
