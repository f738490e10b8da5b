/* The camera: OpenSCAD's camera forms turned into rays (see camera.h and
 * docs/camera.md).
 *
 * OpenSCAD 2021.01 places its camera with a fixed-function OpenGL modelview
 * M = LookAt(eye (0, -d, 0), centre 0, up +z) * Rx(90 - rx) * Ry(-ry) *
 * Rz(-rz) * T(-vpt) (Camera::setVpr stores the negated angles and
 * GLView::setupCamera applies them in that order). Undoing it, the world
 * camera has centre vpt, forward R (0, 1, 0), up R (0, 0, 1) and eye
 * vpt - d R (0, 1, 0), with R = Rz(rz) Ry(ry) Rx(rx - 90). Its 6-value form
 * derives the same angles from eye and centre (ry = 0), which amounts to
 * looking from eye to centre with +z up; for a vertical view OpenSCAD picks
 * rz = 0 looking down and rz = 180 looking up, the same image the
 * contract's fallback (right = f x y) gives.
 */
#include "render/camera.h"

#include <string.h>

#include "base/error.h"

/* ---- exact degree trigonometry ---- */

/* deg reduced to [0, 360). */
static double reduce_degrees(double deg)
{
    double x = fmod(deg, 360.0);
    if (x < 0)
        x += 360.0;
    if (x >= 360.0) /* -tiny + 360 rounds to 360 */
        x = 0.0;
    return x;
}

static double radians(double deg)
{
    return deg * (3.14159265358979323846 / 180.0);
}

/* The foldings below (360 - x, 180 - x, 90 - x, x - 180 within their ranges)
 * are exact by Sterbenz's lemma, so the result is symmetric around every
 * multiple of 90 degrees, exact at them and at 30 and 60 degrees, and
 * sin 45 = cos 45. */
double cam_sin_deg(double deg)
{
    if (!isfinite(deg))
        return NAN;
    double x = reduce_degrees(deg), sign = 1.0;
    if (x >= 180.0) {
        x -= 180.0;
        sign = -1.0;
    }
    if (x > 90.0)
        x = 180.0 - x;
    if (x == 0.0)
        return 0.0;
    if (x == 90.0)
        return sign;
    if (x == 30.0)
        return 0.5 * sign;
    if (x == 45.0)
        return sqrt(0.5) * sign;
    return sign * (x > 45.0 ? cos(radians(90.0 - x)) : sin(radians(x)));
}

double cam_cos_deg(double deg)
{
    if (!isfinite(deg))
        return NAN;
    double x = reduce_degrees(deg), sign = 1.0;
    if (x > 180.0)
        x = 360.0 - x;
    if (x > 90.0) {
        x = 180.0 - x;
        sign = -1.0;
    }
    if (x == 90.0)
        return 0.0;
    if (x == 0.0)
        return sign;
    if (x == 60.0)
        return 0.5 * sign;
    if (x == 45.0)
        return sqrt(0.5) * sign;
    return sign * (x > 45.0 ? sin(radians(90.0 - x)) : cos(radians(x)));
}

/* ---- views ---- */

static int all_finite(const double *p, int n)
{
    for (int k = 0; k < n; k++)
        if (!isfinite(p[k]))
            return 0;
    return 1;
}

sc_status cam_view_lookat(const double p[6], cam_view *view, sc_error *error)
{
    if (!all_finite(p, 6))
        return err_set(error, SC_ERR_ARGUMENT, NULL, "camera values must be finite");
    vec3 eye = v3(p[0], p[1], p[2]), center = v3(p[3], p[4], p[5]);
    vec3 dir = v3_sub(center, eye);
    double len = v3_length(dir);
    if (!(len > 0) || !isfinite(len))
        return err_set(error, SC_ERR_ARGUMENT, NULL,
                       "camera eye and centre are the same point");
    view->center = center;
    view->forward = v3_scale(dir, 1.0 / len);
    view->distance = len;
    view->up = v3(0, 0, 1);
    return SC_OK;
}

/* R = Rz(rz) Ry(ry) Rx(rx - 90) applied to v, with the identities
 * cos(rx - 90) = sin rx and sin(rx - 90) = -cos rx. */
static vec3 gimbal_rotate(double rx, double ry, double rz, vec3 v)
{
    double sx = cam_sin_deg(rx), cx = cam_cos_deg(rx);
    double sy = cam_sin_deg(ry), cy = cam_cos_deg(ry);
    double sz = cam_sin_deg(rz), cz = cam_cos_deg(rz);
    /* Rx(rx - 90): y' = y sx + z cx, z' = -y cx + z sx */
    vec3 a = v3(v.x, v.y * sx + v.z * cx, -v.y * cx + v.z * sx);
    /* Ry(ry): x' = x cy + z sy, z' = -x sy + z cy */
    vec3 b = v3(a.x * cy + a.z * sy, a.y, -a.x * sy + a.z * cy);
    /* Rz(rz): x' = x cz - y sz, y' = x sz + y cz */
    return v3(b.x * cz - b.y * sz, b.x * sz + b.y * cz, b.z);
}

sc_status cam_view_gimbal(const double p[7], cam_view *view, sc_error *error)
{
    if (!all_finite(p, 7))
        return err_set(error, SC_ERR_ARGUMENT, NULL, "camera values must be finite");
    view->center = v3(p[0], p[1], p[2]);
    view->forward = gimbal_rotate(p[3], p[4], p[5], v3(0, 1, 0));
    view->up = gimbal_rotate(p[3], p[4], p[5], v3(0, 0, 1));
    view->distance = p[6];
    return SC_OK;
}

void cam_view_all(cam_view *view, const bbox *bounds, int autocenter, double fov_deg)
{
    if (bbox_is_empty(bounds)) {
        view->center = v3(0, 0, 0);
        view->distance = CAM_DEFAULT_DISTANCE;
        return;
    }
    vec3 box_center = bbox_center(bounds);
    if (autocenter)
        view->center = box_center;
    double half_diagonal = v3_length(bbox_extent(bounds)) / 2;
    double radius = v3_length(v3_sub(box_center, view->center)) + half_diagonal;
    double distance = radius / cam_sin_deg(fov_deg / 2);
    /* A box shrunk to a point would put the eye on the centre. */
    view->distance = distance > 0 && isfinite(distance) ? distance : CAM_DEFAULT_DISTANCE;
}

static sc_status check_fov(double fov_deg, sc_error *error)
{
    if (!(fov_deg > 0 && fov_deg < 180))
        return err_set(error, SC_ERR_ARGUMENT, NULL,
                       "field of view must be between 0 and 180 degrees (got %g)",
                       fov_deg);
    return SC_OK;
}

sc_status cam_view_from_options(const sc_render_options *options, const bbox *bounds,
                                cam_view *view, sc_error *error)
{
    sc_status st = check_fov(options->fov_deg, error);
    if (st)
        return st;
    int viewall = options->viewall, autocenter = options->autocenter;
    switch (options->camera_mode) {
    case SC_CAMERA_VECTOR: {
        st = cam_view_lookat(options->camera, view, error);
        vec3 up = v3(options->up[0], options->up[1], options->up[2]);
        if (!st && v3_is_finite(up) && v3_length(up) > 0)
            view->up = v3_normalize(up); /* a camera() node's up; +z by default */
        break;
    }
    case SC_CAMERA_GIMBAL:
        st = cam_view_gimbal(options->camera, view, error);
        break;
    case SC_CAMERA_AUTO: {
        const double p[7] = {0,
                             0,
                             0,
                             CAM_DEFAULT_RX,
                             CAM_DEFAULT_RY,
                             CAM_DEFAULT_RZ,
                             CAM_DEFAULT_DISTANCE};
        st = cam_view_gimbal(p, view, error);
        viewall = autocenter = 1;
        break;
    }
    default:
        return err_set(error, SC_ERR_ARGUMENT, NULL, "unknown camera mode %d",
                       (int)options->camera_mode);
    }
    if (st)
        return st;
    if (viewall)
        cam_view_all(view, bounds, autocenter, options->fov_deg);
    return SC_OK;
}

/* ---- cameras and rays ---- */

sc_status cam_init(camera *cam, const cam_view *view, double fov_deg,
                   sc_projection projection, int width, int height, sc_error *error)
{
    if (width <= 0 || height <= 0)
        return err_set(error, SC_ERR_ARGUMENT, NULL,
                       "image size must be positive (got %dx%d)", width, height);
    sc_status st = check_fov(fov_deg, error);
    if (st)
        return st;
    if (projection != SC_PROJECTION_PERSPECTIVE &&
        projection != SC_PROJECTION_ORTHOGRAPHIC)
        return err_set(error, SC_ERR_ARGUMENT, NULL, "unknown projection %d",
                       (int)projection);
    if (!(view->distance > 0))
        return err_set(error, SC_ERR_ARGUMENT, NULL,
                       "camera distance must be positive (got %g)", view->distance);
    vec3 eye = v3_madd(view->center, view->forward, -view->distance);
    vec3 dir = v3_sub(view->center, eye);
    double len = v3_length(dir);
    if (!v3_is_finite(eye) || !(len > 0) || !isfinite(len))
        return err_set(error, SC_ERR_ARGUMENT, NULL,
                       "camera eye and centre are the same point");
    vec3 f = v3_scale(dir, 1.0 / len);
    vec3 side = v3_cross(f, view->up);
    if (v3_length(side) == 0) /* looking along the up hint */
        side = v3_cross(f, v3(0, 1, 0));
    if (v3_length(side) == 0) /* only with an up hint parallel to y */
        side = v3_cross(f, v3(1, 0, 0));
    vec3 r = v3_normalize(side);
    cam->eye = eye;
    cam->center = view->center;
    cam->f = f;
    cam->r = r;
    cam->u = v3_cross(r, f);
    cam->a = tan(radians(fov_deg / 2));
    cam->aspect = (double)width / (double)height;
    cam->distance = len;
    cam->width = width;
    cam->height = height;
    cam->projection = projection;
    cam->lens_radius = 0;
    cam->focus = len;
    return SC_OK;
}

sc_status cam_set_lens(camera *cam, double aperture, double focus, sc_error *error)
{
    if (!(aperture >= 0 && isfinite(aperture)))
        return err_set(error, SC_ERR_ARGUMENT, NULL,
                       "aperture must be a non-negative width (got %g)", aperture);
    if (!(focus >= 0 && isfinite(focus)))
        return err_set(error, SC_ERR_ARGUMENT, NULL,
                       "focus distance must be positive (got %g)", focus);
    cam->lens_radius = aperture / 2;
    cam->focus = focus > 0 ? focus : cam->distance;
    return SC_OK;
}

void cam_lens_ray(const camera *cam, double lx, double ly, vec3 *origin, vec3 *direction)
{
    if (!(cam->lens_radius > 0))
        return;
    vec3 shift =
        v3_madd(v3_scale(cam->r, lx * cam->lens_radius), cam->u, ly * cam->lens_radius);
    *origin = v3_add(*origin, shift);
    *direction = v3_madd(*direction, shift, -1 / cam->focus);
}

void cam_ray(const camera *cam, int i, int j, double sx, double sy, vec3 *origin,
             vec3 *direction)
{
    double x = (2.0 * (i + sx) / cam->width - 1.0) * cam->a * cam->aspect;
    double y = (1.0 - 2.0 * (j + sy) / cam->height) * cam->a;
    vec3 offset = v3_add(v3_scale(cam->r, x), v3_scale(cam->u, y));
    if (cam->projection == SC_PROJECTION_ORTHOGRAPHIC) {
        *origin = v3_madd(cam->eye, offset, cam->distance);
        *direction = cam->f;
    } else {
        *origin = cam->eye;
        *direction = v3_add(cam->f, offset);
    }
}

/* OpenSCAD's View menu (MainWindow::viewAngle*, 2021.01) sets the view's
 * object rotation; as $vpr (Camera::getVpr: 90 - x, -y, -z, wrapped) that
 * is: */
static const struct preset_entry {
    const char *name;
    double rotation[3];
} presets[] = {
    [SC_VIEW_PRESET_TOP] = {"top", {0, 0, 0}},
    [SC_VIEW_PRESET_BOTTOM] = {"bottom", {180, 0, 0}},
    [SC_VIEW_PRESET_LEFT] = {"left", {90, 0, 270}},
    [SC_VIEW_PRESET_RIGHT] = {"right", {90, 0, 90}},
    [SC_VIEW_PRESET_FRONT] = {"front", {90, 0, 0}},
    [SC_VIEW_PRESET_BACK] = {"back", {90, 0, 180}},
    [SC_VIEW_PRESET_DIAGONAL] = {"diagonal", {55, 0, 25}},
};
enum { PRESET_COUNT = sizeof presets / sizeof presets[0] };

const char *sc_view_preset_name(sc_view_preset preset)
{
    return preset > SC_VIEW_PRESET_NONE && (int)preset < PRESET_COUNT
               ? presets[preset].name
               : NULL;
}

sc_view_preset sc_view_preset_from_name(const char *name)
{
    for (int k = 1; name && k < PRESET_COUNT; k++)
        if (!strcmp(presets[k].name, name))
            return (sc_view_preset)k;
    return SC_VIEW_PRESET_NONE;
}

int sc_view_preset_rotation(sc_view_preset preset, double rotation[3])
{
    if (!sc_view_preset_name(preset))
        return 0;
    memcpy(rotation, presets[preset].rotation, 3 * sizeof *rotation);
    return 1;
}
