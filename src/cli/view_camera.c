/* The viewer's camera: OpenSCAD's gimbal camera and OpenSCAD's mouse.
 *
 * The state is the very numbers `render --camera=TX,TY,TZ,RX,RY,RZ,D`
 * reads: the centre looked at (OpenSCAD's $vpt), the rotation in degrees
 * ($vpr) and the distance ($vpd). The render camera (src/render/camera.c)
 * looks along R (0, 1, 0) with up R (0, 0, 1), R = Rz(rz) Ry(ry) Rx(rx -
 * 90); so with ry = 0 the forward vector is (-sin rz sin rx, cos rz sin rx,
 * -cos rx), which view_camera_reset inverts for a file's eye-and-centre
 * camera.
 *
 * The mouse follows OpenSCAD 2021.01's QGLView::mouseMoveEvent, whose
 * object_rot is (90 - rx, -ry, -rz) and object_trans is -centre: a drag
 * of (dx, dy) pixels is scaled by 0.7; the left button turns rx by -dy and
 * rz by -dx (ry with shift); the right button moves the centre by -(mx
 * right + mz up), mx = 3 dx d / width, mz = -3 dy d / height, right and up
 * being the camera's; shift-right zooms by -12 dy. Camera::zoom multiplies
 * the distance by 0.9 per notch of 120. The standard views are the
 * renderer's presets (sc_view_preset_rotation), MainWindow's object_rot
 * values in these terms.
 */
#include "cli/view.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static const double pi = 3.14159265358979323846;

static double radians(double deg)
{
    return deg * (pi / 180.0);
}

/* deg in [0, 360). */
static double wrap_degrees(double deg)
{
    double x = fmod(deg, 360.0);
    if (x < 0)
        x += 360.0;
    return x >= 360.0 ? 0.0 : x;
}

/* R v with R = Rz(rz) Ry(ry) Rx(rx - 90), as the render camera builds it. */
static void gimbal_rotate(const double rot[3], const double v[3], double out[3])
{
    double sx = sin(radians(rot[0])), cx = cos(radians(rot[0]));
    double sy = sin(radians(rot[1])), cy = cos(radians(rot[1]));
    double sz = sin(radians(rot[2])), cz = cos(radians(rot[2]));
    /* Rx(rx - 90): cos(rx - 90) = sin rx, sin(rx - 90) = -cos rx */
    double a[3] = {v[0], v[1] * sx + v[2] * cx, -v[1] * cx + v[2] * sx};
    double b[3] = {a[0] * cy + a[2] * sy, a[1], -a[0] * sy + a[2] * cy};
    out[0] = b[0] * cz - b[1] * sz;
    out[1] = b[0] * sz + b[1] * cz;
    out[2] = b[2];
}

void view_camera_view_all(view_camera *cam, const sc_scene *scene,
                          const sc_render_options *options)
{
    double lo[3], hi[3];
    if (!sc_scene_frame_bounds(scene, options, lo, hi)) {
        for (int k = 0; k < 3; k++)
            cam->center[k] = 0;
        cam->distance = 140; /* OpenSCAD's default distance */
        return;
    }
    double diagonal = 0;
    for (int k = 0; k < 3; k++) {
        cam->center[k] = (lo[k] + hi[k]) / 2;
        diagonal += (hi[k] - lo[k]) * (hi[k] - lo[k]);
    }
    /* The sphere around the box fills the vertical field of view. */
    double distance = sqrt(diagonal) / 2 / sin(radians(cam->fov_deg / 2));
    cam->distance = distance > 0 && isfinite(distance) ? distance : 140;
}

void view_camera_init(view_camera *cam, const sc_render_options *options)
{
    memset(cam, 0, sizeof *cam);
    cam->fov_deg = options->fov_deg;
    cam->projection = options->projection;
    cam->rotate[0] = 55; /* OpenSCAD's default view */
    cam->rotate[2] = 25;
    cam->distance = 140; /* and distance */
}

void view_camera_reset(view_camera *cam, const sc_scene *scene,
                       const sc_render_options *options)
{
    cam->fov_deg = options->fov_deg;
    cam->projection = options->projection;
    if (options->camera_mode == SC_CAMERA_VECTOR) {
        const double *eye = options->camera, *center = options->camera + 3;
        double f[3], length = 0;
        for (int k = 0; k < 3; k++) {
            f[k] = center[k] - eye[k];
            length += f[k] * f[k];
        }
        length = sqrt(length);
        if (length > 0 && isfinite(length)) {
            for (int k = 0; k < 3; k++) {
                f[k] /= length;
                cam->center[k] = center[k];
            }
            double c = -f[2] > 1 ? 1 : -f[2] < -1 ? -1 : -f[2];
            cam->rotate[0] = acos(c) * (180.0 / pi);
            cam->rotate[1] = 0;
            cam->rotate[2] = wrap_degrees(atan2(-f[0], f[1]) * (180.0 / pi));
            cam->distance = length;
            return;
        }
    }
    cam->rotate[0] = 55; /* OpenSCAD's default view */
    cam->rotate[1] = 0;
    cam->rotate[2] = 25;
    view_camera_view_all(cam, scene, options);
}

void view_camera_orbit(view_camera *cam, double dx, double dy, int around_y)
{
    cam->rotate[0] = wrap_degrees(cam->rotate[0] - 0.7 * dy);
    if (around_y)
        cam->rotate[1] = wrap_degrees(cam->rotate[1] - 0.7 * dx);
    else
        cam->rotate[2] = wrap_degrees(cam->rotate[2] - 0.7 * dx);
}

void view_camera_pan(view_camera *cam, double dx, double dy, int width, int height)
{
    static const double x_axis[3] = {1, 0, 0}, z_axis[3] = {0, 0, 1};
    double right[3], up[3];
    gimbal_rotate(cam->rotate, x_axis, right);
    gimbal_rotate(cam->rotate, z_axis, up);
    double mx = 0.7 * dx * 3.0 * cam->distance / width;
    double mz = -0.7 * dy * 3.0 * cam->distance / height;
    for (int k = 0; k < 3; k++)
        cam->center[k] -= mx * right[k] + mz * up[k];
}

void view_camera_zoom(view_camera *cam, double delta)
{
    double distance = cam->distance * pow(0.9, delta / 120.0);
    if (distance > 0 && isfinite(distance))
        cam->distance = distance;
}

void view_camera_preset(view_camera *cam, sc_view_preset preset)
{
    sc_view_preset_rotation(preset, cam->rotate);
}

void view_camera_forward(const view_camera *cam, double forward[3])
{
    static const double y_axis[3] = {0, 1, 0};
    gimbal_rotate(cam->rotate, y_axis, forward);
}

void view_camera_apply(const view_camera *cam, sc_render_options *options)
{
    options->camera_mode = SC_CAMERA_GIMBAL;
    for (int k = 0; k < 3; k++) {
        options->camera[k] = cam->center[k];
        options->camera[3 + k] = cam->rotate[k];
    }
    options->camera[6] = cam->distance;
    options->fov_deg = cam->fov_deg;
    options->projection = cam->projection;
    options->viewall = 0;
    options->autocenter = 0;
}

const char *view_camera_format(const view_camera *cam, int width, int height, int spp,
                               char *buf, size_t size)
{
    snprintf(buf, size,
             "--camera=%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g --imgsize=%d,%d "
             "--projection=%s --fov=%.17g --spp=%d",
             cam->center[0], cam->center[1], cam->center[2], cam->rotate[0],
             cam->rotate[1], cam->rotate[2], cam->distance, width, height,
             cam->projection == SC_PROJECTION_ORTHOGRAPHIC ? "o" : "p", cam->fov_deg,
             spp);
    return buf;
}
