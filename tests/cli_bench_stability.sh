# `spancast bench stability` end to end on 16 x 16 images: the CSV has the
# documented header and one row per case, every case and every model has no
# mask mismatch and no NaN, the exit status is 0; bad command lines exit 2.
# (Timing is reported, never asserted.)
#
# Run as: bash cli_bench_stability.sh <path-to-spancast> <source-dir> <work-dir>
. "$(dirname "$0")/testlib.sh"

# 10000 nested levels need about 5 MB of stack in the optimised build and
# several times that under the sanitizers (docs/stability.md).
ulimit -s 262144 2>/dev/null || ulimit -s unlimited 2>/dev/null
# (The 10000-level case itself is tests/test_stability.c's; its rays cost
# time quadratic in the depth, so here it is 2000 levels.)
"$bin" bench stability --csv stab.csv --dir "$src" --size 16 --depth 2000 2>stderr.txt
rc=$?
[ "$rc" = 0 ] || fail "bench exited $rc: $(cat stderr.txt)"
[ "$(head -1 stab.csv)" = "case,pixels,mask_mismatches,max_rel_depth_error,nan_count,seconds" ] ||
    fail "header: $(head -1 stab.csv)"
for c in scale_1e-6 scale_1e6 translate_1e8 random_similarity coincident_difference_at_1e8 \
    thin_wall edge_hole ill_scale_z_1e-9 ill_shear mirror singular deep_differences_2000 \
    wide_union_100000 far_camera_1e9; do
    grep -q "^$c," stab.csv || fail "no row for $c"
done
models=$(ls "$src"/models/*.csg | wc -l)
[ "$(grep -c '^model:' stab.csv)" = "$models" ] || fail "model rows: $(grep -c '^model:' stab.csv)"
awk -F, 'NR > 1 && (NF != 6 || $3 != 0 || $5 != 0 || $2 == 0) { bad++ } END { exit bad > 0 }' \
    stab.csv || fail "rows with mismatches or NaN: $(cat stab.csv)"
# scale about the origin: depth within 1e-9 relative
awk -F, '$1 ~ /^scale_/ && $4 > 1e-9 { bad++ } END { exit bad > 0 }' stab.csv ||
    fail "scale depth errors: $(grep '^scale_' stab.csv)"

"$bin" bench stability 2>err.txt
[ $? = 2 ] || fail "missing --csv should exit 2"
grep -q "missing --csv FILE" err.txt || fail "message: $(cat err.txt)"
"$bin" bench stability --csv x.csv --size 0 2>err.txt
[ $? = 2 ] || fail "--size 0 should exit 2"
"$bin" bench stability --csv x.csv --depth 10001 2>err.txt
[ $? = 2 ] || fail "--depth 10001 should exit 2"
"$bin" bench stability --csv x.csv --bogus 1 2>err.txt
[ $? = 2 ] || fail "unknown option should exit 2"
"$bin" bench stability --csv out.csv --dir /nonexistent 2>err.txt
[ $? = 1 ] || fail "a missing folder should exit 1"
grep -qx "spancast: error: no stability cases in '/nonexistent/tests/stability' (run it in the source folder, or give it with --dir DIR)" \
    err.txt || fail "message: $(cat err.txt)"
[ -e out.csv ] && fail "out.csv written without cases"
# outside the source folder without --dir: the same, not a table of empty rows
"$bin" bench stability --csv out.csv 2>err.txt
[ $? = 1 ] || fail "no cases in . should exit 1"
grep -qx "spancast: error: no stability cases in './tests/stability' (run it in the source folder, or give it with --dir DIR)" \
    err.txt || fail "message: $(cat err.txt)"
[ -e out.csv ] && fail "out.csv written without cases"

[ "$fails" = 0 ] && echo "all passed"
exit "$fails"
