# Bounded work: no input makes a command run away, and a stop is obeyed
# inside the work (docs/limits.md, "Bounded work").
#
#   - A field unresolvable at any scale (a sin argument past 2^53) is
#     refused at load (info and measure too), with the leaf's position; one that is merely far too
#     fine for the image (frequency 1e7 over a unit box) fails on the
#     render's budget of implicit work. Both at 8x8 and at 200x150.
#   - --max-time stops render, measure and a .scad conversion with its
#     message and exit 1, and leaves an existing output untouched.
#   - --max-memory fails a load past it and a render whose image buffers
#     pass it cleanly, and a generous one leaves the image as it was.
#   - SIGTERM inside one slow tile (a 16x16 image is one tile) ends the
#     render promptly with no file written.
#
# Times here are guards for a loaded machine (timeout), never assertions
# about speed; bench/run measures the stop latency.
#
# Run as: bash cli_bounded.sh <path-to-spancast> <source-dir> <work-dir>
. "$(dirname "$0")/testlib.sh"
mkdir -p out tmp

printf 'implicit(f = "sin(1e118 * x) * cos(1e100 * y) + z", bounds = [[-1, -1, -1], [1, 1, 1]]);\n' >huge.csg
printf 'implicit(f = "sin(1e7 * x) * cos(1e6 * y) + z", bounds = [[-1, -1, -1], [1, 1, 1]]);\n' >fine.csg
awk 'BEGIN {
    print "union() {"
    for (i = 0; i < 4000; i++)
        printf "  multmatrix([[1, 0, 0, %g], [0, 1, 0, %g], [0, 0, 1, 0], [0, 0, 0, 1]]) { sphere(r = 1); }\n",
            (i % 64) * 1.5, int(i / 64) * 1.5
    print "}"
}' >slow.csg
printf 'an older image, not a PNG at all\n' >out/old.png
old_sum=$(sha256sum out/old.png)

# expect_error NAME WANT-STDERR CMD...: exit 1, stderr exactly WANT, within
# a guard of 300 s, and out/ holds only old.png, unchanged.
expect_error() {
    local name=$1 want=$2
    shift 2
    check
    timeout 300 "$@" 2>stderr.txt
    local rc=$?
    [ "$rc" = 1 ] || fail "$name: exit $rc (want 1); stderr: $(cat stderr.txt)"
    [ "$(cat stderr.txt)" = "$want" ] || fail "$name: stderr '$(cat stderr.txt)' (want '$want')"
    [ "$(ls -A out)" = old.png ] || fail "$name: left in out/: $(ls -A out)"
    [ "$(sha256sum out/old.png)" = "$old_sum" ] || fail "$name: old.png was changed"
}

for size in 8,8 200,150; do
    expect_error "huge field $size" \
        "huge.csg:1:1: error: implicit surface is not resolvable: the argument of sin reaches 1e+118 within its bounds (beyond 2^53, where doubles are farther apart than its period)" \
        "$bin" render huge.csg -o out/old.png --imgsize=$size -q
    expect_error "fine field $size" \
        "fine.csg:1:1: error: implicit surfaces need more than 4096 evaluations per ray on average (limit is 4096, after the first 262144)" \
        "$bin" render fine.csg -o out/old.png --imgsize=$size -q
done
expect_error "fine field, measure" \
    "fine.csg:1:1: error: implicit surfaces need more than 4096 evaluations per ray on average (limit is 4096, after the first 262144)" \
    "$bin" measure fine.csg -q
# overlaps names the leaf too (its errors exit 2: 1 means overlaps found)
printf 'cube(1);\nimplicit(f = "sin(1e7 * x) * cos(1e6 * y) + z", bounds = [[-1, -1, -1], [1, 1, 1]]);\n' >fine2.csg
check
timeout 300 "$bin" overlaps fine2.csg -q 2>stderr.txt
rc=$?
[ "$rc" = 2 ] && [ "$(cat stderr.txt)" = "fine2.csg:2:1: error: implicit surfaces need more than 4096 evaluations per ray on average (limit is 4096, after the first 262144)" ] ||
    fail "fine field, overlaps: exit $rc, stderr '$(cat stderr.txt)'"

# The unresolvable field is refused at load, at its leaf: info and
# measure, which cast no camera ray, fail on it too.
printf 'cube(1);\n  implicit(f = "z + cos(3 * y) * sin(1e60 * x)", bounds = [[-1, -1, -1], [1, 1, 1]]);\n' >huge2.csg
unresolvable="huge2.csg:2:3: error: implicit surface is not resolvable: the argument of sin reaches 1e+60 within its bounds (beyond 2^53, where doubles are farther apart than its period)"
expect_error "huge field, info" "$unresolvable" "$bin" info huge2.csg
expect_error "huge field, measure" "$unresolvable" "$bin" measure huge2.csg -q

# --max-time: a render of many seconds, a measure to a tolerance it cannot
# reach soon
limit="spancast: error: time limit of 1 s exceeded (--max-time)"
expect_error "render --max-time" "$limit" \
    "$bin" render slow.csg -o out/old.png --imgsize=1000,1000 --spp=64 --threads=1 --max-time=1
expect_error "measure --max-time" "$limit" \
    "$bin" measure slow.csg --tolerance=1e-9 --threads=1 -q --max-time=1
expect_error "compare --max-time" "$limit" \
    "$bin" compare slow.csg slow.csg --tolerance=1e-12 --threads=1 -q --max-time=1
check
"$bin" render slow.csg -o out/x.png --max-time=0 2>stderr.txt
[ $? = 2 ] && grep -q -- "--max-time expects seconds above 0" stderr.txt ||
    fail "--max-time=0: $(cat stderr.txt)"

# --max-memory: a load past the limit fails with the limit's message, a
# render whose image buffers do not fit is refused before any work, and a
# generous limit changes nothing in the image. 500000 positioned spheres
# take 400 to 450 MiB of address space to load (what the limit counts).
awk 'BEGIN {
    print "union() {"
    for (i = 0; i < 500000; i++)
        printf "  multmatrix([[1, 0, 0, %d], [0, 1, 0, %d], [0, 0, 1, 0], [0, 0, 0, 1]]) { sphere(r = 0.4); }\n",
            i % 500, int(i / 500)
    print "}"
}' >big.csg
# Under AddressSanitizer the process reserves terabytes of shadow memory
# before main, so no memory limit can hold: spancast refuses the option
# there, and these cases are left out.
"$bin" info big.csg --max-memory=4G >/dev/null 2>stderr.txt
if grep -q "is below the" stderr.txt; then
    echo "note: $(cat stderr.txt); the --max-memory cases are left out"
else
    check
    "$bin" info big.csg --max-memory=300M >/dev/null 2>stderr.txt
    if grep -q "is below the" stderr.txt; then
        echo "note: this machine's threads need more than 300M; the load case is left out"
    else
        expect_error "load past --max-memory" \
            "spancast: error: loading 'big.csg' ran out of memory: the memory limit of 300.0 MiB is reached" \
            "$bin" render big.csg -o out/old.png --imgsize=64,48 -q --max-memory=300M
        expect_error "measure past --max-memory" \
            "spancast: error: loading 'big.csg' ran out of memory: the memory limit of 300.0 MiB is reached" \
            "$bin" measure big.csg -q --max-memory=300M
    fi
    check
    "$bin" render big.csg -o out/free.png --imgsize=64,48 -q --depth=out/free.exr 2>stderr.txt &&
        "$bin" render big.csg -o out/kept.png --imgsize=64,48 -q --depth=out/kept.exr \
            --max-memory 4G 2>>stderr.txt &&
        cmp -s out/free.png out/kept.png && cmp -s out/free.exr out/kept.exr ||
        fail "a generous --max-memory changed the render: $(cat stderr.txt)"
    rm -f out/free.* out/kept.*
    check
    timeout 300 "$bin" render slow.csg -o out/old.png --depth=out/d.exr --imgsize=4000,4000 --max-memory=200M 2>stderr.txt
    rc=$?
    [ "$rc" = 2 ] && grep -q "^spancast: error: cannot write 'out/old.png': a 4000x4000 render needs 244.1 MiB for its image buffers, more than the memory limit of 200.0 MiB leaves ([0-9.]* [KM]iB in use); only .exr and .tif outputs are written tile by tile\$" stderr.txt ||
        fail "image buffers past --max-memory: exit $rc, stderr '$(cat stderr.txt)'"
    [ "$(sha256sum out/old.png)" = "$old_sum" ] || fail "--max-memory: old.png was changed"
    check
    "$bin" render slow.csg -o out/x.png --max-memory=lots 2>stderr.txt
    [ $? = 2 ] && grep -qx "spancast: error: --max-memory expects a size such as 512M or 2G (got 'lots')" stderr.txt ||
        fail "--max-memory=lots: $(cat stderr.txt)"
fi

# SIGTERM inside one slow tile
caught() {
    local mask
    mask=$(sed -n 's/^SigCgt:[[:space:]]*//p' "/proc/$1/status" 2>/dev/null) || return 1
    [ -n "$mask" ] && (((0x$mask >> ($(kill -l "$2") - 1)) & 1))
}
check
"$bin" render slow.csg -o out/tile.png --imgsize=16,16 --spp=65536 --threads=1 -q 2>stderr.txt &
pid=$!
for ((k = 0; k < 600; k++)); do
    caught "$pid" TERM && break
    sleep 0.1
done
sleep 1
kill -TERM "$pid"
start=$(date +%s)
for ((k = 0; k < 600; k++)); do
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.1
done
if kill -0 "$pid" 2>/dev/null; then
    fail "SIGTERM in a slow tile: still running 60 s later"
    kill -KILL "$pid"
fi
wait "$pid"
rc=$?
[ "$rc" = 143 ] || fail "SIGTERM in a slow tile: exit $rc (want 143)"
[ "$(cat stderr.txt)" = "spancast: interrupted" ] ||
    fail "SIGTERM in a slow tile: stderr '$(cat stderr.txt)'"
[ "$(ls -A out)" = old.png ] || fail "SIGTERM in a slow tile: left $(ls -A out)"

# --max-time during a .scad conversion: OpenSCAD is killed and its
# temporary folder removed
if command -v openscad >/dev/null; then
    check
    printf 'echo(len([for (i = [0:20000]) for (j = [0:20000]) if (i * j < 0) 1]));\ncube(1);\n' >busy_model.scad
    TMPDIR=$work/tmp timeout 300 "$bin" render busy_model.scad -o out/old.png --max-time=2 2>stderr.txt
    rc=$?
    [ "$rc" = 1 ] || fail ".scad --max-time: exit $rc; stderr: $(cat stderr.txt)"
    grep -qx "spancast: error: time limit of 2 s exceeded (--max-time)" stderr.txt ||
        fail ".scad --max-time: stderr '$(cat stderr.txt)'"
    [ -z "$(ls -A tmp)" ] || fail ".scad --max-time: left in TMPDIR: $(ls -A tmp)"
    sleep 1
    pgrep -f "$work/busy_model.scad" >/dev/null && fail ".scad --max-time: OpenSCAD still runs"
    [ "$(sha256sum out/old.png)" = "$old_sum" ] || fail ".scad --max-time: old.png changed"
fi

echo "$checks checks, $fails failed"
[ "$fails" = 0 ]
