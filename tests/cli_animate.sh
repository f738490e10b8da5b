# `spancast render --animate / --turntable / --shutter / --video`
# (src/cli/frames.c). Frames of a .scad model match, byte for byte, single
# renders of the .csg files OpenSCAD's own --animate exports (same $t,
# same names); the frames differ, so $t reaches the model; a second run
# writes the same bytes; a turntable frame is the render from the turned
# camera; a frame with an open shutter is the mean of its sub-frames; the
# video has one frame per frame and a missing ffmpeg is a clear error; bad
# combinations are usage errors. OpenSCAD's part is skipped (exit 77)
# without openscad, the video's without ffmpeg.
#
# Run as: bash cli_animate.sh <path-to-spancast> <source-dir> <work-dir>
. "$(dirname "$0")/testlib.sh"
mkdir -p "$work/tmp"
export TMPDIR="$work/tmp"
view=(--imgsize=64,48 --camera=10,-40,20,10,0,0 --threads=1 -q)

# ---- usage errors ----
expect_usage() { # WANT ARGS...
    local want=$1
    shift
    "$bin" render "$src/models/knob_part.csg" -o usage.png "$@" 2>err.txt
    local rc=$?
    check
    [ "$rc" = 2 ] || fail "$*: exit $rc (want 2)"
    [ "$(cat err.txt)" = "spancast: error: $want" ] || fail "$*: got '$(cat err.txt)'"
    ls usage*.png >/dev/null 2>&1 && fail "$*: an image was written"
}
expect_usage "--animate expects a number of frames from 1 to 99999" --animate=0
expect_usage "--subframes, --video and --fps need --animate or --turntable" \
    --subframes=3
expect_usage "--shutter expects OPEN,CLOSE with 0 <= OPEN <= CLOSE <= 1 (fractions of a frame)" \
    --animate=2 --shutter=0.5,0.2
expect_usage "--animate and --turntable must give the same number of frames" \
    --animate=2 --turntable=3
expect_usage "--animate and --turntable write colour frames only (no --mask, --depth, --normal, --id or --watch)" \
    --animate=2 --depth=d.exr

# ---- turntable on a .csg ----
"$bin" render "$src/models/knob_part.csg" -o turn.png --turntable=4 --imgsize=64,48 \
    --threads=1 -q || fail "turntable did not render"
for i in 0 1 2 3; do
    check
    [ -f "turn0000$i.png" ] || fail "turntable: turn0000$i.png missing"
done
"$bin" render "$src/models/knob_part.csg" -o one.png --camera=0,0,0,55,0,115,140 \
    --viewall --autocenter --imgsize=64,48 --threads=1 -q
check
cmp -s turn00001.png one.png || fail "turntable frame 1 is not the view turned by 90 degrees"
cmp -s turn00000.png turn00001.png && fail "turntable frames 0 and 1 are the same"

# ---- --animate alone on a .csg: the frames are written, with a warning
# that they are all the same ----
"$bin" render "$src/models/knob_part.csg" -o same.png --animate=2 --imgsize=16,12 \
    --threads=1 -q 2>err.txt
rc=$?
check
[ "$rc" = 0 ] || fail "--animate on a .csg: exit $rc: $(cat err.txt)"
want="spancast: warning: --animate: $src/models/knob_part.csg is not a .scad, so \$t changes nothing and every frame is the same image (--turntable turns the camera)"
[ "$(cat err.txt)" = "$want" ] || fail "--animate on a .csg: got '$(cat err.txt)'"
cmp -s same00000.png same00001.png || fail "--animate on a .csg: the frames differ"

# ---- video ----
if command -v ffmpeg >/dev/null && command -v ffprobe >/dev/null; then
    "$bin" render "$src/models/knob_part.csg" -o v.png --turntable=5 --video=turn.mp4 \
        --fps=10 --imgsize=63,47 --threads=1 -q || fail "video: exit $?"
    frames=$(ffprobe -v error -count_frames -select_streams v:0 \
        -show_entries stream=nb_read_frames -of csv=p=0 turn.mp4)
    check
    [ "$frames" = 5 ] || fail "video: $frames frames (want 5)"
    ls turn.tmp* >/dev/null 2>&1 && fail "video: a temporary file was left"
    # through a symbolic link into another folder, over a private file: the
    # link stays, the file it names is replaced and keeps its mode
    mkdir -p videos
    printf 'old' >videos/private.mp4
    chmod 600 videos/private.mp4
    ln -sf videos/private.mp4 linked.mp4
    "$bin" render "$src/models/knob_part.csg" -o l.png --turntable=2 --video=linked.mp4 \
        --fps=10 --imgsize=16,12 --threads=1 -q || fail "video through a link: exit $?"
    check
    [ -L linked.mp4 ] || fail "video through a link: the link was replaced"
    [ "$(cat videos/private.mp4)" != old ] || fail "video through a link: not written"
    [ "$(stat -c %a videos/private.mp4)" = 600 ] ||
        fail "video over a 0600 file: mode $(stat -c %a videos/private.mp4)"
    ls videos/*.tmp* linked.tmp* >/dev/null 2>&1 && fail "video through a link: a temporary was left"
fi
printf 'old' >kept.mp4
PATH=/nonexistent "$bin" render "$src/models/knob_part.csg" -o nv.png --turntable=1 \
    --video=kept.mp4 --imgsize=16,12 -q 2>err.txt
rc=$?
check
[ "$rc" = 1 ] || fail "without ffmpeg: exit $rc (want 1)"
want="spancast: error: cannot encode 'kept.mp4': ffmpeg is not installed ('ffmpeg' was not found in PATH); the frames are written"
[ "$(cat err.txt)" = "$want" ] || fail "without ffmpeg: got '$(cat err.txt)'"
[ "$(cat kept.mp4)" = old ] || fail "without ffmpeg: the earlier video was touched"

# ---- .scad animation against OpenSCAD's own --animate ----
require_tools openscad
cat >slide.scad <<'EOF'
translate([20 * $t, 0, 0]) rotate([0, 0, 90 * $t]) cube([8, 4, 4], center = true);
EOF
"$bin" render slide.scad -o frame.png --animate=5 "${view[@]}" || fail "animate: exit $?"
openscad --animate 5 -o "$work/ref.csg" "$work/slide.scad" >/dev/null 2>&1 ||
    fail "openscad --animate failed"
for i in 0 1 2 3 4; do
    "$bin" render "ref0000$i.csg" -o "ref0000$i.png" "${view[@]}" ||
        fail "ref0000$i.csg did not render"
    check
    cmp -s "frame0000$i.png" "ref0000$i.png" ||
        fail "frame $i differs from OpenSCAD's export at the same \$t"
done
check
cmp -s frame00000.png frame00002.png && fail "\$t does not reach the model"
mkdir again
(cd again && "$bin" render ../slide.scad -o frame.png --animate=5 "${view[@]}")
for i in 0 1 2 3 4; do
    check
    cmp -s "frame0000$i.png" "again/frame0000$i.png" || fail "frame $i is not deterministic"
done
[ -z "$(ls -A "$work/tmp")" ] || fail "temporary files left: $(ls -A "$work/tmp")"

# An open shutter: frame 1 of 2 over its whole interval, 4 sub-frames, is
# the mean of the renders at $t = (1 + (k + 0.5) / 4) / 2 (linear light,
# compared in EXR).
"$bin" render slide.scad -o blur.exr --animate=2 --shutter=0,1 --subframes=4 "${view[@]}" ||
    fail "shutter: exit $?"
for k in 0 1 2 3; do
    t=$(awk "BEGIN { printf \"%.17g\", (1 + ($k + 0.5) / 4) / 2 }")
    sed "s/\\\$t/$t/g" slide.scad >"sub$k.scad"
    "$bin" render "sub$k.scad" -o "sub$k.exr" "${view[@]}" || fail "sub-frame $k: exit $?"
done
oiiotool sub0.exr sub1.exr --add sub2.exr --add sub3.exr --add --mulc 0.25 -o mean.exr
check
idiff -q -fail 1e-5 -warn 1e-5 blur00001.exr mean.exr >/dev/null ||
    fail "the blurred frame is not the mean of its sub-frames"
idiff -q -fail 1e-3 blur00001.exr sub0.exr >/dev/null &&
    fail "the blurred frame equals one sub-frame"

if [ "$fails" != 0 ]; then
    echo "$fails failure(s)"
    exit 1
fi
echo "cli_animate: all $checks checks passed"
