# An imported mesh that is not closed under hull() and projection(), as
# OpenSCAD 2021.01 treats it (seen by running openscad -o on each model):
#  - hull() takes the corners of the mesh it reads, closed or not, and
#    prints nothing: the hull of open.stl below is the corner tetrahedron
#    (4 facets), alone or beside a cube, also under a cut projection,
#    which cuts the hull;
#  - projection() (cut = false) projects the faces of that mesh, closed or
#    not, and prints nothing: the projection of open.stl is the triangle
#    (0, 0), (1, 0), (0, 1), which only its face looking down gives;
#  - projection(cut = true) needs a CGAL Nef polyhedron: it prints "ERROR:
#    The given mesh is not closed! Unable to convert to
#    CGAL_Nef_Polyhedron." and leaves the mesh out of the section (a cube
#    beside it is cut as ever).
# So spancast hulls and projects the mesh silently in both modes, also with
# --strict (there is no warning to make an error), and leaves it out of a
# cut with OpenSCAD's message as a warning in both modes (a section needs a
# solid), an error with --strict. Before, each of these was an error.
# The same holds for a polyhedron that is not closed under projection().
#
# Run as: bash cli_open_mesh.sh <path-to-spancast> <source-dir> <work-dir>
. "$(dirname "$0")/testlib.sh"

# The corner of a tetrahedron without its slanted face: the faces at
# x = 0, y = 0 and z = 0 of the hull of the origin and the unit points.
cat >open.stl <<'STL'
solid open
facet normal 0 0 -1
outer loop
vertex 0 0 0
vertex 0 1 0
vertex 1 0 0
endloop
endfacet
facet normal 0 -1 0
outer loop
vertex 0 0 0
vertex 1 0 0
vertex 0 0 1
endloop
endfacet
facet normal -1 0 0
outer loop
vertex 0 0 0
vertex 0 0 1
vertex 0 1 0
endloop
endfacet
endsolid open
STL
printf 'hull() {\n\timport(file = "open.stl");\n}\n' >hull.csg
printf 'hull() {\n\timport(file = "open.stl");\n\tmultmatrix([[1, 0, 0, 2], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {\n\t\tcube(size = [0.5, 0.5, 0.5], center = false);\n\t}\n}\n' \
    >hull-cube.csg
printf 'linear_extrude(height = 1) {\n\tprojection(cut = false) {\n\t\timport(file = "open.stl");\n\t}\n}\n' \
    >projection.csg
printf 'linear_extrude(height = 1) {\n\tprojection(cut = false) {\n\t\tpolyhedron(points = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], faces = [[0, 1, 2], [0, 3, 1], [0, 2, 3]]);\n\t}\n}\n' \
    >projection-polyhedron.csg
printf 'linear_extrude(height = 1) {\n\tprojection(cut = false) {\n\t\thull() {\n\t\t\timport(file = "open.stl");\n\t\t}\n\t}\n}\n' \
    >projection-hull.csg
printf 'linear_extrude(height = 1) {\n\tprojection(cut = true) {\n\t\tmultmatrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, -0.5], [0, 0, 0, 1]]) {\n\t\t\timport(file = "open.stl");\n\t\t}\n\t\tmultmatrix([[1, 0, 0, 3], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {\n\t\t\tcube(size = [1, 1, 1], center = true);\n\t\t}\n\t}\n}\n' \
    >cut.csg
printf 'linear_extrude(height = 1) {\n\tprojection(cut = true) {\n\t\tmultmatrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, -0.25], [0, 0, 0, 1]]) {\n\t\t\thull() {\n\t\t\t\timport(file = "open.stl");\n\t\t\t}\n\t\t}\n\t}\n}\n' \
    >cut-hull.csg

# inside MODEL WANT OPTIONS... -- POINTS...: spancast inside MODEL at the
# points says WANT (space-separated), exit 0, and its stderr is $want_err.
want_err=
inside() {
    local model=$1 want=$2
    shift 2
    local opts=()
    while [ "$1" != -- ]; do
        opts+=("$1")
        shift
    done
    shift
    local points=()
    for p in "$@"; do points+=(--point="$p"); done
    check
    "$bin" inside "$model" "${points[@]}" "${opts[@]}" >in.txt 2>err.txt ||
        fail "inside $model ${opts[*]}: exit $?: $(cat err.txt)"
    [ "$(tr '\n' ' ' <in.txt)" = "$want " ] ||
        fail "inside $model ${opts[*]}: $(tr '\n' ' ' <in.txt), want $want"
    [ "$(cat err.txt)" = "$want_err" ] ||
        fail "inside $model ${opts[*]}: stderr '$(cat err.txt)', want '$want_err'"
}

for mode in "" --faithful --strict "--faithful --strict"; do
    # shellcheck disable=SC2086
    {
        # the corner tetrahedron: x + y + z < 1 in the positive octant
        inside hull.csg "in in out out" $mode -- 0.2,0.2,0.2 0.1,0.1,0.7 0.4,0.4,0.4 \
            -0.1,0.2,0.2
        # with the cube [2, 2.5] x [0, 0.5]^2: the segment from (1, 0, 0)
        # to (2, 0.2, 0.2) is in, (1.5, 0.9, 0.1) beyond both
        inside hull-cube.csg "in in out" $mode -- 1.5,0.1,0.1 2.2,0.2,0.2 1.5,0.9,0.1
        # the triangle x + y < 1 in the positive quadrant, 1 thick
        inside projection.csg "in in out out" $mode -- 0.2,0.2,0.5 0.7,0.1,0.5 \
            0.6,0.6,0.5 -0.1,0.5,0.5
        inside projection-polyhedron.csg "in in out out" $mode -- 0.2,0.2,0.5 \
            0.7,0.1,0.5 0.6,0.6,0.5 -0.1,0.5,0.5
        inside projection-hull.csg "in in out out" $mode -- 0.2,0.2,0.5 0.7,0.1,0.5 \
            0.6,0.6,0.5 -0.1,0.5,0.5
        # a cut of the hull (a solid) at z = 0.25: the triangle x + y < 0.75
        # (OpenSCAD: its DXF has the corners (0, 0), (0.75, 0), (0, 0.75))
        inside cut-hull.csg "in in out out" $mode -- 0.2,0.2,0.5 0.7,0.02,0.5 \
            0.4,0.4,0.5 -0.1,0.2,0.5
    }
done

# the cut: the open mesh left out with OpenSCAD's message, the cube's
# square [2.5, 3.5] x [-0.5, 0.5] kept
left='left out, as OpenSCAD leaves it out ("The given mesh is not closed! Unable to convert to CGAL_Nef_Polyhedron.")'
edge="imported mesh is not closed (edge (0, 1, 0)-(1, 0, 0) is used by 1 face)"
want_err="cut.csg:4:18: warning: $edge; $left"
for mode in "" --faithful; do
    # shellcheck disable=SC2086
    inside cut.csg "out out in" $mode -- 0.1,0.1,0.5 0.3,0.3,0.5 3,0,0.5
done
# the open mesh alone: its warning and the model's emptiness, and nothing
# of the empty section or extrusion (it follows from the warning), as
# after any import left out
printf 'linear_extrude(height = 1) {\n\tprojection(cut = true) {\n\t\tmultmatrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, -0.5], [0, 0, 0, 1]]) {\n\t\t\timport(file = "open.stl");\n\t\t}\n\t}\n}\n' \
    >cut-alone.csg
want_err="cut-alone.csg:4:18: warning: $edge; $left
cut-alone.csg: warning: the model is empty (nothing to render)"
for mode in "" --faithful; do
    # shellcheck disable=SC2086
    inside cut-alone.csg "out" $mode -- 0.1,0.1,0.5
done
# the same cut of the mesh as a polyhedron, as the model itself, a 2D
# one: the same warning (there is no extrusion to take it)
printf 'projection(cut = true) {\n\tmultmatrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, -0.5], [0, 0, 0, 1]]) {\n\t\tpolyhedron(points = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], faces = [[0, 1, 2], [0, 3, 1], [0, 2, 3]]);\n\t}\n\tmultmatrix([[1, 0, 0, 3], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {\n\t\tcube(size = [1, 1, 1], center = true);\n\t}\n}\n' \
    >cut-2d.csg
polyhedron_edge="polyhedron is not closed (edge 1-2 is used by 1 face)"
want_err="cut-2d.csg:3:3: warning: $polyhedron_edge; $left"
for mode in "" --faithful; do
    # shellcheck disable=SC2086
    inside cut-2d.csg "out out in" $mode -- 0.1,0.1,0 0.3,0.3,0 3,0,0
done
for at in "cut:4:18:$edge" "cut-2d:3:3:$polyhedron_edge"; do
    model=${at%%:*} where=${at#*:}
    where=${where%%:"${at#*:*:*:}"}
    for mode in --strict "--strict --faithful"; do
        check
        # shellcheck disable=SC2086
        "$bin" inside $model.csg --point=3,0,0 $mode >in.txt 2>err.txt &&
            fail "inside $model.csg $mode: exit 0"
        w="$model.csg:$where: error: ${at#*:*:*:}"
        [ "$(cat err.txt)" = "$w" ] || fail "$model.csg $mode: stderr '$(cat err.txt)', want '$w'"
    done
done

# minkowski(): OpenSCAD 2021.01 sums meshes on CGAL's Nef polyhedra, which
# an open mesh cannot become: it prints "ERROR: The given mesh is not
# closed! ..." and the whole minkowski is empty (minkowski() { open;
# cube(1); } beside a cube gives the cube alone, also for a polyhedron);
# an open mesh in a union inside it is left out of that union, and the rest
# is summed (minkowski() { union() { open; translate([3, 0, 0]) cube(1); }
# cube(0.5); } is the box [3, 4.5] x [0, 1.5] x [0, 1.5]).
printf 'minkowski() {\n\timport(file = "open.stl");\n\tcube(size = [1, 1, 1], center = false);\n}\nmultmatrix([[1, 0, 0, 5], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {\n\tcube(size = [1, 1, 1], center = false);\n}\n' \
    >mink.csg
printf 'minkowski() {\n\tpolyhedron(points = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], faces = [[0, 1, 2], [0, 3, 1], [0, 2, 3]]);\n\tcube(size = [1, 1, 1], center = false);\n}\nmultmatrix([[1, 0, 0, 5], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {\n\tcube(size = [1, 1, 1], center = false);\n}\n' \
    >mink-poly.csg
printf 'minkowski() {\n\tunion() {\n\t\timport(file = "open.stl");\n\t\tmultmatrix([[1, 0, 0, 3], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {\n\t\t\tcube(size = [1, 1, 1], center = false);\n\t\t}\n\t}\n\tcube(size = [0.5, 0.5, 0.5], center = false);\n}\n' \
    >mink-union.csg
empty_mink='the minkowski is empty, as OpenSCAD leaves it out ("The given mesh is not closed! Unable to convert to CGAL_Nef_Polyhedron.")'
poly_edge="polyhedron is not closed (edge 1-2 is used by 1 face)"
for mode in "" --faithful; do
    want_err="mink.csg:2:16: warning: $edge; $empty_mink"
    # shellcheck disable=SC2086
    inside mink.csg "out out in" $mode -- 0.5,0.5,0.5 1.5,0.2,0.2 5.5,0.5,0.5
    want_err="mink-poly.csg:2:2: warning: $poly_edge; $empty_mink"
    # shellcheck disable=SC2086
    inside mink-poly.csg "out out in" $mode -- 0.5,0.5,0.5 1.5,0.2,0.2 5.5,0.5,0.5
    want_err="mink-union.csg:3:17: warning: $edge; $left"
    # shellcheck disable=SC2086
    inside mink-union.csg "out out in in out" $mode -- 0.2,0.2,0.2 1.5,0.2,0.2 \
        3.1,0.1,0.1 4.4,1.4,1.4 4.6,0.5,0.5
done
# a union inside a hull is a CGAL union too: the open mesh is left out of
# it (OpenSCAD: hull() { union() { open; translate([3, 0, 0]) cube(1); } }
# is the cube alone), also when a transform unites several children
printf 'hull() {\n\tunion() {\n\t\timport(file = "open.stl");\n\t\tmultmatrix([[1, 0, 0, 3], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {\n\t\t\tcube(size = [1, 1, 1], center = false);\n\t\t}\n\t}\n}\n' \
    >hull-union.csg
printf 'hull() {\n\tmultmatrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {\n\t\timport(file = "open.stl");\n\t\tmultmatrix([[1, 0, 0, 3], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {\n\t\t\tcube(size = [1, 1, 1], center = false);\n\t\t}\n\t}\n}\n' \
    >hull-xform.csg
for mode in "" --faithful; do
    for model in hull-union.csg hull-xform.csg; do
        want_err="$model:3:17: warning: $edge; $left"
        # shellcheck disable=SC2086
        inside "$model" "out out in" $mode -- 0.2,0.2,0.2 2,0.2,0.2 3.5,0.5,0.5
    done
done
# a boolean inside a hull is CGAL's too: the open mesh is left out of it
# (OpenSCAD: hull() { difference() { cube(6); open; } } is the whole cube)
printf 'hull() {\n\tdifference() {\n\t\tcube(size = [2, 2, 2], center = false);\n\t\timport(file = "open.stl");\n\t}\n}\n' \
    >hull-diff.csg
printf 'hull() {\n\tdifference() {\n\t\tcube(size = [2, 2, 2], center = false);\n\t\tpolyhedron(points = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], faces = [[0, 1, 2], [0, 3, 1], [0, 2, 3]]);\n\t}\n}\n' \
    >hull-diff-poly.csg
for mode in "" --faithful; do
    want_err="hull-diff.csg:4:17: warning: $edge; $left"
    # shellcheck disable=SC2086
    inside hull-diff.csg "in in out" $mode -- 0.05,0.05,0.05 1.9,1.9,1.9 2.1,1,1
    want_err="hull-diff-poly.csg:4:3: warning: $poly_edge; $left"
    # shellcheck disable=SC2086
    inside hull-diff-poly.csg "in in out" $mode -- 0.05,0.05,0.05 1.9,1.9,1.9 2.1,1,1
done
# a mesh CGAL takes though an edge has three faces (a face given twice, as
# OpenSCAD's polyhedron(), which CGAL's builder takes): OpenSCAD 2021.01
# sums it with no message, in both modes (minkowski() { import("dup.stl");
# cube(0.5); } against openscad's STL of it: "same"); the default mode
# refused it where the same polyhedron was summed
{
    echo "solid dup"
    for f in "0 0 0;0 1 0;1 0 0" "0 0 0;1 0 0;0 0 1" "1 0 0;0 1 0;0 0 1" \
        "0 0 0;0 0 1;0 1 0" "0 0 0;0 0 1;0 1 0"; do
        echo " facet normal 0 0 0"
        echo "  outer loop"
        IFS=';' read -r a b c <<<"$f"
        printf '   vertex %s\n' "$a" "$b" "$c"
        echo "  endloop"
        echo " endfacet"
    done
    echo "endsolid dup"
} >dup.stl
printf 'minkowski() {\n\timport(file = "dup.stl");\n\tcube(size = [0.5, 0.5, 0.5], center = false);\n}\n' \
    >mink-dup.csg
want_err=""
for mode in "" --faithful; do
    # shellcheck disable=SC2086
    inside mink-dup.csg "in in out out" $mode -- 0.2,0.2,0.2 1.2,0.2,0.2 1.6,0.3,0.3 \
        0.1,0.1,-0.1
done
for case in "mink.csg:2:16: error: $edge" "mink-poly.csg:2:2: error: $poly_edge" \
    "mink-union.csg:3:17: error: $edge" "hull-union.csg:3:17: error: $edge" \
    "hull-diff.csg:4:17: error: $edge" "hull-diff-poly.csg:4:3: error: $poly_edge"; do
    model=${case%%:*}
    for mode in --strict "--strict --faithful"; do
        check
        # shellcheck disable=SC2086
        "$bin" inside "$model" --point=5.5,0.5,0.5 $mode >in.txt 2>err.txt &&
            fail "inside $model $mode: exit 0"
        [ "$(cat err.txt)" = "$case" ] ||
            fail "$model $mode: stderr '$(cat err.txt)', want '$case'"
    done
done

echo "$checks checks, $fails failures"
[ "$fails" = 0 ]
