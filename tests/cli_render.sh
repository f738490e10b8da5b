# `spancast render` and `spancast info` end to end: outputs and their
# formats, both option spellings, thread-count independence, the summary
# line, and that a failed render never destroys an existing output file or
# leaves a temporary behind.
#
# Run as: bash cli_render.sh <path-to-spancast> <source-dir> <work-dir>
. "$(dirname "$0")/testlib.sh"

cat >m.csg <<'EOF'
difference() {
  cube(size = [10, 10, 10], center = true);
  sphere(r = 6.5, $fn = 0, $fa = 12, $fs = 2);
}
EOF
printf 'union() {\n  roof() {\n    square(1);\n  }\n}\n' >bad.csg

# a plain render: nothing on stdout, one summary line on stderr
check
"$bin" render m.csg -o out.png --imgsize=64,48 >stdout.txt 2>stderr.txt
rc=$?
[ "$rc" = 0 ] || fail "render exited $rc: $(cat stderr.txt)"
[ -s stdout.txt ] && fail "render printed on stdout"
grep -Eq '^spancast: wrote out\.png \(64x48\) in [0-9]+\.[0-9]{3} s$' stderr.txt ||
    fail "summary line: '$(cat stderr.txt)'"
[ "$(wc -l <stderr.txt)" = 1 ] || fail "more than one line on stderr"
iinfo out.png | grep -q '64 x   48, 3 channel, uint8 png' || fail "out.png: $(iinfo out.png)"

# --quiet: silence
check
"$bin" render m.csg -o quiet.png --imgsize=64,48 --quiet >stdout.txt 2>stderr.txt ||
    fail "quiet render failed"
[ -s stderr.txt ] && fail "--quiet printed '$(cat stderr.txt)'"
cmp -s out.png quiet.png || fail "--quiet changed the image"

# the AOVs
check
"$bin" render m.csg -o c.png --mask=mask.png --depth=depth.exr --imgsize 32,24 -q ||
    fail "AOV render failed"
iinfo mask.png | grep -q '32 x   24, 1 channel, uint8 png' || fail "mask: $(iinfo mask.png)"
iinfo depth.exr | grep -q '32 x   24, 1 channel, float openexr' ||
    fail "depth: $(iinfo depth.exr)"
"$bin" render m.csg -o c.png --depth=depth.tif --imgsize 32,24 -q || fail "TIFF depth failed"
iinfo depth.tif | grep -q '32 x   24, 1 channel, float tiff' || fail "depth: $(iinfo depth.tif)"
# the corner pixel is background: mask 0, depth +inf; the centre is solid
oiiotool mask.png --printinfo:stats=1 2>/dev/null | grep -q 'Min: 0' || fail "mask has no 0"
oiiotool depth.exr --printinfo:stats=1 2>/dev/null | grep -q 'Inf' || fail "depth has no inf"

# --opt value and --opt=value are the same; so are -oFILE and -o FILE
check
"$bin" render m.csg -o a.png --imgsize=40,30 --camera=30,-40,25,0,0,0 --fov=30 \
    --projection=o -q || fail "render a"
"$bin" render m.csg -ob.png --imgsize 40,30 --camera 30,-40,25,0,0,0 --fov 30 \
    --projection o -q || fail "render b"
cmp -s a.png b.png || fail "the two option spellings differ"
"$bin" render m.csg --imgsize=40,30 --camera=30,-40,25,0,0,0 --fov=30 \
    --projection=p -o p.png -q || fail "render p"
cmp -s a.png p.png && fail "--projection had no effect"

# the gimbal camera and --viewall/--autocenter parse and render
check
"$bin" render m.csg -o g.png --imgsize=40,30 --camera=0,0,0,55,0,25,140 --viewall \
    --autocenter -q || fail "gimbal render"
"$bin" render m.csg -o auto.png --imgsize=40,30 -q || fail "auto render"
cmp -s g.png auto.png || fail "the default view is not gimbal 55,0,25 with viewall+autocenter"
"$bin" render m.csg -o n.png --imgsize=40,30 --camera=0,0,0,55,0,25,-80 --viewall \
    --autocenter -q || fail "viewall does not replace a negative distance"
cmp -s n.png auto.png || fail "viewall with a negative distance differs"

# the image does not depend on the thread count
check
"$bin" render m.csg -o t1.png --imgsize=70,50 --threads=1 -q || fail "threads=1"
"$bin" render m.csg -o t2.png --imgsize=70,50 --threads=2 -q || fail "threads=2"
cmp -s t1.png t2.png || fail "threads 1 and 2 differ"

# a bad model leaves existing outputs alone
check
cp out.png keep.png
cp depth.exr keep.exr
"$bin" render bad.csg -o out.png --depth=depth.exr 2>stderr.txt
rc=$?
[ "$rc" = 1 ] || fail "bad model exited $rc"
[ "$(cat stderr.txt)" = "bad.csg:2:3: error: 'roof' is not supported yet" ] ||
    fail "bad model: '$(cat stderr.txt)'"
cmp -s out.png keep.png || fail "a failed render changed out.png"
cmp -s depth.exr keep.exr || fail "a failed render changed depth.exr"

# a bad mask name leaves the colour output alone too
check
"$bin" render m.csg -o out.png --mask=mask.nope 2>stderr.txt
rc=$?
[ "$rc" = 2 ] || fail "bad mask name exited $rc"
cmp -s out.png keep.png || fail "a rejected command changed out.png"

# an existing output keeps its mode, and a symbolic link stays one: the
# file it names is replaced
check
mkdir -p real
cp keep.png real/target.png
chmod 600 real/target.png
ln -sf real/target.png link.png
"$bin" render m.csg -o link.png --imgsize=9,7 -q || fail "render through a link"
[ -L link.png ] || fail "the output link was replaced by a file"
cmp -s real/target.png keep.png && fail "the file the link names was not written"
[ "$(stat -c %a real/target.png)" = 600 ] ||
    fail "the linked file's mode became $(stat -c %a real/target.png)"
[ "$(ls -A real)" = target.png ] || fail "the link's folder holds $(ls -A real)"
cp keep.png private.png
chmod 640 private.png
"$bin" render m.csg -o private.png --imgsize=9,7 -q || fail "render over private.png"
[ "$(stat -c %a private.png)" = 640 ] || fail "private.png's mode became $(stat -c %a private.png)"

# unwritable destinations
check
"$bin" render m.csg -o nodir/out.png --imgsize=8,8 2>stderr.txt
rc=$?
[ "$rc" = 1 ] || fail "missing folder exited $rc"
[ "$(cat stderr.txt)" = "spancast: error: cannot write 'nodir/out.png': No such file or directory" ] ||
    fail "missing folder: '$(cat stderr.txt)'"
mkdir taken.png
"$bin" render m.csg -o taken.png --imgsize=8,8 2>stderr.txt
rc=$?
[ "$rc" = 1 ] || fail "folder as target exited $rc"
[ "$(cat stderr.txt)" = "spancast: error: cannot write 'taken.png': Is a directory" ] ||
    fail "folder as target: '$(cat stderr.txt)'"
[ -d taken.png ] || fail "the folder in the way is gone"
# A read-only folder keeps its file. Root may write anywhere, so the case
# runs as an ordinary user (run_unprivileged: 'nobody' when this is root).
unprivileged_dir
cp m.csg "$udir/"
mkdir "$udir/locked"
cp keep.png "$udir/locked/out.png"
[ "$(id -u)" != 0 ] || chown -R nobody:nogroup "$udir"
chmod 555 "$udir/locked"
run_unprivileged sh -c 'cd "$1" && { ./spancast render m.csg -o locked/out.png \
    --imgsize=8,8 2>stderr.txt; echo $? >rc.txt; }' sh "$udir"
rc=$(cat "$udir/rc.txt" 2>/dev/null)
chmod 755 "$udir/locked"
[ "$rc" = 1 ] || fail "read-only folder exited ${rc:-nothing}"
[ "$(cat "$udir/stderr.txt")" = "spancast: error: cannot write 'locked/out.png': Permission denied" ] ||
    fail "read-only folder: '$(cat "$udir/stderr.txt" 2>&1)'"
cmp -s "$udir/locked/out.png" keep.png || fail "a read-only folder's file changed"
[ "$(ls -A "$udir/locked")" = out.png ] || fail "read-only folder holds $(ls -A "$udir/locked")"

# no temporary file is ever left behind
check
leftover=$(ls -A | grep '^\.' || true)
[ -z "$leftover" ] || fail "temporaries left: $leftover"

# info
check
"$bin" info m.csg >info.txt 2>stderr.txt || fail "info failed"
cat >want.txt <<'EOF'
model:  m.csg
nodes:  3 (3 as written)
leaves: 2 (2 as written)
depth:  2 (2 as written)
bvh:    0 nodes
kinds:  1 sphere, 1 box
lights: none (the default rig)
materials: 0 mirror, 0 glass, 0 checkered leaves
bounds: [-5, -5, -5] to [5, 5, 5]
frame:  [-5, -5, -5] to [5, 5, 5] (the solid's own box, which the render's default camera frames)
EOF
cmp -s info.txt want.txt || fail "info printed: $(cat info.txt)"
[ -s stderr.txt ] && fail "info printed on stderr"

# info --threads: a union of 1.3 MB (past the 1 MiB at which a load parses
# in two parts), with a warning in each half, loaded on one thread and on
# two, prints the same tree, bounds and warnings
check
awk 'BEGIN { print "union() {"
    for (i = 0; i < 12000; i++) {
        printf "multmatrix([[1, 0, 0, %d], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) { sphere(r = 0.6); }\n", i
        if (i == 100 || i == 11000) print "cube(size = [1, 1, 1], centre = true);"
    }
    print "}" }' >wide.csg
[ "$(wc -c <wide.csg)" -gt 1048576 ] || fail "wide.csg is smaller than 1 MiB"
"$bin" info wide.csg --threads=1 >one.txt 2>one.err || fail "info --threads=1 failed"
"$bin" info wide.csg --threads=2 >two.txt 2>two.err || fail "info --threads=2 failed"
grep -q "^leaves: 12002 " one.txt || fail "info --threads=1 printed: $(cat one.txt)"
cmp -s one.txt two.txt || fail "info on two threads printed: $(cat two.txt)"
[ "$(grep -c "warning: variable centre not specified as parameter" one.err)" = 2 ] ||
    fail "info --threads=1 warned: $(cat one.err)"
cmp -s one.err two.err || fail "info on two threads warned: $(cat two.err)"

echo "$checks groups of checks, $fails failed"
[ "$fails" = 0 ]
