# OpenSCAD 2021.01's leniency with children of the other dimension, end to
# end: a 3D child of a 2D operation, and a 2D child of a 3D one, is left
# out with OpenSCAD's warnings, after the warnings OpenSCAD gives as it
# evaluates it (a boolean through CGAL, an extrusion's children, an
# import's file), and the rest renders with exit 0; the result is checked
# against the model written without what was left out (spancast compare).
# The rest of OpenSCAD's leniency is cli_lenient.sh's.
#
# Run as: bash cli_lenient_dims.sh <path-to-spancast> <source-dir> <work-dir>
. "$(dirname "$0")/testlib.sh"

# ---- 3D children of 2D operations, 2D children of 3D operations ----
cat >extrude.csg <<'M'
linear_extrude(height = 3) {
	square(size = [10, 6], center = false);
	multmatrix([[1, 0, 0, 20], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {
		cube(size = [5, 5, 5], center = false);
	}
}
M
printf 'linear_extrude(height = 3) { square(size = [10, 6], center = false); }\n' >extrude_ref.csg
warns extrude.csg "extrude.csg:3:2: warning: Ignoring 3D child object for 2D operation"
same extrude.csg extrude_ref.csg

cat >union.csg <<'M'
union() {
	cylinder(h = 4, r1 = 3, r2 = 3, center = false);
	circle(r = 8);
	difference() {
		square(size = [2, 2], center = false);
		cube(size = [1, 1, 1], center = false);
	}
}
M
printf 'cylinder(h = 4, r1 = 3, r2 = 3, center = false);\n' >union_ref.csg
warns union.csg "union.csg:6:3: warning: Mixing 2D and 3D objects is not supported
union.csg:6:3: warning: Ignoring 3D child object for 2D operation
union.csg:3:2: warning: Mixing 2D and 3D objects is not supported
union.csg:3:2: warning: Ignoring 2D child object for 3D operation
union.csg:4:2: warning: Ignoring 2D child object for 3D operation"
same union.csg union_ref.csg

# A left-out child is the empty operand, as in OpenSCAD: it empties an
# intersection and subtracts nothing.
printf 'intersection() {\n\tcube(size = [3, 3, 3]);\n\tsquare(size = [10, 10]);\n}\n' >meet.csg
warns meet.csg "meet.csg:3:2: warning: Mixing 2D and 3D objects is not supported
meet.csg:3:2: warning: Ignoring 2D child object for 3D operation
meet.csg: warning: the model is empty (nothing to render)"
cat >cut.csg <<'M'
linear_extrude(height = 3) {
	difference() {
		square(size = [10, 6], center = false);
		cube(size = [3, 3, 3], center = false);
		square(size = [2, 2], center = false);
	}
}
M
printf 'linear_extrude(height = 3) { difference() { square(size = [10, 6]); square(size = [2, 2]); } }\n' >cut_ref.csg
warns cut.csg "cut.csg:4:3: warning: Mixing 2D and 3D objects is not supported
cut.csg:4:3: warning: Ignoring 3D child object for 2D operation"
same cut.csg cut_ref.csg

# An empty 3D child (cube(0), sphere(0), a difference from an empty one)
# mixes nothing, as OpenSCAD 2021.01's isValidDim passes over empty
# geometry: it is only ignored. One that is no geometry at all (an empty
# group; a union or hull with nothing in it; an intersection with an empty
# child) is not even ignored. The first warning is at the first 3D child
# that is not empty, before the others.
cat >empty3d.csg <<'M'
union() {
	square(size = [10, 6], center = false);
	cube(size = [0, 1, 1], center = false);
	sphere(r = 0);
	group() {
		cube(size = [0, 0, 0], center = false);
		cylinder(h = 0, r1 = 1, r2 = 1, center = false);
	}
	group();
	intersection() {
		cube(size = [1, 1, 1], center = false);
		cube(size = [0, 1, 1], center = false);
	}
	difference() {
		polyhedron(points = [], faces = []);
		cube(size = [1, 1, 1], center = false);
	}
	cube(size = [1, 1, 1], center = false);
}
M
printf 'square(size = [10, 6], center = false);\n' >empty3d_ref.csg
cat >empty3d_flat.csg <<'M'
linear_extrude(height = 3) {
	difference() {
		square(size = [10, 6], center = false);
		cube(size = [3, 3, 0], center = false);
		hull() {
			sphere(r = 0);
		}
	}
}
M
printf 'linear_extrude(height = 3) { square(size = [10, 6], center = false); }\n' >empty3d_flat_ref.csg
for mode in "" --faithful; do
    warns empty3d.csg "empty3d.csg:18:2: warning: Mixing 2D and 3D objects is not supported
empty3d.csg:3:2: warning: Ignoring 3D child object for 2D operation
empty3d.csg:4:2: warning: Ignoring 3D child object for 2D operation
empty3d.csg:14:2: warning: Ignoring 3D child object for 2D operation
empty3d.csg:18:2: warning: Ignoring 3D child object for 2D operation" $mode
    warns empty3d_flat.csg "empty3d_flat.csg:4:3: warning: Ignoring 3D child object for 2D operation" $mode
    # shellcheck disable=SC2086
    same empty3d.csg empty3d_ref.csg $mode
    # shellcheck disable=SC2086
    same empty3d_flat.csg empty3d_flat_ref.csg $mode
done

# A difference, intersection or minkowski among those 3D children is
# evaluated with CGAL first (openscad -o /abs/x.stl x.csg prints exactly
# these): one that comes out empty mixes nothing and is only ignored; an
# intersection with an empty operand, and a hull of nothing, are no
# geometry at all, not even ignored; a mesh in one that is not closed gets
# CGAL's error (the warning here, the error with --strict), in a '%' child
# too, and so does one in a union of two or more solids, which CGAL
# unites. Boxes that touch meet in a face, which CGAL's solid keeps: that one
# mixes.
sq='square(size = [10, 6], center = false);'
apart='intersection() {
		cube(size = [1, 1, 1], center = false);
		multmatrix([[1, 0, 0, 5], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {
			cube(size = [1, 1, 1], center = false);
		}
	}'
open='polyhedron(points = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], faces = [[0, 1, 2], [0, 3, 1], [1, 3, 2]], convexity = 1);'
printf 'union() {\n\t%s\n\t%s\n}\n' "$sq" "$apart" >cgal_apart.csg
sed 's/\[\[1, 0, 0, 5\]/[[1, 0, 0, 1]/' cgal_apart.csg >cgal_touch.csg
printf 'union() {\n\t%s\n\thull() {\n\t%s\n\t}\n}\n' "$sq" "$apart" >cgal_hull.csg
printf 'union() {\n\t%s\n\tdifference() {\n\t\tcube(size = [1, 1, 1], center = false);\n\t\tcube(size = [3, 3, 3], center = true);\n\t}\n}\n' "$sq" >cgal_cut.csg
printf 'union() {\n\t%s\n\tintersection() {\n\t\tcube(size = [0, 1, 1], center = false);\n\t\tcube(size = [1, 1, 1], center = false);\n\t}\n}\n' "$sq" >cgal_first.csg
printf 'linear_extrude(height = 3) {\n\t%s\n\tintersection() {\n\t\tcube(size = [0, 1, 1], center = false);\n\t\tcube(size = [1, 0, 1], center = false);\n\t}\n}\n' "$sq" >cgal_extrude.csg
for op in intersection minkowski; do
    printf 'union() {\n\t%s\n\t%s() {\n\t\tcube(size = [1, 1, 1], center = false);\n\t\t%s\n\t}\n}\n' "$sq" "$op" "$open" >"cgal_open_$op.csg"
done
printf 'union() {\n\t%s\n\tmultmatrix([[1, 0, 0, 3], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {\n\t\tcube(size = [1, 1, 1], center = false);\n\t\t%s\n\t}\n}\n' "$sq" "$open" >cgal_open_union.csg
printf 'union() {\n\t%s\n\t%%intersection() {\n\t\tcube(size = [1, 1, 1], center = false);\n\t\t%s\n\t}\n}\n' "$sq" "$open" >cgal_open_bg.csg
not_closed='polyhedron is not closed (edge 0-2 is used by 1 face)'
cgal_said='as OpenSCAD leaves it out ("The given mesh is not closed! Unable to convert to CGAL_Nef_Polyhedron.")'
for mode in "" --faithful; do
    # shellcheck disable=SC2086
    {
        warns cgal_apart.csg "cgal_apart.csg:3:2: warning: Ignoring 3D child object for 2D operation" $mode
        warns cgal_touch.csg "cgal_touch.csg:3:2: warning: Mixing 2D and 3D objects is not supported
cgal_touch.csg:3:2: warning: Ignoring 3D child object for 2D operation" $mode
        warns cgal_hull.csg "" $mode
        warns cgal_cut.csg "cgal_cut.csg:3:2: warning: Ignoring 3D child object for 2D operation" $mode
        warns cgal_first.csg "cgal_first.csg:3:2: warning: Ignoring 3D child object for 2D operation" $mode
        warns cgal_extrude.csg "" $mode
        warns cgal_open_intersection.csg "cgal_open_intersection.csg:5:3: warning: $not_closed; left out, $cgal_said" $mode
        warns cgal_open_minkowski.csg "cgal_open_minkowski.csg:5:3: warning: $not_closed; the minkowski is empty, $cgal_said
cgal_open_minkowski.csg:3:2: warning: Ignoring 3D child object for 2D operation" $mode
        warns cgal_open_union.csg "cgal_open_union.csg:5:3: warning: $not_closed; left out, $cgal_said
cgal_open_union.csg:3:2: warning: Mixing 2D and 3D objects is not supported
cgal_open_union.csg:3:2: warning: Ignoring 3D child object for 2D operation" $mode
        warns cgal_open_bg.csg "cgal_open_bg.csg:5:3: warning: $not_closed; left out, $cgal_said" $mode
        refuses cgal_open_intersection.csg "cgal_open_intersection.csg:5:3: error: $not_closed" $mode
        for f in apart touch hull cut first open_intersection open_minkowski open_union open_bg; do
            same "cgal_$f.csg" empty3d_ref.csg $mode
        done
        same cgal_extrude.csg extrude_ref.csg $mode
    }
done

# An extrusion or import among them is evaluated first too (openscad -o
# /abs/x.stl x.csg prints exactly these): an extrusion of one empty child,
# of no child, or by an angle of 0 is no geometry; one of two empty
# children, or of height 0, is an empty solid, only ignored. An import is
# read: a file that does not open, one without faces, or one whose format
# no reader takes is empty, with its warning; a mesh that is not closed is
# taken as it comes, and mixes. Offset, in whose 2D context an import is
# read as a drawing, says only that it ignores them.
ext='linear_extrude(height = 1, center = false, convexity = 1, scale = [1, 1], $fn = 0, $fa = 12, $fs = 2)'
imp() { printf 'import(file = "%s", layer = "", origin = [0, 0], scale = 1, convexity = 1, $fn = 0, $fa = 12, $fs = 2);' "$1"; }
printf 'union() {\n\t%s\n\t%s {\n\t\tsquare(size = [0, 1], center = false);\n\t}\n\t%s {\n\t\tsquare(size = [0, 1], center = false);\n\t\tsquare(size = [1, 0], center = false);\n\t}\n\trotate_extrude(angle = 0, convexity = 1, $fn = 0, $fa = 12, $fs = 2) {\n\t\tsquare(size = [1, 1], center = false);\n\t}\n\t%s;\n}\n' \
    "$sq" "$ext" "$ext" "$ext" >left_extrude.csg
printf 'union() {\n\t%s\n\t%s {\n\t\tsquare(size = [1, 1], center = false);\n\t}\n}\n' "$sq" "${ext/height = 1/height = 0}" >left_flat.csg
printf 'solid e\nendsolid e\n' >faceless.stl
printf 'solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid t\n' >triangle.stl
printf 'x\n' >thing.obj
for f in missing.stl faceless.stl triangle.stl thing.obj; do
    printf 'union() {\n\t%s\n\t%s\n}\n' "$sq" "$(imp $f)" >"left_${f%.*}.csg"
done
printf 'offset(r = 1, $fn = 0, $fa = 12, $fs = 2) {\n\t%s\n\t%s\n\t%s\n}\n' "$sq" "$(imp missing.stl)" "$(imp triangle.stl)" >left_offset.csg
printf 'offset(r = 1, $fn = 0, $fa = 12, $fs = 2) { %s }\n' "$sq" >offset_ref.csg
opened="Can't open import file 'missing.stl': No such file or directory"
for mode in "" --faithful; do
    # shellcheck disable=SC2086
    {
        warns left_extrude.csg "left_extrude.csg:6:2: warning: Ignoring 3D child object for 2D operation" $mode
        warns left_flat.csg "left_flat.csg:3:2: warning: Ignoring 3D child object for 2D operation" $mode
        warns left_missing.csg "left_missing.csg:3:16: warning: $opened; the import is empty, as OpenSCAD leaves it out (--strict makes it an error)
left_missing.csg:3:2: warning: Ignoring 3D child object for 2D operation" $mode
        warns left_faceless.csg "left_faceless.csg:3:2: warning: Ignoring 3D child object for 2D operation" $mode
        warns left_triangle.csg "left_triangle.csg:3:2: warning: Mixing 2D and 3D objects is not supported
left_triangle.csg:3:2: warning: Ignoring 3D child object for 2D operation" $mode
        warns left_thing.csg "left_thing.csg:3:16: warning: Unsupported file format while trying to import file '\"thing.obj\"' (import() reads .stl, .off, .amf, .3mf, .dxf and .svg files); the import is empty, as OpenSCAD leaves it out (--strict makes it an error)
left_thing.csg:3:2: warning: Ignoring 3D child object for 2D operation" $mode
        warns left_offset.csg "left_offset.csg:3:16: warning: $opened; the import is empty, as OpenSCAD leaves it out (--strict makes it an error)
left_offset.csg:3:2: warning: Ignoring 3D child object for 2D operation
left_offset.csg:4:2: warning: Ignoring 3D child object for 2D operation" $mode
        refuses left_offset.csg "left_offset.csg:3:16: error: $opened" $mode
        for f in extrude flat missing faceless triangle thing; do
            same "left_$f.csg" empty3d_ref.csg $mode
        done
        same left_offset.csg offset_ref.csg $mode
    }
done

# ---- 2D and 3D children in projection, '%' subtrees, --strict ----
cube1='cube(size = [1, 1, 1], center = false);'
bad2d='polygon(points = [[0, 0], [1, 0], [1, "a"]]);'
removed="warning: Transformation matrix contains Not-a-Number and/or Infinity - removing object."
printf 'union() {\n\t%s\n\tsquare(size = [0, 0], center = false);\n}\n' "$cube1" >e_zero.csg

# ---- 2D children of projection ----
# As OpenSCAD 2021.01: projection(cut = false) passes over a child that is
# 2D (a shape, or a group or transform whose first child is) without a
# word; projection(cut = true) unites its children as a 3D operation, so
# each 2D child is 'Ignoring 2D child object for 3D operation', after all
# of them, with no 'Mixing' (it does not check that). The 2D child still
# gives its own warnings first. A 3D operation deeper inside is one like
# any other. A projection with no 3D child is no geometry at all: no
# dimension, no warning in a 3D operation, and a file that starts with one
# is not a 2D model.
cat >proj_cut2d.csg <<'M'
union() {
	cube(size = [2, 2, 2], center = false);
	projection(cut = true) {
		square(size = [1, 1], center = false);
	}
	projection(cut = false) {
		square(size = [1, 1], center = false);
	}
}
M
printf 'cube(size = [2, 2, 2], center = false);\n' >proj_cube_ref.csg
cat >proj_group2d.csg <<'M'
linear_extrude(height = 1) {
	projection(cut = false) {
		group() {
			square(size = [5, 5], center = false);
			cube(size = [4, 4, 1], center = false);
		}
		multmatrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {
			square(size = [1, 1], center = false);
		}
		multmatrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, -0.5], [0, 0, 0, 1]]) { cube(size = [2, 3, 1], center = false); }
	}
}
M
sed 's/cut = false/cut = true/' proj_group2d.csg >proj_group2d_cut.csg
printf 'linear_extrude(height = 1) { square(size = [2, 3], center = false); }\n' >proj_group2d_ref.csg
cat >proj_nested2d.csg <<'M'
projection(cut = true) {
	union() {
		multmatrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, -1], [0, 0, 0, 1]]) {
			cube(size = [2, 2, 2], center = false);
		}
		square(size = [0, 1], center = false);
		square(size = [5, 5], center = false);
	}
}
M
printf 'square(size = [2, 2], center = false);\n' >proj_nested2d_ref.csg
printf 'projection(cut = true) {\n\tsquare(size = [1, 1], center = false);\n}\ncube(size = [2, 2, 2], center = false);\n' >proj_first.csg
printf 'projection(cut = false) {\n\tsquare(size = [1, 1], center = false);\n}\n' >proj_only.csg
for mode in "" --faithful; do
    warns proj_cut2d.csg "proj_cut2d.csg:4:3: warning: Ignoring 2D child object for 3D operation" $mode
    warns proj_group2d.csg "proj_group2d.csg:5:4: warning: Mixing 2D and 3D objects is not supported
proj_group2d.csg:5:4: warning: Ignoring 3D child object for 2D operation" $mode
    warns proj_group2d_cut.csg "proj_group2d_cut.csg:5:4: warning: Mixing 2D and 3D objects is not supported
proj_group2d_cut.csg:5:4: warning: Ignoring 3D child object for 2D operation
proj_group2d_cut.csg:3:3: warning: Ignoring 2D child object for 3D operation
proj_group2d_cut.csg:7:3: warning: Ignoring 2D child object for 3D operation" $mode
    warns proj_nested2d.csg "proj_nested2d.csg:7:3: warning: Mixing 2D and 3D objects is not supported
proj_nested2d.csg:6:3: warning: Ignoring 2D child object for 3D operation
proj_nested2d.csg:7:3: warning: Ignoring 2D child object for 3D operation" $mode
    warns proj_first.csg "proj_first.csg:2:2: warning: Ignoring 2D child object for 3D operation" $mode
    warns proj_only.csg "proj_only.csg: warning: the model is empty (nothing to render)" $mode
    for pair in proj_cut2d.csg:proj_cube_ref.csg proj_first.csg:proj_cube_ref.csg \
        proj_group2d.csg:proj_group2d_ref.csg proj_group2d_cut.csg:proj_group2d_ref.csg \
        proj_nested2d.csg:proj_nested2d_ref.csg; do
        # shellcheck disable=SC2086
        same "${pair%%:*}" "${pair#*:}" $mode
    done
done

# ---- '%' subtrees ----
# A '%' mesh (an extrusion, a polyhedron) is drawn by the preview like any
# other part: the parts have the model's budget of mesh triangles.
printf 'cube(size = [2, 2, 2], center = false);\n%%linear_extrude(height = 1) { square(size = [1, 1], center = false); }\n%%polyhedron(points = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], faces = [[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]]);\n' >pct_mesh.csg
for mode in "" --faithful --preview; do
    warns pct_mesh.csg "" $mode
done

# OpenSCAD 2021.01's render evaluates a '%' subtree before it leaves it
# out: its nodes give their warnings (a 3D operation mixing, a polygon's
# point, an import that does not open, a removed transform), in file
# order; the '%' node itself is no operand of its parent, which says
# nothing of it (the 2D square at line 7). None of it is rendered.
cat >pct.csg <<'M'
union() {
	cube(size = [2, 2, 2], center = false);
	%union() {
		cube(size = [1, 1, 1], center = false);
		square(size = [1, 1], center = false);
	}
	%square(size = [1, 1], center = false);
	%linear_extrude(height = 1) { union() { square(size = [1, 1], center = false); cube(size = [1, 1, 1], center = false); } }
	%polygon(points = [[0, 0], [1, 0], [1, "a"]]);
	%import(file = "missing.stl");
	%multmatrix([[nan, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) { cube(size = [1, 1, 1], center = false); }
}
M
cat >pct_top.csg <<'M'
%union() {
	cube(size = [1, 1, 1], center = false);
	polygon(points = [[0, 0], [1, 0], [1, "a"]]);
}
cube(size = [2, 2, 2], center = false);
M
# the same for a singular transform, whose subtree OpenSCAD evaluates too
cat >pct_singular.csg <<'M'
union() {
	cube(size = [2, 2, 2], center = false);
	multmatrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 0, 0], [0, 0, 0, 1]]) {
		union() {
			cube(size = [1, 1, 1], center = false);
			square(size = [1, 1], center = false);
		}
	}
}
M
printf 'cube(size = [2, 2, 2], center = false);\n' >pct_ref.csg
for mode in "" --faithful; do
    warns pct.csg 'pct.csg:5:3: warning: Mixing 2D and 3D objects is not supported
pct.csg:5:3: warning: Ignoring 2D child object for 3D operation
pct.csg:8:81: warning: Mixing 2D and 3D objects is not supported
pct.csg:8:81: warning: Ignoring 3D child object for 2D operation
pct.csg:9:37: warning: Unable to convert points[2] = [1, "a"] to a vec2 of numbers; the polygon is empty, as OpenSCAD leaves it out (--strict makes it an error)
pct.csg:10:17: warning: Can'"'"'t open import file '"'"'missing.stl'"'"': No such file or directory; the import is empty, as OpenSCAD leaves it out (--strict makes it an error)
pct.csg:11:3: warning: Transformation matrix contains Not-a-Number and/or Infinity - removing object.' $mode
    warns pct_top.csg 'pct_top.csg:3:36: warning: Unable to convert points[2] = [1, "a"] to a vec2 of numbers; the polygon is empty, as OpenSCAD leaves it out (--strict makes it an error)
pct_top.csg:3:2: warning: Ignoring 2D child object for 3D operation' $mode
    warns pct_singular.csg "pct_singular.csg:3:2: warning: singular transform: subtree is empty
pct_singular.csg:6:4: warning: Mixing 2D and 3D objects is not supported
pct_singular.csg:6:4: warning: Ignoring 2D child object for 3D operation" $mode
    for model in pct.csg pct_top.csg pct_singular.csg; do
        # shellcheck disable=SC2086
        same "$model" pct_ref.csg $mode
    done
    # --strict: the first warning is the error
    # shellcheck disable=SC2086
    {
        refuses pct.csg "pct.csg:5:3: error: 2D child object in a 3D operation" $mode
        refuses pct_top.csg "pct_top.csg:3:36: error: wrong type for argument 'points' of 'polygon' (expected a vector of [x, y] points)" $mode
    }
done

# ---- --strict: a child of the other dimension is the error ----
# OpenSCAD 2021.01 ignores a 2D child of a 3D operation and a 3D child of
# a 2D one with its warnings "Mixing 2D and 3D objects is not supported"
# and "Ignoring 2D child object for 3D operation" (or 3D ... 2D), at the
# top level, in 2D operations and extrusions, in hull, minkowski and
# projection (openscad -o /abs/x.stl x.csg, -o /abs/x.dxf for 2D). With
# --strict the first of them is the error, at its position (for a 3D child
# of an extrusion or boolean: cli_lenient_dims.sh).
square1='square(size = [1, 1], center = false);'
printf '%s\n%s\n' "$cube1" "$square1" >dim_top.csg
printf '%s\n%s\n' "$square1" "$cube1" >dim_top2d.csg
printf 'hull() {\n\t%s\n\t%s\n}\n' "$cube1" "$square1" >dim_hull.csg
printf 'minkowski() {\n\t%s\n\t%s\n}\n' "$cube1" "$square1" >dim_mink.csg
printf 'projection(cut = true) {\n\t%s\n\t%s\n}\n' "$cube1" "$square1" >dim_cut.csg
printf 'projection(cut = false) {\n\tunion() {\n\t\t%s\n\t\t%s\n\t}\n}\n' "$cube1" "$square1" >dim_proj.csg
printf 'projection(cut = false) {\n\thull() {\n\t\t%s\n\t\t%s\n\t}\n}\n' "$cube1" "$square1" >dim_proj_hull.csg
printf 'projection(cut = true) {\n\tdifference() {\n\t\t%s\n\t\t%s\n\t}\n}\n' "$cube1" "$square1" >dim_proj_cut.csg
printf 'hull() {\n\tunion() {\n\t\t%s\n\t\t%s\n\t}\n}\n' "$cube1" "$square1" >dim_hull_union.csg
printf 'linear_extrude(height = 1) {\n\thull() {\n\t\t%s\n\t\t%s\n\t}\n}\n' "$square1" "$cube1" >dim_hull2d.csg
printf 'resize(newsize = [2, 2, 2]) {\n\t%s\n\t%s\n}\n' "$cube1" "$square1" >dim_resize.csg
for mode in "" --faithful; do
    # shellcheck disable=SC2086
    {
        warns dim_top.csg "dim_top.csg:2:1: warning: Mixing 2D and 3D objects is not supported
dim_top.csg:2:1: warning: Ignoring 2D child object for 3D operation" $mode
        warns dim_top2d.csg "dim_top2d.csg:2:1: warning: Mixing 2D and 3D objects is not supported
dim_top2d.csg:2:1: warning: Ignoring 3D child object for 2D operation" $mode
        warns dim_hull.csg "dim_hull.csg:3:2: warning: Mixing 2D and 3D objects is not supported
dim_hull.csg:3:2: warning: Ignoring 2D child object for 3D operation" $mode
        warns dim_mink.csg "dim_mink.csg:3:2: warning: Mixing 2D and 3D objects is not supported
dim_mink.csg:3:2: warning: Ignoring 2D child object for 3D operation" $mode
        warns dim_cut.csg "dim_cut.csg:3:2: warning: Ignoring 2D child object for 3D operation" $mode
        warns dim_proj.csg "dim_proj.csg:4:3: warning: Mixing 2D and 3D objects is not supported
dim_proj.csg:4:3: warning: Ignoring 2D child object for 3D operation" $mode
        warns dim_proj_hull.csg "dim_proj_hull.csg:4:3: warning: Mixing 2D and 3D objects is not supported
dim_proj_hull.csg:4:3: warning: Ignoring 2D child object for 3D operation" $mode
        warns dim_proj_cut.csg "dim_proj_cut.csg:4:3: warning: Mixing 2D and 3D objects is not supported
dim_proj_cut.csg:4:3: warning: Ignoring 2D child object for 3D operation" $mode
        warns dim_hull_union.csg "dim_hull_union.csg:4:3: warning: Mixing 2D and 3D objects is not supported
dim_hull_union.csg:4:3: warning: Ignoring 2D child object for 3D operation" $mode
        warns dim_hull2d.csg "dim_hull2d.csg:4:3: warning: Mixing 2D and 3D objects is not supported
dim_hull2d.csg:4:3: warning: Ignoring 3D child object for 2D operation" $mode
        refuses dim_top.csg "dim_top.csg:2:1: error: 2D child object in a 3D operation" $mode
        refuses dim_top2d.csg "dim_top2d.csg:2:1: error: 3D child object in a 2D operation" $mode
        refuses dim_hull.csg "dim_hull.csg:3:2: error: 2D child object in a 3D operation" $mode
        refuses dim_mink.csg "dim_mink.csg:3:2: error: 2D child object in a 3D operation" $mode
        refuses dim_cut.csg "dim_cut.csg:3:2: error: 2D child object in a 3D operation" $mode
        refuses dim_proj.csg "dim_proj.csg:4:3: error: 2D child object in a 3D operation" $mode
        refuses dim_proj_hull.csg "dim_proj_hull.csg:4:3: error: 2D child object in a 3D operation" $mode
        refuses dim_proj_cut.csg "dim_proj_cut.csg:4:3: error: 2D child object in a 3D operation" $mode
        refuses dim_hull_union.csg "dim_hull_union.csg:4:3: error: 2D child object in a 3D operation" $mode
        refuses dim_hull2d.csg "dim_hull2d.csg:4:3: error: 3D child object in a 2D operation" $mode
        warns dim_resize.csg "dim_resize.csg:3:2: warning: Mixing 2D and 3D objects is not supported
dim_resize.csg:3:2: warning: Ignoring 2D child object for 3D operation" $mode
        refuses dim_resize.csg "dim_resize.csg:3:2: error: 2D child object in a 3D operation" $mode
        # an empty child mixes nothing: its "Ignoring" is the error
        refuses e_zero.csg "e_zero.csg:3:2: error: 2D child object in a 3D operation" $mode
    }
done

# ---- a projection without a 3D child in a 3D operation ----
# OpenSCAD 2021.01 makes no geometry of a projection whose children are
# all 2D, so a hull or minkowski (or a union or difference in them) says
# nothing of it; only projection(cut = true) ignores its own 2D child
# (openscad -o /abs/x.stl x.csg prints exactly these).
printf 'hull() {\n\t%s\n\tprojection(cut = false) {\n\t\t%s\n\t}\n}\n' "$cube1" "$square1" >nop_hull.csg
printf 'hull() {\n\t%s\n\tprojection(cut = true) {\n\t\t%s\n\t}\n}\n' "$cube1" "$square1" >nop_hull_cut.csg
printf 'minkowski() {\n\t%s\n\tprojection(cut = false) {\n\t\t%s\n\t}\n}\n' "$cube1" "$square1" >nop_mink.csg
printf 'hull() {\n\t%s\n\tunion() {\n\t\tprojection(cut = false) {\n\t\t\t%s\n\t\t}\n\t}\n}\n' "$cube1" "$square1" >nop_hull_union.csg
printf 'minkowski() {\n\t%s\n\tdifference() {\n\t\t%s\n\t\tprojection(cut = true) {\n\t\t\t%s\n\t\t}\n\t}\n}\n' "$cube1" "$cube1" "$square1" >nop_mink_diff.csg
printf 'hull() {\n\t%s\n\tprojection(cut = false) {\n\t\t%s\n\t}\n\t%s\n}\n' "$cube1" "$square1" "$square1" >nop_hull_then.csg
printf 'hull() {\n\t%s\n}\n' "$cube1" >nop_ref.csg
printf 'minkowski() {\n\t%s\n\t%s\n}\n' "$cube1" "$cube1" >nop_mink_ref.csg
for mode in "" --faithful; do
    # shellcheck disable=SC2086
    {
        warns nop_hull.csg "" $mode
        same nop_hull.csg nop_ref.csg $mode
        warns nop_hull_cut.csg "nop_hull_cut.csg:4:3: warning: Ignoring 2D child object for 3D operation" $mode
        same nop_hull_cut.csg nop_ref.csg $mode
        warns nop_mink.csg "" $mode
        same nop_mink.csg nop_ref.csg $mode
        warns nop_hull_union.csg "" $mode
        same nop_hull_union.csg nop_ref.csg $mode
        warns nop_mink_diff.csg "nop_mink_diff.csg:6:4: warning: Ignoring 2D child object for 3D operation" $mode
        same nop_mink_diff.csg nop_mink_ref.csg $mode
        warns nop_hull_then.csg "nop_hull_then.csg:6:2: warning: Mixing 2D and 3D objects is not supported
nop_hull_then.csg:6:2: warning: Ignoring 2D child object for 3D operation" $mode
        same nop_hull_then.csg nop_ref.csg $mode
        warns nop_hull.csg "" --strict $mode
    }
done

# ---- '%' children in 2D operations, projection and hull ----
# OpenSCAD 2021.01's render evaluates a background child before it leaves
# it out, also in a 2D operation, an extrusion, a 2D model, a projection
# and a hull: its subtree's own warnings are printed (a polygon's point, a
# union that mixes), nothing of the '%' node itself (openscad -o
# /abs/x.stl x.csg; -o /abs/x.dxf for the 2D models).
bad2d='polygon(points = [[0, 0], [1, 0], [1, "a"]]);'
printf 'linear_extrude(height = 1) {\n\t%s\n\t%%union() {\n\t\t%s\n\t\t%s\n\t}\n}\n' "$square1" "$square1" "$bad2d" >bg_extrude.csg
printf 'union() {\n\t%s\n\t%%union() {\n\t\t%s\n\t\t%s\n\t}\n}\n' "$square1" "$square1" "$bad2d" >bg_flat.csg
printf 'linear_extrude(height = 1) {\n\tprojection(cut = false) {\n\t\t%s\n\t\t%%union() {\n\t\t\t%s\n\t\t\t%s\n\t\t}\n\t}\n}\n' "$cube1" "$cube1" "$bad2d" >bg_proj.csg
printf 'linear_extrude(height = 1) {\n\t%s\n\t%%%s\n\t%%union() {\n\t\t%s\n\t\t%s\n\t}\n}\n' "$square1" "$cube1" "$square1" "$cube1" >bg_mixed.csg
printf 'union() {\n\t%s\n\t%%%s\n\t%%union() {\n\t\t%s\n\t\t%s\n\t}\n\t%%%s\n}\n' "$square1" "$cube1" "$square1" "$cube1" "$bad2d" >bg_flat_mixed.csg
printf 'linear_extrude(height = 1) {\n\tprojection(cut = %s) {\n\t\t%s\n\t\t%%%s\n\t\t%%union() {\n\t\t\t%s\n\t\t\t%s\n\t\t}\n\t}\n}\n' false "$cube1" "$bad2d" "$cube1" "$square1" >bg_proj2.csg
printf 'linear_extrude(height = 1) {\n\tprojection(cut = %s) {\n\t\t%s\n\t\t%%%s\n\t\t%%union() {\n\t\t\t%s\n\t\t\t%s\n\t\t}\n\t}\n}\n' true "$cube1" "$bad2d" "$cube1" "$square1" >bg_cut2.csg
printf 'linear_extrude(height = 1) {\n\t%s\n\t%%union() {\n\t\t%s\n\t\t%s\n\t}\n}\n' "$square1" "$cube1" "$square1" >bg_3d.csg
printf 'hull() {\n\t%s\n\t%%%s\n\t%%union() {\n\t\t%s\n\t\t%s\n\t}\n}\n' "$cube1" "$bad2d" "$cube1" "$square1" >bg_hull.csg
printf 'linear_extrude(height = 1) {\n\t%s\n}\n' "$square1" >bg_extrude_ref.csg
printf '%s\n' "$square1" >bg_flat_ref.csg
printf 'linear_extrude(height = 1) {\n\tprojection(cut = false) {\n\t\t%s\n\t}\n}\n' "$cube1" >bg_proj_ref.csg
printf 'hull() {\n\t%s\n}\n' "$cube1" >bg_hull_ref.csg
for mode in "" --faithful; do
    # shellcheck disable=SC2086
    {
        warns bg_extrude.csg "$(unable bg_extrude.csg 5 37)" $mode
        same bg_extrude.csg bg_extrude_ref.csg $mode
        warns bg_flat.csg "$(unable bg_flat.csg 5 37)" $mode
        same bg_flat.csg bg_flat_ref.csg $mode
        warns bg_proj.csg "$(unable bg_proj.csg 6 38)
bg_proj.csg:6:4: warning: Ignoring 2D child object for 3D operation" $mode
        same bg_proj.csg bg_proj_ref.csg $mode
        warns bg_mixed.csg "bg_mixed.csg:6:3: warning: Mixing 2D and 3D objects is not supported
bg_mixed.csg:6:3: warning: Ignoring 3D child object for 2D operation" $mode
        same bg_mixed.csg bg_extrude_ref.csg $mode
        warns bg_flat_mixed.csg "bg_flat_mixed.csg:6:3: warning: Mixing 2D and 3D objects is not supported
bg_flat_mixed.csg:6:3: warning: Ignoring 3D child object for 2D operation
$(unable bg_flat_mixed.csg 8 37)" $mode
        same bg_flat_mixed.csg bg_flat_ref.csg $mode
        for model in bg_proj2.csg bg_cut2.csg; do
            warns $model "$(unable $model 4 38)
$model:7:4: warning: Mixing 2D and 3D objects is not supported
$model:7:4: warning: Ignoring 2D child object for 3D operation" $mode
            same $model bg_proj_ref.csg $mode
        done
        warns bg_3d.csg "bg_3d.csg:5:3: warning: Mixing 2D and 3D objects is not supported
bg_3d.csg:5:3: warning: Ignoring 2D child object for 3D operation" $mode
        same bg_3d.csg bg_extrude_ref.csg $mode
        warns bg_hull.csg "$(unable bg_hull.csg 3 37)
bg_hull.csg:6:3: warning: Mixing 2D and 3D objects is not supported
bg_hull.csg:6:3: warning: Ignoring 2D child object for 3D operation" $mode
        same bg_hull.csg bg_hull_ref.csg $mode
        refuses bg_extrude.csg "bg_extrude.csg:5:37: error: wrong type for argument 'points' of 'polygon' (expected a vector of [x, y] points)" $mode
        refuses bg_mixed.csg "bg_mixed.csg:6:3: error: 3D child object in a 2D operation" $mode
    }
done

# ---- a removed transform under hull, minkowski and projection ----
# OpenSCAD 2021.01 evaluates the children of a multmatrix with a nan or
# inf entry before it removes it, here as elsewhere: their own warnings
# (a polygon's point; a union inside that mixes) come first, then the
# removal, and not its own check of their dimensions (openscad -o
# /abs/x.stl x.scad, with 0/0 in the matrix, prints exactly these).
nan_m='multmatrix([[nan, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]])'
printf 'hull() {\n\t%s\n\t%s {\n\t\t%s\n\t\t%s\n\t}\n}\n' "$cube1" "$nan_m" "$cube1" "$bad2d" >nan_hull.csg
printf 'minkowski() {\n\t%s\n\t%s {\n\t\t%s\n\t\t%s\n\t}\n}\n' "$cube1" "$nan_m" "$cube1" "$bad2d" >nan_mink.csg
printf 'hull() {\n\t%s\n\t%s {\n\t\tunion() {\n\t\t\t%s\n\t\t\t%s\n\t\t}\n\t}\n}\n' "$cube1" "$nan_m" "$cube1" "$square1" >nan_hull_mixed.csg
for cut in false true; do
    printf 'linear_extrude(height = 1) {\n\tprojection(cut = %s) {\n\t\t%s\n\t\t%s {\n\t\t\t%s\n\t\t\t%s\n\t\t}\n\t}\n}\n' "$cut" "$cube1" "$nan_m" "$cube1" "$bad2d" >nan_proj_$cut.csg
done
printf 'linear_extrude(height = 1) {\n\tprojection(cut = false) {\n\t\thull() {\n\t\t\t%s\n\t\t\t%s {\n\t\t\t\t%s\n\t\t\t\t%s\n\t\t\t}\n\t\t}\n\t}\n}\n' "$cube1" "$nan_m" "$cube1" "$bad2d" >nan_proj_hull.csg
printf 'linear_extrude(height = 1) {\n\tprojection(cut = true) {\n\t\tdifference() {\n\t\t\t%s\n\t\t\t%s {\n\t\t\t\t%s\n\t\t\t\t%s\n\t\t\t}\n\t\t}\n\t}\n}\n' "$cube1" "$nan_m" "$cube1" "$bad2d" >nan_cut_diff.csg
printf 'linear_extrude(height = 1) {\n\tprojection(cut = true) {\n\t\t%s\n\t}\n}\n' "$cube1" >nan_cut_ref.csg
removing="warning: Transformation matrix contains Not-a-Number and/or Infinity - removing object."
for mode in "" --faithful; do
    # shellcheck disable=SC2086
    {
        warns nan_hull.csg "$(unable nan_hull.csg 5 37)
nan_hull.csg:3:2: $removing" $mode
        same nan_hull.csg bg_hull_ref.csg $mode
        warns nan_mink.csg "$(unable nan_mink.csg 5 37)
nan_mink.csg:3:2: $removing" $mode
        same nan_mink.csg bg_hull_ref.csg $mode
        warns nan_hull_mixed.csg "nan_hull_mixed.csg:6:4: warning: Mixing 2D and 3D objects is not supported
nan_hull_mixed.csg:6:4: warning: Ignoring 2D child object for 3D operation
nan_hull_mixed.csg:3:2: $removing" $mode
        same nan_hull_mixed.csg bg_hull_ref.csg $mode
        for model in nan_proj_false.csg nan_proj_true.csg; do
            warns $model "$(unable $model 6 38)
$model:4:3: $removing" $mode
        done
        same nan_proj_false.csg bg_proj_ref.csg $mode
        same nan_proj_true.csg nan_cut_ref.csg $mode
        warns nan_proj_hull.csg "$(unable nan_proj_hull.csg 7 39)
nan_proj_hull.csg:5:4: $removing" $mode
        same nan_proj_hull.csg bg_proj_ref.csg $mode
        warns nan_cut_diff.csg "$(unable nan_cut_diff.csg 7 39)
nan_cut_diff.csg:5:4: $removing" $mode
        same nan_cut_diff.csg nan_cut_ref.csg $mode
        refuses nan_hull.csg "nan_hull.csg:5:37: error: wrong type for argument 'points' of 'polygon' (expected a vector of [x, y] points)" $mode
    }
done

# ---- the warnings inside a 3D child that a 2D operation ignores ----
# OpenSCAD 2021.01 evaluates a 3D child of a 2D operation before it
# ignores it, so the warnings of its subtree come first (a polygon's
# point, its own 3D operation's "Ignoring 2D child object for 3D
# operation", a polyhedron's index; a '%' child below it too), then the
# 2D operation's own (openscad -o /abs/x.stl x.csg, -o /abs/x.dxf for the
# 2D model, prints exactly these; its preview, -o x.png, adds "PolySet has
# degenerate polygons" after a polyhedron's index warning, as spancast
# does: see meshes.md).
tetra_bad='polyhedron(points = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], faces = [[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 7]], convexity = 1);'
printf 'linear_extrude(height = 1) {\n\tunion() {\n\t\t%s\n\t\tunion() {\n\t\t\t%s\n\t\t\t%s\n\t\t}\n\t}\n}\n' "$square1" "$cube1" "$bad2d" >in3d_extrude.csg
printf 'union() {\n\t%s\n\tunion() {\n\t\t%s\n\t\t%s\n\t}\n}\n' "$square1" "$cube1" "$bad2d" >in3d_flat.csg
printf 'linear_extrude(height = 1) {\n\t%s\n\t%s\n}\n' "$square1" "$tetra_bad" >in3d_faces.csg
printf 'linear_extrude(height = 1) {\n\t%s\n\tunion() {\n\t\t%s\n\t\t%%%s\n\t}\n}\n' "$square1" "$cube1" "$bad2d" >in3d_bg.csg
printf 'linear_extrude(height = 1) {\n\t%s\n\thull() {\n\t\t%s\n\t\t%s\n\t}\n}\n' "$square1" "$cube1" "$bad2d" >in3d_hull.csg
printf 'rotate_extrude(angle = 360, $fn = 8, $fa = 12, $fs = 2) {\n\tmultmatrix([[1, 0, 0, 2], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {\n\t\t%s\n\t}\n\tunion() {\n\t\t%s\n\t\t%s\n\t}\n}\n' "$square1" "$cube1" "$bad2d" >in3d_revolve.csg
printf 'rotate_extrude(angle = 360, $fn = 8, $fa = 12, $fs = 2) {\n\tmultmatrix([[1, 0, 0, 2], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {\n\t\t%s\n\t}\n}\n' "$square1" >in3d_revolve_ref.csg
# the square in the 3D union is no part of the profile, in exact mode too
printf 'rotate_extrude(angle = 360, $fn = 8, $fa = 12, $fs = 2) {\n\tmultmatrix([[1, 0, 0, 2], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {\n\t\t%s\n\t}\n\tunion() {\n\t\t%s\n\t\tmultmatrix([[1, 0, 0, 5], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {\n\t\t\t%s\n\t\t}\n\t}\n}\n' "$square1" "$cube1" "$square1" >in3d_revolve_far.csg
for mode in "" --faithful; do
    # shellcheck disable=SC2086
    {
        warns in3d_extrude.csg "$(unable in3d_extrude.csg 6 38)
in3d_extrude.csg:6:4: warning: Ignoring 2D child object for 3D operation
in3d_extrude.csg:4:3: warning: Mixing 2D and 3D objects is not supported
in3d_extrude.csg:4:3: warning: Ignoring 3D child object for 2D operation" $mode
        same in3d_extrude.csg bg_extrude_ref.csg $mode
        warns in3d_flat.csg "$(unable in3d_flat.csg 5 37)
in3d_flat.csg:5:3: warning: Ignoring 2D child object for 3D operation
in3d_flat.csg:3:2: warning: Mixing 2D and 3D objects is not supported
in3d_flat.csg:3:2: warning: Ignoring 3D child object for 2D operation" $mode
        same in3d_flat.csg bg_flat_ref.csg $mode
        warns in3d_faces.csg "in3d_faces.csg:3:117: warning: Point index 7 is out of bounds (from faces[3][2])
in3d_faces.csg:3:110: warning: PolySet has degenerate polygons (faces[3] has fewer than 3 points; left out, as OpenSCAD leaves it out)
in3d_faces.csg:3:2: warning: Ignoring 3D child object for 2D operation" $mode
        same in3d_faces.csg bg_extrude_ref.csg $mode
        warns in3d_bg.csg "$(unable in3d_bg.csg 5 38)
in3d_bg.csg:3:2: warning: Ignoring 3D child object for 2D operation" $mode
        same in3d_bg.csg bg_extrude_ref.csg $mode
        warns in3d_hull.csg "$(unable in3d_hull.csg 5 37)
in3d_hull.csg:5:3: warning: Ignoring 2D child object for 3D operation
in3d_hull.csg:3:2: warning: Ignoring 3D child object for 2D operation" $mode
        same in3d_hull.csg bg_extrude_ref.csg $mode
        warns in3d_revolve.csg "$(unable in3d_revolve.csg 7 37)
in3d_revolve.csg:7:3: warning: Ignoring 2D child object for 3D operation
in3d_revolve.csg:5:2: warning: Ignoring 3D child object for 2D operation" $mode
        same in3d_revolve.csg in3d_revolve_ref.csg $mode
        warns in3d_revolve_far.csg "in3d_revolve_far.csg:7:3: warning: Mixing 2D and 3D objects is not supported
in3d_revolve_far.csg:7:3: warning: Ignoring 2D child object for 3D operation
in3d_revolve_far.csg:5:2: warning: Ignoring 3D child object for 2D operation" $mode
        same in3d_revolve_far.csg in3d_revolve_ref.csg $mode
        refuses in3d_extrude.csg "in3d_extrude.csg:6:38: error: wrong type for argument 'points' of 'polygon' (expected a vector of [x, y] points)" $mode
    }
done

# The same for a '%' child of minkowski, and of a boolean inside hull.
printf 'minkowski() {\n\t%s\n\t%%%s\n\t%%union() {\n\t\t%s\n\t\t%s\n\t}\n}\n' "$cube1" "$bad2d" "$cube1" "$square1" >bg_mink.csg
printf 'hull() {\n\tdifference() {\n\t\t%s\n\t\t%%%s\n\t}\n}\n' "$cube1" "$bad2d" >bg_hull_diff.csg
for mode in "" --faithful; do
    # shellcheck disable=SC2086
    {
        warns bg_mink.csg "$(unable bg_mink.csg 3 37)
bg_mink.csg:6:3: warning: Mixing 2D and 3D objects is not supported
bg_mink.csg:6:3: warning: Ignoring 2D child object for 3D operation" $mode
        same bg_mink.csg bg_hull_ref.csg $mode
        warns bg_hull_diff.csg "$(unable bg_hull_diff.csg 4 38)" $mode
        same bg_hull_diff.csg bg_hull_ref.csg $mode
    }
done

# ---- a singular transform and a resize in a projection ----
# OpenSCAD 2021.01 flattens a mesh under a singular multmatrix and projects
# the faces of the flat mesh (crosscheck projection_flattened), but removes
# a Nef polyhedron (here a union of two solids) with "Scaling a 3D object
# with 0 - removing object"; a resize of a flat Nef polyhedron says "Resize
# in direction normal to flat object is not implemented" and leaves it as
# it is. Both warnings come as well where the projection is the model
# itself (a 2D one) as under an extrusion.
flat_union='union() {\n\t\t\tcube(size = [2, 2, 2], center = false);\n\t\t\tmultmatrix([[1, 0, 0, 3], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {\n\t\t\t\tcube(size = [1, 1, 1], center = false);\n\t\t\t}\n\t\t}'
sheets='union() {\n\t\t\tpolyhedron(points = [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], faces = [[0, 1, 2, 3], [3, 2, 1, 0]]);\n\t\t\tpolyhedron(points = [[2, 0, 0], [3, 0, 0], [3, 1, 0], [2, 1, 0]], faces = [[0, 1, 2, 3], [3, 2, 1, 0]]);\n\t\t}'
# shellcheck disable=SC2059
{
    printf "projection(cut = false) {\n\tmultmatrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 0, 0], [0, 0, 0, 1]]) {\n\t\t$flat_union\n\t}\n}\n$square1\n" >flat_nef.csg
    printf "linear_extrude(height = 1) {\n\tprojection(cut = false) {\n\t\tmultmatrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 0, 0], [0, 0, 0, 1]]) {\n\t\t$flat_union\n\t\t}\n\t}\n\t$square1\n}\n" >flat_nef_extruded.csg
    printf "projection(cut = false) {\n\tresize(newsize = [4, 2, 2]) {\n\t\t$sheets\n\t}\n}\n$square1\n" >flat_resize.csg
    printf "hull() {\n\t$cube1\n\tmultmatrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 0, 0], [0, 0, 0, 1]]) {\n\t\t$flat_union\n\t}\n}\n" >flat_hull.csg
    printf "projection(cut = false) {\n\thull() {\n\t\t$cube1\n\t\tmultmatrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 0, 0], [0, 0, 0, 1]]) {\n\t\t$flat_union\n\t\t}\n\t}\n}\n" >flat_proj_hull.csg
    # an extrusion that is not convex flattened in a minkowski, which
    # OpenSCAD finds not closed (its whole sum is empty): not followed, and
    # said so
    printf "minkowski() {\n\t$cube1\n\tmultmatrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 0, 0], [0, 0, 0, 1]]) {\n\t\tlinear_extrude(height = 2) {\n\t\t\tpolygon(points = [[0, 0], [4, 0], [4, 1], [1, 1], [1, 4], [0, 4]]);\n\t\t}\n\t}\n}\n" >flat_mink.csg
}
for mode in "" --faithful; do
    # shellcheck disable=SC2086
    {
        warns flat_nef.csg "flat_nef.csg:2:2: warning: Scaling a 3D object with 0 - removing object" $mode
        warns flat_nef_extruded.csg "flat_nef_extruded.csg:3:3: warning: Scaling a 3D object with 0 - removing object" $mode
        warns flat_resize.csg "flat_resize.csg:2:2: warning: resize in a direction normal to a flat object is not implemented" $mode
        warns flat_hull.csg "flat_hull.csg:3:2: warning: Scaling a 3D object with 0 - removing object" $mode
        warns flat_proj_hull.csg "flat_proj_hull.csg:4:3: warning: Scaling a 3D object with 0 - removing object" $mode
        warns flat_mink.csg "flat_mink.csg:4:3: warning: linear_extrude flattened by a singular multmatrix is not convex: left out of minkowski (not supported yet)" $mode
    }
done
if command -v openscad >/dev/null; then
    for model in flat_nef.dxf flat_resize.dxf flat_hull.stl flat_proj_hull.dxf; do
        check
        openscad -o "$PWD/$model" "${model%.*}.csg" >/dev/null 2>"${model%.*}_os.err"
        grep -q "^WARNING: \(Scaling a 3D object with 0 - removing object\|Resize in direction normal to flat object is not implemented\)" "${model%.*}_os.err" ||
            fail "openscad on ${model%.*}.csg: $(cat "${model%.*}_os.err")"
    done
fi

# With --strict the first of these warnings is the error, at its position.
for mode in "" --faithful; do
    # shellcheck disable=SC2086
    {
        refuses extrude.csg "extrude.csg:3:2: error: 3D child object in a 2D operation" $mode
        refuses union.csg "union.csg:6:3: error: 3D child object in a 2D operation" $mode
        refuses cut.csg "cut.csg:4:3: error: 3D child object in a 2D operation" $mode
    }
done

echo "$checks checks, $fails failed"
[ "$fails" = 0 ]
