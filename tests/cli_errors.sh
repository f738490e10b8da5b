# Command-line errors of `spancast`: every bad invocation gets its exact
# message on stderr and exit status 2 (usage) or 1 (the model or an image);
# --help and --version exit 0.
#
# Run as: bash cli_errors.sh <path-to-spancast> <source-dir> <work-dir>
. "$(dirname "$0")/testlib.sh"

# expect STATUS STDERR ARGS...: runs spancast ARGS and compares the exit
# status and the whole of stderr.
expect() {
    local want_rc=$1 want_err=$2
    shift 2
    checks=$((checks + 1))
    "$bin" "$@" >stdout.txt 2>stderr.txt
    local rc=$?
    local got_err
    got_err=$(cat stderr.txt)
    if [ "$rc" != "$want_rc" ] || [ "$got_err" != "$want_err" ]; then
        echo "FAIL: spancast $*"
        echo "  exit   $rc (want $want_rc)"
        echo "  stderr '$got_err'"
        echo "  want   '$want_err'"
        fails=$((fails + 1))
    fi
}

# expect_usage STDERR-WITHOUT-PREFIX ARGS...
expect_usage() {
    local msg=$1
    shift
    expect 2 "spancast: error: $msg" "$@"
}

# expect_match STATUS REGEX ARGS...: stderr must match the extended regex.
expect_match() {
    local want_rc=$1 pattern=$2
    shift 2
    checks=$((checks + 1))
    "$bin" "$@" >stdout.txt 2>stderr.txt
    local rc=$?
    if [ "$rc" != "$want_rc" ] || ! grep -Eq "$pattern" stderr.txt; then
        echo "FAIL: spancast $*"
        echo "  exit   $rc (want $want_rc)"
        echo "  stderr '$(cat stderr.txt)'"
        echo "  want   /$pattern/"
        fails=$((fails + 1))
    fi
}

printf 'sphere(r = 1);\n' >m.csg

# commands
expect_usage "missing command (try 'spancast --help')"
expect_usage "unknown command 'frobnicate' (expected 'render', 'info', 'spans', 'inside', 'measure', 'overlaps', 'compare', 'view', 'batch' or 'bench')" frobnicate
expect_usage "missing command before '-o' (try 'spancast --help')" -o x.png m.csg
expect_usage "missing input file" render
expect_usage "missing input file" info
expect_usage "missing output file (-o)" render m.csg
expect_usage "unexpected argument 'n.csg'" render m.csg n.csg -o x.png
expect_usage "unexpected argument 'n.csg'" info m.csg n.csg

# options
expect_usage "unknown option '--foo'" render m.csg -o x.png --foo
expect_usage "unknown option '--foo'" render m.csg -o x.png --foo=3
expect_usage "unknown option '-x'" render m.csg -o x.png -x
expect_usage "option '--viewall' takes no value" render m.csg -o x.png --viewall=1
expect_usage "option '--camera' expects a value" render m.csg -o x.png --camera
expect_usage "option '--fov' expects a value" render m.csg -o x.png --fov=
expect_usage "option '-o' expects a value" render m.csg -o
expect_usage "option '-o' does not apply to 'info'" info m.csg -o x.png
expect_usage "option '--camera' does not apply to 'info'" info m.csg --camera=0,0,0,1,1,1

for size in 0,10 10 a,b 10,10,10 -5,5 10,0 " 10,10" 10.5,3 ,; do
    expect_usage "--imgsize expects W,H with positive integers" \
        render m.csg -o x.png --imgsize="$size"
done
expect_usage "--imgsize allows at most 262144 pixels a side" \
    render m.csg -o x.png --imgsize 300000,10

camera_msg="--camera expects 6 numbers (eye, centre) or 7 numbers (translate, rotate, distance)"
for cam in 1,2,3 1,2,3,4,5,x 1,2,3,4,5,6,7,8 1,,2,3,4,5 inf,0,0,1,1,1 ""; do
    if [ -z "$cam" ]; then
        expect_usage "option '--camera' expects a value" render m.csg -o x.png --camera=
    else
        expect_usage "$camera_msg" render m.csg -o x.png --camera="$cam"
    fi
done

for fov in 0 180 -3 abc 1e999; do
    expect_usage "--fov expects an angle in degrees between 0 and 180" \
        render m.csg -o x.png --fov "$fov"
done
expect_usage "--projection expects 'p' (perspective) or 'o' (orthographic)" \
    render m.csg -o x.png --projection=isometric
expect_usage "--threads expects a non-negative integer (0: all cores)" \
    render m.csg -o x.png --threads=-1
expect_usage "--threads expects a non-negative integer (0: all cores)" \
    render m.csg -o x.png --threads two

# camera values the renderer rejects
expect_usage "camera eye and centre are the same point" \
    render m.csg -o x.png --camera=1,2,3,1,2,3
expect_usage "camera distance must be positive (got -80)" \
    render m.csg -o x.png --camera=0,0,0,55,0,25,-80

# output names are checked before the model is read
expect_usage "cannot write 'x.foo': unknown image format" render missing.csg -o x.foo
expect_usage "cannot write 'x': unknown image format" render m.csg -o x
mkdir -p somedir
expect_usage "cannot write 'somedir': it is a folder (an image is a file with an extension: .png, .exr, ...)" render m.csg -o somedir
expect_usage "cannot write 'm.foo': unknown image format" render m.csg -o x.png --mask m.foo
expect_usage "cannot write depth to 'd.png': depth needs a floating-point format (.exr or .tif)" \
    render m.csg -o x.png --depth=d.png

# errors from the model: file:line:col, exit 1
printf 'union() {\n  roof() {\n    square(1);\n  }\n}\n' >roof.csg
expect 1 "roof.csg:2:3: error: 'roof' is not supported yet" render roof.csg -o x.png
expect 1 "roof.csg:2:3: error: 'roof' is not supported yet" info roof.csg
printf 'cube(1;\n' >syntax.csg
expect_match 1 '^syntax\.csg:1:7: error: ' render syntax.csg -o x.png
expect 1 "spancast: error: cannot open 'missing.csg': No such file or directory" \
    render missing.csg -o x.png

# a warning is printed and the render goes on
printf 'union() {\n  cube(1);\n  sphere(r = 0);\n}\n' >warn.csg
expect_match 0 '^warn\.csg:3:3: warning: ' render warn.csg -o w.png --quiet
if [ "$(wc -l <stderr.txt)" != 1 ]; then
    echo "FAIL: the warning run printed more than the warning"
    fails=$((fails + 1))
fi

# help and version
expect 0 "" --help
head -n 1 stdout.txt | grep -q '^usage: spancast render MODEL -o OUT.png \[options\]$' || {
    echo "FAIL: --help does not start with the usage line"
    fails=$((fails + 1))
}
expect 0 "" render m.csg --help
# Each command's --help is its own: it opens with that command's usage
# line, names no other command's, and every option it lists is one the
# command takes (never "unknown option" or "does not apply"); options of
# render alone are not in the others'.
for command in render info spans inside measure overlaps compare batch bench; do
    expect 0 "" "$command" --help
    head -n 1 stdout.txt | grep -q "^usage: spancast $command " || {
        echo "FAIL: spancast $command --help starts with '$(head -n 1 stdout.txt)'"
        fails=$((fails + 1))
    }
    if grep -v "^usage: spancast $command \|^       spancast $command " stdout.txt |
        grep -q '^ *spancast [a-z]'; then
        echo "FAIL: spancast $command --help shows another command's usage"
        fails=$((fails + 1))
    fi
    [ "$command" = bench ] && continue # its options start a benchmark
    cp stdout.txt help.txt
    for option in $(grep -oE -- '(^|[ [|])(--[a-z][a-z-]*|-[a-zA-Z])([^A-Za-z0-9_-]|$)' help.txt |
        sed -E 's/^[ [|]//; s/[^A-Za-z0-9_-]$//' | sort -u); do
        checks=$((checks + 1))
        "$bin" "$command" "$option" >/dev/null 2>stderr.txt </dev/null
        if grep -q "unknown option\|does not apply" stderr.txt; then
            echo "FAIL: spancast $command --help lists $option, which it refuses: $(cat stderr.txt)"
            fails=$((fails + 1))
        fi
    done
    if [ "$command" != render ]; then
        for option in --output --mask --spp --colorscheme --stats --watch; do
            checks=$((checks + 1))
            if grep -q -- "$option\b" help.txt; then
                echo "FAIL: spancast $command --help lists render's $option"
                fails=$((fails + 1))
            fi
        done
    fi
done
expect 0 "" -h
expect 0 "" --version
grep -Eq '^spancast [0-9]+\.[0-9]+\.[0-9]+$' stdout.txt || {
    echo "FAIL: --version printed '$(cat stdout.txt)'"
    fails=$((fails + 1))
}

[ -e x.png ] && { echo "FAIL: a failed command wrote x.png"; fails=$((fails + 1)); }

echo "$checks checks, $fails failed"
[ "$fails" = 0 ]
