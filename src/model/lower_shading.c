/* Lowering of spancast's shading nodes: light(), material(), camera() and
 * background() (model.h; the grammar is in build/build_shading.h). Every
 * argument is read and checked here, the checks that take several
 * arguments too (a light needs a position or a direction, reflect +
 * transmit at most 1), with the rules and messages of the other nodes:
 * unknown arguments are ignored, the last of repeated ones wins, a value of
 * the wrong type is "wrong type for argument 'x' of 'y' (expected ...)" at
 * the value, a value out of range is an error at the value too ("argument
 * 'ior' of 'material' must be positive"). The builder only places what is
 * read here (a light through its transforms) where the node is built.
 */
#include "model/lower_shading.h"

#include <math.h>
#include <string.h>

#include "base/error.h"
#include "model/args.h"
#include "model/colors.h"

/* The node being read, and where errors go. */
typedef struct reader {
    model_reader at;
    const parse_node *n;
    sc_error *error;
} reader;

static const parse_value *value_of(const reader *r, const char *name)
{
    return model_arg(r->n, name, -1);
}

static sc_location loc_of(const reader *r, const parse_value *v)
{
    return model_loc(&r->at, v);
}

static sc_status wrong_type(const reader *r, const char *name, const parse_value *v,
                            const char *expected)
{
    return model_wrong_type(&r->at, r->n, name, v, expected);
}

/* A finite number within [lo, hi] (what names the range in messages). */
static sc_status number(const reader *r, const char *name, double lo, double hi,
                        const char *what, double *out)
{
    const parse_value *v = value_of(r, name);
    if (!v)
        return SC_OK;
    if (v->kind != PARSE_NUMBER)
        return wrong_type(r, name, v, "a number");
    double x = v->u.number;
    if (!(x >= lo && x <= hi)) {
        sc_location loc = loc_of(r, v);
        return err_set(r->error, SC_ERR_SEMANTIC, &loc,
                       "argument '%s' of '%s' must be %s", name, r->n->name, what);
    }
    *out = x;
    return SC_OK;
}

/* A vector of 3 finite numbers; *given says whether it was there. */
static sc_status vector3(const reader *r, const char *name, vec3 *out, int *given)
{
    static const char expected[] = "a vector of 3 numbers";
    const parse_value *v = value_of(r, name);
    *given = 0;
    if (!v)
        return SC_OK;
    if (v->kind != PARSE_VECTOR || v->u.vector.count != 3)
        return wrong_type(r, name, v, expected);
    double c[3];
    for (int k = 0; k < 3; k++) {
        const parse_value *item = &v->u.vector.items[k];
        if (item->kind != PARSE_NUMBER || !isfinite(item->u.number))
            return wrong_type(r, name, item, expected);
        c[k] = item->u.number;
    }
    *out = v3(c[0], c[1], c[2]);
    *given = 1;
    return SC_OK;
}

/* A vector of 2 positive finite numbers; *given says whether it was there. */
static sc_status size2(const reader *r, const char *name, double out[2], int *given)
{
    static const char expected[] = "a vector of 2 positive numbers";
    const parse_value *v = value_of(r, name);
    *given = 0;
    if (!v)
        return SC_OK;
    if (v->kind != PARSE_VECTOR || v->u.vector.count != 2)
        return wrong_type(r, name, v, expected);
    for (int k = 0; k < 2; k++) {
        const parse_value *item = &v->u.vector.items[k];
        if (item->kind != PARSE_NUMBER || !(item->u.number > 0) ||
            !isfinite(item->u.number))
            return wrong_type(r, name, item, expected);
        out[k] = item->u.number;
    }
    *given = 1;
    return SC_OK;
}

/* A colour: [r, g, b] or [r, g, b, a] with components in 0..1, or an
 * OpenSCAD colour name. Alpha is read and dropped. */
static sc_status colour(const reader *r, const char *name, float out[3], int *given)
{
    static const char expected[] = "a vector of 3 or 4 numbers in 0..1 or a colour name";
    const parse_value *v = value_of(r, name);
    *given = 0;
    if (!v)
        return SC_OK;
    float rgba[4];
    if (v->kind == PARSE_STRING) {
        if (!colors_lookup(v->u.string.chars, v->u.string.length, rgba)) {
            sc_location loc = loc_of(r, v);
            return err_set(r->error, SC_ERR_SEMANTIC, &loc, "unknown colour '%s'",
                           v->u.string.chars);
        }
    } else {
        if (v->kind != PARSE_VECTOR || v->u.vector.count < 3 || v->u.vector.count > 4)
            return wrong_type(r, name, v, expected);
        for (uint32_t k = 0; k < v->u.vector.count; k++) {
            const parse_value *item = &v->u.vector.items[k];
            if (item->kind != PARSE_NUMBER ||
                !(item->u.number >= 0 && item->u.number <= 1))
                return wrong_type(r, name, item, expected);
            rgba[k] = (float)item->u.number;
        }
    }
    memcpy(out, rgba, 3 * sizeof(float));
    *given = 1;
    return SC_OK;
}

/* An error at the value of argument name (which is given). */
static sc_status bad_value(const reader *r, const char *name, const char *message)
{
    sc_location loc = loc_of(r, value_of(r, name));
    return err_set(r->error, SC_ERR_SEMANTIC, &loc, "%s", message);
}

static sc_status no_children(const reader *r)
{
    if (r->n->child_count == 0)
        return SC_OK;
    return err_set(r->error, SC_ERR_SEMANTIC, &r->n->loc, "'%s' takes no children",
                   r->n->name);
}

/* The frame of a rectangular light of size w x h facing along normal, its
 * height along up projected onto its plane (see shading.h). Returns 0 when
 * up is parallel to the normal. */
static int rect_frame(shading_light *light, vec3 normal, vec3 up, const double size[2])
{
    vec3 n = v3_normalize(normal);
    vec3 v = v3_sub(up, v3_scale(n, v3_dot(up, n)));
    if (!(v3_length(v) > 1e-9 * v3_length(up)))
        return 0;
    v = v3_normalize(v);
    vec3 w = v3_cross(v, n); /* right, for a viewer facing the lit side */
    light->normal = n;
    light->half_width = v3_scale(w, size[0] / 2);
    light->half_height = v3_scale(v, size[1] / 2);
    return 1;
}

sc_status model_read_light(const model_reader *at, const parse_node *n,
                           shading_light *out)
{
    sc_error *error = at->error;
    reader r = {*at, n, error};
    shading_light light;
    memset(&light, 0, sizeof light);
    light.color[0] = light.color[1] = light.color[2] = 1;
    light.intensity = 1;
    vec3 position = v3(0, 0, 0), direction = v3(0, 0, 0);
    vec3 normal = v3(0, 0, -1), up = v3(0, 0, 1);
    double size[2] = {0, 0};
    int has_position, has_direction, has_color, has_size, has_normal, has_up;
    sc_status st = no_children(&r);
    if (!st)
        st = vector3(&r, "position", &position, &has_position);
    if (!st)
        st = vector3(&r, "direction", &direction, &has_direction);
    if (!st)
        st = colour(&r, "color", light.color, &has_color);
    if (!st)
        st = number(&r, "intensity", 0, HUGE_VAL, "a non-negative number",
                    &light.intensity);
    if (!st)
        st = number(&r, "radius", 0, HUGE_VAL, "a non-negative number", &light.radius);
    if (!st)
        st = size2(&r, "size", size, &has_size);
    if (!st)
        st = vector3(&r, "normal", &normal, &has_normal);
    if (!st)
        st = vector3(&r, "up", &up, &has_up);
    if (st)
        return st;
    if (has_position == has_direction)
        return err_set(error, SC_ERR_SEMANTIC, &n->loc,
                       "'light' needs either position or direction");
    if (has_direction && !(v3_length(direction) > 0))
        return bad_value(&r, "direction",
                         "argument 'direction' of 'light' must not be zero");
    if (has_direction && light.radius > 0)
        return bad_value(&r, "radius", "a directional light has no radius");
    if (!has_size && (has_normal || has_up))
        return bad_value(&r, has_normal ? "normal" : "up",
                         "only a light with a size has a normal and an up direction");
    if (has_size && has_direction)
        return bad_value(&r, "size", "a directional light has no size");
    if (has_size && light.radius > 0)
        return bad_value(&r, "size", "a light has a radius or a size, not both");
    if (has_normal && !(v3_length(normal) > 0))
        return bad_value(&r, "normal", "argument 'normal' of 'light' must not be zero");
    if (has_size && !has_up && fabs(v3_normalize(normal).z) > 1 - 1e-12)
        up = v3(0, 1, 0); /* a light facing up or down: its height along +y */
    if (has_position) {
        light.kind = SHADING_LIGHT_POINT;
        light.position = position;
    } else {
        light.kind = SHADING_LIGHT_DIRECTIONAL;
        light.direction = direction;
    }
    if (has_size) {
        light.kind = SHADING_LIGHT_RECT;
        if (!rect_frame(&light, normal, up, size))
            return bad_value(&r, has_up ? "up" : "normal",
                             "the up direction of a light must not be parallel to its "
                             "normal");
    }
    *out = light;
    return SC_OK;
}

sc_status model_read_camera(const model_reader *at, const parse_node *n,
                            shading_camera *out)
{
    sc_error *error = at->error;
    reader r = {*at, n, error};
    shading_camera cam;
    memset(&cam, 0, sizeof cam);
    vec3 eye, center, up = v3(0, 0, 1);
    int has_eye, has_center, has_up;
    cam.fov_deg = 22.5;
    cam.projection = SC_PROJECTION_PERSPECTIVE;
    sc_status st = no_children(&r);
    if (!st)
        st = vector3(&r, "eye", &eye, &has_eye);
    if (!st)
        st = vector3(&r, "center", &center, &has_center);
    if (!st)
        st = vector3(&r, "up", &up, &has_up);
    if (!st)
        st = number(&r, "fov", 1e-6, 180 - 1e-6, "between 0 and 180 degrees",
                    &cam.fov_deg);
    if (!st)
        st = number(&r, "aperture", 0, HUGE_VAL, "a non-negative number", &cam.aperture);
    if (!st)
        st = number(&r, "focus", 0, HUGE_VAL, "a positive number", &cam.focus);
    if (st)
        return st;
    const parse_value *p = value_of(&r, "projection");
    if (p) {
        if (p->kind != PARSE_STRING)
            return wrong_type(&r, "projection", p, "\"perspective\" or \"orthographic\"");
        if (!strcmp(p->u.string.chars, "orthographic"))
            cam.projection = SC_PROJECTION_ORTHOGRAPHIC;
        else if (strcmp(p->u.string.chars, "perspective"))
            return wrong_type(&r, "projection", p, "\"perspective\" or \"orthographic\"");
    }
    if (value_of(&r, "focus") && !(cam.focus > 0))
        return bad_value(&r, "focus",
                         "argument 'focus' of 'camera' must be a positive "
                         "number");
    if (!has_eye || !has_center)
        return err_set(error, SC_ERR_SEMANTIC, &n->loc, "'camera' needs eye and center");
    if (v3_length(v3_sub(center, eye)) == 0)
        return err_set(error, SC_ERR_SEMANTIC, &n->loc,
                       "camera eye and centre are the same point");
    if (!(v3_length(up) > 0))
        return bad_value(&r, "up", "argument 'up' of 'camera' must not be zero");
    cam.eye[0] = eye.x, cam.eye[1] = eye.y, cam.eye[2] = eye.z;
    cam.center[0] = center.x, cam.center[1] = center.y, cam.center[2] = center.z;
    cam.up[0] = up.x, cam.up[1] = up.y, cam.up[2] = up.z;
    *out = cam;
    return SC_OK;
}

sc_status model_read_background(const model_reader *at, const parse_node *n, float c[3])
{
    sc_error *error = at->error;
    reader r = {*at, n, error};
    int given;
    sc_status st = no_children(&r);
    if (!st)
        st = colour(&r, "color", c, &given);
    if (st)
        return st;
    if (!given)
        return err_set(error, SC_ERR_SEMANTIC, &n->loc, "'background' needs a color");
    return SC_OK;
}

sc_status model_read_material(const model_reader *at, const parse_node *n,
                              model_material *out)
{
    sc_error *error = at->error;
    reader r = {*at, n, error};
    shading_material m = shading_default_material();
    float *base = out->color;
    int has_color, has_color2;
    const char *unit = "a number in 0..1";
    const char *positive = "a positive number";
    sc_status st = colour(&r, "color", base, &has_color);
    if (!st)
        st = number(&r, "ambient", 0, 1, unit, &m.ambient);
    if (!st)
        st = number(&r, "diffuse", 0, 1, unit, &m.diffuse);
    if (!st)
        st = number(&r, "specular", 0, 1, unit, &m.specular);
    if (!st)
        st = number(&r, "shininess", 0, 1e6, "a number in 0..1e6", &m.shininess);
    if (!st)
        st = number(&r, "reflect", 0, 1, unit, &m.reflect);
    if (!st)
        st = number(&r, "transmit", 0, 1, unit, &m.transmit);
    if (!st)
        st = number(&r, "ior", 1e-3, 1e3, "a positive number up to 1000", &m.ior);
    if (!st)
        st = number(&r, "checker", 0, HUGE_VAL, positive, &m.checker);
    if (!st)
        st = colour(&r, "color2", m.color2, &has_color2);
    if (!st)
        st = number(&r, "roughness", 0, 1, unit, &m.roughness);
    if (st)
        return st;
    if (value_of(&r, "checker") && !(m.checker > 0))
        return bad_value(&r, "checker",
                         "argument 'checker' of 'material' must be a positive number");
    if (m.reflect + m.transmit > 1)
        return err_set(error, SC_ERR_SEMANTIC, &n->loc,
                       "'material': reflect + transmit must not exceed 1");
    out->material = m;
    out->has_color = has_color;
    return SC_OK;
}
