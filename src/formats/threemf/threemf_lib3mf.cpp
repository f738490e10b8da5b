/* spancast-3mf.so: 3MF files read by lib3mf 1.8, as OpenSCAD 2021.01's
 * import_3mf.cc reads them (threemf.h): every mesh object's vertices and
 * triangles, the indices checked against the object's vertex count, and
 * where each object starts (OpenSCAD unites the objects). The only code
 * that links lib3mf, loaded on demand (threemf.c); its arrays grow by the
 * project's rule (base/grow.c, built into the plugin). */
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <new>

#include <Model/COM/NMR_DLLInterfaces.h>

extern "C" {
#include "base/grow.h"
}

/* The entry point threemf.h declares as threemf_read_fn (that header is
 * the library's, which this plugin does not see). */
extern "C" int spancast_3mf_read(const char *path, uint32_t max_points, double **xyz_out,
                                 uint32_t *point_count, uint32_t **indices_out,
                                 uint32_t *face_count, uint32_t **objects_out,
                                 uint32_t *object_count, char *err, size_t err_size);

using namespace NMR;

namespace
{

/* Owns a lib3mf object until the end of its scope. */
struct released {
    PLib3MFBase *p;
    explicit released(PLib3MFBase *q) : p(q) {}
    ~released()
    {
        if (p)
            lib3mf_release(p);
    }
    released(const released &) = delete;
    released &operator=(const released &) = delete;
};

int failure(PLib3MFBase *from, const char *what, char *err, size_t err_size)
{
    DWORD code = 0;
    LPCSTR message = nullptr;
    if (from && lib3mf_getlasterror(from, &code, &message) == LIB3MF_OK && message &&
        message[0])
        snprintf(err, err_size, "%s: %s", what, message);
    else
        snprintf(err, err_size, "%s", what);
    return 0;
}

/* What the objects read so far make (freed unless handed out). */
struct arrays {
    double *xyz = nullptr;       /* 3 per point */
    uint32_t *indices = nullptr; /* 3 per triangle, into all objects' points */
    uint32_t *objects = nullptr; /* 2 per object and 2 more: first point, triangle */
    size_t points = 0, faces = 0, object_count = 0;
    size_t point_cap = 0, face_cap = 0, object_cap = 0; /* grow_array's, in items */
    arrays() = default;
    arrays(const arrays &) = delete;
    arrays &operator=(const arrays &) = delete;
    ~arrays()
    {
        free(xyz);
        free(indices);
        free(objects);
    }
};

/* Records where the next object (or the end) starts: 0 when memory ran out. */
int start_object(arrays &a)
{
    if (!grow_array((void **)&a.objects, &a.object_cap, 2 * (a.object_count + 1),
                    sizeof *a.objects))
        return 0;
    a.objects[2 * a.object_count] = (uint32_t)a.points;
    a.objects[2 * a.object_count + 1] = (uint32_t)a.faces;
    return 1;
}

/* Appends one mesh object's points and triangles to a; 0 with why in err. */
int read_object(PLib3MFModelResource *object, uint32_t max_points, arrays &a, char *err,
                size_t err_size)
{
    DWORD nv = 0, nt = 0;
    if (lib3mf_meshobject_getvertexcount(object, &nv) != LIB3MF_OK ||
        lib3mf_meshobject_gettrianglecount(object, &nt) != LIB3MF_OK)
        return failure(object, "cannot read a mesh object", err, err_size);
    if (a.points + nv > max_points || a.faces + nt > max_points ||
        a.object_count + 1 > max_points) {
        snprintf(err, err_size, "too many vertices or triangles (limit is %u)",
                 (unsigned)max_points);
        return 0;
    }
    MODELMESHVERTEX *v = new MODELMESHVERTEX[nv ? nv : 1];
    MODELMESHTRIANGLE *t = new (std::nothrow) MODELMESHTRIANGLE[nt ? nt : 1];
    if (!t) {
        delete[] v;
        throw std::bad_alloc();
    }
    DWORD got_v = 0, got_t = 0;
    bool ok =
        (nv == 0 || lib3mf_meshobject_getvertices(object, v, nv, &got_v) == LIB3MF_OK) &&
        (nt == 0 ||
         lib3mf_meshobject_gettriangleindices(object, t, nt, &got_t) == LIB3MF_OK);
    bool memory =
        ok && start_object(a) &&
        grow_array((void **)&a.xyz, &a.point_cap, 3 * (a.points + nv), sizeof *a.xyz) &&
        grow_array((void **)&a.indices, &a.face_cap, 3 * (a.faces + nt),
                   sizeof *a.indices);
    if (!ok)
        snprintf(err, err_size, "cannot read a mesh object");
    else if (!memory)
        snprintf(err, err_size, "out of memory");
    ok = ok && memory;
    for (DWORD i = 0; ok && i < nt; i++)
        for (int k = 0; k < 3 && ok; k++)
            if (t[i].m_nIndices[k] >= nv) {
                ok = false;
                snprintf(err, err_size,
                         "triangle %lu of object %u: vertex index %lu is not one "
                         "of its %lu vertices",
                         (unsigned long)i, (unsigned)a.object_count,
                         (unsigned long)t[i].m_nIndices[k], (unsigned long)nv);
            }
    if (ok) {
        for (DWORD i = 0; i < nv; i++)
            for (int k = 0; k < 3; k++)
                a.xyz[3 * (a.points + i) + k] = v[i].m_fPosition[k];
        for (DWORD i = 0; i < nt; i++)
            for (int k = 0; k < 3; k++)
                a.indices[3 * (a.faces + i) + k] =
                    (uint32_t)(a.points + t[i].m_nIndices[k]);
        a.points += nv;
        a.faces += nt;
        a.object_count++;
    }
    delete[] v;
    delete[] t;
    return ok;
}

} // namespace

extern "C" int spancast_3mf_read(const char *path, uint32_t max_points, double **xyz_out,
                                 uint32_t *point_count, uint32_t **indices_out,
                                 uint32_t *face_count, uint32_t **objects_out,
                                 uint32_t *object_count, char *err, size_t err_size)
{
    if (err_size)
        err[0] = 0;
    *xyz_out = nullptr;
    *indices_out = nullptr;
    *objects_out = nullptr;
    *point_count = *face_count = *object_count = 0;
    arrays a;
    try {
        PLib3MFModel *model = nullptr;
        if (lib3mf_createmodel(&model) != LIB3MF_OK)
            return failure(nullptr, "cannot create a 3MF model", err, err_size);
        released model_owner(model);
        PLib3MFModelReader *reader = nullptr;
        if (lib3mf_model_queryreader(model, "3mf", &reader) != LIB3MF_OK)
            return failure(model, "cannot create a 3MF reader", err, err_size);
        released reader_owner(reader);
        if (lib3mf_reader_readfromfileutf8(reader, path) != LIB3MF_OK)
            return failure(reader, "not a readable 3MF file", err, err_size);
        PLib3MFModelResourceIterator *it = nullptr;
        if (lib3mf_model_getmeshobjects(model, &it) != LIB3MF_OK)
            return failure(model, "cannot list the mesh objects", err, err_size);
        released it_owner(it);
        for (;;) {
            BOOL has_next = 0;
            if (lib3mf_resourceiterator_movenext(it, &has_next) != LIB3MF_OK)
                break;
            if (!has_next)
                break;
            PLib3MFModelResource *object = nullptr;
            if (lib3mf_resourceiterator_getcurrent(it, &object) != LIB3MF_OK)
                break;
            released object_owner(object);
            if (!read_object(object, max_points, a, err, err_size))
                return 0;
        }
        if (!start_object(a)) {
            snprintf(err, err_size, "out of memory");
            return 0;
        }
        *xyz_out = a.xyz;
        *indices_out = a.indices;
        *objects_out = a.objects;
        a.xyz = nullptr;
        a.indices = a.objects = nullptr;
        *point_count = (uint32_t)a.points;
        *face_count = (uint32_t)a.faces;
        *object_count = (uint32_t)a.object_count;
        return 1;
    } catch (const std::bad_alloc &) {
        snprintf(err, err_size, "out of memory");
        return 0;
    }
}
