/* spancast-3mf.so: 3MF files read by lib3mf 1.8, as OpenSCAD 2021.01's
 * import_3mf.cc reads them (threemf.h): every mesh object's vertices and
 * triangles, the indices checked against the object's vertex count. The
 * only code that links lib3mf, loaded on demand (threemf.c). */
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <new>

#include <Model/COM/NMR_DLLInterfaces.h>

/* The entry point threemf.h declares as threemf_read_fn (that header is
 * the library's, which this plugin does not see). */
extern "C" int spancast_3mf_read(const char *path, uint32_t max_points, double **xyz_out,
                                 uint32_t *point_count, uint32_t **indices_out,
                                 uint32_t *face_count, uint32_t *object_count, char *err,
                                 size_t err_size);

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

} // namespace

extern "C" int spancast_3mf_read(const char *path, uint32_t max_points, double **xyz_out,
                                 uint32_t *point_count, uint32_t **indices_out,
                                 uint32_t *face_count, uint32_t *object_count, char *err,
                                 size_t err_size)
{
    if (err_size)
        err[0] = 0;
    *xyz_out = nullptr;
    *indices_out = nullptr;
    *point_count = *face_count = *object_count = 0;
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
        size_t points = 0, faces = 0, point_cap = 0, face_cap = 0;
        double *xyz = nullptr;
        uint32_t *indices = nullptr;
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
            DWORD nv = 0, nt = 0;
            if (lib3mf_meshobject_getvertexcount(object, &nv) != LIB3MF_OK ||
                lib3mf_meshobject_gettrianglecount(object, &nt) != LIB3MF_OK) {
                free(xyz);
                free(indices);
                return failure(object, "cannot read a mesh object", err, err_size);
            }
            if (points + nv > max_points || faces + nt > max_points) {
                free(xyz);
                free(indices);
                snprintf(err, err_size, "too many vertices or triangles (limit is %u)",
                         (unsigned)max_points);
                return 0;
            }
            MODELMESHVERTEX *v = new MODELMESHVERTEX[nv ? nv : 1];
            MODELMESHTRIANGLE *t = new MODELMESHTRIANGLE[nt ? nt : 1];
            DWORD got_v = 0, got_t = 0;
            bool ok = (nv == 0 || lib3mf_meshobject_getvertices(object, v, nv, &got_v) ==
                                      LIB3MF_OK) &&
                      (nt == 0 || lib3mf_meshobject_gettriangleindices(
                                      object, t, nt, &got_t) == LIB3MF_OK);
            if (ok && points + nv > point_cap) {
                size_t cap = point_cap ? point_cap : 1024;
                while (cap < points + nv)
                    cap *= 2;
                double *grown = (double *)realloc(xyz, 3 * cap * sizeof *grown);
                ok = grown != nullptr;
                if (ok)
                    xyz = grown, point_cap = cap;
            }
            if (ok && faces + nt > face_cap) {
                size_t cap = face_cap ? face_cap : 1024;
                while (cap < faces + nt)
                    cap *= 2;
                uint32_t *grown = (uint32_t *)realloc(indices, 3 * cap * sizeof *grown);
                ok = grown != nullptr;
                if (ok)
                    indices = grown, face_cap = cap;
            }
            for (DWORD i = 0; ok && i < nt; i++)
                for (int k = 0; k < 3; k++)
                    if (t[i].m_nIndices[k] >= nv) {
                        ok = false;
                        snprintf(err, err_size,
                                 "triangle %lu of object %u: vertex index %lu is not one "
                                 "of its %lu vertices",
                                 (unsigned long)i, (unsigned)*object_count,
                                 (unsigned long)t[i].m_nIndices[k], (unsigned long)nv);
                    }
            if (!ok) {
                delete[] v;
                delete[] t;
                free(xyz);
                free(indices);
                if (!strstr(err, "vertex index"))
                    snprintf(err, err_size, "out of memory");
                return 0;
            }
            for (DWORD i = 0; i < nv; i++)
                for (int k = 0; k < 3; k++)
                    xyz[3 * (points + i) + k] = v[i].m_fPosition[k];
            for (DWORD i = 0; i < nt; i++)
                for (int k = 0; k < 3; k++)
                    indices[3 * (faces + i) + k] =
                        (uint32_t)(points + t[i].m_nIndices[k]);
            delete[] v;
            delete[] t;
            points += nv;
            faces += nt;
            (*object_count)++;
        }
        *xyz_out = xyz;
        *indices_out = indices;
        *point_count = (uint32_t)points;
        *face_count = (uint32_t)faces;
        return 1;
    } catch (const std::bad_alloc &) {
        snprintf(err, err_size, "out of memory");
        return 0;
    }
}
