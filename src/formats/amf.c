/* AMF meshes as OpenSCAD 2021.01 reads them (import_amf.cc): XML through
 * libxml2 (xml.h), and from it only the elements at OpenSCAD's paths,
 *
 *   /amf/object                                       a new object
 *   /amf/object/mesh/vertices/vertex/coordinates      x, y, z: a vertex
 *   /amf/object/mesh/volume/triangle                  v1, v2, v3: a triangle
 *
 * with no namespace prefix. Vertex indices count from the first vertex of
 * the object (across its meshes); a coordinate or index left out keeps the
 * value the previous vertex or triangle gave it (0 at first), as in
 * OpenSCAD. The units attribute, metadata, colours, materials,
 * constellations and curved-triangle edges are not read, as OpenSCAD does
 * not read them. A zipped AMF is unzipped first (amf_unzip), as OpenSCAD
 * reads through libzip any file that libzip opens as an archive.
 *
 * OpenSCAD stops at a value that is not a number (boost::lexical_cast:
 * the whole text, no spaces) with a warning, and at an index out of range
 * it reads past its array; here both are errors with the file's line.
 * OpenSCAD unites several objects with CGAL (each object one solid, all
 * its meshes and volumes together); here their triangles are returned
 * together with where each object starts, and the caller builds each
 * object and unites them.
 */
#include "formats/amf.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "base/grow.h"
#include "formats/xml.h"

typedef struct reader {
    const char *name;
    const sc_location *at;
    sc_error *error;
    amf_mesh *out;
    uint32_t point_cap, index_cap, face_cap, object_point_cap, object_face_cap;
    uint32_t object_first; /* the current object's first point */
    double xyz[3];         /* the last coordinates given */
    long v[3];             /* the last indices given */
    sc_status status;
} reader;

static sc_status fail(reader *r, sc_status status, int line, const char *fmt,
                      const char *arg)
{
    char why[256];
    snprintf(why, sizeof why, fmt, arg);
    sc_location here = {r->at->file, line, 1}; /* the file is the model */
    if (line > 0)
        r->status = err_set(r->error, status, r->at->line ? r->at : &here,
                            "import: %s:%d: %s", r->name, line, why);
    else
        r->status = err_set(r->error, status, r->at, "import: %s: %s", r->name, why);
    return r->status;
}

/* boost::lexical_cast<double>: the whole text a number, no spaces. */
static int read_double(const char *s, double *out)
{
    if (!*s || isspace((unsigned char)*s) ||
        (s[0] == '0' && (s[1] == 'x' || s[1] == 'X')))
        return 0;
    char *end;
    errno = 0;
    double x = strtod(s, &end);
    if (*end || !isfinite(x))
        return 0;
    *out = x;
    return 1;
}

static int read_long(const char *s, long *out)
{
    if (!*s || isspace((unsigned char)*s))
        return 0;
    char *end;
    errno = 0;
    long x = strtol(s, &end, 10);
    if (*end || errno)
        return 0;
    *out = x;
    return 1;
}

static sc_status vertex(reader *r, const xml_element *coordinates)
{
    static const char *const axes[] = {"x", "y", "z"};
    for (int i = 0; i < 3; i++)
        for (const xml_element *k = coordinates->first_child; k; k = k->next)
            if (!strcmp(k->name, axes[i]) && !read_double(k->text, &r->xyz[i]))
                return fail(r, SC_ERR_SYNTAX, k->line, "'%s' is not a number", k->text);
    amf_mesh *m = r->out;
    if (m->point_count >= AMF_MAX_POINTS)
        return fail(r, SC_ERR_LIMIT, coordinates->line, "%s", "too many vertices");
    if (!grow_array32((void **)&m->points, &r->point_cap, m->point_count + 1,
                      sizeof *m->points))
        return fail(r, SC_ERR_NOMEM, 0, "%s", "out of memory");
    m->points[m->point_count++] = v3(r->xyz[0], r->xyz[1], r->xyz[2]);
    return SC_OK;
}

static sc_status triangle(reader *r, const xml_element *t)
{
    static const char *const corners[] = {"v1", "v2", "v3"};
    amf_mesh *m = r->out;
    uint32_t object_points = m->point_count - r->object_first;
    for (int i = 0; i < 3; i++)
        for (const xml_element *k = t->first_child; k; k = k->next)
            if (!strcmp(k->name, corners[i]) && !read_long(k->text, &r->v[i]))
                return fail(r, SC_ERR_SYNTAX, k->line, "'%s' is not an index", k->text);
    for (int i = 0; i < 3; i++)
        if (r->v[i] < 0 || (unsigned long)r->v[i] >= object_points) {
            char what[64];
            snprintf(what, sizeof what, "%ld", r->v[i]);
            return fail(r, SC_ERR_SEMANTIC, t->line,
                        "vertex index %s is not one of the object's vertices", what);
        }
    if (m->face_count >= AMF_MAX_POINTS)
        return fail(r, SC_ERR_LIMIT, t->line, "%s", "too many triangles");
    if (!grow_array32((void **)&m->indices, &r->index_cap, 3 * (m->face_count + 1),
                      sizeof *m->indices) ||
        !grow_array32((void **)&m->face_start, &r->face_cap, m->face_count + 2,
                      sizeof *m->face_start))
        return fail(r, SC_ERR_NOMEM, 0, "%s", "out of memory");
    for (int i = 0; i < 3; i++)
        m->indices[3 * m->face_count + (uint32_t)i] = r->object_first + (uint32_t)r->v[i];
    m->face_start[m->face_count] = 3 * m->face_count;
    m->face_count++;
    m->face_start[m->face_count] = 3 * m->face_count;
    return SC_OK;
}

/* Where the objects start, with room for the end of the last. */
static sc_status start_object(reader *r, uint32_t object, uint32_t point, uint32_t face)
{
    amf_mesh *m = r->out;
    if (!grow_array32((void **)&m->object_points, &r->object_point_cap, object + 2,
                      sizeof *m->object_points) ||
        !grow_array32((void **)&m->object_faces, &r->object_face_cap, object + 2,
                      sizeof *m->object_faces))
        return fail(r, SC_ERR_NOMEM, 0, "%s", "out of memory");
    m->object_points[object] = point;
    m->object_faces[object] = face;
    return SC_OK;
}

static sc_status object(reader *r, const xml_element *o)
{
    if (r->out->object_count >= AMF_MAX_POINTS)
        return fail(r, SC_ERR_LIMIT, o->line, "%s", "too many objects");
    if (start_object(r, r->out->object_count, r->out->point_count, r->out->face_count))
        return r->status;
    r->out->object_count++;
    r->object_first = r->out->point_count;
    sc_status st = SC_OK;
    for (const xml_element *mesh = o->first_child; mesh && st == SC_OK;
         mesh = mesh->next) {
        if (strcmp(mesh->name, "mesh"))
            continue;
        for (const xml_element *part = mesh->first_child; part && st == SC_OK;
             part = part->next) {
            int is_vertices = !strcmp(part->name, "vertices");
            int is_volume = !strcmp(part->name, "volume");
            for (const xml_element *k = part->first_child; k && st == SC_OK;
                 k = k->next) {
                if (is_vertices && !strcmp(k->name, "vertex")) {
                    for (const xml_element *c = k->first_child; c && st == SC_OK;
                         c = c->next)
                        if (!strcmp(c->name, "coordinates"))
                            st = vertex(r, c);
                } else if (is_volume && !strcmp(k->name, "triangle")) {
                    st = triangle(r, k);
                }
            }
        }
    }
    return st;
}

sc_status amf_read(const char *text, size_t size, const char *name, const sc_location *at,
                   amf_mesh *out, sc_error *error)
{
    memset(out, 0, sizeof *out);
    reader r;
    memset(&r, 0, sizeof r);
    r.name = name;
    r.at = at;
    r.error = error;
    r.out = out;
    xml_doc doc;
    char why[256];
    int line = 0;
    int code = xml_parse(text, size, &doc, why, sizeof why, &line);
    if (code != XML_OK) {
        fail(&r,
             code == XML_ERR_NOMEM    ? SC_ERR_NOMEM
             : code == XML_ERR_LIMIT  ? SC_ERR_LIMIT
             : code == XML_ERR_PLUGIN ? SC_ERR_IO
                                      : SC_ERR_SYNTAX,
             line, "%s", why);
    } else if (strcmp(doc.root->name, "amf")) {
        fail(&r, SC_ERR_SYNTAX, doc.root->line, "the root element is <%s>, not <amf>",
             doc.root->name);
    } else {
        for (const xml_element *o = doc.root->first_child; o && r.status == SC_OK;
             o = o->next)
            if (!strcmp(o->name, "object"))
                object(&r, o);
        if (r.status == SC_OK && out->object_count)
            start_object(&r, out->object_count, out->point_count, out->face_count);
    }
    xml_free(&doc);
    return r.status;
}

void amf_mesh_free(amf_mesh *m)
{
    free(m->points);
    free(m->indices);
    free(m->face_start);
    free(m->object_points);
    free(m->object_faces);
    memset(m, 0, sizeof *m);
}

sc_status amf_unzip(const char *data, size_t size, const char *path, const char *name,
                    const sc_location *at, size_t max_size, char **text,
                    size_t *text_size, char *warning, size_t warning_size,
                    sc_error *error)
{
    *text = NULL;
    *text_size = 0;
    if (warning_size)
        warning[0] = 0;
    const char *slash = strrchr(path, '/');
    const char *entry = slash ? slash + 1 : path;
    char single[256], why[256];
    int code = xml_unzip(data, size, entry, max_size, text, text_size, single,
                         sizeof single, why, sizeof why);
    if (code == XML_NOT_ZIP)
        return SC_OK;
    if (code == XML_OK) {
        if (single[0])
            snprintf(warning, warning_size,
                     "Can't read file '%s' from zipped AMF '%s'; trying to read single "
                     "entry '%s'",
                     entry, path, single);
        return SC_OK;
    }
    sc_status status = code == XML_ERR_NOMEM    ? SC_ERR_NOMEM
                       : code == XML_ERR_LIMIT  ? SC_ERR_LIMIT
                       : code == XML_ERR_PLUGIN ? SC_ERR_IO
                                                : SC_ERR_SYNTAX;
    return err_set(error, status, at,
                   "import: %s: can't read file '%s' from zipped AMF: %s", name, entry,
                   why);
}
