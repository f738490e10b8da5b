/* Regions of the 2D engine (twod.h): growable arrays of contours, their
 * signed areas (the shoelace formula, positive counter-clockwise), the
 * convex hull of a point set, and which outlines OpenSCAD's clipper takes
 * when some lie past its range.
 *
 * The hull is Andrew's monotone chain: the points sorted by x then y, a
 * lower and an upper chain built by dropping every point that does not
 * turn left (cross product <= 0), so collinear and repeated points are
 * left out. The result is one counter-clockwise contour, as OpenSCAD's
 * 2D hull (CGAL's convex_hull_2 on double points) makes it; where the
 * contour starts does not change the region.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "base/grow.h"
#include "twod/twod.h"

/* A coordinate as OpenSCAD 2021.01 hands it to Clipper: times 2^16
 * (CLIPPER_SCALE), converted to a 64-bit integer as C++ converts on
 * x86-64 (cvttsd2si: a value out of range gives INT64_MIN). */
static int64_t clipper_coord(double v)
{
    double d = v * TWOD_CLIPPER_SCALE;
    if (!(d >= -9223372036854775808.0 && d < 9223372036854775808.0))
        return INT64_MIN;
    return (int64_t)d;
}

/* A point of a region and its place on the clipper's grid. */
typedef struct grid_point {
    int64_t gx, gy;
    double x, y;
} grid_point;

static int grid_point_cmp(const void *a, const void *b)
{
    const grid_point *p = a, *q = b;
    if (p->gx != q->gx)
        return p->gx < q->gx ? -1 : 1;
    if (p->gy != q->gy)
        return p->gy < q->gy ? -1 : 1;
    if (p->x != q->x)
        return p->x < q->x ? -1 : 1;
    return (p->y > q->y) - (p->y < q->y);
}

int twod_restore_points(twod_region *r, const twod_region *from)
{
    uint32_t n = from->point_count;
    if (!n || !r->point_count)
        return 1;
    grid_point *sorted = malloc((size_t)n * sizeof *sorted);
    if (!sorted)
        return 0;
    for (uint32_t i = 0; i < n; i++) {
        double x = from->xy[2 * i], y = from->xy[2 * i + 1];
        sorted[i] = (grid_point){clipper_coord(x), clipper_coord(y), x, y};
    }
    qsort(sorted, n, sizeof *sorted, grid_point_cmp);
    for (uint32_t i = 0; i < r->point_count; i++) {
        int64_t gx = clipper_coord(r->xy[2 * i]), gy = clipper_coord(r->xy[2 * i + 1]);
        uint32_t lo = 0, hi = n; /* the first of sorted at or past (gx, gy) */
        while (lo < hi) {
            uint32_t mid = lo + (hi - lo) / 2;
            if (sorted[mid].gx < gx || (sorted[mid].gx == gx && sorted[mid].gy < gy))
                lo = mid + 1;
            else
                hi = mid;
        }
        if (lo < n && sorted[lo].gx == gx && sorted[lo].gy == gy) {
            r->xy[2 * i] = sorted[lo].x;
            r->xy[2 * i + 1] = sorted[lo].y;
        }
    }
    free(sorted);
    return 1;
}

/* Clipper 6.4's RangeTest: past hiRange (2^62 - 1) in magnitude throws.
 * Its test of -X > hiRange is compiled as X < -hiRange, so INT64_MIN (any
 * coordinate past the conversion's range) throws too: OpenSCAD 2021.01
 * refuses 1e20 as it refuses 1e14. */
static int clipper_out_of_range(int64_t c)
{
    const int64_t hi = INT64_C(0x3FFFFFFFFFFFFFFF);
    return c > hi || c < -hi;
}

/* The points converted (clipper_coord) into pt, turned round when the
 * polygon is not sanitized and Clipper's Orientation (its Area in double)
 * finds them clockwise, repeats at the end dropped (those equal to the
 * first, then those equal to the one before), an outline of fewer than 3
 * points left untested, then each point's RangeTest. */
int twod_clipper_outline(const double *xy, const uint32_t *index, uint32_t n,
                         int sanitized, int64_t *pt)
{
    for (uint32_t i = 0; i < n; i++) {
        uint32_t k = index ? index[i] : i;
        pt[2 * i] = clipper_coord(xy[2 * k]);
        pt[2 * i + 1] = clipper_coord(xy[2 * k + 1]);
    }
    if (n >= 3 && !sanitized) {
        double a = 0;
        for (uint32_t i = 0, j = n - 1; i < n; j = i++)
            a += ((double)pt[2 * j] + (double)pt[2 * i]) *
                 ((double)pt[2 * j + 1] - (double)pt[2 * i + 1]);
        if (-a * 0.5 < 0) /* not Orientation: reversed */
            for (uint32_t i = 0, j = n - 1; i < j; i++, j--)
                for (int c = 0; c < 2; c++) {
                    int64_t t = pt[2 * i + c];
                    pt[2 * i + c] = pt[2 * j + c];
                    pt[2 * j + c] = t;
                }
    }
    long high = (long)n - 1;
#define SAME(a, b) (pt[2 * (a)] == pt[2 * (b)] && pt[2 * (a) + 1] == pt[2 * (b) + 1])
    while (high > 0 && SAME(high, 0))
        high--;
    while (high > 0 && SAME(high, high - 1))
        high--;
#undef SAME
    if (high < 2)
        return TWOD_OUTLINE_SKIPPED;
    for (long i = 0; i <= high; i++)
        if (clipper_out_of_range(pt[2 * i]) || clipper_out_of_range(pt[2 * i + 1]))
            return TWOD_OUTLINE_REFUSED;
    return TWOD_OUTLINE_TAKEN;
}

long twod_clipper_admit(twod_region *r)
{
    int large = 0;
    for (size_t i = 0; i < 2 * (size_t)r->point_count && !large; i++)
        large = !twod_in_range(r->xy[i]);
    if (!large)
        return 0;
    uint32_t longest = 1;
    for (uint32_t k = 0; k < r->contour_count; k++)
        if (r->start[k + 1] - r->start[k] > longest)
            longest = r->start[k + 1] - r->start[k];
    int64_t *pt = malloc(2 * (size_t)longest * sizeof *pt);
    if (!pt)
        return -1;
    long refused = 0;
    uint32_t kept = 0, at = 0;
    for (uint32_t k = 0; k < r->contour_count && !refused; k++) {
        uint32_t first = r->start[k], n = r->start[k + 1] - first;
        int how =
            twod_clipper_outline(r->xy + 2 * (size_t)first, NULL, n, r->sanitized, pt);
        int drop = how == TWOD_OUTLINE_REFUSED;
        for (uint32_t i = 0; i < 2 * n && how == TWOD_OUTLINE_SKIPPED && !drop; i++)
            drop = !twod_in_range(r->xy[2 * (size_t)first + i]);
        if (how == TWOD_OUTLINE_REFUSED)
            refused = (long)k + 1;
        if (drop)
            continue;
        memmove(r->xy + 2 * (size_t)at, r->xy + 2 * (size_t)first,
                2 * (size_t)n * sizeof *r->xy);
        r->start[kept++] = at;
        at += n;
    }
    free(pt);
    r->start[kept] = at;
    r->contour_count = kept;
    r->point_count = at;
    return refused;
}

void twod_init(twod_region *r)
{
    memset(r, 0, sizeof *r);
}

void twod_free(twod_region *r)
{
    free(r->xy);
    free(r->start);
    twod_init(r);
}

void twod_clear(twod_region *r)
{
    r->point_count = 0;
    r->contour_count = 0;
    r->sanitized = 0;
}

void twod_move(twod_region *dst, twod_region *src)
{
    if (dst == src)
        return;
    twod_free(dst);
    *dst = *src;
    twod_init(src);
}

int twod_begin_contour(twod_region *r)
{
    if (!grow_array32((void **)&r->start, &r->start_cap, r->contour_count + 2,
                      sizeof *r->start))
        return 0;
    r->start[r->contour_count] = r->point_count;
    r->contour_count++;
    r->start[r->contour_count] = r->point_count;
    return 1;
}

int twod_add_point(twod_region *r, double x, double y)
{
    if (r->point_count >= TWOD_MAX_POINTS || r->contour_count == 0)
        return 0;
    if (r->point_count + 1 > r->point_cap) {
        uint32_t cap = r->point_cap * 2;
        if (!grow_array32((void **)&r->xy, &cap, 2 * (r->point_count + 1), sizeof *r->xy))
            return 0;
        r->point_cap = cap / 2;
    }
    r->xy[2 * r->point_count] = x;
    r->xy[2 * r->point_count + 1] = y;
    r->point_count++;
    r->start[r->contour_count] = r->point_count;
    return 1;
}

int twod_add_moved(twod_region *r, const affine2 *m, double x, double y)
{
    double mx, my;
    affine2_apply(m, x, y, &mx, &my);
    return twod_add_point(r, mx, my);
}

void twod_end_contour(twod_region *r)
{
    uint32_t k = r->contour_count - 1, s = r->start[k], n = r->point_count;
    if (n - s >= 2 && r->xy[2 * s] == r->xy[2 * n - 2] &&
        r->xy[2 * s + 1] == r->xy[2 * n - 1])
        n--;
    if (n - s < 3) {
        r->point_count = s;
        r->contour_count = k;
        return;
    }
    r->point_count = n;
    r->start[k + 1] = n;
}

void twod_reverse_contour(twod_region *r, uint32_t k)
{
    if (r->start[k + 1] - r->start[k] < 2)
        return;
    uint32_t i = r->start[k], j = r->start[k + 1] - 1;
    for (; i < j; i++, j--) {
        for (int c = 0; c < 2; c++) {
            double t = r->xy[2 * i + c];
            r->xy[2 * i + c] = r->xy[2 * j + c];
            r->xy[2 * j + c] = t;
        }
    }
}

double twod_ring_area(const double *xy, uint32_t first, uint32_t end)
{
    double a = 0;
    for (uint32_t i = first; i < end; i++) {
        uint32_t j = i + 1 < end ? i + 1 : first;
        a += xy[2 * i] * xy[2 * j + 1] - xy[2 * j] * xy[2 * i + 1];
    }
    return a / 2;
}

double twod_contour_area(const twod_region *r, uint32_t k)
{
    return twod_ring_area(r->xy, r->start[k], r->start[k + 1]);
}

double twod_area(const twod_region *r)
{
    double a = 0;
    for (uint32_t k = 0; k < r->contour_count; k++)
        a += twod_contour_area(r, k);
    return a;
}

static int compare_xy(const void *pa, const void *pb)
{
    const double *a = pa, *b = pb;
    if (a[0] != b[0])
        return a[0] < b[0] ? -1 : 1;
    return (a[1] > b[1]) - (a[1] < b[1]);
}

static double turn(const double *o, const double *a, const double *b)
{
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

int twod_hull(const double *xy, uint32_t count, twod_region *out)
{
    twod_clear(out);
    if (count == 0)
        return 1;
    double *p = malloc((size_t)count * 2 * sizeof *p);
    double *h = malloc(((size_t)count * 2 + 2) * 2 * sizeof *h);
    if (!p || !h) {
        free(p);
        free(h);
        return 0;
    }
    memcpy(p, xy, (size_t)count * 2 * sizeof *p);
    qsort(p, count, 2 * sizeof *p, compare_xy);
    size_t k = 0;
    for (uint32_t i = 0; i < count; i++) { /* lower chain */
        while (k >= 2 && turn(&h[2 * (k - 2)], &h[2 * (k - 1)], &p[2 * i]) <= 0)
            k--;
        h[2 * k] = p[2 * i];
        h[2 * k + 1] = p[2 * i + 1];
        k++;
    }
    for (size_t i = count - 1, lower = k + 1; i-- > 0;) { /* upper chain */
        while (k >= lower && turn(&h[2 * (k - 2)], &h[2 * (k - 1)], &p[2 * i]) <= 0)
            k--;
        h[2 * k] = p[2 * i];
        h[2 * k + 1] = p[2 * i + 1];
        k++;
    }
    int ok = 1;
    if (k > 3) { /* the last point repeats the first */
        ok = twod_begin_contour(out);
        for (size_t i = 0; ok && i + 1 < k; i++)
            ok = twod_add_point(out, h[2 * i], h[2 * i + 1]);
    }
    free(p);
    free(h);
    return ok;
}
