"""Mesh files for the shell tests that import them (tests/cli_*.sh), written
the way the tests need them: AMF text of several objects, 3MF packages (a
zip of the model, its content types and its relationship) of mesh objects
with build items and components. An object is (points, triangles), the
triangles three indices into its own points.

    python3 -c 'import sys; sys.path.insert(0, SRC + "/tests"); import meshfiles; ...'
"""
import zipfile

CORE = "http://schemas.microsoft.com/3dmanufacturing/core/2015/02"


def cube(origin, size, inward=False, drop=0):
    """A box from origin with sides size (a number or three), its triangles
    wound outward (inward: the other way), the last drop of them left out."""
    sx, sy, sz = size if isinstance(size, (tuple, list)) else (size, size, size)
    x, y, z = origin
    points = [(x + dx * sx, y + dy * sy, z + dz * sz)
              for dz in (0, 1) for dy in (0, 1) for dx in (0, 1)]
    tris = [(0, 2, 1), (1, 2, 3), (4, 5, 6), (5, 7, 6), (0, 1, 4), (1, 5, 4),
            (2, 6, 3), (3, 6, 7), (0, 4, 2), (2, 4, 6), (1, 3, 5), (3, 7, 5)]
    if inward:
        tris = [(a, c, b) for a, b, c in tris]
    return points, tris[:len(tris) - drop]


def amf(objects):
    """The text of an AMF file of objects, one <object> each."""
    out = ['<?xml version="1.0" encoding="UTF-8"?>\n<amf unit="millimeter">\n']
    for i, (points, tris) in enumerate(objects):
        out.append(' <object id="%d"><mesh><vertices>\n' % i)
        out += ['  <vertex><coordinates><x>%g</x><y>%g</y><z>%g</z></coordinates></vertex>\n'
                % p for p in points]
        out.append(' </vertices><volume>\n')
        out += ['  <triangle><v1>%d</v1><v2>%d</v2><v3>%d</v3></triangle>\n' % t
                for t in tris]
        out.append(' </volume></mesh></object>\n')
    out.append('</amf>\n')
    return ''.join(out)


def mesh(points, tris):
    """A 3MF <mesh> element."""
    return ('<mesh><vertices>'
            + ''.join('<vertex x="%g" y="%g" z="%g"/>' % p for p in points)
            + '</vertices><triangles>'
            + ''.join('<triangle v1="%d" v2="%d" v3="%d"/>' % t for t in tris)
            + '</triangles></mesh>')


def package(path, resources, build):
    """Writes the 3MF package at path: resources and build are the text
    inside the model's <resources> and <build> elements."""
    model = ('<?xml version="1.0" encoding="UTF-8"?>\n'
             '<model unit="millimeter" xmlns="%s"><resources>%s</resources>'
             '<build>%s</build></model>\n' % (CORE, resources, build))
    types = ('<?xml version="1.0" encoding="UTF-8"?>\n'
             '<Types xmlns="http://schemas.openxmlformats.org/package/2006/content-types">'
             '<Default Extension="rels" ContentType="application/vnd.openxmlformats-package.relationships+xml"/>'
             '<Default Extension="model" ContentType="application/vnd.ms-package.3dmanufacturing-3dmodel+xml"/>'
             '</Types>\n')
    rels = ('<?xml version="1.0" encoding="UTF-8"?>\n'
            '<Relationships xmlns="http://schemas.openxmlformats.org/package/2006/relationships">'
            '<Relationship Target="/3D/3dmodel.model" Id="rel0" '
            'Type="http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel"/>'
            '</Relationships>\n')
    with zipfile.ZipFile(path, 'w', zipfile.ZIP_DEFLATED) as z:
        z.writestr('[Content_Types].xml', types)
        z.writestr('_rels/.rels', rels)
        z.writestr('3D/3dmodel.model', model)


def threemf(path, objects):
    """Writes a 3MF package of objects, each a mesh object with its own
    build item."""
    package(path,
            ''.join('<object id="%d" type="model">%s</object>' % (i + 1, mesh(*o))
                    for i, o in enumerate(objects)),
            ''.join('<item objectid="%d"/>' % (i + 1) for i in range(len(objects))))
