/* The 2D engine's polygon clipper: OpenSCAD 2021.01's ClipperUtils on
 * Clipper 6.4 (Debian's libpolyclipping), behind a C interface (twod.h).
 *
 * What OpenSCAD does, and this file repeats step by step:
 *   - into the clipper, each point is scaled by 2^16 and converted to a
 *     64-bit integer by truncation (C++'s double to integer conversion);
 *     a region that is not sanitized has each contour turned
 *     counter-clockwise first, a sanitized one keeps its orientation;
 *   - sanitize: the even-odd union of the contours;
 *   - booleans: every child sanitized where it is not, the first added as
 *     subject and the others as clip, executed with non-zero fill for both;
 *     an intersection of more than two is a chain of binary ones, each
 *     result fed back as the next subject;
 *   - offset: ClipperOffset with miter limit 1000000 and the caller's arc
 *     tolerance (scaled), closed polygons;
 *   - a mesh's projection: every face's contour turned counter-clockwise,
 *     all united with non-zero fill, strictly simple; a section's loops
 *     united with non-zero fill as they run;
 *   - minkowski: the sum of each pair of contours as quads (one per pair of
 *     edges, each turned counter-clockwise), plus each child's contours
 *     moved to the first point of each counter-clockwise contour of the
 *     other, united with non-zero fill; more than two children fold left.
 *     Where both sides are one convex contour, the union of those quads is
 *     the convex polygon whose edges are both contours' edges merged by
 *     direction, in exact integer arithmetic: that polygon goes into the
 *     union instead of the n m quads (two circles of 1000 fragments: a
 *     million quads, whose union took 105 s);
 *   - out of the clipper, the result tree's contours in its own order, each
 *     cleaned (CleanPolygon: points within 1.415 grid units of their
 *     neighbours' line are dropped), those of fewer than 3 points left out,
 *     and divided by 2^16.
 * Clipper reports its range errors and allocation failures by exceptions;
 * none leaves this file.
 */
#include <algorithm>
#include <cmath>
#include <new>
#include <vector>

#include <clipper.hpp>

extern "C" {
#include "twod/twod.h"
}

using ClipperLib::cInt;
using ClipperLib::IntPoint;
using ClipperLib::Path;
using ClipperLib::Paths;
using ClipperLib::PolyNode;
using ClipperLib::PolyTree;

namespace
{

const double miter_limit = 1000000.0;

struct too_many_points {
};
struct range_error {
};

Paths to_paths(const twod_region &r, bool keep_orientation)
{
    Paths out;
    out.reserve(r.contour_count);
    for (uint32_t k = 0; k < r.contour_count; k++) {
        Path p;
        p.reserve(r.start[k + 1] - r.start[k]);
        for (uint32_t i = r.start[k]; i < r.start[k + 1]; i++) {
            double x = r.xy[2 * i], y = r.xy[2 * i + 1];
            if (!(twod_in_range(x) && twod_in_range(y)))
                throw range_error();
            p.emplace_back(static_cast<cInt>(x * TWOD_CLIPPER_SCALE),
                           static_cast<cInt>(y * TWOD_CLIPPER_SCALE));
        }
        if (!keep_orientation && !ClipperLib::Orientation(p))
            std::reverse(p.begin(), p.end());
        out.push_back(std::move(p));
    }
    return out;
}

Paths to_paths(const twod_region &r)
{
    return to_paths(r, r.sanitized != 0);
}

void to_region(const PolyTree &tree, twod_region *out)
{
    twod_clear(out);
    for (const PolyNode *node = tree.GetFirst(); node; node = node->GetNext()) {
        Path cleaned;
        ClipperLib::CleanPolygon(node->Contour, cleaned);
        if (cleaned.size() < 3)
            continue;
        if (!twod_begin_contour(out))
            throw std::bad_alloc();
        for (const IntPoint &p : cleaned) {
            if (out->point_count >= TWOD_MAX_POINTS)
                throw too_many_points();
            if (!twod_add_point(out, 1.0 * static_cast<double>(p.X) / TWOD_CLIPPER_SCALE,
                                1.0 * static_cast<double>(p.Y) / TWOD_CLIPPER_SCALE))
                throw std::bad_alloc();
        }
    }
    out->sanitized = 1;
}

void sanitize_paths(const Paths &paths, PolyTree &result)
{
    ClipperLib::Clipper clipper;
    clipper.AddPaths(paths, ClipperLib::ptSubject, true);
    clipper.Execute(ClipperLib::ctUnion, result, ClipperLib::pftEvenOdd);
}

/* A child's paths as apply() takes them: sanitized where it is not. */
Paths child_paths(const twod_region *r)
{
    if (!r)
        return Paths();
    Paths paths = to_paths(*r);
    if (!r->sanitized) {
        PolyTree tree;
        sanitize_paths(paths, tree);
        ClipperLib::PolyTreeToPaths(tree, paths);
    }
    return paths;
}

/* The quads of the sum of two closed contours (no union inside). */
void minkowski_quads(const Path &poly, const Path &path, Paths &quads)
{
    size_t poly_count = poly.size(), path_count = path.size();
    if (poly_count == 0 || path_count == 0)
        return;
    Paths moved(path_count);
    for (size_t i = 0; i < path_count; i++) {
        moved[i].reserve(poly_count);
        for (size_t j = 0; j < poly_count; j++)
            moved[i].emplace_back(path[i].X + poly[j].X, path[i].Y + poly[j].Y);
    }
    for (size_t i = 0; i < path_count; i++) {
        for (size_t j = 0; j < poly_count; j++) {
            Path quad;
            quad.reserve(4);
            quad.push_back(moved[i % path_count][j % poly_count]);
            quad.push_back(moved[(i + 1) % path_count][j % poly_count]);
            quad.push_back(moved[(i + 1) % path_count][(j + 1) % poly_count]);
            quad.push_back(moved[i % path_count][(j + 1) % poly_count]);
            if (!ClipperLib::Orientation(quad))
                ClipperLib::ReversePath(quad);
            quads.push_back(std::move(quad));
        }
    }
}

/* Convex sums. Edge directions are compared by angle from +x in [0, 2 pi),
 * exactly: coordinates stay below 2^62, so cross products of differences
 * fit in 128 bits. */
typedef __int128 wide;

wide cross(const IntPoint &u, const IntPoint &v)
{
    return (wide)u.X * v.Y - (wide)u.Y * v.X;
}

int half_of(const IntPoint &v)
{
    return v.Y < 0 || (v.Y == 0 && v.X < 0);
}

/* Whether direction u comes strictly before v. */
bool angle_less(const IntPoint &u, const IntPoint &v)
{
    int hu = half_of(u), hv = half_of(v);
    return hu != hv ? hu < hv : cross(u, v) > 0;
}

/* A counter-clockwise convex path as its edge vectors, starting at the
 * edge of least angle, with that edge's start in *start: true, or false
 * where it is clockwise or not convex (a reflex corner, a spike, more than
 * one turn, or no area). Repeated points are skipped. */
bool convex_edges(const Path &path, std::vector<IntPoint> &edges, IntPoint *start)
{
    Path p;
    p.reserve(path.size());
    for (const IntPoint &q : path)
        if (p.empty() || !(q == p.back()))
            p.push_back(q);
    while (p.size() > 1 && p.front() == p.back())
        p.pop_back();
    size_t n = p.size();
    if (n < 3)
        return false;
    if (!ClipperLib::Orientation(p))
        return false; /* clockwise: the quads' path leaves out its insides */
    edges.resize(n);
    for (size_t i = 0; i < n; i++) {
        const IntPoint &a = p[i], &b = p[(i + 1) % n];
        edges[i] = IntPoint(b.X - a.X, b.Y - a.Y);
    }
    size_t first = 0, descents = 0;
    bool turned = false;
    for (size_t i = 0; i < n; i++) {
        const IntPoint &u = edges[i], &v = edges[(i + 1) % n];
        wide c = cross(u, v);
        if (c < 0 || (c == 0 && (wide)u.X * v.X + (wide)u.Y * v.Y <= 0))
            return false; /* reflex, or a spike back along itself */
        turned = turned || c > 0;
        if (angle_less(v, u)) {
            descents++;
            first = (i + 1) % n;
        }
    }
    if (descents != 1 || !turned)
        return false; /* wound more than once, or flat */
    std::rotate(edges.begin(), edges.begin() + (std::ptrdiff_t)first, edges.end());
    *start = p[first];
    return true;
}

/* The sum of two convex contours a and b, where both are (convex_edges):
 * true and the polygon in sum, else false. */
bool convex_sum(const Path &a, const Path &b, Path &sum)
{
    std::vector<IntPoint> ea, eb;
    IntPoint sa, sb;
    if (!convex_edges(a, ea, &sa) || !convex_edges(b, eb, &sb))
        return false;
    sum.clear();
    sum.reserve(ea.size() + eb.size());
    IntPoint p(sa.X + sb.X, sa.Y + sb.Y);
    size_t i = 0, j = 0;
    while (i < ea.size() || j < eb.size()) {
        sum.push_back(p);
        bool take_a = j == eb.size() || (i < ea.size() && !angle_less(eb[j], ea[i]));
        bool take_b = i == ea.size() || (j < eb.size() && !angle_less(ea[i], eb[j]));
        if (take_a) {
            p.X += ea[i].X;
            p.Y += ea[i].Y;
            i++;
        }
        if (take_b) {
            p.X += eb[j].X;
            p.Y += eb[j].Y;
            j++;
        }
    }
    return true;
}

/* a moved to the first point of each counter-clockwise contour of b. */
void minkowski_insides(const Paths &a, const Paths &b, Paths &target)
{
    for (const Path &b_path : b) {
        if (b_path.empty() || !ClipperLib::Orientation(b_path))
            continue;
        IntPoint delta = b_path[0];
        for (const Path &path : a) {
            target.push_back(path);
            for (IntPoint &p : target.back()) {
                p.X += delta.X;
                p.Y += delta.Y;
            }
        }
    }
}

template <typename F> int guarded(F f)
{
    try {
        f();
        return TWOD_CLIP_OK;
    } catch (const std::bad_alloc &) {
        return TWOD_CLIP_NOMEM;
    } catch (const too_many_points &) {
        return TWOD_CLIP_TOO_MANY;
    } catch (...) {
        /* range_error, or Clipper's clipperException for coordinates out
         * of its range */
        return TWOD_CLIP_RANGE;
    }
}

} // namespace

extern "C" int twod_clip_sanitize(twod_region *r)
{
    return guarded([&] {
        PolyTree tree;
        sanitize_paths(to_paths(*r), tree);
        to_region(tree, r);
    });
}

extern "C" int twod_clip_apply(twod_region *const *children, uint32_t count, twod_op op,
                               twod_region *out)
{
    return guarded([&] {
        std::vector<Paths> all;
        all.reserve(count);
        for (uint32_t i = 0; i < count; i++)
            all.push_back(child_paths(children[i]));
        ClipperLib::Clipper clipper;
        PolyTree result;
        if (op == TWOD_INTERSECTION && all.size() >= 2) {
            Paths source = all[0];
            for (size_t i = 1; i < all.size(); i++) {
                clipper.AddPaths(source, ClipperLib::ptSubject, true);
                clipper.AddPaths(all[i], ClipperLib::ptClip, true);
                clipper.Execute(ClipperLib::ctIntersection, result,
                                ClipperLib::pftNonZero, ClipperLib::pftNonZero);
                if (i + 1 != all.size()) {
                    ClipperLib::PolyTreeToPaths(result, source);
                    clipper.Clear();
                }
            }
            to_region(result, out);
            return;
        }
        for (size_t i = 0; i < all.size(); i++)
            clipper.AddPaths(all[i], i == 0 ? ClipperLib::ptSubject : ClipperLib::ptClip,
                             true);
        ClipperLib::ClipType type = op == TWOD_UNION        ? ClipperLib::ctUnion
                                    : op == TWOD_DIFFERENCE ? ClipperLib::ctDifference
                                                            : ClipperLib::ctIntersection;
        clipper.Execute(type, result, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
        to_region(result, out);
    });
}

extern "C" int twod_clip_union_nonzero(twod_region *r, int orient)
{
    return guarded([&] {
        ClipperLib::Clipper clipper;
        clipper.AddPaths(to_paths(*r, orient != 1), ClipperLib::ptSubject, true);
        PolyTree result;
        /* as OpenSCAD: the faces' union, then that union made strictly
         * simple (strict on every face at once is far slower). A
         * section's loops take the second pass too: where two loops run
         * along one line the other way (a cap's outline and its hole, cut
         * across), the first union can join the parts on either side of
         * the hole by a bridge of no width, which only the second takes
         * apart, as OpenSCAD's exact section has them */
        Paths united;
        clipper.Execute(ClipperLib::ctUnion, united, ClipperLib::pftNonZero,
                        ClipperLib::pftNonZero);
        clipper.Clear();
        clipper.StrictlySimple(true);
        clipper.AddPaths(united, ClipperLib::ptSubject, true);
        clipper.Execute(ClipperLib::ctUnion, result, ClipperLib::pftNonZero,
                        ClipperLib::pftNonZero);
        to_region(result, r);
    });
}

extern "C" int twod_clip_union_positive(twod_region *r)
{
    return guarded([&] {
        ClipperLib::Clipper clipper;
        /* strictly simple: a contour that touches itself (a bridge out to
         * a hole) would lose its spikes to to_region's CleanPolygon, and a
         * hole left without the part it took out of would fill under a
         * later non-zero union */
        clipper.StrictlySimple(true);
        clipper.AddPaths(to_paths(*r, true), ClipperLib::ptSubject, true);
        PolyTree result;
        clipper.Execute(ClipperLib::ctUnion, result, ClipperLib::pftPositive,
                        ClipperLib::pftPositive);
        to_region(result, r);
    });
}

extern "C" int twod_clip_offset(const twod_region *in, double delta, twod_join join,
                                double arc_tolerance, twod_region *out)
{
    return guarded([&] {
        if (!twod_in_range(delta))
            throw range_error();
        ClipperLib::JoinType type = join == TWOD_JOIN_ROUND   ? ClipperLib::jtRound
                                    : join == TWOD_JOIN_MITER ? ClipperLib::jtMiter
                                                              : ClipperLib::jtSquare;
        ClipperLib::ClipperOffset offset(miter_limit, arc_tolerance * TWOD_CLIPPER_SCALE);
        offset.AddPaths(to_paths(*in), type, ClipperLib::etClosedPolygon);
        PolyTree result;
        offset.Execute(result, delta * TWOD_CLIPPER_SCALE);
        to_region(result, out);
    });
}

extern "C" int twod_clip_minkowski(twod_region *const *children, uint32_t count,
                                   twod_region *out)
{
    return guarded([&] {
        ClipperLib::Clipper clipper;
        Paths lhs = children[0] ? to_paths(*children[0]) : Paths();
        for (uint32_t i = 1; i < count; i++) {
            if (!children[i])
                continue;
            Paths terms(1);
            Paths rhs = to_paths(*children[i]);
            if (lhs.size() != 1 || rhs.size() != 1 ||
                !convex_sum(lhs[0], rhs[0], terms[0])) {
                terms.clear();
                for (const Path &rhs_path : rhs)
                    for (const Path &lhs_path : lhs)
                        minkowski_quads(lhs_path, rhs_path, terms);
                minkowski_insides(lhs, rhs, terms);
                minkowski_insides(rhs, lhs, terms);
            }
            clipper.Clear();
            clipper.AddPaths(terms, ClipperLib::ptSubject, true);
            if (i + 1 != count)
                clipper.Execute(ClipperLib::ctUnion, lhs, ClipperLib::pftNonZero,
                                ClipperLib::pftNonZero);
        }
        PolyTree result;
        clipper.Execute(ClipperLib::ctUnion, result, ClipperLib::pftNonZero,
                        ClipperLib::pftNonZero);
        to_region(result, out);
    });
}
