#!/usr/bin/env python3
"""chord.py: how far OpenSCAD 2021.01's mesh of a model can lie from the
exact solid, computed from the model's .csg alone, independently of
spancast (the code under test), for the exact-mode cross-check.

usage: chord.py MODEL.csg
prints one line:  DELTA GAMMA   (world units, radians), or
                  none REASON   when no bound is derived for the model.

DELTA bounds the Hausdorff distance between each curved leaf's exact
surface and OpenSCAD's polygons of it, in world units; GAMMA bounds the
angle between a mesh facet's normal and the exact surface's normal at any
point of the surface over that facet (compare.c widens it to the facet's
neighbours). Both are maxima over the model's curved leaves; a model with
no curved leaf prints "0 0": its exact solid is OpenSCAD's own polygons.

Fragments (OpenSCAD 2021.01 src/calc.cc, get_fragments_from_r): 3 when
r < GRID_FINE = 2^-20 or $fn is not finite; int(max($fn, 3)) when
$fn > 0; else ceil(max(min(360 / $fa, 2 pi r / $fs), 5)).

Circle (circle(r), and a cylinder's ends): n = fragments(r) points on the
circle at angles 360 k / n, so each side is a chord of half-angle
a = pi / n. Its sagitta bounds the distance: delta = r (1 - cos a); the
arc's normals over a chord turn by at most a from the chord's normal:
gamma = a.

Cylinder(h, r1, r2) (src/primitives.cc): n = fragments(max(r1, r2)) for
both ends, side facets through points k, k + 1 of both circles. Every
horizontal slice of the mesh is the regular n-gon inscribed in the slice of
the exact cone, so delta = max(r1, r2) (1 - cos a). A facet's normal lies
in its mid-azimuth plane, tilted by psi' with tan psi' = tan psi / cos a
against the cone's psi; the cone's normal at azimuth phi from that plane
is within phi of the mid-azimuth normal (their dot product is
cos^2 psi cos phi + sin^2 psi >= cos phi), and psi' - psi is at most
atan((1 - cos a) / (2 sqrt(cos a))) (the maximum over tan psi of
tan(psi' - psi) = tan psi (1 - c) / (c + tan^2 psi), at tan psi = sqrt c),
so gamma = a + that (0 for r1 = r2).

Sphere(r): n = fragments(r), rings = (n + 1) / 2 circles of n points at
polar angles (i + 0.5) 180 / rings, the first and last ring closed by
flat caps, quads between rings. All vertices lie on the sphere, so the
mesh is a convex polyhedron inscribed in it, and the Hausdorff distance of
the two surfaces is r - d_min, d_min the smallest distance from the centre
to a face plane (along any ray from the centre both surfaces are crossed
once, at radii d >= d_min and r). A cap plane is at r cos(pi / (2 rings)).
A quad between polar angles phi_a, phi_b = phi_a + pi / rings and azimuths
+-a: by symmetry its plane holds the azimuthal direction, and in the
mid-azimuth section its edge runs through (cos a sin phi, cos phi) for
phi = phi_a, phi_b, points of the ellipse (cos a sin phi, cos phi). Scaling
x by 1 / cos a maps them to the unit circle, where the chord is at
cos(pi / (2 rings)) from the centre along (sin phi_m, cos phi_m); back in
the section the distance is cos(pi / (2 rings)) /
sqrt(sin^2 phi_m / cos^2 a + cos^2 phi_m) >= cos(pi / (2 rings)) cos a. So
delta = r (1 - cos(pi / (2 rings)) cos a), and gamma, the largest angle
between a face normal and the radius through a point of that face (a
vertex), is acos(cos(pi / (2 rings)) cos a).

linear_extrude(height) without twist and with scale 1: the prism of the
2D polygons, every horizontal slice the 2D shape: the 2D bounds carry over
unchanged. Twist, or a scale other than 1 on curved outlines, has no bound
here (OpenSCAD's slices define that solid).

rotate_extrude(angle): fragments = int(max(fragments(max_x - min_x) *
|angle| / 360, 1)) (src/GeometryEvaluator.cc, rotatePolygon; min_x,
max_x over the profile's vertices, both starting at 0), steps of
s = |angle| / fragments. A profile point at radius x sweeps an arc whose
chords have sagitta x (1 - cos(s / 2)); with the profile's own delta2,
delta = delta2 + x_max (1 - cos(s / 2)). A facet is a chord-trapezoid of
the cone swept by one profile edge (the cylinder's case above, with
a = s / 2), and the profile edge is itself within gamma2 of the exact
profile's normal: gamma = gamma2 + gamma_cone(s / 2). With $fn = 0 the
fragment count needs the profile's extent, known here only for unions of
circles, squares and polygons under 2D transforms.

Transforms: a leaf's bounds are mapped to the world by the accumulated
linear part A of its multmatrix chain. Distances grow by at most the
largest singular value s_max of A; the angle between two normals mapped by
A^-T grows as tan gamma' <= (s_max / s_min) tan gamma. The singular values
come from the eigenvalues of A^T A (Jacobi rotations), widened by a
relative 1e-9 for rounding.

Booleans, groups, colours, render, hull or minkowski of polyhedra only:
each boundary point of the mesh's result lies on some leaf's mesh, within
delta of that leaf's exact surface, so the bounds are the maxima over the
leaves. Hull and minkowski of curved leaves, offset with round joins or
of curved outlines, text (font curves), DXF and SVG imports (their arcs),
resize of curved leaves (the scale comes from each side's own box) and
any other node have no bound here (a projection adds none: spancast
builds it from OpenSCAD's polygons in both modes; its extent is unknown
here, so rotate_extrude of one has no bound): the model is reported as not
exact-checkable with the reason.
"""
import math
import re
import sys

GRID_FINE = 2.0 ** -20


class NotCheckable(Exception):
    pass


# --- the .csg grammar: statement = [modifiers] name '(' args ')' (';' | '{' statement* '}')
TOKEN = re.compile(r'\s*(?:(//[^\n]*|/\*.*?\*/)|("(?:\\.|[^"\\])*")|'
                   r'([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)|'
                   r'([A-Za-z_$][A-Za-z0-9_$]*)|(.))', re.S)


def tokens(text):
    out = []
    for m in TOKEN.finditer(text):
        comment, string, number, name, punct = m.groups()
        if comment:
            continue
        if string is not None:
            out.append(('str', string[1:-1]))
        elif number is not None:
            out.append(('num', float(number)))
        elif name is not None:
            out.append(('name', name))
        elif punct is not None and not punct.isspace():
            out.append(('p', punct))
    return out


class Parser:
    def __init__(self, toks):
        self.t = toks
        self.i = 0

    def peek(self):
        return self.t[self.i] if self.i < len(self.t) else ('eof', None)

    def take(self, kind=None, value=None):
        tok = self.peek()
        if (kind and tok[0] != kind) or (value is not None and tok[1] != value):
            raise SyntaxError('expected %s %s, got %r' % (kind, value, tok))
        self.i += 1
        return tok

    def value(self):
        kind, v = self.peek()
        if kind == 'p' and v == '[':
            self.take()
            items = []
            while self.peek() != ('p', ']'):
                items.append(self.value())
                if self.peek() == ('p', ','):
                    self.take()
            self.take('p', ']')
            return items
        if kind == 'p' and v == '-':
            self.take()
            return -self.value()
        self.take()
        if kind == 'name':
            return {'true': True, 'false': False}.get(v, None)
        return v

    def statement(self):
        while self.peek()[0] == 'p' and self.peek()[1] in '%#!*':
            self.take()
        name = self.take('name')[1]
        self.take('p', '(')
        args, pos = {}, []
        while self.peek() != ('p', ')'):
            if self.peek()[0] == 'name' and self.t[self.i + 1] == ('p', '='):
                key = self.take()[1]
                self.take()
                args[key] = self.value()
            else:
                pos.append(self.value())
            if self.peek() == ('p', ','):
                self.take()
        self.take('p', ')')
        children = []
        if self.peek() == ('p', '{'):
            self.take()
            while self.peek() != ('p', '}'):
                if self.peek() == ('p', ';'):
                    self.take()
                    continue
                children.append(self.statement())
            self.take()
        else:
            self.take('p', ';')
        return (name, args, pos, children)

    def program(self):
        nodes = []
        while self.peek()[0] != 'eof':
            if self.peek() == ('p', ';'):
                self.take()
                continue
            nodes.append(self.statement())
        return nodes


# --- numbers of OpenSCAD's tessellation
def fragments(r, args):
    fn = num(args.get('$fn', 0))
    fs = num(args.get('$fs', 2))
    fa = num(args.get('$fa', 12))
    if r < GRID_FINE or math.isinf(fn) or math.isnan(fn):
        return 3
    if fn > 0:
        return int(fn if fn >= 3 else 3)
    return int(math.ceil(max(min(360.0 / fa, r * 2 * math.pi / fs), 5)))


def num(v, default=0.0):
    return float(v) if isinstance(v, (int, float)) and not isinstance(v, bool) else default


def cone_gamma(a):
    """gamma of a chord-trapezoid of half-angle a on a cone (see the header)."""
    c = math.cos(a)
    return a + math.atan((1 - c) / (2 * math.sqrt(c))) if c > 0 else math.pi / 2


# --- 3 x 3 linear algebra
def matmul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(3)) for j in range(3)] for i in range(3)]


IDENTITY = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]


def singular_values(a):
    """(s_min, s_max) of a, widened by a relative 1e-9."""
    m = [[sum(a[k][i] * a[k][j] for k in range(3)) for j in range(3)] for i in range(3)]
    for _ in range(60):
        off = max(abs(m[0][1]), abs(m[0][2]), abs(m[1][2]))
        if off <= 1e-30 + 1e-17 * max(abs(m[i][i]) for i in range(3)):
            break
        for p, q in ((0, 1), (0, 2), (1, 2)):
            if m[p][q] == 0:
                continue
            theta = (m[q][q] - m[p][p]) / (2 * m[p][q])
            t = math.copysign(1.0, theta) / (abs(theta) + math.sqrt(theta * theta + 1))
            c = 1 / math.sqrt(t * t + 1)
            s = t * c
            for k in range(3):  # columns p, q
                mkp, mkq = m[k][p], m[k][q]
                m[k][p], m[k][q] = c * mkp - s * mkq, s * mkp + c * mkq
            for k in range(3):  # rows p, q
                mpk, mqk = m[p][k], m[q][k]
                m[p][k], m[q][k] = c * mpk - s * mqk, s * mpk + c * mqk
    eig = [max(m[i][i], 0.0) for i in range(3)]
    return math.sqrt(min(eig)) * (1 - 1e-9), math.sqrt(max(eig)) * (1 + 1e-9)


def linear_part(m):
    """The 3 x 3 linear part of a multmatrix argument."""
    try:
        return [[float(m[i][j]) for j in range(3)] for i in range(3)]
    except (TypeError, IndexError, ValueError):
        raise NotCheckable('multmatrix without a 3 x 3 linear part')


def to_world(a, delta, gamma):
    """(delta, gamma) of a leaf mapped by the linear map a (see the header)."""
    if delta == 0:
        return 0.0, 0.0
    s_min, s_max = singular_values(a)
    if s_min <= 0:
        return 0.0, 0.0  # flattened: empty in both
    g = math.atan(s_max / s_min * math.tan(gamma)) if gamma < math.pi / 2 else math.pi / 2
    return delta * s_max, g


# --- the walk
GROUPS = {'group', 'union', 'difference', 'intersection', 'color', 'render'}
MESH_FILES = ('.stl', '.off', '.amf', '.3mf')


class Walk:
    def __init__(self):
        self.delta = 0.0
        self.gamma = 0.0

    def add(self, a, delta, gamma):
        d, g = to_world(a, delta, gamma)
        self.delta = max(self.delta, d)
        self.gamma = max(self.gamma, g)

    def node3(self, node, a):
        name, args, pos, children = node
        if name in GROUPS:
            for c in children:
                self.node3(c, a)
        elif name == 'multmatrix':
            m = args.get('m', pos[0] if pos else None)
            for c in children:
                self.node3(c, matmul(a, linear_part(m)))
        elif name in ('cube', 'polyhedron', 'surface'):
            pass
        elif name == 'import':
            if not str(args.get('file', '')).lower().endswith(MESH_FILES):
                raise NotCheckable('import of %s: its curves are OpenSCAD\'s reader\'s'
                                   % str(args.get('file', '?')).rsplit('.', 1)[-1])
        elif name == 'sphere':
            r = num(args.get('r', 1))
            n = fragments(r, args)
            rings = (n + 1) // 2
            c = math.cos(math.pi / (2 * rings)) * math.cos(math.pi / n)
            self.add(a, r * (1 - c), math.acos(c))
        elif name == 'cylinder':
            r1, r2 = num(args.get('r1', 1)), num(args.get('r2', 1))
            if num(args.get('h', 1)) <= 0 or r1 < 0 or r2 < 0 or max(r1, r2) <= 0:
                return
            n = fragments(max(r1, r2), args)
            half = math.pi / n
            gamma = half if r1 == r2 else cone_gamma(half)
            self.add(a, max(r1, r2) * (1 - math.cos(half)), gamma)
        elif name in ('hull', 'minkowski', 'resize'):
            inner = Walk()
            for c in children:
                inner.node3(c, a)
            if inner.delta > 0:
                raise NotCheckable('%s of curved leaves' % name)
        elif name in ('linear_extrude', 'rotate_extrude') and 'file' in args:
            raise NotCheckable('%s of a file: its curves are OpenSCAD\'s DXF reader\'s'
                               % name)
        elif name == 'linear_extrude':
            if num(args.get('twist', 0)) != 0:
                raise NotCheckable('twisted linear_extrude')
            scale = args.get('scale', 1)
            sx, sy = (scale if isinstance(scale, list) else [scale, scale])[:2]
            shape = Shape()
            for c in children:
                shape.node2(c, IDENTITY2)
            if shape.delta > 0 and (num(sx, 1) != 1 or num(sy, 1) != 1):
                raise NotCheckable('scaled linear_extrude of curved outlines')
            if shape.delta == 0 and num(sx, 1) != num(sy, 1):
                raise NotCheckable('linear_extrude with a non-uniform scale')
            self.add(a, shape.delta, shape.gamma)
        elif name == 'rotate_extrude':
            shape = Shape()
            for c in children:
                shape.node2(c, IDENTITY2)
            angle = num(args.get('angle', 360), 360)
            fn = num(args.get('$fn', 0))
            if fn > 0 and not math.isinf(fn):
                extent = 1.0  # any r >= GRID_FINE gives the same count
            elif shape.exact_extent:
                extent = shape.max_x - shape.min_x
            else:
                raise NotCheckable('rotate_extrude with $fn = 0 of a 2D boolean '
                                   '(its fragment count needs the extent)')
            count = int(max(fragments(extent, args) * abs(angle) / 360, 1))
            half = math.radians(abs(angle) / count) / 2
            if math.isinf(shape.x_max):
                raise NotCheckable('rotate_extrude of %s (its extent)' % shape.unbounded)
            delta = shape.delta + shape.x_max * (1 - math.cos(half))
            if delta > 0:
                self.add(a, delta, shape.gamma + cone_gamma(half))
        else:
            raise NotCheckable('%s: no bound for this node' % name)


IDENTITY2 = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]  # 2D affine: rows x, y; columns x, y, 1


class Shape:
    """Bounds of a 2D subtree in its extrusion's frame: delta and gamma as
    above, x_max (an upper bound of |x| over the exact shape and the
    polygons), and the polygons' vertex range [min_x, max_x] (both from 0,
    as OpenSCAD counts it) when exact_extent."""

    def __init__(self):
        self.delta = 0.0
        self.gamma = 0.0
        self.x_max = 0.0
        self.min_x = 0.0
        self.max_x = 0.0
        self.exact_extent = True
        self.unbounded = 'an offset'  # what made x_max infinite

    def points(self, t, pts):
        for x, y in pts:
            px = t[0][0] * x + t[0][1] * y + t[0][2]
            self.min_x = min(self.min_x, px)
            self.max_x = max(self.max_x, px)
            self.x_max = max(self.x_max, abs(px))

    def node2(self, node, t, exact=True):
        name, args, pos, children = node
        if name in ('group', 'union', 'color', 'render'):
            for c in children:
                self.node2(c, t, exact)
        elif name in ('difference', 'intersection'):
            for c in children:
                self.node2(c, t, False)
        elif name == 'multmatrix':
            m = args.get('m', pos[0] if pos else None)
            try:
                l = [[float(m[i][j]) for j in (0, 1, 3)] for i in (0, 1)]
            except (TypeError, IndexError, ValueError):
                raise NotCheckable('multmatrix without a 2D part')
            u = [[t[i][0] * l[0][j] + t[i][1] * l[1][j] + (t[i][2] if j == 2 else 0)
                  for j in range(3)] for i in range(2)]
            for c in children:
                self.node2(c, u, exact)
        elif name == 'square':
            size = args.get('size', 1)
            w, h = (size if isinstance(size, list) else [size, size])[:2]
            w, h = num(w), num(h)
            x0, y0 = (-w / 2, -h / 2) if args.get('center') else (0.0, 0.0)
            self.points(t, [(x0, y0), (x0 + w, y0), (x0, y0 + h), (x0 + w, y0 + h)])
            self.exact_extent &= exact
        elif name == 'polygon':
            pts = args.get('points', pos[0] if pos else [])
            self.points(t, [(num(p[0]), num(p[1])) for p in pts])
            self.exact_extent &= exact
        elif name == 'circle':
            r = num(args.get('r', 1))
            if r <= 0:
                return
            n = fragments(r, args)
            self.points(t, [(r * math.cos(2 * math.pi * k / n),
                             r * math.sin(2 * math.pi * k / n)) for k in range(n)])
            self.exact_extent &= exact
            a = [[t[0][0], t[0][1], 0.0], [t[1][0], t[1][1], 0.0], [0.0, 0.0, 1.0]]
            s_min, s_max = singular_values(a)
            if s_min <= 0:
                return
            # The exact ellipse reaches r s_max from its centre.
            self.x_max = max(self.x_max, abs(t[0][2]) + r * s_max)
            half = math.pi / n
            d, g = to_world(a, r * (1 - math.cos(half)), half)
            self.delta = max(self.delta, d)
            self.gamma = max(self.gamma, g)
        elif name in ('offset', 'hull', 'minkowski'):
            inner, x_sum = Shape(), 0.0
            for c in children:
                part = Shape()
                part.node2(c, t, False)
                inner.node2(c, t, False)
                x_sum += part.x_max
            if inner.delta > 0:
                raise NotCheckable('2D %s of curved outlines' % name)
            if name == 'offset' and 'r' in args and num(args['r']) != 0:
                raise NotCheckable('offset with round joins')
            if name == 'hull':
                self.x_max = max(self.x_max, inner.x_max)  # a hull of the points
            elif name == 'minkowski':
                self.x_max = max(self.x_max, x_sum)  # at most the children's sum
            else:
                self.x_max = math.inf  # mitred corners reach beyond delta
                self.unbounded = 'an offset'
            self.exact_extent = False
        elif name == 'projection':
            # spancast builds a projection from OpenSCAD's polygons of its 3D
            # children in both modes, so it adds no chord error; its extent
            # is not derived here.
            self.x_max = math.inf
            self.exact_extent = False
            self.unbounded = 'a projection'
        elif name == 'import':
            raise NotCheckable('2D import of %s: its curves are OpenSCAD\'s reader\'s'
                               % str(args.get('file', '?')).rsplit('.', 1)[-1])
        else:
            raise NotCheckable('%s: no bound for this node' % name)


def main():
    if len(sys.argv) != 2:
        print('usage: chord.py MODEL.csg', file=sys.stderr)
        return 2
    with open(sys.argv[1], encoding='utf-8', errors='replace') as f:
        text = f.read()
    try:
        tree = Parser(tokens(text)).program()
    except (SyntaxError, IndexError) as e:
        print('chord.py: %s: %s' % (sys.argv[1], e), file=sys.stderr)
        return 2
    walk = Walk()
    try:
        for node in tree:
            walk.node3(node, IDENTITY)
    except NotCheckable as e:
        print('none %s' % e)
        return 0
    print('%.17g %.17g' % (walk.delta, walk.gamma))
    return 0


if __name__ == '__main__':
    sys.exit(main())
