# text() and EXR go through plugins loaded on first use: spancast-text.so
# (fontconfig, HarfBuzz, FreeType and what they bring: glib, PCRE2,
# graphite2, Brotli, expat) and spancast-exr.so (OpenEXR, Imath, Iex,
# IlmThread). --version, --help, info and a PNG render of a model without
# text load neither plugin nor any of those libraries (ld.so's own log);
# a text model loads the text plugin, an EXR render (scanline or tiled) and
# reading an EXR back load the EXR plugin; a broken plugin is an error that
# names it, with a non-zero exit and no image.
#
# Run as: bash cli_lazy_text_exr.sh <path-to-spancast> <source-dir> <work-dir>
. "$(dirname "$0")/testlib.sh"

cat >plain.csg <<'CSG'
difference() { cube(10, center = true); sphere(6); }
CSG
cat >text.csg <<'CSG'
group() {
  linear_extrude(height = 2, center = false, convexity = 1, scale = [1, 1], $fn = 0, $fa = 12, $fs = 2) {
    text(text = "Hi", size = 10, spacing = 1, font = "Liberation Sans", direction = "ltr", language = "en", script = "latn", halign = "left", valign = "baseline", $fn = 0, $fa = 12, $fs = 2);
  }
}
CSG

# heavy: the files that only the plugins may load.
heavy='file=[^ ]*(spancast-text\.so|spancast-exr\.so|libfontconfig|libharfbuzz|libfreetype|libglib|libgraphite2|libbrotli|libexpat|libOpenEXR|libImath|libIex|libIlmThread)'
# loads LOG PATTERN: did the run that wrote LOG.* load a file matching PATTERN?
loads() { cat "$1".* 2>/dev/null | grep -Eq "$2"; }

for run in version help info png; do
    check
    case $run in
    version) args=(--version) ;;
    help) args=(--help) ;;
    info) args=(info plain.csg) ;;
    png) args=(render plain.csg -o plain.png --imgsize=32,24 -q) ;;
    esac
    LD_DEBUG=files LD_DEBUG_OUTPUT="$PWD/ld-$run" "$bin" "${args[@]}" >out.txt 2>&1 ||
        fail "$run failed: $(cat out.txt)"
    ! loads "ld-$run" "$heavy" ||
        fail "$run loaded $(cat ld-"$run".* | grep -Eo "$heavy[^ ]*" | sort -u | tr '\n' ' ')"
done

check
LD_DEBUG=files LD_DEBUG_OUTPUT="$PWD/ld-text" "$bin" render text.csg -o text.png \
    --imgsize=64,32 -q >out.txt 2>&1 || fail "render of a text model failed: $(cat out.txt)"
loads ld-text 'file=[^ ]*spancast-text\.so' || fail "a text model did not load spancast-text.so"
loads ld-text 'file=[^ ]*spancast-exr\.so' && fail "a PNG render of text loaded spancast-exr.so"
[ -s text.png ] || fail "no image of the text model"

for how in scanline tiled; do
    check
    extra=()
    [ "$how" = tiled ] && extra=(--tiled)
    LD_DEBUG=files LD_DEBUG_OUTPUT="$PWD/ld-$how" "$bin" render plain.csg -o "$how.exr" \
        --imgsize=32,24 -q "${extra[@]}" >out.txt 2>&1 ||
        fail "$how EXR render failed: $(cat out.txt)"
    loads "ld-$how" 'file=[^ ]*spancast-exr\.so' || fail "a $how EXR did not load spancast-exr.so"
    loads "ld-$how" 'file=[^ ]*spancast-text\.so' && fail "a $how EXR loaded spancast-text.so"
    [ "$(head -c 4 "$how.exr" | od -An -tx1 | tr -d ' ')" = 762f3101 ] ||
        fail "$how.exr is not an EXR file"
done
# Broken plugins (another plugin under their names) beside a copy of the
# tool: an error naming the plugin and what it lacks, a non-zero exit, no
# image.
mkdir broken
cp "$bin" broken/spancast
cp "$(dirname "$bin")/spancast-tiff.so" broken/spancast-text.so
cp "$(dirname "$bin")/spancast-tiff.so" broken/spancast-exr.so
check
if broken/spancast render text.csg -o broken.png -q 2>err.txt; then
    fail "a broken text plugin was not an error"
fi
grep -q "^text.csg:3:5: error: text: cannot load the text plugin (spancast-text.so): it lacks spancast_text_layout$" err.txt ||
    fail "broken text plugin message: $(cat err.txt)"
[ -e broken.png ] && fail "an image was written with a broken text plugin"
for how in scanline tiled; do
    check
    extra=()
    [ "$how" = tiled ] && extra=(--tiled)
    if broken/spancast render plain.csg -o "broken-$how.exr" --imgsize=32,24 -q \
        "${extra[@]}" 2>err.txt; then
        fail "a broken EXR plugin was not an error ($how)"
    fi
    grep -q "cannot load the EXR plugin (spancast-exr.so): it lacks spancast_exr_write" err.txt ||
        fail "broken EXR plugin message ($how): $(cat err.txt)"
    [ -e "broken-$how.exr" ] && fail "an image was written with a broken EXR plugin ($how)"
done
# A PNG render needs neither plugin: the broken ones are never opened.
check
broken/spancast render plain.csg -o fine.png --imgsize=32,24 -q 2>err.txt ||
    fail "a PNG render beside broken text and EXR plugins failed: $(cat err.txt)"

echo "$checks checks, $fails failures"
[ "$fails" = 0 ]
