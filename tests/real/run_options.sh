#!/usr/bin/env bash
# tests/real/run takes the values of its options: -b BUILD works from any
# directory, and -j, -t, -r and -s are accepted with theirs.
#   run_options.sh BUILD_DIR
set -u
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
build=$(cd "$1" && pwd)
elsewhere=$(mktemp -d)
trap 'rm -rf "$elsewhere"' EXIT
cd "$elsewhere" || exit 1
if ! out=$(bash "$here/run" -b "$build" -j 2 -t 60 -r 60 -s 40,30 --no-run \
    openscad-examples/Old/example001 2>&1); then
    echo "run -b $build --no-run failed from $elsewhere:"
    echo "$out"
    exit 1
fi
if ! grep -q '^model ' <<<"$out" || ! grep -q '^openscad-examples/Old/example001 ' <<<"$out"; then
    echo "run -b $build --no-run printed no table:"
    echo "$out"
    exit 1
fi
