# The shading options of `spancast render` end to end: a model's own camera
# and the command line over it, --threads byte-identity with several samples
# per pixel and a sphere light, --region against a crop of the full image,
# --stats and --stats=json, the normal and id AOVs, metadata in the files,
# the progress bar (only on a terminal, never with --quiet), and usage
# errors of the new options.
#
# Run as: bash cli_shading.sh <path-to-spancast> <source-dir> <work-dir>
. "$(dirname "$0")/testlib.sh"
require_tools python3 script

model=$src/models/whitted.csg
size=--imgsize=96,72

# the file's camera is used and written into the metadata
check
"$bin" render "$model" -o cam.png $size -q || fail "render of whitted.csg failed"
iinfo -v cam.png | grep -q 'spancast:camera: "eye 2,-13,5.5 center 0,0,1 ' ||
    fail "camera metadata: $(iinfo -v cam.png)"
iinfo -v cam.png | grep -q 'Software: "spancast ' || fail "no Software metadata"
iinfo -v cam.png | grep -q 'oiio:ColorSpace: "sRGB"' || fail "PNG not tagged sRGB"

# the command line wins over the file
check
"$bin" render "$model" -o cam2.png $size -q --camera=0,-20,5,0,0,1 --fov=30 ||
    fail "render with --camera failed"
iinfo -v cam2.png | grep -q 'spancast:camera: "eye 0,-20,5 center 0,0,1 .* fov 30 ' ||
    fail "--camera did not override: $(iinfo -v cam2.png | grep camera)"

# one thread or two: the same bytes, with 4 samples per pixel
check
# (PNG files compared whole; OpenEXR files carry the time they were
# written, so those are compared pixel for pixel, exactly)
"$bin" render "$model" -o t1.png $size -q --spp=4 --threads=1 || fail "threads=1 failed"
"$bin" render "$model" -o t2.png $size -q --spp=4 --threads=2 || fail "threads=2 failed"
cmp -s t1.png t2.png || fail "--threads=1 and --threads=2 differ (PNG)"
"$bin" render "$model" -o t1.exr $size -q --spp=4 --threads=1 || fail "threads=1 failed"
"$bin" render "$model" -o t2.exr $size -q --spp=4 --threads=2 || fail "threads=2 failed"
idiff -fail 0 -failpercent 0 -warn 0 t1.exr t2.exr >/dev/null ||
    fail "--threads=1 and --threads=2 differ (EXR)"
iinfo -v t1.exr | grep -q 'oiio:ColorSpace: "Linear"' || fail "EXR not tagged linear"

# a region is the same crop of the full image
check
"$bin" render "$model" -o crop.exr $size -q --spp=4 --region=17,9,61,50 ||
    fail "region render failed"
iinfo crop.exr | grep -q '44 x   41, 3 channel' || fail "crop size: $(iinfo crop.exr)"
oiiotool t1.exr --cut 44x41+17+9 -o cut.exr
idiff -fail 0 -failpercent 0 -warn 0 cut.exr crop.exr >/dev/null ||
    fail "--region differs from the crop of the full image"

# --max-depth: 0 turns the mirror and the glass off
check
"$bin" render "$model" -o d5.exr $size -q || fail "default depth failed"
"$bin" render "$model" -o d0.exr $size -q --max-depth=0 || fail "max-depth 0 failed"
idiff -fail 0 -failpercent 0 -warn 0 d0.exr d5.exr >/dev/null 2>&1 &&
    fail "--max-depth=0 changed nothing"

# statistics
check
"$bin" render "$model" -o s.png $size -q --stats >stats.txt || fail "--stats failed"
for key in 'rays:' 'camera 6912,' 'shadow ' 'reflection ' 'refraction ' \
    'primitive tests:' 'span operations:' 'seconds:' 'load ' 'trace ' 'write '; do
    grep -q "$key" stats.txt || fail "--stats lacks '$key': $(cat stats.txt)"
done
"$bin" render "$model" -o s.png $size -q --stats=json >stats.json || fail "--stats=json"
for key in '"camera": 6912' '"shadow": ' '"reflection": ' '"refraction": ' \
    '"primitive_tests": ' '"span_operations": ' '"load": ' '"setup": ' '"trace": ' \
    '"write": ' '"total": '; do
    grep -q "$key" stats.json || fail "--stats=json lacks '$key': $(cat stats.json)"
done
python3 -c 'import json, sys; json.load(open(sys.argv[1]))' stats.json ||
    fail "--stats=json is not JSON"

# the normal and id AOVs
check
"$bin" render "$model" -o a.png $size -q --normal=n.exr --id=id.exr || fail "AOVs failed"
iinfo n.exr | grep -q '96 x   72, 3 channel, float openexr' || fail "n.exr: $(iinfo n.exr)"
iinfo -v n.exr | grep -q 'channel list: X, Y, Z' || fail "normal channels"
iinfo -v id.exr | grep -q 'channel list: id' || fail "id channel"
oiiotool id.exr --printstats | grep -q 'Stats Min: -1.000000' || fail "id has no -1"
oiiotool id.exr --printstats | grep -q 'Stats Max: 2.000000' || fail "id max is not 2"

# the progress bar: on a terminal only, never with --quiet
check
"$bin" render "$model" -o p.png $size 2>err.txt || fail "render failed"
grep -q '\[' err.txt && fail "progress bar on a non-terminal"
script -qc "'$bin' render '$model' -o p.png $size" /dev/null >tty.txt
grep -q '100%' tty.txt || fail "no progress bar on a terminal: $(cat tty.txt)"
script -qc "'$bin' render '$model' -o p.png $size --quiet" /dev/null >tty.txt
[ -s tty.txt ] && fail "--quiet printed on a terminal: $(cat tty.txt)"

# usage errors
check
expect_usage() {
    "$bin" render "$model" -o u.png "$1" >/dev/null 2>err.txt
    rc=$?
    [ "$rc" = 2 ] || fail "$1 exited $rc"
    [ "$(cat err.txt)" = "spancast: error: $2" ] || fail "$1 said '$(cat err.txt)'"
}
expect_usage --spp=0 "--spp expects an integer from 1 to 65536"
expect_usage --max-depth=65 "--max-depth expects an integer from 0 to 64"
expect_usage --region=5,5,5,9 \
    "--region expects X0,Y0,X1,Y1 with 0 <= X0 < X1 and 0 <= Y0 < Y1 (X1, Y1 exclusive)"
expect_usage --stats=xml "--stats takes no value or '=json'"
expect_usage --normal=n.png \
    "cannot write normals to 'n.png': normals needs a floating-point format (.exr or .tif)"
expect_usage --region=0,0,900,10 \
    "region 0,0,900,10 is not a non-empty crop of the 800x600 image"

echo "$checks groups of checks, $fails failed"
[ "$fails" = 0 ]
