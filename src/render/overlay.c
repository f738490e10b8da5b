/* Overlay lines: see overlay.h for what is drawn.
 *
 * A 3D line is clipped to the part in front of OpenSCAD's near plane (0.1
 * of the camera distance in perspective), projected to pixel coordinates
 * by inverting the camera's ray formula (camera.h), and kept with its end
 * depths. A sample at (px, py) is on a line when its distance to the
 * projected segment is at most half a pixel (OpenSCAD's lines are one
 * pixel wide); the line's depth there is interpolated in 1/z, which is
 * linear in the image under perspective. Labels are a 5 x 7 pixel font of
 * the capitals the view names use.
 */
#include "render/overlay.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "formats/color.h"

#define LINE_HALF_WIDTH 0.5
#define NEAR_FRACTION 0.1 /* OpenSCAD's near plane: 0.1 of the distance */

double overlay_depth(const camera *cam, vec3 p)
{
    return v3_dot(v3_sub(p, cam->eye), cam->f);
}

/* Pixel coordinates of p, which lies in front of the eye. */
static void project(const camera *cam, vec3 p, double *px, double *py)
{
    vec3 v = v3_sub(p, cam->eye);
    double x, y;
    if (cam->projection == SC_PROJECTION_ORTHOGRAPHIC) {
        x = v3_dot(v, cam->r) / cam->distance;
        y = v3_dot(v, cam->u) / cam->distance;
    } else {
        double z = v3_dot(v, cam->f);
        x = v3_dot(v, cam->r) / z;
        y = v3_dot(v, cam->u) / z;
    }
    *px = (x / (cam->a * cam->aspect) + 1) * cam->width / 2;
    *py = (1 - y / cam->a) * cam->height / 2;
}

typedef struct line_list {
    overlay_line *v;
    int n, cap;
    int failed;
} line_list;

static void push(line_list *l, const overlay_line *line)
{
    if (l->n == l->cap) {
        int cap = l->cap ? 2 * l->cap : 64;
        overlay_line *v = realloc(l->v, (size_t)cap * sizeof *v);
        if (!v) {
            l->failed = 1;
            return;
        }
        l->v = v;
        l->cap = cap;
    }
    l->v[l->n++] = *line;
}

/* llvmpipe's sign: -1 below 0, else 1. */
static double sign_of(double x)
{
    return x < 0 ? -1 : 1;
}

static double frac_of(double x)
{
    return x - floor(x);
}

/* Whether llvmpipe (Mesa's software OpenGL, which draws OpenSCAD's off
 * screen images) draws the end pixels of the line from (a1, c1) to
 * (a2, c2), in window coordinates (y up) with a its major axis: its test
 * of the diamond exit rule, which decides by where the line meets the
 * pixel's middle column, taken as llvmpipe takes it (lp_setup_line.c). */
static void diamond_ends(double a1, double c1, double a2, double c2, int *draw_start,
                         int *draw_end)
{
    double da = a1 - a2, dc = c1 - c2; /* llvmpipe's: from the end to the start */
    double slope = dc / da;
    double a1diff = a1 - floor(a1) - 0.5, c1diff = c1 - floor(c1) - 0.5;
    double a2diff = a2 - floor(a2) - 0.5, c2diff = c2 - floor(c2) - 0.5;
    if (c2diff == -0.5 && dc < 0)
        c2diff = 0.5;
    if (fabs(a1diff) + fabs(c1diff) < 0.5)
        *draw_start = 1;
    else if (sign_of(a1diff) == sign_of(-da))
        *draw_start = 0;
    else if (sign_of(-c1diff) != sign_of(dc))
        *draw_start = 1;
    else {
        double cross = frac_of(c1) + a1diff * slope;
        *draw_start = cross > 0 && cross < 1;
    }
    if (fabs(a2diff) + fabs(c2diff) < 0.5)
        *draw_end = 0;
    else if (sign_of(a2diff) != sign_of(-da))
        *draw_end = 0;
    else if (sign_of(-c2diff) == sign_of(dc))
        *draw_end = 1;
    else {
        double cross = frac_of(c2) + a2diff * slope;
        *draw_end = cross > 0 && cross < 1;
    }
}

/* Fits a wide line's ends as llvmpipe rasterises one: the ends snapped to
 * 1/256 pixel; the columns (rows for a line nearer the vertical) of its
 * end pixels drawn as diamond_ends says, each end moved along the line to
 * the edge of its column where its pixel centre would say otherwise.
 * height: the image's, to turn rows into OpenGL's y up. */
static void fit_wide(overlay_line *l, int height)
{
    double x0 = round(l->x0 * 256) / 256, y0 = round((height - l->y0) * 256) / 256;
    double x1 = round(l->x1 * 256) / 256, y1 = round((height - l->y1) * 256) / 256;
    int x_major = fabs(x1 - x0) >= fabs(y1 - y0);
    double a0 = x_major ? x0 : y0, c0 = x_major ? y0 : x0;
    double a1 = x_major ? x1 : y1, c1 = x_major ? y1 : x1;
    if (a0 != a1) { /* else no length: nothing is drawn (on_wide) */
        int draw_start, draw_end;
        diamond_ends(a0, c0, a1, c1, &draw_start, &draw_end);
        int forward = a0 < a1;
        double lo = forward ? a0 : a1, hi = forward ? a1 : a0;
        double clo = forward ? c0 : c1, chi = forward ? c1 : c0;
        double slope = (chi - clo) / (hi - lo);
        int draw_lo = forward ? draw_start : draw_end;
        int draw_hi = forward ? draw_end : draw_start;
        double flo = floor(lo), fhi = floor(hi), to_lo = lo, to_hi = hi;
        if ((lo <= flo + 0.5) != draw_lo) /* the column's centre is inside from lo */
            to_lo = draw_lo ? flo : flo + 1;
        if ((hi > fhi + 0.5) != draw_hi) /* and before hi */
            to_hi = draw_hi ? fhi + 1 : fhi;
        if (to_lo > to_hi)
            to_lo = to_hi;
        /* each end moves along the line */
        clo += (to_lo - lo) * slope;
        chi += (to_hi - hi) * slope;
        a0 = forward ? to_lo : to_hi;
        a1 = forward ? to_hi : to_lo;
        c0 = forward ? clo : chi;
        c1 = forward ? chi : clo;
    }
    l->x0 = x_major ? a0 : c0;
    l->y0 = height - (x_major ? c0 : a0);
    l->x1 = x_major ? a1 : c1;
    l->y1 = height - (x_major ? c1 : a1);
}

/* Adds the 3D segment a-b, clipped to the near plane: occluded by the
 * model, and wide (overlay_line) or not. */
static void add_segment(line_list *l, const camera *cam, vec3 a, vec3 b, int stipple,
                        int color, int occluded, int wide)
{
    double near = cam->projection == SC_PROJECTION_ORTHOGRAPHIC
                      ? -INFINITY
                      : NEAR_FRACTION * cam->distance;
    double za = overlay_depth(cam, a), zb = overlay_depth(cam, b);
    if (za < near && zb < near)
        return;
    if (za < near)
        a = v3_madd(a, v3_sub(b, a), (near - za) / (zb - za)), za = near;
    else if (zb < near)
        b = v3_madd(b, v3_sub(a, b), (near - zb) / (za - zb)), zb = near;
    overlay_line line;
    project(cam, a, &line.x0, &line.y0);
    project(cam, b, &line.x1, &line.y1);
    line.z0 = za;
    line.z1 = zb;
    line.stipple = stipple;
    line.occluded = occluded;
    line.color = color;
    line.wide = wide;
    if (wide)
        fit_wide(&line, cam->height);

    push(l, &line);
}

/* Adds the 3D segment a-b, occluded by the model. */
static void add_3d(line_list *l, const camera *cam, vec3 a, vec3 b, int stipple,
                   int color)
{
    add_segment(l, cam, a, b, stipple, color, 1, 0);
}

/* Adds a line in pixel coordinates, drawn over everything. */
static void add_2d(line_list *l, double x0, double y0, double x1, double y1, int color)
{
    overlay_line line = {x0, y0, x1, y1, 1, 1, 0, 0, color, 0};
    push(l, &line);
}

enum { COLOR_AXES, COLOR_CROSSHAIR, COLOR_RED, COLOR_GREEN, COLOR_BLUE, COLOR_EDGE_2D };

/* Adds each outline as a closed loop of wide lines over the model. */
static void add_outlines(line_list *l, const camera *cam, const overlay_outlines *o)
{
    for (uint32_t k = 0; k < o->count; k++) {
        uint32_t first = o->start[k], end = o->start[k + 1];
        for (uint32_t i = first; i < end; i++) {
            uint32_t j = i + 1 < end ? i + 1 : first;
            const double *a = o->points + 3 * (size_t)i, *b = o->points + 3 * (size_t)j;
            add_segment(l, cam, v3(a[0], a[1], a[2]), v3(b[0], b[1], b[2]), 0,
                        COLOR_EDGE_2D, 0, 1);
        }
    }
}

static void add_axes(line_list *l, const camera *cam, double len)
{
    for (int k = 0; k < 3; k++) {
        double e[3] = {0, 0, 0};
        e[k] = len;
        vec3 tip = v3(e[0], e[1], e[2]);
        add_3d(l, cam, v3(0, 0, 0), tip, 0, COLOR_AXES);
        add_3d(l, cam, v3(0, 0, 0), v3_neg(tip), 1, COLOR_AXES);
    }
}

static void add_scales(line_list *l, const camera *cam, double len)
{
    double unit = pow(10, floor(log10(len)));
    double step = unit / 10;
    int count = 0;
    for (double i = 0; i < len && count < 1000; i += step, count++) {
        double arm = len / (count > 0 && count % 10 == 0 ? 30.0 : 60.0);
        for (int sign = 1; sign >= -1; sign -= 2) {
            double p = sign * i;
            int st = sign < 0;
            add_3d(l, cam, v3(p, 0, 0), v3(p, -arm, 0), st, COLOR_AXES);
            add_3d(l, cam, v3(0, p, 0), v3(-arm, p, 0), st, COLOR_AXES);
            add_3d(l, cam, v3(0, 0, p), v3(-arm, 0, p), st, COLOR_AXES);
        }
    }
}

static void add_crosshairs(line_list *l, const camera *cam)
{
    double vd = cam->distance / 8;
    for (int xf = -1; xf <= 1; xf += 2)
        for (int yf = -1; yf <= 1; yf += 2) {
            vec3 d = v3(xf * vd, yf * vd, vd);
            add_3d(l, cam, v3_sub(cam->center, d), v3_add(cam->center, d), 0,
                   COLOR_CROSSHAIR);
        }
}

/* The small axes of the lower left corner, with their letters. */
static void add_small_axes(line_list *l, const camera *cam)
{
    double half = cam->height / 2.0;
    double ox = 0.1 * cam->width, oy = 0.9 * cam->height;
    vec3 axis[3] = {v3(1, 0, 0), v3(0, 1, 0), v3(0, 0, 1)};
    double lx[3], ly[3];
    for (int k = 0; k < 3; k++) {
        double sx = v3_dot(axis[k], cam->r), sy = v3_dot(axis[k], cam->u);
        add_2d(l, ox, oy, ox + 10.0 / 90 * half * sx, oy - 10.0 / 90 * half * sy,
               COLOR_RED + k);
        lx[k] = round(ox + 12.0 / 90 * half * sx);
        ly[k] = round(oy - 12.0 / 90 * half * sy);
    }
    const double d = 3;
    add_2d(l, lx[0] - d, ly[0] + d, lx[0] + d, ly[0] - d, COLOR_AXES); /* X */
    add_2d(l, lx[0] - d, ly[0] - d, lx[0] + d, ly[0] + d, COLOR_AXES);
    add_2d(l, lx[1] - d, ly[1] + d, lx[1] + d, ly[1] - d, COLOR_AXES); /* Y */
    add_2d(l, lx[1] - d, ly[1] - d, lx[1], ly[1], COLOR_AXES);
    add_2d(l, lx[2] - d, ly[2] + d, lx[2] + d, ly[2] + d, COLOR_AXES); /* Z */
    add_2d(l, lx[2] - d, ly[2] - d, lx[2] + d, ly[2] - d, COLOR_AXES);
    add_2d(l, lx[2] - d, ly[2] + d, lx[2] + d, ly[2] - d, COLOR_AXES);
}

static void linear3(const float in[3], double out[3])
{
    for (int k = 0; k < 3; k++)
        out[k] = color_srgb_to_linear(in[k]);
}

#define OVERLAY_CELL 16 /* pixels on a side of the cells lines are sorted into */
#define WIDE_HALF 1.0   /* a wide line covers 1 pixel each side of it */

/* Squared distance from (px, py) to the segment, and the parameter s of
 * the nearest point. */
static double segment_distance2(const overlay_line *l, double px, double py, double *s)
{
    double dx = l->x1 - l->x0, dy = l->y1 - l->y0;
    double len2 = dx * dx + dy * dy;
    double t = len2 > 0 ? ((px - l->x0) * dx + (py - l->y0) * dy) / len2 : 0;
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    double ex = l->x0 + t * dx - px, ey = l->y0 + t * dy - py;
    *s = t;
    return ex * ex + ey * ey;
}

/* Whether the cell (cx, cy) may hold points of line l: its centre is
 * within half its diagonal, and a margin above any line's reach, of the
 * segment. */
static int line_in_cell(const overlay_line *l, int cx, int cy)
{
    double half = OVERLAY_CELL / 2.0, s;
    double reach = half * 1.4142135623730951 + 2 * WIDE_HALF;
    return segment_distance2(l, (cx + 0.5) * OVERLAY_CELL, (cy + 0.5) * OVERLAY_CELL,
                             &s) <= reach * reach;
}

/* The range of cells [*c0, *c1] along one image axis of n cells that the
 * coordinates a and b, widened by 2 * WIDE_HALF, reach; *c1 < *c0 when
 * none. */
static void cell_range(double a, double b, int n, int *c0, int *c1)
{
    double lo = floor((fmin(a, b) - 2 * WIDE_HALF) / OVERLAY_CELL);
    double hi = floor((fmax(a, b) + 2 * WIDE_HALF) / OVERLAY_CELL);
    lo = fmax(lo, 0);
    hi = fmin(hi, n - 1);
    if (!(lo <= hi)) { /* also NaN */
        *c0 = 0;
        *c1 = -1;
        return;
    }
    *c0 = (int)lo;
    *c1 = (int)hi;
}

/* Sorts ov's lines into the cells of the image (overlay.cell_*), in two
 * passes: count, then fill. Returns 0 when out of memory. */
static int sort_into_cells(overlay *ov)
{
    ov->cells_x = (ov->cam->width + OVERLAY_CELL - 1) / OVERLAY_CELL;
    ov->cells_y = (ov->cam->height + OVERLAY_CELL - 1) / OVERLAY_CELL;
    size_t cells = (size_t)ov->cells_x * (size_t)ov->cells_y;
    ov->cell_start = calloc(cells + 1, sizeof *ov->cell_start);
    if (!ov->cell_start)
        return 0;
    uint32_t *fill = NULL;
    for (int pass = 0; pass < 2; pass++) {
        for (int k = 0; k < ov->count; k++) {
            const overlay_line *l = &ov->lines[k];
            int x0, x1, y0, y1;
            cell_range(l->x0, l->x1, ov->cells_x, &x0, &x1);
            cell_range(l->y0, l->y1, ov->cells_y, &y0, &y1);
            for (int cy = y0; cy <= y1; cy++)
                for (int cx = x0; cx <= x1; cx++) {
                    if (!line_in_cell(l, cx, cy))
                        continue;
                    size_t c = (size_t)cy * (size_t)ov->cells_x + (size_t)cx;
                    if (pass == 0)
                        ov->cell_start[c + 1]++;
                    else
                        ov->cell_lines[fill[c]++] = (uint32_t)k;
                }
        }
        if (pass == 1)
            break;
        for (size_t c = 0; c < cells; c++)
            ov->cell_start[c + 1] += ov->cell_start[c];
        ov->cell_lines =
            malloc(((size_t)ov->cell_start[cells] + 1) * sizeof *ov->cell_lines);
        fill = malloc(cells * sizeof *fill);
        if (!ov->cell_lines || !fill) {
            free(fill);
            return 0;
        }
        memcpy(fill, ov->cell_start, cells * sizeof *fill);
    }
    free(fill);
    return 1;
}

sc_status overlay_prepare(overlay *ov, const camera *cam, unsigned view,
                          const sc_color_scheme *scheme, const overlay_outlines *outlines,
                          const char *label, int border, sc_error *error)
{
    memset(ov, 0, sizeof *ov);
    ov->cam = cam;
    ov->label = label;
    ov->border = border;
    linear3(scheme->axes, ov->colors[COLOR_AXES]);
    linear3(scheme->crosshair, ov->colors[COLOR_CROSSHAIR]);
    for (int k = 0; k < 3; k++) {
        double *c = ov->colors[COLOR_RED + k];
        c[0] = c[1] = c[2] = 0;
        c[k] = 1;
    }
    line_list l = {NULL, 0, 0, 0};
    /* in OpenSCAD's order (GLView::paintGL): the small axes last */
    if (view & SC_VIEW_CROSSHAIRS)
        add_crosshairs(&l, cam);
    if (view & SC_VIEW_AXES) {
        add_axes(&l, cam, cam->distance);
        if (view & SC_VIEW_SCALES)
            add_scales(&l, cam, cam->distance);
    }
    if (outlines) {
        linear3(outlines->color, ov->colors[COLOR_EDGE_2D]);
        add_outlines(&l, cam, outlines);
    }
    if (view & SC_VIEW_AXES)
        add_small_axes(&l, cam);
    ov->lines = l.v;
    ov->count = l.n;
    if (l.failed || !sort_into_cells(ov)) {
        overlay_release(ov);
        return err_nomem(error, NULL);
    }
    return SC_OK;
}

void overlay_release(overlay *ov)
{
    free(ov->lines);
    free(ov->cell_start);
    free(ov->cell_lines);
    memset(ov, 0, sizeof *ov);
}

/* 5 x 7 capitals for the view names: one row a byte, bit 4 the left
 * column. */
static const struct glyph {
    char c;
    unsigned char rows[7];
} glyphs[] = {
    {'A', {0x0e, 0x11, 0x11, 0x1f, 0x11, 0x11, 0x11}},
    {'B', {0x1e, 0x11, 0x11, 0x1e, 0x11, 0x11, 0x1e}},
    {'C', {0x0e, 0x11, 0x10, 0x10, 0x10, 0x11, 0x0e}},
    {'D', {0x1e, 0x11, 0x11, 0x11, 0x11, 0x11, 0x1e}},
    {'E', {0x1f, 0x10, 0x10, 0x1e, 0x10, 0x10, 0x1f}},
    {'F', {0x1f, 0x10, 0x10, 0x1e, 0x10, 0x10, 0x10}},
    {'G', {0x0e, 0x11, 0x10, 0x17, 0x11, 0x11, 0x0f}},
    {'H', {0x11, 0x11, 0x11, 0x1f, 0x11, 0x11, 0x11}},
    {'I', {0x0e, 0x04, 0x04, 0x04, 0x04, 0x04, 0x0e}},
    {'K', {0x11, 0x12, 0x14, 0x18, 0x14, 0x12, 0x11}},
    {'L', {0x10, 0x10, 0x10, 0x10, 0x10, 0x10, 0x1f}},
    {'M', {0x11, 0x1b, 0x15, 0x15, 0x11, 0x11, 0x11}},
    {'N', {0x11, 0x19, 0x15, 0x13, 0x11, 0x11, 0x11}},
    {'O', {0x0e, 0x11, 0x11, 0x11, 0x11, 0x11, 0x0e}},
    {'P', {0x1e, 0x11, 0x11, 0x1e, 0x10, 0x10, 0x10}},
    {'R', {0x1e, 0x11, 0x11, 0x1e, 0x14, 0x12, 0x11}},
    {'T', {0x1f, 0x04, 0x04, 0x04, 0x04, 0x04, 0x04}},
};

#define LABEL_MARGIN 4 /* pixels from the tile's corner */

/* Whether (px, py) is on a lit cell of the label's text. */
static int on_label(const char *text, int scale, double px, double py)
{
    int cx = (int)floor((px - LABEL_MARGIN) / scale);
    int cy = (int)floor((py - LABEL_MARGIN) / scale);
    if (px < LABEL_MARGIN || py < LABEL_MARGIN || cy >= 7)
        return 0;
    int index = cx / 6, column = cx % 6; /* 5 columns and a space */
    if (column == 5 || index >= (int)strlen(text))
        return 0;
    for (size_t g = 0; g < sizeof glyphs / sizeof glyphs[0]; g++)
        if (glyphs[g].c == text[index])
            return (glyphs[g].rows[cy] >> (4 - column)) & 1;
    return 0;
}

/* Whether (px, py) is on the wide line l, and where (s along it): within
 * WIDE_HALF of it across its major axis, and along that axis in [lo, hi),
 * as OpenGL fills a wide line's pixel centres. */
static int on_wide(const overlay_line *l, double px, double py, double *s)
{
    double dx = l->x1 - l->x0, dy = l->y1 - l->y0;
    int x_major = fabs(dx) >= fabs(dy);
    double along = x_major ? px : py, across = x_major ? py : px;
    double a0 = x_major ? l->x0 : l->y0, a1 = x_major ? l->x1 : l->y1;
    double c0 = x_major ? l->y0 : l->x0, c1 = x_major ? l->y1 : l->x1;
    if (!(fmin(a0, a1) <= along && along < fmax(a0, a1)))
        return 0; /* also a line of no length */
    double t = (along - a0) / (a1 - a0);
    double off = across - (c0 + t * (c1 - c0));
    *s = t;
    return -WIDE_HALF <= off && off < WIDE_HALF;
}

int overlay_sample(const overlay *ov, double px, double py, double surface_depth,
                   double out[3])
{
    if (ov->label) {
        int scale = ov->cam->height >= 300 ? 2 : 1;
        if (on_label(ov->label, scale, px, py)) {
            memcpy(out, ov->colors[COLOR_AXES], 3 * sizeof *out);
            return 1;
        }
    }
    if (ov->border && (px < 1 || py < 1)) {
        memcpy(out, ov->colors[COLOR_AXES], 3 * sizeof *out);
        return 1;
    }
    if (!ov->count)
        return 0;
    int cx = (int)fmin(fmax(floor(px / OVERLAY_CELL), 0), ov->cells_x - 1);
    int cy = (int)fmin(fmax(floor(py / OVERLAY_CELL), 0), ov->cells_y - 1);
    size_t cell = (size_t)cy * (size_t)ov->cells_x + (size_t)cx;
    /* Later lines are drawn over earlier ones, as OpenSCAD draws them. */
    for (uint32_t q = ov->cell_start[cell + 1]; q-- > ov->cell_start[cell];) {
        const overlay_line *l = &ov->lines[ov->cell_lines[q]];
        double s;
        if (l->wide
                ? !on_wide(l, px, py, &s)
                : segment_distance2(l, px, py, &s) > LINE_HALF_WIDTH * LINE_HALF_WIDTH)
            continue;
        if (l->stipple) {
            double along = s * hypot(l->x1 - l->x0, l->y1 - l->y0);
            if (((long)floor(along / 3)) % 2 == 0)
                continue;
        }
        if (l->occluded) {
            double depth;
            if (ov->cam->projection == SC_PROJECTION_ORTHOGRAPHIC)
                depth = l->z0 + s * (l->z1 - l->z0);
            else
                depth = 1 / ((1 - s) / l->z0 + s / l->z1);
            if (!(depth < surface_depth))
                continue;
        }
        memcpy(out, ov->colors[l->color], 3 * sizeof *out);
        return 1;
    }
    return 0;
}
