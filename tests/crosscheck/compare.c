/* compare: judges spancast's mask and depth images against the reference
 * caster's (tests/reference/refcast) for the same camera, and prints one
 * row of the cross-check report.
 *
 * usage: compare REF_MASK REF_DEPTH MASK DEPTH [--exact=KIND,R,FN --cos=REF_COS]
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
 * Exact mode (--exact): spancast renders the true solid, the reference is
 * OpenSCAD's mesh of a sphere or cylinder of radius R with FN fragments.
 * The mesh is inscribed; its largest gap to the surface, delta, and the
 * largest angle between a facet's normal and the surface normal at its
 * corners, beta = acos(1 - delta / R), come from the tessellation itself
 * (faithful.c's planes: delta = R - min d over the curved faces). Along a
 * ray that meets the true surface at incidence theta, the two hits are at
 * most  R c - sqrt(R^2 c^2 - 2 R delta + delta^2),  c = cos(theta), apart:
 * the path across a spherical shell of radii R and R - delta, which also
 * bounds the path across a cylindrical one. theta is not known exactly; the
 * facet's incidence theta_m (--cos, from the reference) gives
 * cos(theta) >= cos(theta_m + beta). Pixels where that bound is below 0.3
 * (near-grazing) are not depth-checked. The mesh's silhouette lies inside
 * the true one by up to delta, a band that crosses many pixel centres, so
 * the mask rule is only that every difference lies within 1 pixel of a
 * silhouette edge of the reference, without the 0.05 % count.
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
#include "model/faithful.h"

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

/* delta and beta of OpenSCAD's tessellation of a sphere or cylinder of
 * radius r with fn fragments: see the header comment. Returns 0 on a bad
 * kind. */
static int tessellation_error(const char *kind, double r, double fn, double *delta,
                              double *beta)
{
    csg_builder *csg = csg_builder_new();
    prim p;
    sc_error error;
    sc_status st;
    int curved_from; /* curved faces start at this plane index */
    if (!strcmp(kind, "sphere")) {
        st = faithful_sphere(csg, r, fn, 12, 2, NULL, &p, &error);
        curved_from = 2;
    } else if (!strcmp(kind, "cylinder")) {
        st = faithful_cylinder(csg, 0, 1, r, r, fn, 12, 2, NULL, &p, &error);
        curved_from = 2;
    } else {
        csg_builder_free(csg);
        return 0;
    }
    if (st != SC_OK) {
        csg_builder_free(csg);
        return 0;
    }
    double dmin = r;
    for (uint32_t k = (uint32_t)curved_from; k < p.u.convex.count; k++) {
        const plane *pl = &p.u.convex.planes[k];
        double horizontal = !strcmp(kind, "sphere") ? 1 : hypot(pl->n.x, pl->n.y);
        dmin = fmin(dmin, pl->d / (horizontal * v3_length(pl->n)));
    }
    csg_builder_free(csg);
    *delta = r - dmin;
    *beta = acos(dmin / r);
    return 1;
}

int main(int argc, char **argv)
{
    const char *exact = NULL, *cos_path = NULL;
    const char *paths[4];
    int npaths = 0;
    for (int k = 1; k < argc; k++) {
        if (!strncmp(argv[k], "--exact=", 8))
            exact = argv[k] + 8;
        else if (!strncmp(argv[k], "--cos=", 6))
            cos_path = argv[k] + 6;
        else if (npaths < 4)
            paths[npaths++] = argv[k];
        else
            npaths = 5;
    }
    char kind[16] = "";
    double radius = 0, fn = 0, delta = 0, beta = 0;
    if (npaths != 4 || (exact && (!cos_path || sscanf(exact, "%15[a-z],%lf,%lf", kind,
                                                      &radius, &fn) != 3))) {
        fprintf(stderr, "usage: compare REF_MASK REF_DEPTH MASK DEPTH "
                        "[--exact=sphere|cylinder,R,FN --cos=REF_COS]\n");
        return 2;
    }
    if (exact && !tessellation_error(kind, radius, fn, &delta, &beta)) {
        fprintf(stderr, "compare: bad --exact=%s\n", exact);
        return 2;
    }
    images im;
    memset(&im, 0, sizeof im);
    int ok = load(paths[0], &im.ref_mask, 0, 0);
    int w = im.ref_mask.width, h = im.ref_mask.height;
    ok = ok && load(paths[1], &im.ref_depth, w, h) && load(paths[2], &im.mask, w, h) &&
         load(paths[3], &im.depth, w, h) && (!exact || load(cos_path, &im.ref_cos, w, h));
    if (!ok)
        return 2;

    long pixels = (long)w * h, mismatches = 0, far = 0, checked = 0, bad = 0;
    double max_err = 0, sum_err = 0;
    for (int j = 0; j < h; j++) {
        for (int i = 0; i < w; i++) {
            if (hit(&im.ref_mask, i, j) != hit(&im.mask, i, j)) {
                mismatches++;
                if (!near_silhouette(&im.ref_mask, i, j)) {
                    if (far++ < 5)
                        fprintf(stderr,
                                "compare: pixel (%d, %d) differs away from an edge\n", i,
                                j);
                }
                continue;
            }
            if (!hit(&im.mask, i, j) || is_edge(&im, i, j))
                continue;
            double ref = at(&im.ref_depth, i, j), ours = at(&im.depth, i, j);
            double err;
            if (exact) {
                double theta = acos(fmin(1.0, at(&im.ref_cos, i, j))) + beta;
                double c = cos(theta);
                if (!(c >= 0.3))
                    continue;
                double bound = radius * c - sqrt(radius * radius * c * c -
                                                 2 * radius * delta + delta * delta);
                err = fabs(ours - ref) / (bound + 1e-5 * ref);
            } else {
                err = fabs(ours - ref) / ref;
            }
            checked++;
            max_err = fmax(max_err, err);
            sum_err += err;
            if (exact ? !(err <= 1) : !(err <= 1e-5)) {
                if (bad++ < 5)
                    fprintf(stderr,
                            "compare: pixel (%d, %d): depth %.9g, reference %.9g\n", i, j,
                            ours, ref);
            }
        }
    }
    int too_many = !exact && mismatches * 2000 > pixels;
    int pass = far == 0 && bad == 0 && !too_many;
    if (too_many)
        fprintf(stderr, "compare: %ld mask mismatches, more than 0.05 %% of %ld\n",
                mismatches, pixels);
    if (far)
        fprintf(stderr, "compare: %ld mask mismatches away from silhouette edges\n", far);
    if (bad)
        fprintf(stderr, "compare: %ld pixels beyond the depth tolerance\n", bad);
    printf("%ld %ld %ld %.3g %.3g\n", pixels, mismatches, checked, max_err,
           checked ? sum_err / (double)checked : 0.0);
    image_data_free(&im.ref_mask);
    image_data_free(&im.ref_depth);
    image_data_free(&im.mask);
    image_data_free(&im.depth);
    image_data_free(&im.ref_cos);
    return pass ? 0 : 1;
}
