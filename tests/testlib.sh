# Sourced by the tests/cli_*.sh scripts, which are run as
#   bash cli_X.sh <path-to-spancast> <source-dir> <work-dir>
# It sets bin (spancast, absolute), src (the source tree, absolute) and work
# (emptied, absolute, and the current directory), and the counters the
# scripts report with: fail MESSAGE counts and prints a failure, check
# counts one check. skip and require_tools stop a test that cannot run
# here; run_unprivileged runs a command as an ordinary user.
set -u
bin=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
src=$(cd "$2" && pwd)
work=$3
rm -rf "$work"
mkdir -p "$work"
work=$(cd "$work" && pwd)
cd "$work" || exit 1

fails=0
checks=0
fail() {
    echo "FAIL: $*"
    fails=$((fails + 1))
}
check() {
    checks=$((checks + 1))
}

# skip REASON: the rest of the test cannot run on this machine. Exits 77,
# which CTest reports as skipped (SKIP_RETURN_CODE), never as passed; a
# failure counted before the skip still fails the test. scripts/test, which
# installs every tool the suite uses, sets SPANCAST_NO_SKIP=1: there a skip
# is a failure, since it means an install step is missing.
skip() {
    if [ "$fails" != 0 ]; then
        echo "$fails failure(s) before the skip ($*)"
        exit 1
    fi
    if [ "${SPANCAST_NO_SKIP:-0}" = 1 ]; then
        echo "FAIL: cannot skip with SPANCAST_NO_SKIP=1: $*"
        exit 1
    fi
    echo "skipped: $*"
    exit 77
}

# require_tools TOOL...: skip unless every TOOL is in PATH.
require_tools() {
    local tool
    for tool; do
        command -v "$tool" >/dev/null || skip "$tool is not installed"
    done
}

# unprivileged_dir: sets udir to a new, empty folder under /tmp that the
# user of run_unprivileged owns, with a copy of spancast as $udir/spancast.
# The checkout and build tree may sit under a folder that user cannot enter
# (a mode-0700 home), so what it runs and reads is copied there. Removed
# when the script exits.
unprivileged_dir() {
    [ "$(id -u)" != 0 ] || require_tools setpriv
    udir=$(mktemp -d /tmp/spancast-test.XXXXXX) || exit 1
    # shellcheck disable=SC2064 # expand now: the trap removes this folder
    trap "rm -rf '$udir'" EXIT
    cp "$bin" "$udir/spancast"
    chmod 755 "$udir" "$udir/spancast"
    [ "$(id -u)" != 0 ] || chown -R nobody:nogroup "$udir"
}

# run_unprivileged CMD...: runs CMD as an ordinary user. Root may write
# anywhere, so a permission case run as root proves nothing; as root the
# command runs as 'nobody' (setpriv, util-linux), otherwise as the caller.
run_unprivileged() {
    if [ "$(id -u)" = 0 ]; then
        setpriv --reuid=nobody --regid=nogroup --clear-groups --reset-env -- "$@"
    else
        "$@"
    fi
}

# mpirun as the tests run it: any number of ranks on this machine, as root
# too. Open MPI 4.1 unloads its components (dlclose) in MPI_Finalize, so
# what they leave allocated has no module name by the time LeakSanitizer
# looks, and no suppression by library name can match it. The ranks
# therefore run without leak checking; AddressSanitizer's other checks and
# UBSan stay on, and the same render, tile and batch code is leak-checked
# in each test's single-process runs.
mpirun_test() {
    OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 \
        ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0 \
        mpirun --oversubscribe "$@"
}

# Skips the test unless mpirun and spancast-mpi are there; lets mpirun run
# as root (this machine's tests do).
require_mpi() {
    require_tools mpirun
    [ -x "$(dirname "$bin")/spancast-mpi" ] ||
        skip "spancast-mpi was not built (no MPI development files at configure time)"
    export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
}

# ---- the leniency tests' checks (cli_lenient*.sh) ----

# same A B [OPTIONS]: spancast compare (with OPTIONS) finds the two models
# the same.
same() {
    check
    "$bin" compare "$1" "$2" -q "${@:3}" >compare.txt 2>compare.err ||
        fail "compare $* : exit $? $(cat compare.err)"
    [ "$(tail -n 1 compare.txt)" = same ] ||
        fail "$1 and $2 differ ${*:3}: $(tail -n 12 compare.txt | tr '\n' ' ')"
}

# warns MODEL EXPECTED [render options]: spancast render MODEL prints
# exactly EXPECTED on stderr and exits 0.
warns() {
    local model=$1 expected=$2
    shift 2
    check
    "$bin" render "$model" -o out.png --imgsize=64,48 -q "$@" 2>err.txt
    local rc=$?
    [ "$rc" = 0 ] || fail "$model: exit $rc: $(cat err.txt)"
    [ "$(cat err.txt)" = "$expected" ] ||
        fail "$model: stderr '$(cat err.txt)', want '$expected'"
}

# refuses MODEL EXPECTED [render options]: spancast render MODEL --strict
# prints exactly EXPECTED on stderr, exits 1 and writes no image.
refuses() {
    local model=$1 expected=$2
    shift 2
    check
    rm -f strict.png
    "$bin" render "$model" -o strict.png --imgsize=64,48 -q --strict "$@" 2>err.txt
    local rc=$?
    [ "$rc" = 1 ] || fail "$model --strict $*: exit $rc: $(cat err.txt)"
    [ "$(cat err.txt)" = "$expected" ] ||
        fail "$model --strict $*: stderr '$(cat err.txt)', want '$expected'"
    [ -e strict.png ] && fail "$model --strict $*: an image was written"
}

# unable MODEL LINE COLUMN: the warning for the point [1, "a"] of the
# third point of a polygon, which OpenSCAD cannot convert.
unable() {
    printf '%s:%s:%s: warning: Unable to convert points[2] = [1, "a"] to a vec2 of numbers; the polygon is empty, as OpenSCAD leaves it out (--strict makes it an error)' "$@"
}
