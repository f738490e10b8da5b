# `spancast render --tiled` (and images too large to hold whole): tiled
# EXR and TIFF files written tile by tile, pixel for pixel the whole render's, in
# bounded memory, through a temporary; outputs that cannot be streamed are
# refused before any work.
#
# Run as: bash cli_tiled.sh <path-to-spancast> <source-dir> <work-dir>
. "$(dirname "$0")/testlib.sh"
require_tools idiff iinfo

cat >m.csg <<'CSG'
difference() {
  cube(size = [10, 10, 10], center = true);
  sphere(r = 6.5, $fn = 0, $fa = 12, $fs = 2);
}
CSG

# The same pixels as one render, every output, with samples and edges:
# tiled EXR against the scanline EXR, tiled TIFF (libtiff) against the
# untiled TIFF (which OpenImageIO writes); in tiles, compressed.
opts=(--imgsize=300,200 --spp=2 --view=edges -q)
for ext in exr tif; do
    check
    "$bin" render m.csg -o "whole.$ext" --mask="whole-mask.$ext" --depth="whole-depth.$ext" \
        --normal="whole-normal.$ext" --id="whole-id.$ext" "${opts[@]}" ||
        fail "whole .$ext render failed"
    "$bin" render m.csg -o "tiled.$ext" --mask="tiled-mask.$ext" --depth="tiled-depth.$ext" \
        --normal="tiled-normal.$ext" --id="tiled-id.$ext" "${opts[@]}" --tiled ||
        fail "--tiled .$ext failed"
    for out in "" -mask -depth -normal -id; do
        check
        idiff -fail 0 -warn 0 "whole$out.$ext" "tiled$out.$ext" >idiff.txt 2>&1 ||
            fail "tiled$out.$ext differs from whole$out.$ext: $(tail -n 3 idiff.txt)"
        iinfo -v "tiled$out.$ext" >info.txt
        grep -q 'tile size: 32 x 32' info.txt && grep -q 'compression: "zip"' info.txt ||
            fail "tiled$out.$ext is not tiled and compressed: $(head -n 6 info.txt)"
    done
done
iinfo tiled-mask.tif | grep -q '300 x  200, 1 channel, uint8 tiff' ||
    fail "tiled-mask.tif: $(iinfo tiled-mask.tif)"
iinfo tiled.tif | grep -q '300 x  200, 3 channel, float tiff' || fail "tiled.tif: $(iinfo tiled.tif)"
ls -a | grep -q '\.tmp-' && fail "a temporary was left behind: $(ls -a | grep '\.tmp-')"

# libtiff is loaded only by a streamed TIFF, through its plugin: a PNG or a
# tiled EXR render loads neither it nor OpenImageIO (ld.so's own log).
for out in png exr; do
    check
    extra=()
    [ "$out" = exr ] && extra=(--tiled)
    LD_DEBUG=files LD_DEBUG_OUTPUT="$PWD/ld-$out" "$bin" render m.csg -o "lean.$out" \
        --imgsize=32,24 -q "${extra[@]}" || fail "the .$out render failed"
    ! cat ld-"$out".* | grep -Eq 'file=[^ ]*(libtiff|libOpenImageIO)' ||
        fail "a .$out render loaded $(cat ld-"$out".* | grep -Eo 'file=[^ ]*(libtiff|libOpenImageIO)[^ ]*' | sort -u | tr '\n' ' ')"
done
check
LD_DEBUG=files LD_DEBUG_OUTPUT="$PWD/ld-tif" "$bin" render m.csg -o lean.tif --imgsize=32,24 \
    -q --tiled || fail "the tiled .tif render failed"
cat ld-tif.* | grep -Eq 'file=[^ ]*spancast-tiff\.so' || fail "a tiled .tif did not load spancast-tiff.so"

# A crop, tiled, is the crop.
check
"$bin" render m.csg -o crop.exr --region=10,20,250,180 --imgsize=300,200 -q ||
    fail "crop failed"
"$bin" render m.csg -o crop-tiled.exr --region=10,20,250,180 --imgsize=300,200 -q --tiled ||
    fail "tiled crop failed"
idiff -fail 0 -warn 0 crop.exr crop-tiled.exr >idiff.txt 2>&1 ||
    fail "tiled crop differs: $(tail -n 3 idiff.txt)"

# Only EXR and TIFF are written tile by tile: other outputs are refused up front,
# and an existing file is left alone.
check
echo keep >keep.png
"$bin" render m.csg -o keep.png --tiled -q 2>err.txt
rc=$?
[ "$rc" = 2 ] || fail "--tiled to .png exited $rc"
grep -qx "spancast: error: cannot write 'keep.png': --tiled writes each tile as it is done; only .exr and .tif outputs are written tile by tile" err.txt ||
    fail "--tiled to .png: '$(cat err.txt)'"
[ "$(cat keep.png)" = keep ] || fail "--tiled to .png touched keep.png"
# An image whose buffers do not fit anywhere must be streamed: a PNG of it
# is refused with the budget's reason, before any work.
check
"$bin" render m.csg -o huge.png --imgsize=200000,200000 -q 2>err.txt
rc=$?
[ "$rc" = 2 ] || fail "a 200000x200000 PNG exited $rc"
grep -qx "spancast: error: cannot write 'huge.png': a 200000x200000 render needs 447.0 GiB of image buffers (limit is 16 GiB); only .exr and .tif outputs are written tile by tile" err.txt ||
    fail "a 200000x200000 PNG: '$(cat err.txt)'"
[ -e huge.png ] && fail "huge.png was written"

# Interrupted while the tiles are being written: the temporary is
# removed, the existing target is left as it was, and the tool dies of
# the signal.
check
echo keep >keep.exr
"$bin" render m.csg -o keep.exr --imgsize=4000,3000 --spp=4 --tiled -q 2>int.txt &
pid=$!
for _ in $(seq 600); do # up to 60 s for the first tile to reach the file
    ls -a | grep -q '^\.keep\.tmp-' && break
    sleep 0.1
done
ls -a | grep -q '^\.keep\.tmp-' || fail "no temporary appeared for keep.exr"
kill -TERM "$pid" # (a background job of a script ignores SIGINT)
wait "$pid"
rc=$?
[ "$rc" = 143 ] || fail "the interrupted tiled render exited $rc: $(cat int.txt)"
grep -qx "spancast: interrupted" int.txt || fail "interrupted: '$(cat int.txt)'"
[ "$(cat keep.exr)" = keep ] || fail "the interrupted render touched keep.exr"
ls -a | grep -q '\.tmp-' && fail "the interrupted render left $(ls -a | grep '\.tmp-')"

# Memory: colour, depth and normals of 4000 x 3000 pixels take 336 MB as
# buffers; streamed, the peak (GNU time's %M, KiB) stays under a third of
# that. The model is small in the frame, so most rays miss and the run is
# short. The image is this large so that the fixed cost, which does not
# grow with it, stays small beside it in both builds: an 8 x 8 render peaks
# at about 8 MB, and at about 25 MB under AddressSanitizer, whose freed
# tiles also wait in its quarantine (kept small, or it would be counted).
# The same for tiled TIFF.
if [ -x /usr/bin/time ]; then
    for ext in exr tif; do
        check
        ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}quarantine_size_mb=4 \
            /usr/bin/time -f %M -o rss.txt "$bin" render m.csg -o "big.$ext" \
            --depth="big-depth.$ext" --normal="big-normal.$ext" --imgsize=4000,3000 \
            --camera=0,0,0,55,0,25,3000 --tiled -q || fail "the 4000x3000 tiled .$ext render failed"
        peak_kib=$(tail -n 1 rss.txt)
        buffers_kib=$((4000 * 3000 * 28 / 1024))
        [ "$peak_kib" -lt $((buffers_kib / 3)) ] ||
            fail ".$ext: peak memory $peak_kib KiB, not under a third of the image's $buffers_kib KiB"
    done
    iinfo big.exr | grep -q '4000 x 3000, 3 channel, float openexr' ||
        fail "big.exr: $(iinfo big.exr)"
    iinfo big.tif | grep -q '4000 x 3000, 3 channel, float tiff' || fail "big.tif: $(iinfo big.tif)"
else
    skip "GNU time (/usr/bin/time) is not installed"
fi

echo "$checks checks, $fails failures"
[ "$fails" = 0 ]
