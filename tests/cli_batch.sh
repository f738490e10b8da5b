# `spancast batch JOBS`: one spancast command a line, shell quoting and
# comments, paths relative to the jobs file, each job once; a broken model
# is reported with its message and the others complete; the table, the
# JSON, the exit status; malformed jobs files; and the same under mpirun.
#
# Run as: bash cli_batch.sh <path-to-spancast> <source-dir> <work-dir>
. "$(dirname "$0")/testlib.sh"
require_tools python3

mkdir lib
cp "$src/models/bracket.csg" lib/part.csg
printf 'union() {\n  roof() {\n    square(1);\n  }\n}\n' >lib/broken.csg
cat >lib/jobs.txt <<'JOBS'
# the model library, checked at each change
render part.csg -o part.png --imgsize=64,48   # the bracket

render broken.csg -o broken.png --imgsize=64,48
  render "part.csg" -o 'part two.png' --imgsize=32,24 --mask=part\ mask.png
info part.csg
JOBS

# From another folder: the jobs' paths are relative to lib/.
check
"$bin" batch lib/jobs.txt >table.txt 2>err.txt
rc=$?
[ "$rc" = 1 ] || fail "a batch with a broken model exited $rc"
[ -s err.txt ] && fail "batch printed on stderr: $(cat err.txt)"
for f in part.png "part two.png" "part mask.png"; do
    [ -s "lib/$f" ] || fail "the batch did not write lib/$f"
done
[ -e lib/broken.png ] && fail "the broken job wrote an image"
"$bin" render lib/part.csg -o ref.png --imgsize=64,48 -q
cmp -s ref.png lib/part.png || fail "the batch's part.png differs from a render's"
check
grep -Eq '^1 +2 +0 +[0-9.]+  render part\.csg -o part\.png --imgsize=64,48$' table.txt ||
    fail "job 1 in the table: $(cat table.txt)"
grep -Eq "^2 +4 +1 +[0-9.]+  render broken\.csg -o broken\.png --imgsize=64,48$" table.txt ||
    fail "job 2 in the table: $(cat table.txt)"
grep -q "^ *broken.csg:2:3: error: 'roof' is not supported yet$" table.txt ||
    fail "the broken job's message: $(cat table.txt)"
grep -Eq "^3 +5 +0 +[0-9.]+  render part\.csg -o 'part two\.png' --imgsize=32,24 '--mask=part mask\.png'$" table.txt ||
    fail "job 3 (quoted words) in the table: $(cat table.txt)"
grep -Eq '^4 +6 +0 ' table.txt || fail "job 4 (info): $(cat table.txt)"
# What a job that succeeded printed is under its row too: info's report.
sed -n '/^4 /,/^4 jobs/p' table.txt | grep -Eq '^ +\| bounds: \[' ||
    fail "job 4's report is not in the table: $(cat table.txt)"
grep -Eq '^4 jobs: 3 succeeded, 1 failed, in [0-9.]+ s$' table.txt ||
    fail "the summary line: $(tail -n 1 table.txt)"

# --json: the same, parsed.
check
"$bin" batch lib/jobs.txt --json >batch.json 2>err.txt
rc=$?
[ "$rc" = 1 ] || fail "--json exited $rc"
python3 - batch.json <<'PY' || fail "batch.json: $(cat batch.json)"
import json, sys
d = json.load(open(sys.argv[1]))
jobs = d["jobs"]
assert [j["line"] for j in jobs] == [2, 4, 5, 6], jobs
assert [j["ok"] for j in jobs] == [True, False, True, True], jobs
assert jobs[1]["exit"] == 1
assert jobs[1]["message"] == "broken.csg:2:3: error: 'roof' is not supported yet", jobs[1]
assert jobs[2]["args"][3] == "part two.png" and jobs[2]["args"][5] == "--mask=part mask.png", jobs[2]
assert d["succeeded"] == 3 and d["failed"] == 1, d
assert "\nbounds: [" in jobs[3]["output"], jobs[3]
PY

# A failed job's whole output, not only its last line, bounded: a model
# with 600 warnings (about 40 KB of them) and a camera that looks nowhere.
check
{
    echo 'union() {'
    for i in $(seq 600); do echo '  sphere(r = 0);'; done
    echo '}'
} >lib/warns.csg
printf 'render warns.csg -o never.png --camera=1,1,1,1,1,1 --imgsize=8,6\n' >lib/long.txt
"$bin" batch lib/long.txt >long.txt 2>err.txt
[ $? = 1 ] || fail "the long job's batch did not fail: $(tail -n 3 long.txt)"
grep -q '^ *| warns\.csg:2:3: warning: ' long.txt || fail "the long job's first warning: $(head -n 5 long.txt)"
grep -Eq '^ *\| \[\.\.\. [0-9]+ bytes left out \.\.\.\]$' long.txt ||
    fail "the long job's output is not bounded: $(wc -c <long.txt) bytes"
grep -qx ' *| spancast: error: camera eye and centre are the same point' long.txt ||
    fail "the long job's last line: $(tail -n 3 long.txt)"
[ "$(wc -c <long.txt)" -lt 40000 ] || fail "the long job's table: $(wc -c <long.txt) bytes"
"$bin" batch lib/long.txt --json >long.json 2>err.txt
python3 - long.json lib/warns.csg <<'PY' || fail "long.json: $(head -c 600 long.json)"
import json, sys
job = json.load(open(sys.argv[1]))["jobs"][0]
out = job["output"]
assert job["message"] == "spancast: error: camera eye and centre are the same point", job
assert out.startswith("warns.csg:2:3: warning: "), out[:200]
assert out.rstrip("\n").endswith(job["message"]), out[-200:]
assert " bytes left out ...]" in out and len(out) <= 16 * 1024 + 64, len(out)
PY

# Every job succeeding: exit 0.
check
printf 'render part.csg -o ok.png --imgsize=16,12\n' >lib/ok.txt
"$bin" batch lib/ok.txt >out.txt 2>&1 || fail "a good batch failed: $(cat out.txt)"
grep -q '^1 job: 1 succeeded, 0 failed' out.txt || fail "a good batch: $(cat out.txt)"

# Malformed jobs files: file:line:col, exit 2, nothing run.
expect_syntax() {
    local want=$1 text=$2
    check
    printf '%s\n' "$text" >lib/bad.txt
    "$bin" batch lib/bad.txt >out.txt 2>err.txt
    local rc=$?
    [ "$rc" = 2 ] || fail "'$text': exit $rc"
    [ "$(cat err.txt)" = "$want" ] || fail "'$text': '$(cat err.txt)', want '$want'"
    [ -e lib/never.png ] && fail "'$text' ran a job"
}
expect_syntax "lib/bad.txt:2:17: error: unterminated double quote" \
    "$(printf 'render part.csg -o never.png\nrender part.csg "-o never.png')"
expect_syntax "lib/bad.txt:1:8: error: unterminated single quote" "render 'part.csg -o never.png"
expect_syntax "lib/bad.txt:1:29: error: backslash at the end of the line" \
    'render part.csg -o never.png\'
expect_syntax "lib/bad.txt:1:1: error: a job cannot be a batch" "batch jobs.txt"
check
"$bin" batch lib/none.txt >out.txt 2>err.txt
rc=$?
[ "$rc" = 1 ] || fail "a missing jobs file exited $rc"
grep -qx "spancast: error: cannot read 'lib/none.txt': No such file or directory" err.txt ||
    fail "a missing jobs file: '$(cat err.txt)'"
# The jobs file's limit, 64 MiB (limits.md): one job, then comments up to
# exactly the limit, runs; one byte more is refused before any job runs.
check
{ printf 'info part.csg\n'; yes '# padding' | head -c $((64 * 1048576 - 14)); } >lib/full.txt
[ "$(wc -c <lib/full.txt)" = $((64 * 1048576)) ] || fail "full.txt is $(wc -c <lib/full.txt) bytes"
"$bin" batch lib/full.txt >out.txt 2>err.txt
rc=$?
[ "$rc" = 0 ] || fail "a jobs file of 64 MiB exited $rc: $(cat err.txt)"
grep -Eq '^1 +1 +0 ' out.txt || fail "a jobs file of 64 MiB: $(cat out.txt)"
printf '#' >>lib/full.txt
"$bin" batch lib/full.txt >out.txt 2>err.txt
rc=$?
[ "$rc" = 1 ] || fail "a jobs file past 64 MiB exited $rc"
grep -qx "spancast: error: cannot read 'lib/full.txt': file is too large" err.txt ||
    fail "a jobs file past 64 MiB: '$(cat err.txt)'"
rm -f lib/full.txt
check
"$bin" batch >out.txt 2>err.txt
[ $? = 2 ] && grep -qx "spancast: error: missing jobs file" err.txt ||
    fail "batch without a file: '$(cat err.txt)'"

# Across ranks: each job once, the same files and table.
if command -v mpirun >/dev/null && [ -x "$(dirname "$bin")/spancast-mpi" ]; then
    check
    rm -f lib/*.png
    mpirun_test -np 3 "$bin" batch lib/jobs.txt --json >mpi.json 2>err.txt
    python3 - mpi.json batch.json <<'PY' || fail "mpi.json: $(cat mpi.json) $(cat err.txt)"
import json, re, sys
a, b = (json.load(open(p)) for p in sys.argv[1:])
# The outputs alike but for the times they report.
untimed = lambda s: re.sub(r" in [0-9.]+ s\b", " in (time) s", s)
strip = lambda d: [(j["line"], j["exit"], j["message"], untimed(j["output"])) for j in d["jobs"]]
assert strip(a) == strip(b), (strip(a), strip(b))
PY
    cmp -s ref.png lib/part.png || fail "part.png from the batch on 3 ranks differs"
fi

echo "$checks checks, $fails failures"
[ "$fails" = 0 ]
