# `--faithful` on the command line: spheres and cylinders become OpenSCAD's
# polyhedra. A square-ringed sphere ($fn = 4) seen straight down along a
# corner direction: the exact sphere covers pixels the polyhedron leaves
# out, and its top is nearer (depth 10 - r against 10 - r cos 45). 'info'
# accepts the option too, and the help text names it. A fragment count over
# the limit is an error in faithful mode only.
#
# Run as: bash cli_faithful.sh <path-to-spancast> <source-dir> <work-dir>
. "$(dirname "$0")/testlib.sh"

printf 'sphere($fn = 4, $fa = 12, $fs = 2, r = 2);\n' >m.csg
view=(--camera=0,0,10,0,0,0 --imgsize=41,41 --projection=o --fov=30 -q)
"$bin" render m.csg -o exact.png --mask=exact_mask.png --depth=exact.exr "${view[@]}" ||
    fail "exact render"
"$bin" render m.csg --faithful -o f.png --mask=f_mask.png --depth=f.exr "${view[@]}" ||
    fail "faithful render"
# Coverage: the exact disc of radius 2 against the inscribed square.
exact_hits=$(oiiotool exact_mask.png --printstats 2>/dev/null | sed -n 's/.*Avg: *//p')
faithful_hits=$(oiiotool f_mask.png --printstats 2>/dev/null | sed -n 's/.*Avg: *//p')
awk -v e="$exact_hits" -v f="$faithful_hits" 'BEGIN { exit !(e + 0 > 0 && f + 0 > 0 && f + 0 < e + 0) }' ||
    fail "faithful coverage $faithful_hits is not below exact coverage $exact_hits"
# Depth at the centre pixel (20, 20), on the axis: 10 - 2 exact, 10 - 2 cos 45 faithful.
centre() { oiiotool "$1" --cut 1x1+20+20 -o centre.exr >/dev/null 2>&1 &&
    oiiotool centre.exr --printstats 2>/dev/null | sed -n 's/.*Avg: *//p'; }
awk -v d="$(centre exact.exr)" 'BEGIN { exit !(d + 0 > 7.9999 && d + 0 < 8.0001) }' ||
    fail "exact centre depth $(centre exact.exr)"
awk -v d="$(centre f.exr)" 'BEGIN { exit !(d + 0 > 8.5857 && d + 0 < 8.5859) }' ||
    fail "faithful centre depth $(centre f.exr)"

"$bin" info m.csg --faithful >info.txt 2>&1 || fail "info --faithful: $(cat info.txt)"
grep -q '^bounds: \[-1\.41421, -1\.41421, -1\.41421\] to \[1\.41421, 1\.41421, 1\.41421\]$' \
    info.txt || fail "faithful bounds: $(cat info.txt)"
"$bin" --help | grep -q -- '--faithful' || fail "--help does not name --faithful"

# 5000 fragments: inside the parser's $fn limit (65536), past a faithful sphere's (4096)
printf 'sphere($fn = 5000, r = 1);\n' >big.csg
"$bin" render big.csg --faithful -o big.png -q 2>err.txt
[ $? = 1 ] || fail "too many fragments should exit 1"
[ "$(cat err.txt)" = "big.csg:1:1: error: faithful mode: \$fn, \$fa and \$fs of radius 1 give too many fragments (limit is 4096)" ] ||
    fail "message: $(cat err.txt)"
"$bin" render big.csg -o big.png -q --imgsize=8,8 || fail "exact mode ignores \$fn"

[ "$fails" = 0 ] && echo "cli_faithful: all checks passed"
exit "$fails"
