/* compare: judges spancast's mask and depth images against the reference
 * caster's (tests/reference/refcast) for the same camera, and prints one
 * row of the cross-check report.
 *
 * usage: compare REF_MASK REF_DEPTH MASK DEPTH
 *                [--exact=DELTA,GAMMA --cos=REF_COS --camera=EX,EY,EZ,CX,CY,CZ
 *                 [--projection=p|o] [--fov=DEG]]
 *
 * Faithful mode (default): both sides hold the same polyhedron, spancast
 * from the 6-digit numbers of the .csg in double, the reference from the
 * same numbers meshed by OpenSCAD and rounded to float32 in the STL.
 *   mask: at most 0.05 % of the pixels differ, and every differing pixel is
 *   within 1 pixel of a silhouette edge of the reference (its 3 x 3
 *   neighbourhood in the reference mask holds both a hit and a miss);
 *   depth: relative difference at most 1e-5 where both hit, away from
 *   edges: the pixel's 3 x 3 neighbourhood is all hits in both masks and
 *   the reference depth is continuous across it (see is_edge). The
 *   reference's vertices are float32 (relative rounding 6e-8) and, before
 *   CGAL booleans, snapped by OpenSCAD to a grid of 2^-20 (about 1e-6
 *   absolute); a moved vertex moves the depth by its shift over the cosine
 *   of the incidence. 1e-5 leaves room for both on the suite's models,
 *   which are a few units across or more and seen from tens of units.
 *
 * Exact mode (--exact=DELTA,GAMMA, with --cos, --camera, --projection and
 * --fov as given to refcast): spancast renders the true solid, the
 * reference is OpenSCAD's mesh of it. tests/crosscheck/chord.py derives,
 * from the model's .csg and independently of spancast, DELTA, a bound on
 * the distance between each curved leaf's exact surface and its polygons
 * (world units), and GAMMA, a bound on the angle between a facet's normal
 * and the exact normal over that facet. Nothing here reads spancast's
 * tessellation.
 *   Pixel footprint: the camera contract (README) samples the image plane
 *   at unit distance with a step of 2 a / H, a = tan(fov / 2). A ray at
 *   angle psi off the axis (tan^2 psi = x^2 + y^2) sees a step of the
 *   plane as at least (2 a / H) cos^2 psi of angle, so at distance t along
 *   it one pixel spans at least f(t) = t (2 a / H) cos^2 psi across the
 *   ray (orthographic: f = 2 a |c - e| / H everywhere). A boundary moved
 *   by DELTA moves in the image by at most K(t) = DELTA / f(t) pixels.
 *   mask: a mismatch is a pixel between the two silhouettes. Every
 *   mismatch must lie within ceil(K) + 1 pixels of a silhouette edge of
 *   either image (the 1: rasterisation; near_silhouette adds it), K at the
 *   depth of the side that hits there: of either, since a feature thinner
 *   than a pixel on the mesh's side may have no silhouette there at all.
 *   Their number is at most the area of that band, the sum over the
 *   contour pixels b of either image (pixels with a 4-neighbour of the
 *   other kind, about two per pixel of contour length, one each side) of
 *   ceil(K_b) + 1, K_b at the nearest hit's depth: the band holds
 *   2 ceil(K) + 1 pixels across per pixel of length.
 *   depth: where both hit, let F be the reference's facet (normal n,
 *   incidence cos theta_m = --cos) and S the exact surface near the hit.
 *   Over F and its neighbours S's normal is within beta = 3 GAMMA of n
 *   (within GAMMA of its own facet's normal, whose neighbour shares a
 *   vertex where both are within GAMMA of S's normal), so S is a graph over
 *   F's plane with slope at most tan beta. A mesh point within DELTA of
 *   such a graph is at most h = DELTA / cos beta above or below it along
 *   n. Along the ray the height over S changes at a rate of at least
 *   cos theta_m - sin theta_m tan beta = cos(theta_m + beta) / cos beta, so
 *   the two hits are at most h cos beta / cos(theta_m + beta) =
 *   DELTA / cos(theta_m + beta) apart. Where theta_m + beta >= 90 degrees
 *   (near-grazing) the bound does not hold and the pixel is not
 *   depth-checked. The rest of the faithful tolerance (1e-5 of the depth,
 *   float32 and grid rounding) is added. The argument needs one surface on
 *   both sides: pixels within R = ceil(L / f) + 1 pixels of an edge (see
 *   is_edge) are skipped, L = DELTA max(1, tan(theta_m + beta)) the
 *   farthest the two hits and the surfaces' points near them lie apart
 *   across the ray.
 *
 * Exit status 0 when every check passes, 1 otherwise (the reasons on
 * stderr), 2 on bad usage or unreadable images. The row on stdout:
 * pixels, mask mismatches, depth-checked pixels, max and mean relative
 * depth error (exact mode: max and mean of difference / bound).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "formats/image_read.h"

#define PI 3.14159265358979323846

typedef struct images {
    image_data ref_mask, ref_depth, mask, depth, ref_cos;
} images;

static int hit(const image_data *mask, int i, int j)
{
    return mask->pixels[(size_t)j * (size_t)mask->width + (size_t)i] > 0.5f;
}

static double at(const image_data *img, int i, int j)
{
    return img->pixels[(size_t)j * (size_t)img->width + (size_t)i];
}

/* A silhouette edge of mask at (i, j): its 3 x 3 neighbourhood (clipped to
 * the image) holds both a hit and a miss. */
static int near_silhouette(const image_data *mask, int i, int j)
{
    int hits = 0, misses = 0;
    for (int dj = -1; dj <= 1; dj++) {
        for (int di = -1; di <= 1; di++) {
            int x = i + di, y = j + dj;
            if (x < 0 || y < 0 || x >= mask->width || y >= mask->height)
                continue;
            if (hit(mask, x, y))
                hits++;
            else
                misses++;
        }
    }
    return hits && misses;
}

/* An edge for the depth check: a neighbour outside the image or missed by
 * either side, or a jump in the reference depth. Along each of the four
 * lines through the pixel, a smooth surface steps about equally on both
 * sides; a step more than 4 times the other (plus 1e-4 of the depth)
 * is an occlusion edge or a sharp crease, where the hit may lie on either
 * side. */
static int is_edge(const images *im, int i, int j)
{
    int w = im->ref_mask.width, h = im->ref_mask.height;
    if (i < 1 || j < 1 || i >= w - 1 || j >= h - 1)
        return 1;
    for (int dj = -1; dj <= 1; dj++)
        for (int di = -1; di <= 1; di++)
            if (!hit(&im->ref_mask, i + di, j + dj) || !hit(&im->mask, i + di, j + dj))
                return 1;
    static const int dirs[4][2] = {{1, 0}, {0, 1}, {1, 1}, {1, -1}};
    double d = at(&im->ref_depth, i, j);
    for (int k = 0; k < 4; k++) {
        double a = fabs(d - at(&im->ref_depth, i - dirs[k][0], j - dirs[k][1]));
        double b = fabs(at(&im->ref_depth, i + dirs[k][0], j + dirs[k][1]) - d);
        if (fmax(a, b) > 4 * fmin(a, b) + 1e-4 * d)
            return 1;
    }
    return 0;
}

static int load(const char *path, image_data *img, int width, int height)
{
    char err[256];
    if (!image_read(path, img, err, sizeof err)) {
        fprintf(stderr, "compare: %s\n", err);
        return 0;
    }
    if (img->channels != 1 || (width && (img->width != width || img->height != height))) {
        fprintf(stderr, "compare: %s: expected one channel of %dx%d\n", path, width,
                height);
        return 0;
    }
    return 1;
}

/* The exact-mode bound: chord.py's numbers and what compare needs of the
 * camera to turn world distances into pixels (see the header). */
typedef struct exact_bound {
    double delta;           /* DELTA, world units */
    double beta;            /* 3 GAMMA, radians */
    double a;               /* tan(fov / 2) */
    double ortho_footprint; /* 2 a |c - e| / H when orthographic, else 0 */
    int width, height;
} exact_bound;

/* The smallest width across the ray, in world units, of pixel (i, j) at
 * distance t along its ray. */
static double footprint(const exact_bound *b, int i, int j, double t)
{
    if (b->ortho_footprint > 0)
        return b->ortho_footprint;
    double x = (2 * (i + 0.5) / b->width - 1) * b->a * b->width / b->height;
    double y = (1 - 2 * (j + 0.5) / b->height) * b->a;
    double cos2 = 1 / (1 + x * x + y * y);
    return t * (2 * b->a / b->height) * cos2;
}

/* ceil(distance / footprint) pixels: how far a boundary moved by distance
 * at distance t can move in the image. */
static long pixels_for(const exact_bound *b, int i, int j, double t, double distance)
{
    double f = footprint(b, i, j, t);
    double k = f > 0 ? ceil(distance / f) : INFINITY;
    return k < 1e6 ? (long)k : 1000000;
}

/* Summed-area table of a 0/1 map: sat[(j + 1) (w + 1) + i + 1] = number of
 * set pixels in rows < j + 1 and columns < i + 1. */
static long *summed_area(const unsigned char *map, int w, int h)
{
    long *sat = calloc((size_t)(w + 1) * (size_t)(h + 1), sizeof *sat);
    if (!sat)
        return NULL;
    for (int j = 0; j < h; j++)
        for (int i = 0; i < w; i++)
            sat[(size_t)(j + 1) * (size_t)(w + 1) + (size_t)(i + 1)] =
                map[(size_t)j * (size_t)w + (size_t)i] +
                sat[(size_t)j * (size_t)(w + 1) + (size_t)(i + 1)] +
                sat[(size_t)(j + 1) * (size_t)(w + 1) + (size_t)i] -
                sat[(size_t)j * (size_t)(w + 1) + (size_t)i];
    return sat;
}

/* Whether any pixel of the map within Chebyshev distance r of (i, j) is set. */
static int any_within(const long *sat, int w, int h, int i, int j, long r)
{
    long x0 = i - r < 0 ? 0 : i - r, y0 = j - r < 0 ? 0 : j - r;
    long x1 = i + r + 1 > w ? w : i + r + 1, y1 = j + r + 1 > h ? h : j + r + 1;
    size_t s = (size_t)w + 1;
    return sat[(size_t)y1 * s + (size_t)x1] - sat[(size_t)y0 * s + (size_t)x1] -
               sat[(size_t)y1 * s + (size_t)x0] + sat[(size_t)y0 * s + (size_t)x0] >
           0;
}

static int parse_numbers(const char *text, double *out, int count)
{
    for (int k = 0; k < count; k++) {
        char *end;
        out[k] = strtod(text, &end);
        if (end == text || !isfinite(out[k]) || *end != (k + 1 < count ? ',' : '\0'))
            return 0;
        text = end + 1;
    }
    return 1;
}

typedef struct counts {
    long mismatches, far, checked, bad, too_many;
    double max_err, sum_err;
} counts;

static void report_depth(counts *c, int i, int j, double ours, double ref, double err,
                         double limit)
{
    c->checked++;
    c->max_err = fmax(c->max_err, err);
    c->sum_err += err;
    if (!(err <= limit) && c->bad++ < 5)
        fprintf(stderr, "compare: pixel (%d, %d): depth %.9g, reference %.9g\n", i, j,
                ours, ref);
}

/* The faithful rules of the header. */
static void judge_faithful(const images *im, counts *c)
{
    int w = im->ref_mask.width, h = im->ref_mask.height;
    for (int j = 0; j < h; j++) {
        for (int i = 0; i < w; i++) {
            if (hit(&im->ref_mask, i, j) != hit(&im->mask, i, j)) {
                c->mismatches++;
                if (!near_silhouette(&im->ref_mask, i, j) && c->far++ < 5)
                    fprintf(stderr, "compare: pixel (%d, %d) differs away from an edge\n",
                            i, j);
                continue;
            }
            if (!hit(&im->mask, i, j) || is_edge(im, i, j))
                continue;
            double ref = at(&im->ref_depth, i, j), ours = at(&im->depth, i, j);
            report_depth(c, i, j, ours, ref, fabs(ours - ref) / ref, 1e-5);
        }
    }
    long pixels = (long)w * h;
    if (c->mismatches * 2000 > pixels) {
        c->too_many = 1;
        fprintf(stderr, "compare: %ld mask mismatches, more than 0.05 %% of %ld\n",
                c->mismatches, pixels);
    }
}

/* The nearest hit's depth at (i, j): its own where either side hits (the
 * reference first), else the smallest over its hit 4-neighbours; +inf when
 * none hits. */
static double hit_depth(const images *im, int i, int j)
{
    if (hit(&im->ref_mask, i, j))
        return at(&im->ref_depth, i, j);
    if (hit(&im->mask, i, j))
        return at(&im->depth, i, j);
    static const int nb[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
    double t = INFINITY;
    for (int k = 0; k < 4; k++) {
        int x = i + nb[k][0], y = j + nb[k][1];
        if (x < 0 || y < 0 || x >= im->ref_mask.width || y >= im->ref_mask.height)
            continue;
        if (hit(&im->ref_mask, x, y))
            t = fmin(t, at(&im->ref_depth, x, y));
        if (hit(&im->mask, x, y))
            t = fmin(t, at(&im->depth, x, y));
    }
    return t;
}

/* The exact rules of the header. Returns 0 when out of memory. */
static int judge_exact(const images *im, const exact_bound *b, counts *c)
{
    int w = im->ref_mask.width, h = im->ref_mask.height;
    size_t n = (size_t)w * (size_t)h;
    unsigned char *silhouette = calloc(n, 1), *edge = calloc(n, 1);
    long *silhouette_sat = NULL, *edge_sat = NULL;
    if (silhouette && edge) {
        for (int j = 0; j < h; j++) {
            for (int i = 0; i < w; i++) {
                size_t p = (size_t)j * (size_t)w + (size_t)i;
                silhouette[p] = (unsigned char)(near_silhouette(&im->ref_mask, i, j) ||
                                                near_silhouette(&im->mask, i, j));
                edge[p] = (unsigned char)(hit(&im->ref_mask, i, j) &&
                                          hit(&im->mask, i, j) && is_edge(im, i, j));
            }
        }
        silhouette_sat = summed_area(silhouette, w, h);
        edge_sat = summed_area(edge, w, h);
    }
    if (!silhouette_sat || !edge_sat) {
        free(silhouette);
        free(edge);
        free(silhouette_sat);
        free(edge_sat);
        return 0;
    }
    double band = 0; /* the bound on the number of mismatches */
    static const int nb[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
    for (int j = 0; j < h; j++) {
        for (int i = 0; i < w; i++) {
            int ref_hit = hit(&im->ref_mask, i, j), our_hit = hit(&im->mask, i, j);
            for (int k = 0; k < 4; k++) {
                int x = i + nb[k][0], y = j + nb[k][1];
                if (x >= 0 && y >= 0 && x < w && y < h &&
                    (hit(&im->ref_mask, x, y) != ref_hit ||
                     hit(&im->mask, x, y) != our_hit)) {
                    band +=
                        (double)pixels_for(b, i, j, hit_depth(im, i, j), b->delta) + 1;
                    break;
                }
            }
            if (ref_hit != our_hit) {
                c->mismatches++;
                long k = pixels_for(b, i, j, hit_depth(im, i, j), b->delta);
                if (!any_within(silhouette_sat, w, h, i, j, k) && c->far++ < 5)
                    fprintf(stderr,
                            "compare: pixel (%d, %d) differs farther than %ld pixels "
                            "from an edge\n",
                            i, j, k + 1);
                continue;
            }
            if (!ref_hit)
                continue;
            double ref = at(&im->ref_depth, i, j), ours = at(&im->depth, i, j);
            double theta = acos(fmin(1.0, at(&im->ref_cos, i, j))) + b->beta;
            if (!(theta < (PI / 2)))
                continue; /* near-grazing: no bound */
            double across = b->delta * fmax(1.0, tan(theta));
            if (any_within(edge_sat, w, h, i, j, pixels_for(b, i, j, ref, across) + 1))
                continue;
            double bound = b->delta / cos(theta) + 1e-5 * ref;
            report_depth(c, i, j, ours, ref, fabs(ours - ref) / bound, 1);
        }
    }
    if ((double)c->mismatches > band) {
        c->too_many = 1;
        fprintf(stderr,
                "compare: %ld mask mismatches, more than the %.0f the chord error "
                "allows along the silhouette\n",
                c->mismatches, band);
    }
    free(silhouette);
    free(edge);
    free(silhouette_sat);
    free(edge_sat);
    return 1;
}

int main(int argc, char **argv)
{
    const char *exact = NULL, *cos_path = NULL, *camera = NULL, *projection = "p";
    const char *fov_text = "22.5";
    const char *paths[4];
    int npaths = 0;
    for (int k = 1; k < argc; k++) {
        if (!strncmp(argv[k], "--exact=", 8))
            exact = argv[k] + 8;
        else if (!strncmp(argv[k], "--cos=", 6))
            cos_path = argv[k] + 6;
        else if (!strncmp(argv[k], "--camera=", 9))
            camera = argv[k] + 9;
        else if (!strncmp(argv[k], "--projection=", 13))
            projection = argv[k] + 13;
        else if (!strncmp(argv[k], "--fov=", 6))
            fov_text = argv[k] + 6;
        else if (npaths < 4)
            paths[npaths++] = argv[k];
        else
            npaths = 5;
    }
    double bound_in[2], cam[6], fov;
    exact_bound b;
    memset(&b, 0, sizeof b);
    int usage = npaths != 4;
    if (exact)
        usage = usage || !cos_path || !camera || !parse_numbers(exact, bound_in, 2) ||
                !parse_numbers(camera, cam, 6) || !parse_numbers(fov_text, &fov, 1) ||
                !(bound_in[0] >= 0) || !(bound_in[1] >= 0) || !(fov > 0 && fov < 180) ||
                (strcmp(projection, "p") && strcmp(projection, "o"));
    if (usage) {
        fprintf(stderr, "usage: compare REF_MASK REF_DEPTH MASK DEPTH "
                        "[--exact=DELTA,GAMMA --cos=REF_COS "
                        "--camera=EX,EY,EZ,CX,CY,CZ [--projection=p|o] [--fov=DEG]]\n");
        return 2;
    }
    images im;
    memset(&im, 0, sizeof im);
    int ok = load(paths[0], &im.ref_mask, 0, 0);
    int w = im.ref_mask.width, h = im.ref_mask.height;
    ok = ok && load(paths[1], &im.ref_depth, w, h) && load(paths[2], &im.mask, w, h) &&
         load(paths[3], &im.depth, w, h) && (!exact || load(cos_path, &im.ref_cos, w, h));
    counts c;
    memset(&c, 0, sizeof c);
    if (ok && exact) {
        b.delta = bound_in[0];
        b.beta = 3 * bound_in[1];
        b.a = tan(fov * PI / 360);
        b.width = w;
        b.height = h;
        if (!strcmp(projection, "o"))
            b.ortho_footprint = 2 * b.a *
                                sqrt((cam[3] - cam[0]) * (cam[3] - cam[0]) +
                                     (cam[4] - cam[1]) * (cam[4] - cam[1]) +
                                     (cam[5] - cam[2]) * (cam[5] - cam[2])) /
                                h;
        if (!judge_exact(&im, &b, &c)) {
            fprintf(stderr, "compare: out of memory\n");
            ok = 0;
        }
    } else if (ok) {
        judge_faithful(&im, &c);
    }
    if (ok) {
        if (c.far)
            fprintf(stderr, "compare: %ld mask mismatches away from silhouette edges\n",
                    c.far);
        if (c.bad)
            fprintf(stderr, "compare: %ld pixels beyond the depth tolerance\n", c.bad);
        printf("%ld %ld %ld %.3g %.3g\n", (long)w * h, c.mismatches, c.checked, c.max_err,
               c.checked ? c.sum_err / (double)c.checked : 0.0);
    }
    image_data_free(&im.ref_mask);
    image_data_free(&im.ref_depth);
    image_data_free(&im.mask);
    image_data_free(&im.depth);
    image_data_free(&im.ref_cos);
    if (!ok)
        return 2;
    return c.far == 0 && c.bad == 0 && !c.too_many ? 0 : 1;
}
