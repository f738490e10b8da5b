# No lost files: SIGINT or SIGTERM in the middle of a render, or in the
# middle of writing the image, leaves an existing output byte for byte as it
# was and no temporary file behind; the tool says "spancast: interrupted"
# and dies of the signal. Input files are never written.
#
# The render is made slow deterministically (4000 spheres in one union, one
# thread, 1000x1000 pixels: many seconds even in an optimised build), so a
# signal sent a moment after the start always lands before the image is
# complete. For the write, the process is stopped (SIGSTOP) as soon as the
# temporary file appears, signalled, and continued: the writer then sees the
# cancel flag before its rename.
#
# Run as: bash cli_interrupt.sh <path-to-spancast> <source-dir> <work-dir>
. "$(dirname "$0")/testlib.sh"
mkdir -p "$work/out"

awk 'BEGIN {
    print "union() {"
    for (i = 0; i < 4000; i++)
        printf "  multmatrix([[1, 0, 0, %g], [0, 1, 0, %g], [0, 0, 1, 0], [0, 0, 0, 1]]) { sphere(r = 1); }\n",
            (i % 64) * 1.5, int(i / 64) * 1.5
    print "}"
}' >slow.csg
printf 'group();\n' >empty.csg
printf 'an older image, not a PNG at all\n' >out/old.png
input_sum=$(sha256sum slow.csg empty.csg)
input_time=$(stat -c %Y slow.csg empty.csg)
old_sum=$(sha256sum out/old.png)

# no_leftovers: the output folder holds only old.png.
no_leftovers() {
    local left
    left=$(ls -A out | grep -v '^old\.png$')
    [ -z "$left" ] || fail "$1: left behind: $left"
    [ "$(sha256sum out/old.png)" = "$old_sum" ] || fail "$1: old.png was changed"
}

# caught PID SIG: whether process PID has a handler for signal SIG (its
# SigCgt mask in /proc, bit SIG - 1). A signal sent before the handler is
# installed kills the process silently, which says nothing about the tool.
caught() {
    local mask
    mask=$(sed -n 's/^SigCgt:[[:space:]]*//p' "/proc/$1/status" 2>/dev/null) || return 1
    [ -n "$mask" ] && (((0x$mask >> ($(kill -l "$2") - 1)) & 1))
}

# during the render: SIGTERM, then SIGINT (job control on, so the background
# job does not start with SIGINT ignored)
for sig in TERM INT; do
    checks=$((checks + 1))
    set -m
    "$bin" render slow.csg -o out/old.png --imgsize=1000,1000 --threads=1 --spp=1024 \
        2>stderr.txt &
    pid=$!
    set +m
    # Signal once the handler is in place (a generous guard of 60 s for a
    # loaded machine; it takes well under a second), then a moment later,
    # inside the render of many seconds.
    for ((k = 0; k < 600; k++)); do
        caught "$pid" "$sig" && break
        sleep 0.1
    done
    caught "$pid" "$sig" || fail "render + SIG$sig: no handler after 60 s"
    sleep 0.5
    kill -"$sig" "$pid"
    wait "$pid"
    rc=$?
    want=$((128 + $(kill -l "$sig")))
    [ "$rc" = "$want" ] || fail "render + SIG$sig: exit $rc (want $want)"
    [ "$(cat stderr.txt)" = "spancast: interrupted" ] ||
        fail "render + SIG$sig: stderr '$(cat stderr.txt)'"
    no_leftovers "render + SIG$sig"
done

# during the write: stop the process when its temporary appears
checks=$((checks + 1))
"$bin" render empty.csg -o out/old.png --imgsize=4000,3000 --threads=1 2>stderr.txt &
pid=$!
seen=0
for ((k = 0; k < 2000000; k++)); do
    tmp=(out/.old.tmp-*)
    if [ -e "${tmp[0]}" ]; then
        kill -STOP "$pid"
        seen=1
        break
    fi
    kill -0 "$pid" 2>/dev/null || break
done
kill -TERM "$pid"
kill -CONT "$pid"
wait "$pid"
rc=$?
if [ "$seen" = 1 ]; then
    [ "$rc" = 143 ] || fail "write + SIGTERM: exit $rc (want 143)"
    [ "$(cat stderr.txt)" = "empty.csg: warning: the model is empty (nothing to render)
spancast: interrupted" ] || fail "write + SIGTERM: stderr '$(cat stderr.txt)'"
    no_leftovers "write + SIGTERM"
else
    fail "write + SIGTERM: the temporary file was never seen (exit $rc)"
fi

# a render that is not interrupted does replace the file (the checks above
# would pass for a tool that never writes)
checks=$((checks + 1))
"$bin" render empty.csg -o out/old.png --imgsize=8,8 -q 2>stderr.txt ||
    fail "plain render failed: $(cat stderr.txt)"
[ "$(sha256sum out/old.png)" != "$old_sum" ] || fail "plain render did not write"
[ "$(ls -A out)" = "old.png" ] || fail "plain render left: $(ls -A out)"

checks=$((checks + 1))
[ "$(sha256sum slow.csg empty.csg)" = "$input_sum" ] || fail "an input file changed"
[ "$(stat -c %Y slow.csg empty.csg)" = "$input_time" ] || fail "an input file was touched"

echo "$checks checks, $fails failed"
[ "$fails" = 0 ]
