// refcast: the cross-check suite's reference caster.
//
// It loads the triangle mesh OpenSCAD exports for a model (binary STL,
// `openscad --export-format binstl`, float32 vertices) into CGAL's AABB
// tree and casts the rays of spancast's camera contract (README "Camera
// contract", docs/camera.md) through it, written here independently of
// spancast's own camera code: for eye e, centre c, up hint h = z,
//   f = normalize(c - e), r = normalize(f x h) (f x y when f is parallel
//   to h), u = r x f, a = tan(fov / 2),
//   x = (2 (i + 0.5) / W - 1) a W / H, y = (1 - 2 (j + 0.5) / H) a,
//   perspective: origin e, direction f + x r + y u;
//   orthographic: origin e + |c - e| (x r + y u), direction f.
// The first intersection along each ray (CGAL's exact predicates decide
// which triangles the ray meets, so a ray through a shared edge never slips
// between two triangles) gives the mask (255 on a hit) and the depth (the
// distance from the origin to the hit, +inf on a miss), written through
// spancast's own image writers so both sides produce the same formats.
// With --cos it also writes |cos| of the angle between the ray and the hit
// triangle's normal (0 on a miss), which the exact-mode check needs.
//
// usage: refcast MESH.stl --camera=ex,ey,ez,cx,cy,cz --imgsize=W,H
//                [--fov=DEG] [--projection=p|o] --mask=M.png --depth=D.exr
//                [--cos=C.exr]
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "formats/framebuffer.h" /* the image writers take a framebuffer built here */
#include "spancast/spancast.h"

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef K::Vector_3 Vector;
typedef K::Ray_3 Ray;
typedef K::Triangle_3 Triangle;
typedef std::vector<Triangle>::const_iterator Iterator;
typedef CGAL::AABB_triangle_primitive<K, Iterator> Primitive;
typedef CGAL::AABB_traits<K, Primitive> Traits;
typedef CGAL::AABB_tree<Traits> Tree;

namespace
{

int fail(const char *message, const std::string &what)
{
    std::fprintf(stderr, "refcast: error: %s%s\n", message, what.c_str());
    return 1;
}

// Reads a binary STL: 80-byte header, uint32 count, then per triangle a
// normal and three vertices as little-endian float32, and a uint16.
// Degenerate triangles (no area) are left out: they bound nothing.
bool read_stl(const char *path, std::vector<Triangle> &out)
{
    std::ifstream in(path, std::ios::binary);
    char header[80];
    uint32_t count = 0;
    if (!in.read(header, 80) || !in.read(reinterpret_cast<char *>(&count), 4))
        return false;
    for (uint32_t k = 0; k < count; k++) {
        unsigned char record[50];
        if (!in.read(reinterpret_cast<char *>(record), 50))
            return false;
        float v[12];
        std::memcpy(v, record, sizeof v);
        Point a(v[3], v[4], v[5]), b(v[6], v[7], v[8]), c(v[9], v[10], v[11]);
        Triangle t(a, b, c);
        if (!t.is_degenerate())
            out.push_back(t);
    }
    return true;
}

bool parse_numbers(const char *text, double *out, int count)
{
    for (int k = 0; k < count; k++) {
        char *end;
        out[k] = std::strtod(text, &end);
        if (end == text || !std::isfinite(out[k]))
            return false;
        if (k + 1 < count && *end != ',')
            return false;
        text = end + 1;
        if (k + 1 == count && *end != '\0')
            return false;
    }
    return true;
}

struct vec {
    double x, y, z;
};
vec sub(vec a, vec b)
{
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
vec add(vec a, vec b)
{
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
vec mul(vec a, double s)
{
    return {a.x * s, a.y * s, a.z * s};
}
vec cross(vec a, vec b)
{
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
double len(vec a)
{
    return std::sqrt(a.x * a.x + a.y * a.y + a.z * a.z);
}
vec unit(vec a)
{
    return mul(a, 1.0 / len(a));
}

} // namespace

int main(int argc, char **argv)
{
    const char *mesh = nullptr, *mask_path = nullptr, *depth_path = nullptr,
               *cos_path = nullptr;
    double camera[6];
    bool has_camera = false, ortho = false;
    double size[2] = {0, 0}, fov = 22.5;
    for (int k = 1; k < argc; k++) {
        std::string a = argv[k];
        auto value = [&](const char *name) -> const char * {
            size_t n = std::strlen(name);
            return a.compare(0, n, name) == 0 ? argv[k] + n : nullptr;
        };
        const char *v;
        if ((v = value("--camera="))) {
            if (!parse_numbers(v, camera, 6))
                return fail("bad --camera: ", v);
            has_camera = true;
        } else if ((v = value("--imgsize="))) {
            if (!parse_numbers(v, size, 2) || size[0] < 1 || size[1] < 1)
                return fail("bad --imgsize: ", v);
        } else if ((v = value("--fov="))) {
            if (!parse_numbers(v, &fov, 1) || !(fov > 0 && fov < 180))
                return fail("bad --fov: ", v);
        } else if ((v = value("--projection="))) {
            ortho = std::strcmp(v, "o") == 0;
        } else if ((v = value("--mask="))) {
            mask_path = v;
        } else if ((v = value("--depth="))) {
            depth_path = v;
        } else if ((v = value("--cos="))) {
            cos_path = v;
        } else if (a.size() > 1 && a[0] == '-') {
            return fail("unknown option ", a);
        } else {
            mesh = argv[k];
        }
    }
    if (!mesh || !has_camera || size[0] < 1 || !mask_path || !depth_path)
        return fail("usage: refcast MESH.stl --camera=E,C --imgsize=W,H "
                    "[--fov=DEG] [--projection=p|o] --mask=M --depth=D [--cos=C]",
                    "");

    std::vector<Triangle> triangles;
    if (!read_stl(mesh, triangles))
        return fail("cannot read binary STL ", mesh);
    Tree tree(triangles.begin(), triangles.end());

    const int width = int(size[0]), height = int(size[1]);
    vec e = {camera[0], camera[1], camera[2]}, c = {camera[3], camera[4], camera[5]};
    vec f = unit(sub(c, e));
    vec r = cross(f, vec{0, 0, 1});
    if (len(r) == 0)
        r = cross(f, vec{0, 1, 0});
    r = unit(r);
    vec u = cross(r, f);
    double a = std::tan(fov * M_PI / 360.0);
    double distance = len(sub(c, e));

    size_t pixels = size_t(width) * size_t(height);
    std::vector<uint8_t> mask(pixels, 0);
    std::vector<float> depth(pixels, std::numeric_limits<float>::infinity());
    std::vector<float> cosine(pixels, 0.0f);
    for (int j = 0; j < height; j++) {
        for (int i = 0; i < width; i++) {
            double x = (2 * (i + 0.5) / width - 1) * a * width / height;
            double y = (1 - 2 * (j + 0.5) / height) * a;
            vec o = e, d = add(f, add(mul(r, x), mul(u, y)));
            if (ortho) {
                o = add(e, mul(add(mul(r, x), mul(u, y)), distance));
                d = f;
            }
            Point origin(o.x, o.y, o.z);
            Ray ray(origin, Vector(d.x, d.y, d.z));
            auto hit = tree.first_intersection(ray);
            if (!hit)
                continue;
            double dist;
            if (const Point *p = boost::get<Point>(&hit->first)) {
                dist = std::sqrt(CGAL::to_double(CGAL::squared_distance(origin, *p)));
            } else {
                // The ray runs inside the triangle's plane: the nearer end.
                const K::Segment_3 *s = boost::get<K::Segment_3>(&hit->first);
                dist = std::sqrt(std::min(
                    CGAL::to_double(CGAL::squared_distance(origin, s->source())),
                    CGAL::to_double(CGAL::squared_distance(origin, s->target()))));
            }
            size_t idx = size_t(j) * size_t(width) + size_t(i);
            mask[idx] = 255;
            depth[idx] = float(dist);
            Vector n = hit->second->supporting_plane().orthogonal_vector();
            double nd = n.x() * d.x + n.y() * d.y + n.z() * d.z;
            cosine[idx] = float(std::fabs(nd) / (std::sqrt(n.squared_length()) * len(d)));
        }
    }

    sc_framebuffer fb;
    std::memset(&fb, 0, sizeof fb);
    fb.width = width;
    fb.height = height;
    fb.mask = mask.data();
    fb.depth = depth.data();
    sc_error error;
    if (sc_framebuffer_write_mask(&fb, mask_path, &error) != SC_OK ||
        sc_framebuffer_write_depth(&fb, depth_path, &error) != SC_OK)
        return fail("", error.message);
    if (cos_path) {
        fb.depth = cosine.data();
        if (sc_framebuffer_write_depth(&fb, cos_path, &error) != SC_OK)
            return fail("", error.message);
    }
    return 0;
}
