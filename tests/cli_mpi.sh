# `mpirun -np N spancast render ...`: the tool hands over to spancast-mpi,
# rank 0 hands tiles out to every rank, and every output is byte for byte
# the single-process one (colour, mask, depth, normals, ids; assembled,
# tiled EXR and tiled TIFF; a .scad converted once); errors are reported
# once, by rank 0; a tool without spancast-mpi says so under mpirun.
#
# Run as: bash cli_mpi.sh <path-to-spancast> <source-dir> <work-dir>
. "$(dirname "$0")/testlib.sh"
require_mpi
mpi() {
    local np=$1
    shift
    mpirun_test -np "$np" "$@"
}

cp "$src/models/bracket.csg" m.csg
opts=(--imgsize=200,150 --spp=2 --view=edges -q)

# The reference: one process.
"$bin" render m.csg -o one.png --mask=one-mask.png --depth=one-depth.exr \
    --normal=one-normal.exr --id=one-id.exr "${opts[@]}" || fail "the plain render failed"
"$bin" render m.csg -o one-tiled.exr --mask=one-tiled-mask.exr \
    --depth=one-tiled-depth.exr "${opts[@]}" --tiled || fail "the plain tiled render failed"
"$bin" render m.csg -o one-tiled.tif --mask=one-tiled-mask.tif "${opts[@]}" --tiled ||
    fail "the plain tiled TIFF render failed"
for np in 2 3; do
    check
    mpi "$np" "$bin" render m.csg -o "np$np.png" --mask="np$np-mask.png" \
        --depth="np$np-depth.exr" --normal="np$np-normal.exr" --id="np$np-id.exr" \
        "${opts[@]}" >out.txt 2>&1 || fail "np $np: $(tail -n 5 out.txt)"
    for out in .png -mask.png -depth.exr -normal.exr -id.exr; do
        cmp -s "one$out" "np$np$out" || fail "np $np: np$np$out differs from one$out"
    done
    check
    mpi "$np" "$bin" render m.csg -o "np$np-tiled.exr" --mask="np$np-tiled-mask.exr" \
        --depth="np$np-tiled-depth.exr" "${opts[@]}" --tiled >out.txt 2>&1 ||
        fail "np $np --tiled: $(tail -n 5 out.txt)"
    for out in -tiled.exr -tiled-mask.exr -tiled-depth.exr; do
        cmp -s "one$out" "np$np$out" || fail "np $np: np$np$out differs from one$out"
    done
    check
    mpi "$np" "$bin" render m.csg -o "np$np-tiled.tif" --mask="np$np-tiled-mask.tif" \
        "${opts[@]}" --tiled >out.txt 2>&1 || fail "np $np --tiled .tif: $(tail -n 5 out.txt)"
    for out in -tiled.tif -tiled-mask.tif; do
        cmp -s "one$out" "np$np$out" || fail "np $np: np$np$out differs from one$out"
    done
done

# A contact sheet with sections and ambient occlusion, across 3 ranks.
check
sheet=(--sheet=top,front,right,diagonal --imgsize=96,72 --section=0,-1,0,-25 --ao=2 -q)
"$bin" render m.csg -o sheet-one.png "${sheet[@]}" || fail "the plain sheet failed"
mpi 3 "$bin" render m.csg -o sheet-np3.png "${sheet[@]}" >out.txt 2>&1 ||
    fail "sheet on 3 ranks: $(tail -n 5 out.txt)"
cmp -s sheet-one.png sheet-np3.png || fail "the sheet on 3 ranks differs"

# The summary line comes once, from rank 0.
check
mpi 2 "$bin" render m.csg -o summary.png --imgsize=64,48 >out.txt 2>err.txt ||
    fail "np 2 summary: $(cat err.txt)"
[ "$(grep -c '^spancast: wrote summary.png (64x48) in' err.txt)" = 1 ] ||
    fail "the summary line under mpirun: '$(cat err.txt)'"

# A .scad is converted by OpenSCAD once, on rank 0.
if command -v openscad >/dev/null; then
    check
    cp "$src/models/bracket.scad" b.scad
    "$bin" render b.scad -o scad-one.png --imgsize=64,48 -q || fail "plain .scad render"
    mpi 2 "$bin" render b.scad -o scad-np2.png --imgsize=64,48 -q >out.txt 2>&1 ||
        fail ".scad on 2 ranks: $(tail -n 5 out.txt)"
    cmp -s scad-one.png scad-np2.png || fail "the .scad render on 2 ranks differs"
    # A font the .scad uses (use <font.ttf>) is registered on every rank.
    check
    mkdir -p fonts && cp "$src/tests/data/fonts/marvosym.ttf" fonts/
    printf 'use <fonts/marvosym.ttf>\ntext("0123 AB", font = "MarVoSym", size = 10);\n' >sym.scad
    "$bin" render sym.scad -o sym-one.png --imgsize=64,48 -q || fail "plain sym.scad render"
    mpi 2 "$bin" render sym.scad -o sym-np2.png --imgsize=64,48 -q >out.txt 2>&1 ||
        fail "sym.scad on 2 ranks: $(tail -n 5 out.txt)"
    cmp -s sym-one.png sym-np2.png || fail "the font's render on 2 ranks differs"
fi

# A model that does not load: its message once, a failure exit, no file.
check
printf 'union() {\n  roof() {\n    square(1);\n  }\n}\n' >bad.csg
mpi 2 "$bin" render bad.csg -o bad.png -q >out.txt 2>err.txt && fail "bad.csg under mpirun succeeded"
[ "$(grep -c "^bad.csg:2:3: error: 'roof' is not supported yet" err.txt)" = 1 ] ||
    fail "bad.csg under mpirun: '$(cat err.txt)'"
[ -e bad.png ] && fail "bad.png was written"
# A render that fails on the ranks (a camera looking nowhere): once too.
check
mpi 2 "$bin" render m.csg -o cam.png --camera=1,1,1,1,1,1 -q >out.txt 2>err.txt &&
    fail "a degenerate camera under mpirun succeeded"
"$bin" render m.csg -o cam.png --camera=1,1,1,1,1,1 -q 2>one-err.txt
[ "$(grep -cF "$(cat one-err.txt)" err.txt)" = 1 ] ||
    fail "camera error under mpirun: '$(cat err.txt)', alone: '$(cat one-err.txt)'"
[ -e cam.png ] && fail "cam.png was written"
# An output rank 0 cannot write: every rank stops (a rank that stopped
# alone would leave the others waiting for it; the guard catches a hang).
check
timeout 300 env ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0 \
    mpirun --oversubscribe -np 2 "$bin" render m.csg -o no/such/folder.png -q \
    >out.txt 2>err.txt
rc=$?
[ "$rc" = 124 ] && fail "an unwritable output under mpirun hung"
[ "$rc" = 0 ] && fail "an unwritable output under mpirun succeeded"
[ "$(grep -c "^spancast: error: cannot write 'no/such/folder.png': No such file or directory$" err.txt)" = 1 ] ||
    fail "an unwritable output under mpirun: '$(cat err.txt)'"
# --watch is for one process.
check
mpi 2 "$bin" render m.csg -o w.png --watch -q >out.txt 2>err.txt && fail "--watch under mpirun ran"
grep -q "^spancast: error: --watch does not run under mpirun$" err.txt ||
    fail "--watch under mpirun: '$(cat err.txt)'"

# One rank: nothing changes (no MPI at all). Several ranks without
# spancast-mpi beside the tool: an error, not N copies writing one file.
check
OMPI_COMM_WORLD_SIZE=1 "$bin" render m.csg -o size1.png "${opts[@]}" || fail "size 1 failed"
cmp -s one.png size1.png || fail "OMPI_COMM_WORLD_SIZE=1 changed the image"
check
mkdir alone
cp "$bin" alone/spancast
OMPI_COMM_WORLD_SIZE=2 alone/spancast render m.csg -o alone.png -q 2>err.txt
rc=$?
[ "$rc" = 1 ] || fail "without spancast-mpi under 2 ranks: exit $rc"
grep -qx "spancast: error: running under mpirun with 2 ranks, but this build has no MPI support (no spancast-mpi beside spancast)" err.txt ||
    fail "without spancast-mpi: '$(cat err.txt)'"
[ -e alone.png ] && fail "alone.png was written"

echo "$checks checks, $fails failures"
[ "$fails" = 0 ]
