/* SVG drawings as OpenSCAD 2021.01 reads them (import_svg.cc and its
 * libsvg), for import("x.svg"). The XML is libxml2's (xml.h); the rules
 * below are OpenSCAD's, kept where they differ from the SVG standard,
 * since a model should look the same in both:
 *
 *   - Shapes: path, rect (rounded corners through a path, its numbers
 *     printed with 6 significant digits as OpenSCAD prints them), circle
 *     and ellipse (40 points, the first at 9 degrees), line, polyline,
 *     polygon. g, text and tspan are groups; svg is the page. Text draws
 *     nothing, and a defs subtree is left out. Any other element (a,
 *     switch, symbol, clipPath, ...) is transparent: not drawn itself, its
 *     transform ignored, its children drawn.
 *   - Curves: a fixed 20 points per quadratic or cubic Bezier, and
 *     |sweep| * 10 / 180 + 4 steps per elliptical arc (SVG's
 *     implementation notes, F.6.5, radii scaled up when too small); $fn,
 *     $fa and $fs play no part. An arc with a zero radius is a line, as
 *     SVG says (OpenSCAD computes NaN there); one that ends where it
 *     starts is left out, as SVG says and OpenSCAD does.
 *   - Strokes: line and polyline are always their stroke; an open subpath
 *     of a path (ends more than 0.1 apart) is its stroke, except the last
 *     one of a path that closed some subpath with z. The stroke is
 *     Clipper's offset of the untransformed points (svg_stroke.h), width
 *     from the element's stroke-width attribute or its style (below 0.01,
 *     or unreadable: 1), caps and joins from stroke-linecap and
 *     stroke-linejoin. Fill, fill-rule, stroke colour and display are
 *     not read.
 *   - Numbers: an attribute's number must be the whole attribute, else it
 *     is 0 ("2px" in stroke-width is 0). A path's data splits at spaces,
 *     commas, '-' and the command letters, and at a second '.' ("1.5.5"
 *     is 1.5 and .5); "1e-5" is one number, "1E-5" is not.
 *   - Transforms: matrix, translate, scale, rotate (with a centre),
 *     skewX, skewY, composed through the ancestors; the svg element's own
 *     transform is not read.
 *   - The page: width and height with a unit (px 96 to the inch, pt, pc,
 *     in, cm, mm; none: the import's dpi, 72 by default). With a viewBox,
 *     user units scale to the page (preserveAspectRatio: the aligned,
 *     uniform scale of meet or slice; none: each axis its own); without
 *     one, a user unit is a millimetre. y points up: y = height - y.
 *     center = true centres the bounds on the origin instead. A page
 *     whose scale is not finite (a viewBox of zero width, say, unless
 *     meet takes the other axis's scale) draws nothing: OpenSCAD's
 *     points are not finite there, and it draws none.
 *   - Fill: each shape's own rings are combined even-odd (OpenSCAD's
 *     sanitize), then all shapes united (non-zero), through the clipper.
 */
#include "formats/svg.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "formats/svg_stroke.h"
#include "formats/xml.h"
#include "model/faithful.h"

typedef struct mat3 {
    double a, b, c, d, e, f; /* x' = a x + c y + e, y' = b x + d y + f */
} mat3;

static const mat3 identity = {1, 0, 0, 1, 0, 0};

static mat3 mat_mul(mat3 p, mat3 q) /* p after q */
{
    return (mat3){p.a * q.a + p.c * q.b,       p.b * q.a + p.d * q.b,
                  p.a * q.c + p.c * q.d,       p.b * q.c + p.d * q.d,
                  p.a * q.e + p.c * q.f + p.e, p.b * q.e + p.d * q.f + p.f};
}

/* An open path being made: points, 2 per point. */
typedef struct points {
    double *xy;
    size_t count, cap;
} points;

/* The state of one reading. */
typedef struct reader {
    const char *name;
    const sc_location *at;
    sc_error *error;
    twod_region **shapes; /* each shape's rings, in page units */
    size_t shape_count, shape_cap;
    double scale[2];   /* of the last page seen */
    double viewbox[2]; /* its viewBox x, y */
    double align[2];
    double height_mm;
    double box[4]; /* min x, min y, max x, max y of scale * point; empty: min > max */
    int nomem, range;
    int blank; /* a page whose scale is not finite */
} reader;

/* ---- numbers ---- */

/* The length of the number at s (sign, digits, fraction, exponent), 0
 * when there is none. */
static size_t number_length(const char *s)
{
    size_t i = 0, digits = 0;
    if (s[i] == '+' || s[i] == '-')
        i++;
    while (isdigit((unsigned char)s[i]))
        i++, digits++;
    if (s[i] == '.') {
        i++;
        while (isdigit((unsigned char)s[i]))
            i++, digits++;
    }
    if (!digits)
        return 0;
    if (s[i] == 'e' || s[i] == 'E') {
        size_t j = i + 1;
        if (s[j] == '+' || s[j] == '-')
            j++;
        if (isdigit((unsigned char)s[j])) {
            while (isdigit((unsigned char)s[j]))
                j++;
            i = j;
        }
    }
    return i;
}

/* OpenSCAD's parse_double: the number that is the whole of s, else 0. */
static double whole_number(const char *s, size_t n)
{
    if (!s || !n)
        return 0;
    char buf[128];
    if (n >= sizeof buf)
        return 0;
    memcpy(buf, s, n);
    buf[n] = 0;
    size_t len = number_length(buf);
    if (len != n)
        return 0;
    return strtod(buf, NULL);
}

static double attr_number(const xml_element *e, const char *name)
{
    const char *v = xml_attr_value(e, name);
    return v ? whole_number(v, strlen(v)) : 0;
}

/* ---- output ---- */

static int commit_point(reader *r, twod_region *shape, const mat3 *m, double x, double y)
{
    double tx = m->a * x + m->c * y + m->e, ty = m->b * x + m->d * y + m->f;
    double sx = r->scale[0] * tx, sy = r->scale[1] * ty;
    if (sx < r->box[0])
        r->box[0] = sx;
    if (sy < r->box[1])
        r->box[1] = sy;
    if (sx > r->box[2])
        r->box[2] = sx;
    if (sy > r->box[3])
        r->box[3] = sy;
    if (!isfinite(tx) || !isfinite(ty)) { /* past the range: svg_read */
        r->range = 1;
        return 0;
    }
    if (!twod_add_point(shape, tx, ty)) {
        r->nomem = 1;
        return 0;
    }
    return 1;
}

/* Adds the path p, moved by m, as a ring of shape. */
static int commit_path(reader *r, twod_region *shape, const mat3 *m, const points *p)
{
    if (!p->count)
        return 1;
    if (!twod_begin_contour(shape)) {
        r->nomem = 1;
        return 0;
    }
    for (size_t i = 0; i < p->count; i++)
        if (!commit_point(r, shape, m, p->xy[2 * i], p->xy[2 * i + 1]))
            return 0;
    twod_end_contour(shape);
    return 1;
}

static int push(reader *r, points *p, double x, double y)
{
    if (p->count == p->cap) {
        size_t cap = p->cap ? 2 * p->cap : 64;
        if (cap > TWOD_MAX_POINTS) {
            r->range = 1;
            return 0;
        }
        double *xy = realloc(p->xy, 2 * cap * sizeof *xy);
        if (!xy) {
            r->nomem = 1;
            return 0;
        }
        p->xy = xy;
        p->cap = cap;
    }
    p->xy[2 * p->count] = x;
    p->xy[2 * p->count + 1] = y;
    p->count++;
    return 1;
}

/* ---- strokes ---- */

/* OpenSCAD's shape::get_style: the value of name in the style attribute,
 * "a:b;c:d" split exactly, without trimming. */
static const char *style_value(const xml_element *e, const char *name, size_t *len)
{
    const char *style = xml_attr_value(e, "style");
    if (!style)
        return NULL;
    size_t name_len = strlen(name);
    for (const char *s = style;;) {
        const char *end = strchr(s, ';');
        size_t n = end ? (size_t)(end - s) : strlen(s);
        const char *colon = memchr(s, ':', n);
        if (colon && !memchr(colon + 1, ':', n - (size_t)(colon + 1 - s)) &&
            (size_t)(colon - s) == name_len && !memcmp(s, name, name_len)) {
            *len = n - (size_t)(colon + 1 - s);
            return colon + 1;
        }
        if (!end)
            return NULL;
        s = end + 1;
    }
}

/* An attribute, or else its style entry; *len its length. */
static const char *stroke_attr(const xml_element *e, const char *name, size_t *len)
{
    const char *v = xml_attr_value(e, name);
    if (v && v[0]) {
        *len = strlen(v);
        return v;
    }
    return style_value(e, name, len);
}

static int same(const char *v, size_t n, const char *word)
{
    return v && n == strlen(word) && !memcmp(v, word, n);
}

static int stroke(reader *r, const xml_element *e, twod_region *shape, const mat3 *m,
                  const points *p)
{
    size_t n = 0;
    const char *v = stroke_attr(e, "stroke-width", &n);
    double width = v ? whole_number(v, n) : 0;
    if (width < 0.01)
        width = 1;
    v = stroke_attr(e, "stroke-linecap", &n);
    svg_cap cap = same(v, n, "butt")    ? SVG_CAP_BUTT
                  : same(v, n, "round") ? SVG_CAP_ROUND
                                        : SVG_CAP_SQUARE;
    v = stroke_attr(e, "stroke-linejoin", &n);
    /* OpenSCAD maps bevel to Clipper's square join, everything else but
     * round to miter */
    svg_join join = same(v, n, "bevel")   ? SVG_JOIN_SQUARE
                    : same(v, n, "round") ? SVG_JOIN_ROUND
                                          : SVG_JOIN_MITER;
    twod_region outline;
    twod_init(&outline);
    int code = svg_stroke(p->xy, p->count, width, join, cap, &outline);
    int ok = code > 0;
    if (code == 0)
        r->nomem = 1;
    else if (code < 0)
        r->range = 1;
    for (uint32_t k = 0; ok && k < outline.contour_count; k++) {
        points ring = {outline.xy + 2 * outline.start[k],
                       outline.start[k + 1] - outline.start[k], 0};
        /* OpenSCAD closes each ring by repeating its first point, which
         * neither the bounds nor the clipper see */
        ok = commit_path(r, shape, m, &ring) && ok;
    }
    twod_free(&outline);
    return ok;
}

static int is_open(const points *p)
{
    double dx = p->xy[0] - p->xy[2 * p->count - 2],
           dy = p->xy[1] - p->xy[2 * p->count - 1];
    return sqrt(dx * dx + dy * dy) > 0.1;
}

/* ---- paths ---- */

static double deg_atan2(double y, double x)
{
    return atan2(y, x) * (180.0 / 3.14159265358979323846);
}

static double vector_angle(double ux, double uy, double vx, double vy)
{
    double angle = deg_atan2(vy, vx) - deg_atan2(uy, ux);
    return angle < 0 ? angle + 360 : angle;
}

/* SVG's implementation notes F.6.5 with OpenSCAD's steps. */
static int arc_to(reader *r, points *p, double x1, double y1, double rx, double ry,
                  double x2, double y2, double angle, int large, int sweep)
{
    /* a zero radius is a line; so is anything not finite, whose end point
     * the output then refuses as out of range */
    if (rx == 0 || ry == 0 || !isfinite(x1 + y1 + rx + ry + x2 + y2 + angle))
        return push(r, p, x2, y2);
    /* an arc that ends where it starts is no arc (F.6.2; OpenSCAD's steps
     * come out of a NaN there, and it draws none) */
    if (x1 == x2 && y1 == y2)
        return 1;
    double cos_a = faithful_cos_deg(angle), sin_a = faithful_sin_deg(angle);
    double dx = (x1 - x2) / 2, dy = (y1 - y2) / 2;
    double x1_ = cos_a * dx + sin_a * dy, y1_ = -sin_a * dx + cos_a * dy;
    double d = (x1_ * x1_) / (rx * rx) + (y1_ * y1_) / (ry * ry);
    if (d > 1) {
        rx = fabs(sqrt(d) * rx);
        ry = fabs(sqrt(d) * ry);
    }
    double t1 = rx * rx * ry * ry - rx * rx * y1_ * y1_ - ry * ry * x1_ * x1_;
    double t2 = rx * rx * y1_ * y1_ + ry * ry * x1_ * x1_;
    if (t1 < 0)
        t1 = 0;
    double t3 = t2 > 0 ? sqrt(t1 / t2) : 0;
    if (large == sweep)
        t3 = -t3;
    double cx_ = t3 * rx * y1_ / ry, cy_ = t3 * -ry * x1_ / rx;
    double cx = cos_a * cx_ - sin_a * cy_ + (x1 + x2) / 2.0;
    double cy = sin_a * cx_ + cos_a * cy_ + (y1 + y2) / 2.0;
    double ux = (x1_ - cx_) / rx, uy = (y1_ - cy_) / ry;
    double vx = (-x1_ - cx_) / rx, vy = (-y1_ - cy_) / ry;
    double theta = vector_angle(1, 0, ux, uy);
    double delta = vector_angle(ux, uy, vx, vy);
    if (!sweep)
        delta -= 360;
    int steps = (int)(fabs(delta) * 10.0 / 180 + 4);
    for (int a = 0; a <= steps; ++a) {
        double phi = theta + delta * a / steps;
        double xx =
            cos_a * faithful_cos_deg(phi) * rx - sin_a * faithful_sin_deg(phi) * ry;
        double yy =
            sin_a * faithful_cos_deg(phi) * rx + cos_a * faithful_sin_deg(phi) * ry;
        if (!push(r, p, xx + cx, yy + cy))
            return 0;
    }
    return 1;
}

static int quad_to(reader *r, points *p, double x, double y, double cx, double cy,
                   double x2, double y2)
{
    for (int i = 1; i <= 20; i++) {
        double a = i * (1.0 / 20), t = 1 - a;
        if (!push(r, p, x * t * t + cx * 2 * t * a + x2 * a * a,
                  y * t * t + cy * 2 * t * a + y2 * a * a))
            return 0;
    }
    return 1;
}

static int cubic_to(reader *r, points *p, double x, double y, double cx1, double cy1,
                    double cx2, double cy2, double x2, double y2)
{
    for (int i = 1; i <= 20; i++) {
        double a = i * (1.0 / 20), t = 1 - a;
        if (!push(r, p,
                  x * t * t * t + cx1 * 3 * t * t * a + cx2 * 3 * t * a * a +
                      x2 * a * a * a,
                  y * t * t * t + cy1 * 3 * t * t * a + cy2 * 3 * t * a * a +
                      y2 * a * a * a))
            return 0;
    }
    return 1;
}

/* The tokens of a path's data, as OpenSCAD's tokenizer splits them:
 * separators ' ' and ',' dropped, '-' and the command letters kept as
 * tokens of their own, and a token with two dots or more split after
 * each part that follows a dot. */
typedef struct token {
    const char *s;
    size_t n;
} token;

static const char commands[] = "-zmlcqahvstZMLCQAHVST";

static int is_command(char c)
{
    return c && strchr(commands, c) != NULL;
}

/* Calls the path's state machine on each token; 0 on failure.
 *
 * A command's numbers fill its fields in order (command_fields) as they
 * come, as OpenSCAD's parser fills them, so a command cut short by the
 * next letter leaves what it read: S and T reflect the control point that
 * the last numbers read left behind. The last number completes the
 * command (complete_command); then the same letter repeats. */
typedef struct path_state {
    reader *r;
    const xml_element *e;
    twod_region *shape;
    const mat3 *m;
    points cur;
    double x, y, xx, yy, rx, ry, cx1, cy1, cx2, cy2, angle;
    double large, sweep; /* an arc's flags as read; set above 0.5 */
    int last_cubic, last_quad, point, negate, closed;
    char cmd;
    char exp[128];
    size_t exp_n;
} path_state;

/* Ends the current subpath: an open one is stroked, a closed one a ring. */
static int end_subpath(path_state *s, int may_stroke)
{
    int ok = 1;
    if (s->cur.count) {
        if (may_stroke && is_open(&s->cur))
            ok = stroke(s->r, s->e, s->shape, s->m, &s->cur);
        else
            ok = commit_path(s->r, s->shape, s->m, &s->cur);
    }
    s->cur.count = 0;
    return ok;
}

/* The fields the numbers of command c fill, in order, into field[]; their
 * count (0 for z, which takes none). xx and yy are the end point, made
 * absolute when the command completes. */
static int command_fields(path_state *s, char c, double **field)
{
    switch (tolower((unsigned char)c)) {
    case 'a':
        field[0] = &s->rx;
        field[1] = &s->ry;
        field[2] = &s->angle;
        field[3] = &s->large;
        field[4] = &s->sweep;
        field[5] = &s->xx;
        field[6] = &s->yy;
        return 7;
    case 'c':
        field[0] = &s->cx1;
        field[1] = &s->cy1;
        field[2] = &s->cx2;
        field[3] = &s->cy2;
        field[4] = &s->xx;
        field[5] = &s->yy;
        return 6;
    case 's':
        field[0] = &s->cx2;
        field[1] = &s->cy2;
        field[2] = &s->xx;
        field[3] = &s->yy;
        return 4;
    case 'q':
        field[0] = &s->cx1;
        field[1] = &s->cy1;
        field[2] = &s->xx;
        field[3] = &s->yy;
        return 4;
    case 'l':
    case 'm':
    case 't':
        field[0] = &s->xx;
        field[1] = &s->yy;
        return 2;
    case 'h':
        field[0] = &s->xx;
        return 1;
    case 'v':
        field[0] = &s->yy;
        return 1;
    default:
        return 0;
    }
}

/* Draws the command whose numbers are all read, from (x, y) to (xx, yy),
 * which becomes the current point; 0 on failure. */
static int complete_command(path_state *s, int rel)
{
    reader *r = s->r;
    points *cur = &s->cur;
    char c = (char)tolower((unsigned char)s->cmd);
    int ok = 1;
    if (c == 'h')
        s->yy = s->y;
    if (c == 'v')
        s->xx = s->x;
    if (rel) {
        if (c != 'v')
            s->xx += s->x;
        if (c != 'h')
            s->yy += s->y;
        if (c == 'c' || c == 'q') {
            s->cx1 += s->x;
            s->cy1 += s->y;
        }
        if (c == 'c' || c == 's') {
            s->cx2 += s->x;
            s->cy2 += s->y;
        }
    }
    switch (c) {
    case 'a':
        ok = arc_to(r, cur, s->x, s->y, fabs(s->rx), fabs(s->ry), s->xx, s->yy, s->angle,
                    s->large > 0.5, s->sweep > 0.5);
        break;
    case 'c':
    case 's':
        ok = cubic_to(r, cur, s->x, s->y, s->cx1, s->cy1, s->cx2, s->cy2, s->xx, s->yy);
        break;
    case 'q':
    case 't':
        ok = quad_to(r, cur, s->x, s->y, s->cx1, s->cy1, s->xx, s->yy);
        break;
    case 'm':
        s->cmd = rel ? 'l' : 'L';
        ok = end_subpath(s, 1) && push(r, cur, s->xx, s->yy);
        break;
    default: /* l, h, v */
        ok = push(r, cur, s->xx, s->yy);
        break;
    }
    s->x = s->xx;
    s->y = s->yy;
    s->point = -1;
    s->last_cubic = c == 'c' || c == 's';
    s->last_quad = c == 'q' || c == 't';
    return ok;
}

static int path_token(path_state *s, const char *v, size_t n)
{
    double p = 0;
    if (n == 1 && is_command(v[0])) {
        if (v[0] == '-') {
            s->negate = 1;
            return 1;
        }
        s->point = -1;
        s->cmd = v[0];
    } else {
        if (v[n - 1] == 'e') {
            size_t k = 0;
            if (s->negate && n + 1 < sizeof s->exp)
                s->exp[k++] = '-';
            if (k + n < sizeof s->exp) {
                memcpy(s->exp + k, v, n);
                k += n;
            }
            s->exp_n = k;
            s->negate = 0;
            return 1;
        }
        if (!s->exp_n) {
            p = whole_number(v, n);
            p = s->negate ? -p : p;
        } else {
            char buf[256];
            size_t k = s->exp_n;
            memcpy(buf, s->exp, k);
            if (s->negate)
                buf[k++] = '-';
            if (k + n < sizeof buf) {
                memcpy(buf + k, v, n);
                k += n;
            }
            p = whole_number(buf, k);
            s->exp_n = 0;
        }
        s->negate = 0;
    }
    int ok = 1;
    if (s->cmd == 'z' || s->cmd == 'Z') {
        /* on the letter and on every number after it */
        points *cur = &s->cur;
        if (cur->count) {
            double x0 = cur->xy[0], y0 = cur->xy[1];
            ok = push(s->r, cur, x0, y0) && end_subpath(s, 0);
            s->x = x0;
            s->y = y0;
        }
        s->closed = 1;
        s->last_cubic = s->last_quad = 0;
    } else if (s->point >= 0) {
        double *field[7];
        int count = command_fields(s, s->cmd, field);
        char c = (char)tolower((unsigned char)s->cmd);
        if (s->point == 0 && c == 's') {
            /* the first control point mirrors the last cubic's second */
            s->cx1 = s->last_cubic ? 2 * s->x - s->cx2 : s->x;
            s->cy1 = s->last_cubic ? 2 * s->y - s->cy2 : s->y;
        } else if (s->point == 0 && c == 't') {
            s->cx1 = s->last_quad ? 2 * s->x - s->cx1 : s->x;
            s->cy1 = s->last_quad ? 2 * s->y - s->cy1 : s->y;
        }
        if (s->point < count) {
            *field[s->point] = p;
            if (s->point == count - 1)
                ok = complete_command(s, islower((unsigned char)s->cmd));
        }
    }
    s->point++;
    return ok;
}

/* Splits one run between separators at its dots (OpenSCAD's split_dots)
 * and hands the parts to path_token. */
static int path_word(path_state *s, const char *v, size_t n)
{
    size_t dots = 0;
    for (size_t i = 0; i < n; i++)
        dots += v[i] == '.';
    if (dots < 2)
        return path_token(s, v, n);
    const char *text = v;
    int dot_seen = 0;
    for (size_t i = 0; i < n;) {
        size_t j = i;
        if (v[i] == '.')
            j++;
        else
            while (j < n && v[j] != '.')
                j++;
        if (v[i] == '.') {
            dot_seen = 1;
        } else if (dot_seen) {
            if (!path_token(s, text, (size_t)(v + j - text)))
                return 0;
            text = v + j;
        }
        i = j;
    }
    return 1;
}

static int read_path_data(reader *r, const xml_element *e, const char *d,
                          twod_region *shape, const mat3 *m)
{
    path_state s;
    memset(&s, 0, sizeof s);
    s.r = r;
    s.e = e;
    s.shape = shape;
    s.m = m;
    s.cmd = ' ';
    int ok = 1;
    for (const char *c = d; ok && *c;) {
        if (*c == ' ' || *c == ',') {
            c++;
            continue;
        }
        if (is_command(*c)) {
            ok = path_token(&s, c, 1);
            c++;
            continue;
        }
        const char *start = c;
        while (*c && *c != ' ' && *c != ',' && !is_command(*c))
            c++;
        ok = path_word(&s, start, (size_t)(c - start));
    }
    /* the last subpath: stroked when open, unless some subpath closed */
    if (ok)
        ok = end_subpath(&s, !s.closed);
    free(s.cur.xy);
    return ok;
}

/* ---- shapes ---- */

static int points_list(reader *r, const char *v, points *p)
{
    double x = 0;
    int first = 1;
    for (const char *c = v ? v : ""; *c;) {
        if (*c == ' ' || *c == ',') {
            c++;
            continue;
        }
        const char *start = c;
        while (*c && *c != ' ' && *c != ',')
            c++;
        double q = whole_number(start, (size_t)(c - start));
        if (first)
            x = q;
        else if (!push(r, p, x, q))
            return 0;
        first = !first;
    }
    return 1;
}

static int ellipse(reader *r, points *p, double x, double y, double rx, double ry)
{
    for (int i = 1; i <= 40; i++) {
        double a = i * 360.0 / 40;
        if (!push(r, p, rx * faithful_sin_deg(a) + x, ry * faithful_cos_deg(a) + y))
            return 0;
    }
    return 1;
}

static int rect(reader *r, const xml_element *e, twod_region *shape, const mat3 *m)
{
    double x = attr_number(e, "x"), y = attr_number(e, "y");
    double w = attr_number(e, "width"), h = attr_number(e, "height");
    double rx = attr_number(e, "rx"), ry = attr_number(e, "ry");
    int has_rx = !(fabs(rx) < 1e-8), has_ry = !(fabs(ry) < 1e-8);
    if (has_rx || has_ry) {
        if (!has_rx)
            rx = ry;
        else if (!has_ry)
            ry = rx;
        if (rx > w / 2)
            rx = w / 2;
        if (ry > h / 2)
            ry = h / 2;
        char d[1024];
        snprintf(d, sizeof d,
                 "M %g,%g H %g A %g,%g 0 0,1 %g,%g V %g A %g,%g 0 0,1 %g,%g H %g "
                 "A %g,%g 0 0,1 %g,%g V %g A %g,%g 0 0,1 %g,%g z",
                 x + rx, y, x + w - rx, rx, ry, x + w, y + ry, y + h - ry, rx, ry,
                 x + w - rx, y + h, x + rx, rx, ry, x, y + h - ry, y + ry, rx, ry, x + rx,
                 y);
        return read_path_data(r, e, d, shape, m);
    }
    points p = {NULL, 0, 0};
    int ok = push(r, &p, x, y) && push(r, &p, x + w, y) && push(r, &p, x + w, y + h) &&
             push(r, &p, x, y + h) && push(r, &p, x, y) && commit_path(r, shape, m, &p);
    free(p.xy);
    return ok;
}

/* The rings of the shape element e (of a kind that has some) into shape. */
static int shape_rings(reader *r, const xml_element *e, twod_region *shape, const mat3 *m)
{
    const char *name = e->name;
    points p = {NULL, 0, 0};
    int ok = 1;
    if (!strcmp(name, "path")) {
        const char *d = xml_attr_value(e, "d");
        return read_path_data(r, e, d ? d : "", shape, m);
    } else if (!strcmp(name, "rect")) {
        return rect(r, e, shape, m);
    } else if (!strcmp(name, "circle")) {
        double radius = attr_number(e, "r");
        ok = ellipse(r, &p, attr_number(e, "cx"), attr_number(e, "cy"), radius, radius) &&
             commit_path(r, shape, m, &p);
    } else if (!strcmp(name, "ellipse")) {
        ok = ellipse(r, &p, attr_number(e, "cx"), attr_number(e, "cy"),
                     attr_number(e, "rx"), attr_number(e, "ry")) &&
             commit_path(r, shape, m, &p);
    } else if (!strcmp(name, "line")) {
        ok = push(r, &p, attr_number(e, "x1"), attr_number(e, "y1")) &&
             push(r, &p, attr_number(e, "x2"), attr_number(e, "y2")) &&
             stroke(r, e, shape, m, &p);
    } else if (!strcmp(name, "polyline")) {
        ok = points_list(r, xml_attr_value(e, "points"), &p) &&
             (p.count == 0 || stroke(r, e, shape, m, &p));
    } else if (!strcmp(name, "polygon")) {
        ok = points_list(r, xml_attr_value(e, "points"), &p);
        if (ok && p.count)
            ok = push(r, &p, p.xy[0], p.xy[1]) && commit_path(r, shape, m, &p);
    }
    free(p.xy);
    return ok;
}

/* ---- transforms ---- */

/* The transform attribute's list of operations, composed in order (the
 * first outermost), as OpenSCAD reads them: an operation with the wrong
 * number of arguments is the identity; unknown words are skipped. */
static mat3 read_transform(const char *t)
{
    static const struct {
        const char *word;
        char op;
    } ops[] = {{"matrix", 'm'}, {"translate", 't'}, {"scale", 's'},
               {"rotate", 'r'}, {"skewX", 'x'},     {"skewY", 'y'}};
    mat3 total = identity;
    char op = 0;
    double args[8];
    int count = 0;
    for (const char *c = t;; c++) {
        int word = 0;
        size_t len = 0;
        for (size_t k = 0; *c && k < sizeof ops / sizeof ops[0]; k++) {
            len = strlen(ops[k].word);
            if (!strncmp(c, ops[k].word, len)) {
                word = ops[k].op;
                break;
            }
        }
        if (!word && *c && strchr("mtsrxy", *c)) /* a letter alone names one too */
            word = *c, len = 1;
        if (word || !*c) {
            if (op) {
                double *a = args;
                mat3 m = identity;
                if (op == 'm' && count == 6)
                    m = (mat3){a[0], a[1], a[2], a[3], a[4], a[5]};
                else if (op == 't' && (count == 1 || count == 2))
                    m.e = a[0], m.f = count > 1 ? a[1] : 0;
                else if (op == 's' && (count == 1 || count == 2))
                    m.a = a[0], m.d = count > 1 ? a[1] : a[0];
                else if (op == 'r' && (count == 1 || count == 3)) {
                    double cs = faithful_cos_deg(a[0]), sn = faithful_sin_deg(a[0]);
                    mat3 rot = {cs, sn, -sn, cs, 0, 0};
                    if (count == 3) {
                        mat3 to = {1, 0, 0, 1, a[1], a[2]},
                             from = {1, 0, 0, 1, -a[1], -a[2]};
                        rot = mat_mul(to, mat_mul(rot, from));
                    }
                    m = rot;
                } else if ((op == 'x' || op == 'y') && count == 1) {
                    double tn = faithful_sin_deg(a[0]) / faithful_cos_deg(a[0]);
                    if (op == 'x')
                        m.c = tn;
                    else
                        m.b = tn;
                }
                total = mat_mul(total, m);
            }
            if (!*c)
                break;
            op = (char)word;
            count = 0;
            c += len - 1;
            continue;
        }
        if (*c == ' ' || *c == ',' || *c == '(' || *c == ')')
            continue;
        const char *start = c;
        while (c[1] && !strchr(" ,()", c[1]) && !strchr("mtsrxy", c[1]))
            c++;
        if (count < 8)
            args[count] = whole_number(start, (size_t)(c + 1 - start));
        count++;
    }
    return total;
}

/* ---- the page ---- */

typedef enum unit {
    U_UNDEFINED,
    U_NONE,
    U_PX,
    U_PT,
    U_PC,
    U_IN,
    U_CM,
    U_MM,
    U_OTHER
} unit;

static const char *skip_space(const char *s)
{
    while (*s && isspace((unsigned char)*s))
        s++;
    return s;
}

/* OpenSCAD's parse_length: a number, then maybe a unit, spaces allowed
 * around them, and nothing else. */
static double read_length(const char *v, unit *u)
{
    *u = U_UNDEFINED;
    if (!v)
        return 0;
    const char *s = skip_space(v);
    size_t n = number_length(s);
    if (!n)
        return 0;
    double x = strtod(s, NULL);
    s = skip_space(s + n);
    static const struct {
        const char *name;
        unit u;
    } units[] = {{"em", U_OTHER}, {"ex", U_OTHER}, {"px", U_PX},
                 {"in", U_IN},    {"cm", U_CM},    {"mm", U_MM},
                 {"pt", U_PT},    {"pc", U_PC},    {"%", U_OTHER}};
    unit found = U_NONE;
    for (size_t k = 0; k < sizeof units / sizeof units[0]; k++) {
        size_t len = strlen(units[k].name);
        if (!strncmp(s, units[k].name, len)) {
            found = units[k].u;
            s += len;
            break;
        }
    }
    if (*skip_space(s))
        return 0;
    *u = found;
    return x;
}

static double to_mm(double x, unit u, double viewbox, int viewbox_valid, double dpi)
{
    switch (u) {
    case U_NONE:
        return 25.4 * x / dpi;
    case U_PX:
        return 25.4 * x / 96.0;
    case U_PT:
        return 25.4 * x / 72.0;
    case U_PC:
        return 25.4 * x / 6.0;
    case U_IN:
        return 25.4 * x;
    case U_CM:
        return 10 * x;
    case U_MM:
        return x;
    case U_UNDEFINED: /* the viewBox at the dpi (older Illustrator files) */
        return viewbox_valid ? 25.4 * viewbox / dpi : 0.0;
    default: /* em, ex, % */
        return viewbox_valid ? viewbox : 0.0;
    }
}

/* 4 numbers, each maybe followed by a comma, width and height >= 0. */
static int read_viewbox(const char *v, double box[4])
{
    if (!v)
        return 0;
    const char *s = v;
    for (int i = 0; i < 4; i++) {
        s = skip_space(s);
        size_t n = number_length(s);
        if (!n)
            return 0;
        box[i] = strtod(s, NULL);
        s = skip_space(s + n);
        if (i < 3 && *s == ',')
            s++;
    }
    return !*skip_space(s) && box[2] >= 0 && box[3] >= 0;
}

enum { ALIGN_NONE, ALIGN_MIN, ALIGN_MID, ALIGN_MAX };

/* preserveAspectRatio: [defer] align [meet | slice]; default xMidYMid
 * meet, and so when unreadable. */
static void read_alignment(const char *v, int *ax, int *ay, int *meet)
{
    *ax = *ay = ALIGN_MID;
    *meet = 1;
    if (!v)
        return;
    const char *s = skip_space(v);
    if (!strncmp(s, "defer", 5))
        s = skip_space(s + 5);
    static const char *const names[] = {"xMinYMin", "xMidYMin", "xMaxYMin",
                                        "xMinYMid", "xMidYMid", "xMaxYMid",
                                        "xMinYMax", "xMidYMax", "xMaxYMax"};
    int x = -1, y = -1;
    if (!strncmp(s, "none", 4)) {
        x = y = ALIGN_NONE;
        s += 4;
    } else {
        for (int k = 0; k < 9; k++)
            if (!strncmp(s, names[k], 8)) {
                x = ALIGN_MIN + k % 3;
                y = ALIGN_MIN + k / 3;
                s += 8;
                break;
            }
    }
    if (x < 0)
        return;
    s = skip_space(s);
    int m = 1, given = 0;
    if (!strncmp(s, "meet", 4))
        s += 4, given = 1;
    else if (!strncmp(s, "slice", 5))
        s += 5, m = 0, given = 1;
    if (*skip_space(s))
        return; /* not the whole value: the default */
    *ax = x;
    *ay = y;
    *meet = given ? m : 1;
}

static double alignment(int a, double page_mm, double scale, double viewbox)
{
    return a == ALIGN_MID   ? page_mm / 2.0 - scale * viewbox / 2.0
           : a == ALIGN_MAX ? page_mm - scale * viewbox
                            : 0.0;
}

static void read_page(reader *r, const xml_element *e, double dpi)
{
    unit wu, hu;
    double w = read_length(xml_attr_value(e, "width"), &wu);
    double h = read_length(xml_attr_value(e, "height"), &hu);
    double box[4] = {0, 0, 0, 0};
    int valid = read_viewbox(xml_attr_value(e, "viewBox"), box);
    double width_mm = to_mm(w, wu, box[2], valid, dpi);
    r->height_mm = to_mm(h, hu, box[3], valid, dpi);
    if (!valid)
        return;
    int ax, ay, meet;
    read_alignment(xml_attr_value(e, "preserveAspectRatio"), &ax, &ay, &meet);
    r->viewbox[0] = box[0];
    r->viewbox[1] = box[1];
    r->scale[0] = width_mm / box[2];
    r->scale[1] = r->height_mm / box[3];
    if (ax != ALIGN_NONE) {
        double s = meet ? fmin(r->scale[0], r->scale[1]) : fmax(r->scale[0], r->scale[1]);
        r->scale[0] = r->scale[1] = s;
        r->align[0] = alignment(ax, width_mm, s, box[2]);
        r->align[1] = alignment(ay, r->height_mm, s, box[3]);
    }
    r->blank |= !isfinite(r->scale[0]) || !isfinite(r->scale[1]);
}

/* ---- the walk ---- */

static int is_shape(const char *name)
{
    static const char *const names[] = {"path", "rect",     "circle", "ellipse",
                                        "line", "polyline", "polygon"};
    for (size_t k = 0; k < sizeof names / sizeof names[0]; k++)
        if (!strcmp(name, names[k]))
            return 1;
    return 0;
}

static int is_group(const char *name)
{
    return !strcmp(name, "g") || !strcmp(name, "text") || !strcmp(name, "tspan");
}

static int add_shape(reader *r, twod_region **out)
{
    if (r->shape_count == r->shape_cap) {
        size_t cap = r->shape_cap ? 2 * r->shape_cap : 64;
        twod_region **grown = realloc(r->shapes, cap * sizeof *grown);
        if (!grown)
            return 0;
        r->shapes = grown;
        r->shape_cap = cap;
    }
    twod_region *shape = malloc(sizeof *shape);
    if (!shape)
        return 0;
    twod_init(shape);
    r->shapes[r->shape_count++] = shape;
    *out = shape;
    return 1;
}

/* Visits e and its subtree; m is the transform of its nearest drawn
 * ancestor (groups and shapes), has_parent whether it has one (the page
 * does not, nor its transform count). */
static int visit(reader *r, const xml_element *e, const mat3 *m, int has_parent,
                 double dpi, int depth)
{
    if (depth > XML_MAX_DEPTH)
        return 1;
    const char *name = e->name;
    if (!strcmp(name, "defs"))
        return 1;
    mat3 own = *m;
    int known = 0;
    if (!strcmp(name, "svg")) {
        read_page(r, e, dpi);
        known = 1;
    } else if (is_group(name) || is_shape(name)) {
        known = 1;
        const char *t = xml_attr_value(e, "transform");
        if (has_parent && t)
            own = mat_mul(*m, read_transform(t));
    }
    if (is_shape(name)) {
        twod_region *shape;
        if (!add_shape(r, &shape)) {
            r->nomem = 1;
            return 0;
        }
        if (!shape_rings(r, e, shape, &own))
            return 0;
    }
    for (const xml_element *k = e->first_child; k; k = k->next)
        if (!visit(r, k, &own, has_parent || known, dpi, depth + 1))
            return 0;
    return 1;
}

static sc_status fail(reader *r, sc_status status, int line, const char *why)
{
    if (line > 0)
        return err_set(r->error, status, r->at, "import: %s:%d: %s", r->name, line, why);
    return err_set(r->error, status, r->at, "import: %s: %s", r->name, why);
}

sc_status svg_read(const char *text, size_t size, const char *name, const sc_location *at,
                   const svg_options *o, twod_region *out, svg_refused *refused_shapes,
                   sc_error *error)
{
    twod_clear(out);
    if (refused_shapes)
        refused_shapes->shapes = refused_shapes->first = 0;
    reader r;
    memset(&r, 0, sizeof r);
    r.name = name;
    r.at = at;
    r.error = error;
    r.scale[0] = r.scale[1] = 1;
    r.box[0] = r.box[1] = INFINITY;
    r.box[2] = r.box[3] = -INFINITY;
    xml_doc doc;
    char why[256];
    int line = 0;
    int code = xml_parse(text, size, &doc, why, sizeof why, &line);
    sc_status st = SC_OK;
    if (code != XML_OK) {
        st = fail(&r,
                  code == XML_ERR_NOMEM    ? SC_ERR_NOMEM
                  : code == XML_ERR_LIMIT  ? SC_ERR_LIMIT
                  : code == XML_ERR_PLUGIN ? SC_ERR_IO
                                           : SC_ERR_SYNTAX,
                  line, why);
    } else if (!visit(&r, doc.root, &identity, 0, o->dpi, 0)) {
        st = r.range ? fail(&r, SC_ERR_LIMIT, 0,
                            "coordinates out of range (or more than 10^7 points)")
                     : fail(&r, SC_ERR_NOMEM, 0, "out of memory");
    }
    xml_free(&doc);
    if (st == SC_OK && r.shape_count && !r.blank) {
        /* page units: x = scale (x - viewbox x) - cx, y = scale (-viewbox
         * y - y) + cy, OpenSCAD's formula (the viewBox's y enters with
         * the flip's sign) */
        int empty = r.box[0] > r.box[2];
        double cx = o->center ? (empty ? 0 : (r.box[0] + r.box[2]) / 2) : -r.align[0];
        double cy = o->center ? (empty ? 0 : (r.box[1] + r.box[3]) / 2)
                              : r.height_mm - r.align[1];
        for (size_t i = 0; i < r.shape_count && st == SC_OK; i++) {
            twod_region *shape = r.shapes[i];
            for (uint32_t k = 0; k < shape->point_count; k++) {
                double *p = shape->xy + 2 * k;
                p[0] = r.scale[0] * (-r.viewbox[0] + p[0]) - cx;
                p[1] = r.scale[1] * (-r.viewbox[1] - p[1]) + cy;
                if (!isfinite(p[0]) || !isfinite(p[1])) {
                    st = fail(&r, SC_ERR_LIMIT, 0,
                              "the page's scale makes coordinates out of range");
                    break;
                }
            }
        }
        /* OpenSCAD sanitizes each shape, where its clipper refuses an
         * outline past its range with those after it */
        for (size_t i = 0; i < r.shape_count && st == SC_OK; i++) {
            r.shapes[i]->sanitized = 0;
            long refused = twod_clipper_admit(r.shapes[i]);
            if (refused < 0)
                st = fail(&r, SC_ERR_NOMEM, 0, "out of memory");
            else if (refused > 0 && refused_shapes && !refused_shapes->shapes++)
                refused_shapes->first = (uint32_t)i + 1;
        }
        if (st == SC_OK) {
            int clip =
                twod_clip_apply(r.shapes, (uint32_t)r.shape_count, TWOD_UNION, out);
            if (clip == TWOD_CLIP_NOMEM)
                st = fail(&r, SC_ERR_NOMEM, 0, "out of memory");
            else if (clip != TWOD_CLIP_OK)
                st =
                    fail(&r, SC_ERR_LIMIT, 0, "the drawing is too large for the clipper");
        }
    }
    for (size_t i = 0; i < r.shape_count; i++) {
        twod_free(r.shapes[i]);
        free(r.shapes[i]);
    }
    free(r.shapes);
    return st;
}

sc_status svg_read_file(const char *path, const char *name, const sc_location *at,
                        const svg_options *o, twod_region *out, svg_refused *refused,
                        sc_error *error)
{
    if (refused)
        refused->shapes = refused->first = 0;
    FILE *f = fopen(path, "rb");
    if (!f)
        return err_set(error, SC_ERR_IO, at, "import: %s: cannot open: %s", name,
                       strerror(errno));
    char *text = malloc(SVG_MAX_FILE + 1);
    if (!text) {
        fclose(f);
        return err_nomem(error, at);
    }
    size_t size = fread(text, 1, SVG_MAX_FILE + 1, f);
    int bad = ferror(f);
    fclose(f);
    sc_status st;
    if (bad)
        st = err_set(error, SC_ERR_IO, at, "import: %s: read error", name);
    else if (size > SVG_MAX_FILE)
        st = err_set(error, SC_ERR_LIMIT, at,
                     "import: %s: file too large (limit is %u MiB)", name,
                     SVG_MAX_FILE / (1024u * 1024u));
    else
        st = svg_read(text, size, name, at, o, out, refused, error);
    free(text);
    return st;
}
