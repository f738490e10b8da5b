# Runs the query example on its built-in drilled cube and checks what it
# prints against the values worked out by hand: the line y = z = 5 along
# x runs through the cube from x = 0 to 10 and through the hole (radius 2
# about x = y = 5) from 3 to 7, whose wall is a subtracted surface;
# (5, 5, 5) is in the hole; the volume is 1000 - 40 pi = 874.336 and the
# area 600 + 32 pi = 700.531 (to the example's tolerance of 1e-3), the
# centroid (5, 5, 5).
#   bash check_query.sh PATH-TO-spancast-query-example
set -u
out=$("$1") || { echo "FAIL: the example exited with $?"; exit 1; }
echo "$out"
fails=0
expect() {
    grep -qx -- "$1" <<<"$out" || { echo "FAIL: no line '$1'"; fails=$((fails + 1)); }
}
expect 'span 0: x from 0 to 3 (box at line 2 to cylinder at line 4, a subtracted surface)'
expect 'span 1: x from 7 to 10 (cylinder at line 4 to box at line 2, a subtracted surface)'
expect 'point (5, 5, 5): out'
expect 'point (1, 1, 1): in'
expect 'volume 874\.[34][0-9]* +- [0-9.e-]*'
expect 'area 700.[4-6][0-9]* +- [0-9.e-]*'
expect 'centroid (5, 5, 5)'
[ "$fails" = 0 ]
