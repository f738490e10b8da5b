# Sourced by the tests/cli_*.sh scripts, which are run as
#   bash cli_X.sh <path-to-spancast> <source-dir> <work-dir>
# It sets bin (spancast, absolute), src (the source tree, absolute) and work
# (emptied, absolute, and the current directory), and the counters the
# scripts report with: fail MESSAGE counts and prints a failure, check
# counts one check.
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
