# The bad-input corpus (tests/bad-input/): every malformed model gets its
# exact messages and exit status, every malformed command line its exact
# message, and no case leaves a file behind.
#
#   NAME.csg + NAME.expected   `spancast render NAME.csg` (run in that
#                              folder, 8x8, quiet) must print exactly
#                              NAME.expected on stderr and exit 1 when it
#                              holds an error, 0 when it holds only warnings
#                              (or nothing: a documented treatment);
#   cmdlines.txt               STATUS | ARGUMENTS | STDERR, one per line.
#
# Run as: bash cli_bad_input.sh <path-to-spancast> <source-dir> <work-dir>
. "$(dirname "$0")/testlib.sh"
corpus=$src/tests/bad-input
export LSAN_OPTIONS="suppressions=$src/tests/imports.lsan-suppressions:print_suppressions=0${LSAN_OPTIONS:+:$LSAN_OPTIONS}"
mkdir -p "$work/out"

cd "$corpus" || exit 1
for model in *.csg; do
    name=${model%.csg}
    checks=$((checks + 1))
    [ -f "$name.expected" ] || { fail "$model has no $name.expected"; continue; }
    want_rc=0
    grep -q ': error: ' "$name.expected" && want_rc=1
    "$bin" render "$model" -o "$work/out/$name.png" --imgsize=8,8 --threads=1 -q \
        2>"$work/stderr.txt"
    rc=$?
    if [ "$rc" != "$want_rc" ] || ! cmp -s "$work/stderr.txt" "$name.expected"; then
        fail "$model: exit $rc (want $want_rc)"
        diff "$name.expected" "$work/stderr.txt" | sed 's/^/    /'
    fi
    if [ "$want_rc" = 1 ] && [ -e "$work/out/$name.png" ]; then
        fail "$model: a failed render wrote an image"
    fi
done
rm -rf "$work/out" "$work/stderr.txt"

cd "$work" || exit 1
printf 'sphere(r = 1);\n' >m.csg
printf 'cube(1;\n' >bad.csg
mkdir folder.png
printf 'not a folder\n' >file
before=$(ls -A | sort)
while IFS= read -r line; do
    case $line in '#'* | '') continue ;; esac
    checks=$((checks + 1))
    want_rc=${line%% | *}
    rest=${line#* | }
    args=${rest%% | *}
    want_err=${rest#* | }
    # shellcheck disable=SC2086 # arguments are split at spaces on purpose
    "$bin" $args >stdout.txt 2>stderr.txt
    rc=$?
    got_err=$(cat stderr.txt)
    if [ "$rc" != "$want_rc" ] || [ "$got_err" != "$want_err" ]; then
        fail "spancast $args"
        echo "    exit   $rc (want $want_rc)"
        echo "    stderr '$got_err'"
        echo "    want   '$want_err'"
    fi
    rm -f stdout.txt stderr.txt
    after=$(ls -A | sort)
    [ "$after" = "$before" ] || fail "spancast $args left: $(comm -13 <(echo "$before") <(echo "$after") | tr '\n' ' ')"
    [ -z "$(ls -A folder.png)" ] || fail "spancast $args wrote into folder.png"
done <"$corpus/cmdlines.txt"

# A folder without write permission. Root may write anywhere, so the case
# runs as an ordinary user (run_unprivileged: 'nobody' when this is root).
check
unprivileged_dir
cp m.csg "$udir/"
run_unprivileged sh -c 'cd "$1" && mkdir locked && chmod 555 locked &&
    { ./spancast render m.csg -o locked/x.png --imgsize=8,8 2>stderr.txt
      echo $? >rc.txt; }' sh "$udir"
rc=$(cat "$udir/rc.txt" 2>/dev/null)
want="spancast: error: cannot write 'locked/x.png': Permission denied"
[ "$rc" = 1 ] && [ "$(cat "$udir/stderr.txt")" = "$want" ] ||
    fail "locked folder: exit ${rc:-none}, stderr '$(cat "$udir/stderr.txt" 2>&1)'"
[ -z "$(ls -A "$udir/locked")" ] || fail "locked folder: it holds $(ls -A "$udir/locked")"

echo "$checks checks, $fails failed"
[ "$fails" = 0 ]
