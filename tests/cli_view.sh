# spancast view and spancast render --watch, end to end.
#
# Without a display, view fails with a clear error and exit 1, and render's
# preview options are refused with render's own messages. Then, under Xvfb
# (xvfb-run), the viewer is driven with real input events (xdotool) and
# its window captured (ImageMagick's import): a drag changes the image, P/O
# switch the projection; Ctrl+3 (the renderer's crosshairs), Ctrl+1
# (edges), Ctrl+2 (axes and scales), X (a section plane) and A (ambient
# occlusion) each change the image and put their render option in the
# title, and pressed again restore both; C picks the next colour scheme;
# Ctrl+S writes a screenshot with edges, the scheme and a hatched section
# (--section-style on the command line) that equals `spancast render` with
# the printed options pixel for pixel; a click prints what the ray hit,
# rewriting the model makes the new geometry appear with the camera kept,
# a broken file keeps the old image and shows its error (title, red frame,
# stderr), a warning shows in the title and on stderr, and Ctrl+Q quits.
# render --watch renders again when the model or a file a .scad includes
# changes, keeps the last image when the model breaks, and dies of SIGINT.
#
# The viewer's state is read from its title ("done" once the view is fully
# refined, "load #N" after N loads, the view as render options). Waits are
# polls with generous guards (the sanitizer build renders far slower);
# nothing is timed.
#
# Run as: bash cli_view.sh <path-to-spancast> <source-dir> <work-dir>
. "$(dirname "$0")/testlib.sh"

# Under the sanitizers, the display libraries' own leaks (X11, SDL's
# drivers) are suppressed by library name; spancast's are still reported.
export LSAN_OPTIONS="suppressions=$src/tests/view.lsan-suppressions${LSAN_OPTIONS:+:$LSAN_OPTIONS}"

if [ -z "${SPANCAST_VIEW_XVFB:-}" ]; then
    # ---- without a display
    printf 'cube([10, 10, 10]);\n' >m.csg
    checks=$((checks + 1))
    env -u DISPLAY -u WAYLAND_DISPLAY -u SDL_VIDEODRIVER "$bin" view m.csg \
        >out.txt 2>err.txt
    st=$?
    [ "$st" = 1 ] || fail "no display: exit $st, expected 1"
    grep -q "^spancast: error: view needs a display" err.txt ||
        fail "no display: message: $(cat err.txt)"
    for driver in dummy offscreen; do
        checks=$((checks + 1))
        SDL_VIDEODRIVER=$driver "$bin" view m.csg >out.txt 2>err.txt
        st=$?
        [ "$st" = 1 ] || fail "SDL_VIDEODRIVER=$driver: exit $st, expected 1"
        grep -q "^spancast: error: view needs a display (SDL's video driver '$driver'" \
            err.txt || fail "SDL_VIDEODRIVER=$driver: message: $(cat err.txt)"
    done
    checks=$((checks + 1))
    "$bin" view missing.csg >out.txt 2>err.txt
    st=$?
    [ "$st" = 1 ] || fail "missing model: exit $st, expected 1"
    grep -qx "spancast: error: cannot open 'missing.csg': No such file or directory" \
        err.txt || fail "missing model: message: $(cat err.txt)"
    checks=$((checks + 1))
    "$bin" view >out.txt 2>err.txt
    st=$?
    [ "$st" = 2 ] || fail "no model: exit $st, expected 2"
    "$bin" view --help >out.txt 2>err.txt || fail "view --help: exit $?"
    grep -q "^usage: spancast view MODEL" out.txt || fail "view --help: $(cat out.txt)"
    "$bin" view m.csg --spp=0 >out.txt 2>err.txt
    st=$?
    [ "$st" = 2 ] || fail "--spp=0: exit $st, expected 2"
    # render's preview options, read with render's checks and messages
    checks=$((checks + 1))
    for option in --colorscheme=Nope --view=edges,bogus --section=1,2 --lighting=x \
        --view-preset=up --ao=-1 --edge-width=17; do
        "$bin" view m.csg "$option" >out.txt 2>err.txt
        st=$?
        [ "$st" = 2 ] || fail "view $option: exit $st, expected 2"
        "$bin" render m.csg -o m.png "$option" >out.txt 2>render.txt
        cmp -s err.txt render.txt ||
            fail "view $option: '$(cat err.txt)', render says '$(cat render.txt)'"
    done

    # ---- render --watch: a .csg
    checks=$((checks + 1))
    printf 'cube([10, 10, 10]);\n' >w.csg
    # job control on, so that the background job does not start with SIGINT
    # ignored
    set -m
    "$bin" render w.csg -o w.png --imgsize=80,60 --watch >watch.out 2>watch.err &
    pid=$!
    set +m
    for ((k = 0; k < 300; k++)); do
        [ -s w.png ] && break
        sleep 0.1
    done
    [ -s w.png ] || fail "render --watch: no first image in 30 s"
    first=$(sha256sum <w.png)
    sleep 0.3 # a change within the first render's second would have the same mtime
    printf 'sphere(r = 8);\n' >w.csg
    for ((k = 0; k < 300; k++)); do
        [ "$(sha256sum <w.png)" != "$first" ] && break
        sleep 0.1
    done
    second=$(sha256sum <w.png)
    [ "$second" != "$first" ] || fail "render --watch: no new image 30 s after the change"
    printf 'sphere(r = 8\n' >w.csg
    for ((k = 0; k < 300; k++)); do
        grep -q "w.csg:2:1: error:" watch.err && break
        sleep 0.1
    done
    grep -q "w.csg:2:1: error:" watch.err ||
        fail "render --watch: broken model: no error: $(cat watch.err)"
    [ "$(sha256sum <w.png)" = "$second" ] || fail "render --watch: a broken model changed w.png"
    kill -INT "$pid"
    wait "$pid"
    st=$?
    [ "$st" = 130 ] || fail "render --watch: SIGINT: exit $st, expected 130"
    grep -q "^spancast: interrupted" watch.err || fail "render --watch: no 'interrupted'"

    # ---- render --watch: a file a .scad model includes
    # poll SECONDS COMMAND...: until the command succeeds; 1 if it never does.
    poll() {
        local k
        for ((k = 0; k < $1 * 10; k++)); do
            "${@:2}" && return 0
            sleep 0.1
        done
        return 1
    }
    changed() { [ "$(sha256sum <"$1")" != "$2" ]; }
    # watch_scad MODEL OUT: render --watch in the background, as $pid,
    # with stderr in MODEL.err.
    watch_scad() {
        set -m
        "$bin" render "$1" -o "$2" --imgsize=80,60 --watch >"$1.out" 2>"$1.err" &
        pid=$!
        set +m
    }
    if command -v openscad >/dev/null; then
        checks=$((checks + 1))
        printf 'size = 10;\n' >inc.scad
        printf 'include <inc.scad>\ncube(size);\n' >w.scad
        watch_scad w.scad s.png
        poll 60 test -s s.png || fail "render --watch .scad: no first image in 60 s"
        first=$(sha256sum <s.png)
        sleep 0.3
        printf 'size = 4;\n' >inc.scad
        poll 60 changed s.png "$first" ||
            fail "render --watch .scad: no new image 60 s after inc.scad changed"
        grep -q "^spancast: .*inc\.scad changed, rendering again$" w.scad.err ||
            fail "render --watch .scad: the change not put on inc.scad: $(cat w.scad.err)"
        kill -INT "$pid"
        wait "$pid"

        # a .scad that never converted: OpenSCAD's error at its position;
        # the files its text names (OpenSCAD writes no dependency file when
        # it fails) are watched: changing the mesh it imports converts it
        # again, and fixing the file it includes renders it
        checks=$((checks + 1))
        printf 'size = 10\n' >broken.scad
        printf 'solid m\nendsolid m\n' >mesh.stl
        printf '// the size\ninclude <broken.scad>\ncube(size);\n%s\n' \
            'module unused() { import(file = "mesh.stl"); }' >nb.scad
        watch_scad nb.scad nb.png
        poll 60 grep -q "error:" nb.scad.err
        [ "$(head -n 1 nb.scad.err)" = "nb.scad:3:1: error: Parser error: syntax error" ] ||
            fail "render --watch broken .scad: $(cat nb.scad.err)"
        twice() { [ "$(grep -c "error:" nb.scad.err)" -ge 2 ]; }
        sleep 0.3
        printf 'solid m\nendsolid m\n\n' >mesh.stl
        poll 60 twice || fail "render --watch broken .scad: mesh.stl not watched: $(cat nb.scad.err)"
        printf 'size = 6;\n' >broken.scad
        poll 60 test -s nb.png || fail "render --watch broken .scad: no image 60 s after the fix"
        kill -INT "$pid"
        wait "$pid"
    fi

    # ---- the window, under Xvfb
    require_tools xvfb-run xdotool import compare convert
    SPANCAST_VIEW_XVFB=1 SPANCAST_VIEW_FAILS=$fails SPANCAST_VIEW_CHECKS=$checks \
        xvfb-run -a -n 140 -s "-screen 0 1024x768x24" bash "$src/tests/cli_view.sh" "$bin" "$src" \
        "$work.xvfb"
    exit $?
fi

fails=${SPANCAST_VIEW_FAILS:-0}
checks=${SPANCAST_VIEW_CHECKS:-0}
W=200
H=150

# title: the viewer's window title.
title() {
    xdotool getwindowname "$wid" 2>/dev/null
}

# wait_title PATTERN SECONDS: waits until the title matches the glob.
wait_title() {
    local k t
    for ((k = 0; k < $2 * 10; k++)); do
        t=$(title)
        # shellcheck disable=SC2053 # a glob on purpose
        [[ "$t" == $1 ]] && return 0
        sleep 0.1
    done
    echo "title after $2 s: $t"
    return 1
}

# wait_file FILE PATTERN SECONDS: waits until a line of FILE matches the
# extended regular expression.
wait_file() {
    local k
    for ((k = 0; k < $3 * 10; k++)); do
        grep -Eq "$2" "$1" && return 0
        sleep 0.1
    done
    return 1
}

# camera: the --camera option in the title.
camera() {
    title | grep -o -- '--camera=[^ ]*'
}

capture() {
    import -window "$wid" "$1"
}

# differ A B: the number of pixels that differ.
differ() {
    compare -metric AE "$1" "$2" null: 2>&1
}

# pixel IMAGE X Y: "srgb(R,G,B)".
pixel() {
    convert "$1" -format "%[pixel:p{$2,$3}]" info:
}

cat >m.csg <<'EOF'
difference() {
  cube([20, 20, 20]);
  multmatrix([[1, 0, 0, 10], [0, 1, 0, 10], [0, 0, 1, -1], [0, 0, 0, 1]]) {
    cylinder(r1 = 5, r2 = 5, h = 22);
  }
}
EOF
"$bin" view m.csg --imgsize=$W,$H --spp=2 --verbose --section-style hatch >view.out \
    2>view.err &
pid=$!
wid=$(timeout 60 xdotool search --sync --name '^spancast view' | head -n 1)
if [ -z "$wid" ]; then
    fail "no viewer window in 60 s: $(cat view.err)"
    kill "$pid" 2>/dev/null
    exit 1
fi
xdotool mousemove --window "$wid" $((W / 2)) $((H / 2))

# the first view, refined
checks=$((checks + 1))
wait_title "* - done - load #1 *" 120 || fail "first view: never done"
capture a.png
convert -size ${W}x$H xc:'#ffffe5' background.png
n=$(differ a.png background.png)
[ "$n" -gt 1000 ] || fail "first view: only $n pixels differ from the background"
grep -q "^loaded m.csg in " view.out || fail "first view: no 'loaded' line"

# a left drag rotates
checks=$((checks + 1))
before=$(camera)
xdotool mousedown 1
for ((k = 0; k < 10; k++)); do
    xdotool mousemove_relative -- 6 2
    sleep 0.05
done
xdotool mouseup 1
for ((k = 0; k < 1200; k++)); do
    [ "$(camera)" != "$before" ] && [[ "$(title)" == *" - done - "* ]] && break
    sleep 0.1
done
[ "$(camera)" != "$before" ] || fail "drag: the camera did not move"
[[ "$(title)" == *" - done - "* ]] || fail "drag: never done: $(title)"
capture b.png
n=$(differ a.png b.png)
[ "$n" -gt 200 ] || fail "drag: only $n pixels changed"
grep -q "^frame coarse " view.out || fail "drag: no coarse frame"

# O switches to orthographic, P back; Ctrl+3 draws the crosshairs
checks=$((checks + 1))
xdotool key o
wait_title "* - done - *--projection=o * - orthographic" 120 || fail "O: not orthographic"
grep -q "^orthographic$" view.out || fail "O: no 'orthographic' line"
capture c.png
n=$(differ b.png c.png)
[ "$n" -gt 50 ] || fail "O: only $n pixels changed"
xdotool key p
wait_title "* - done - *--projection=p --fov=22.5 --spp=2 - perspective" 120 ||
    fail "P: not perspective"
grep -q "^perspective$" view.out || fail "P: no 'perspective' line"
capture c0.png

# toggle KEY OPTION NAME: the key puts OPTION into the title's render
# options and changes the image; the same key takes it out again and the
# image is the one before.
toggle() {
    checks=$((checks + 1))
    xdotool key "$1"
    wait_title "* - done - *--spp=2 $2 - *" 120 || fail "$3: not in the title"
    capture t1.png
    n=$(differ c0.png t1.png)
    [ "$n" -gt 20 ] || fail "$3: only $n pixels changed"
    grep -q "^$3 on$" view.out || fail "$3: no '$3 on' line"
    xdotool key "$1"
    wait_title "* - done - *--spp=2 - *" 120 || fail "$3: not off again: $(title)"
    capture t2.png
    n=$(differ c0.png t2.png)
    [ "$n" = 0 ] || fail "$3: off again, $n pixels differ from before"
}
toggle ctrl+3 --view=crosshairs crosshairs
toggle ctrl+1 --view=edges edges
toggle ctrl+2 --view=axes,scales axes
toggle x "--section=*,* --section-style=hatch" section
toggle a --ao=8 "ambient occlusion"

# C: the next colour scheme after Cornfield, the first of those known
checks=$((checks + 1))
xdotool key c
wait_title "* - done - *--spp=2 *--colorscheme=* - *" 120 || fail "C: no scheme in the title"
grep -q "^colour scheme " view.out || fail "C: no 'colour scheme' line"

# screenshot_line FILE: the first 'screenshot:' line of FILE as $line, its
# image as $shot and the arguments of its render command as $command.
screenshot_line() {
    line=$(grep "^screenshot: " "$1" | head -n 1)
    shot=$(echo "$line" | sed 's/^screenshot: \([^:]*\): .*/\1/')
    command=$(echo "$line" | sed 's/^screenshot: [^:]*: spancast render //')
}

# Ctrl+S: the screenshot, with edges, the scheme and a hatched section, is
# what `spancast render` writes with the printed options
checks=$((checks + 1))
xdotool key ctrl+1
xdotool key x
wait_title "* - done - *--view=edges --section=* --section-style=hatch - *" 120 ||
    fail "screenshot: edges and section not on: $(title)"
xdotool key ctrl+s
if wait_file view.out "^screenshot: " 120; then
    screenshot_line view.out
    case "$command" in
    "m.csg -o $shot --camera="*"--colorscheme="*" --view=edges --section="*) ;;
    *) fail "screenshot: unexpected command: $line" ;;
    esac
    # shellcheck disable=SC2086 # the printed options, split as a shell would
    eval "\"\$bin\" render $command -q -o reference.png"
    n=$(differ "$shot" reference.png)
    [ "$n" = 0 ] || fail "screenshot: $n pixels differ from spancast render ($line)"
    xdotool key ctrl+1
    xdotool key x
    wait_title "* - done - *--colorscheme=* - section off" 120 ||
        fail "screenshot: edges and section not off again: $(title)"
else
    fail "screenshot: no 'screenshot:' line in 120 s"
fi

# a click picks: the leaf hit, its source position, the spans
checks=$((checks + 1))
wait_title "* - done - *" 120
xdotool mousemove --window "$wid" $((W / 2 + 30)) $((H / 2)) click 1
if wait_file view.out "^pick $((W / 2 + 30)),$((H / 2)): " 30; then
    grep -Eq "^pick $((W / 2 + 30)),$((H / 2)): (box|cylinder) \(leaf [01]\) at m\.csg:[23]:[0-9]+, distance [0-9.]+, [0-9]+ spans?$" \
        view.out || fail "pick: $(grep '^pick' view.out)"
    grep -Eq "^  span 1: length [0-9.e+-]+, in t=" view.out || fail "pick: no spans"
else
    fail "pick: no 'pick' line"
fi
wait_title "* - pick $((W / 2 + 30)),$((H / 2)): *" 30 || fail "pick: not in the title"

# rewriting the model makes the new geometry appear, the camera stays
checks=$((checks + 1))
wait_title "* - done - *" 120
capture e0.png
before=$(camera)
cat >m.csg.new <<'EOF'
union() {
  cube([20, 20, 20]);
  multmatrix([[1, 0, 0, 10], [0, 1, 0, 10], [0, 0, 1, 20], [0, 0, 0, 1]]) {
    sphere(r = 8);
  }
}
EOF
mv m.csg.new m.csg
wait_title "* - done - load #2 *" 30 || fail "reload: not reloaded and done in 30 s"
[ "$(camera)" = "$before" ] || fail "reload: the camera moved: $before -> $(camera)"
capture e.png
n=$(differ e0.png e.png)
[ "$n" -gt 200 ] || fail "reload: only $n pixels changed"

# a broken file: the old image stays, the error shows in the title, a red
# frame and on stderr
checks=$((checks + 1))
printf 'union() {\n  cube([20, 20, 20]);\n  sphere(r = 8;\n}\n' >m.csg
wait_file view.err "^m\.csg:3:15: error: " 30 ||
    fail "broken model: no error on stderr: $(cat view.err)"
wait_title "* - ERROR m.csg:3:15: error: *" 30 || fail "broken model: no error in the title"
capture f.png
[ "$(pixel f.png 1 1)" = "srgb(208,16,16)" ] || fail "broken model: no red frame"
convert e.png -crop $((W - 8))x$((H - 8))+4+4 +repage e-inner.png
convert f.png -crop $((W - 8))x$((H - 8))+4+4 +repage f-inner.png
n=$(differ e-inner.png f-inner.png)
[ "$n" = 0 ] || fail "broken model: $n pixels of the old image changed"
printf 'cube([20, 20, 30]);\n' >m.csg
wait_title "* - done - load #3 *" 30 || fail "fixed model: not reloaded in 30 s"
case "$(title)" in
*ERROR*) fail "fixed model: the error stayed in the title" ;;
esac

# a model with a warning: on stderr as render prints it, and in the title
checks=$((checks + 1))
printf 'cube([20, 20, 30]) sphere(r = 8);\n' >m.csg
want="m.csg:1:1: module cube() does not support child modules"
wait_title "* - WARNING $want - done - load #4 *" 30 || fail "warning: not in the title"
grep -qxF "m.csg:1:1: warning: module cube() does not support child modules" view.err ||
    fail "warning: not on stderr: $(cat view.err)"

# Ctrl+Q quits
checks=$((checks + 1))
xdotool key ctrl+q
for ((k = 0; k < 300; k++)); do
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.1
done
if kill -0 "$pid" 2>/dev/null; then
    fail "Ctrl+Q: still running after 30 s"
    kill "$pid"
fi
wait "$pid"
st=$?
[ "$st" = 0 ] || fail "Ctrl+Q: exit $st: $(cat view.err)"

# A .scad whose include is broken from the start: OpenSCAD's error at its
# position in the title and on stderr, and fixing the include (known only
# from the source) loads it. Refining adds passes up to --spp; a screenshot
# slower than --max-time is given up and writes nothing.
if command -v openscad >/dev/null; then
    checks=$((checks + 1))
    printf 'size = 10\n' >part.scad
    printf '// the part\ninclude <part.scad>\nsphere(size);\n' >s.scad
    "$bin" view s.scad --imgsize=$W,$H --spp=64 --ao=16 --max-time=0.01 --verbose \
        >sview.out 2>sview.err &
    pid=$!
    wid=$(timeout 60 xdotool search --sync --name '^spancast view: s.scad' | head -n 1)
    if [ -n "$wid" ]; then
        wait_file sview.err "^s\.scad:3:1: error: Parser error: syntax error$" 60 ||
            fail "broken .scad: no error on stderr: $(cat sview.err)"
        wait_title "* - ERROR s.scad:3:1: error: Parser error: syntax error*" 30 ||
            fail "broken .scad: no error in the title"
        # no model yet: the title's command has OpenSCAD's default view
        case "$(title)" in
        *" --camera=0,0,0,55,0,25,140 "*" --fov=22.5 "*) ;;
        *) fail "broken .scad: the title's camera is not the default: $(title)" ;;
        esac
        grep -q "spancast-\|\.csg" sview.err && fail "broken .scad: a temporary name"
        printf 'size = 6;\n' >part.scad
        wait_title "* - done - load #1 *" 300 || fail "broken .scad: the fix not loaded"
        for samples in 1 4 16 64; do
            grep -q "^frame refine ${W}x$H spp $samples: " sview.out ||
                fail "refining: no pass to $samples samples: $(grep '^frame' sview.out)"
        done
        # a pick names the source with the line of OpenSCAD's export, never
        # the export's own name
        xdotool mousemove --window "$wid" $((W / 2)) $((H / 2)) click 1
        if wait_file sview.out "^pick $((W / 2)),$((H / 2)): " 30; then
            grep -Eq "^pick $((W / 2)),$((H / 2)): sphere \(leaf 0\) at s\.scad \(line [0-9]+ of OpenSCAD's export\), distance " sview.out ||
                fail "pick in a .scad: $(grep '^pick' sview.out)"
            grep -q "\.csg" sview.out && fail "pick in a .scad names a .csg: $(grep -A2 '^pick' sview.out)"
        else
            fail "pick in a .scad: no 'pick' line"
        fi
        xdotool key ctrl+1 # a new view: the screenshot renders all 64 samples
        xdotool key ctrl+s
        wait_file sview.err "time limit of 0.01 s exceeded \(--max-time\); s-view-1\.png not written" 60 ||
            fail "--max-time: no error: $(cat sview.err)"
        [ -e s-view-1.png ] && fail "--max-time: the screenshot was written"
        xdotool key ctrl+q
        wait "$pid" || fail "broken .scad: exit $?: $(cat sview.err)"
    else
        fail "broken .scad: no viewer window in 60 s: $(cat sview.err)"
        kill "$pid" 2>/dev/null
    fi
fi

# A .scad with -D: the screenshot's command carries the settings, and
# running it writes the same image (without them it would not: r is 1 in
# the file).
if command -v openscad >/dev/null; then
    checks=$((checks + 1))
    printf 'r = 1;\nsphere(r, $fn = 24);\n' >d.scad
    "$bin" view d.scad -D 'r=3' --imgsize=$W,$H --spp=1 --verbose >dview.out 2>dview.err &
    pid=$!
    wid=$(timeout 60 xdotool search --sync --name '^spancast view: d.scad' | head -n 1)
    if [ -n "$wid" ]; then
        wait_title "* - done - load #1 *" 300 || fail "-D: the model never done"
        xdotool key ctrl+s
        if wait_file dview.out "^screenshot: " 120; then
            screenshot_line dview.out
            case "$command" in
            "d.scad -o $shot "*" -D r=3") ;;
            *) fail "-D: the screenshot's command has no -D r=3: $line" ;;
            esac
            # shellcheck disable=SC2086 # the printed options, split as a shell would
            eval "\"\$bin\" render $command -q -o dreference.png"
            n=$(differ "$shot" dreference.png)
            [ "$n" = 0 ] || fail "-D: $n pixels differ from spancast render ($line)"
        else
            fail "-D: no 'screenshot:' line in 120 s: $(cat dview.err)"
        fi
        xdotool key ctrl+q
        wait "$pid" || fail "-D: exit $?: $(cat dview.err)"
    else
        fail "-D: no viewer window in 60 s: $(cat dview.err)"
        kill "$pid" 2>/dev/null
    fi
fi

echo "$checks checks, $fails failures"
[ "$fails" = 0 ]
