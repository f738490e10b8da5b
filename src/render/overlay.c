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

/* Adds the 3D segment a-b, clipped to the near plane. */
static void add_3d(line_list *l, const camera *cam, vec3 a, vec3 b, int stipple,
                   int color)
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
    line.occluded = 1;
    line.color = color;
    push(l, &line);
}

/* Adds a line in pixel coordinates, drawn over everything. */
static void add_2d(line_list *l, double x0, double y0, double x1, double y1, int color)
{
    overlay_line line = {x0, y0, x1, y1, 1, 1, 0, 0, color};
    push(l, &line);
}

enum { COLOR_AXES, COLOR_CROSSHAIR, COLOR_RED, COLOR_GREEN, COLOR_BLUE };

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

sc_status overlay_prepare(overlay *ov, const camera *cam, unsigned view,
                          const sc_color_scheme *scheme, const char *label, int border,
                          sc_error *error)
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
    if (view & SC_VIEW_CROSSHAIRS)
        add_crosshairs(&l, cam);
    if (view & SC_VIEW_AXES) {
        add_axes(&l, cam, cam->distance);
        if (view & SC_VIEW_SCALES)
            add_scales(&l, cam, cam->distance);
        add_small_axes(&l, cam);
    }
    if (l.failed) {
        free(l.v);
        return err_nomem(error, NULL);
    }
    ov->lines = l.v;
    ov->count = l.n;
    return SC_OK;
}

void overlay_release(overlay *ov)
{
    free(ov->lines);
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
    /* Later lines are drawn over earlier ones, as OpenSCAD draws them. */
    for (int k = ov->count - 1; k >= 0; k--) {
        const overlay_line *l = &ov->lines[k];
        double s;
        if (segment_distance2(l, px, py, &s) > LINE_HALF_WIDTH * LINE_HALF_WIDTH)
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
