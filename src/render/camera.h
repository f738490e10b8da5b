/* The camera: how a pixel becomes a ray.
 *
 * Every way of placing the camera (OpenSCAD's 6-value eye/centre form, its
 * 7-value gimbal form, the default view, --viewall, --autocenter) is first
 * turned into a cam_view (a centre, a viewing direction, a signed distance
 * and an up hint), and a cam_view plus the field of view, the projection
 * and the image size into a camera: eye e, centre c and the orthonormal
 * basis f (forward), r (right), u (up). Pixel (i, j), column i from the
 * left, row j from the top, sampled at offset (sx, sy) inside the pixel
 * ((0.5, 0.5) is its centre), looks along
 *
 *   x = (2 (i + sx) / W - 1) a W / H,   y = (1 - 2 (j + sy) / H) a,
 *   a = tan(fov / 2);
 *   perspective:  origin e,                        direction f + x r + y u;
 *   orthographic: origin e + |c - e| (x r + y u),  direction f.
 *
 * The directions are not normalised, so the ray parameter t of a hit is not
 * its distance; the distance is t |d|.
 *
 * A thin lens (depth of field) of diameter A focused at distance D moves
 * the ray's origin to a point of the lens, o' = o + (A / 2)(lx r + ly u)
 * for (lx, ly) on the unit disc, and turns it through the point the
 * pinhole ray reaches at forward depth D: d' = d - (A / 2)(lx r + ly u) / D
 * (d has forward component 1 in both projections, so that point is o + D d
 * and d' keeps forward component 1). Points at depth D stay sharp; a point
 * at depth z spreads over a disc of diameter A |z - D| / z on the plane at
 * depth D, the circle of confusion (docs/distribution.md). docs/camera.md is the
 * reference for other tools that want to reproduce these rays, with the OpenSCAD 2021.01
 * conversions written out as formulas.
 */
#ifndef SPANCAST_RENDER_CAMERA_H
#define SPANCAST_RENDER_CAMERA_H

#include "math/vec.h"
#include "spancast/spancast.h"

/* OpenSCAD's defaults (Camera.cc, 2021.01): the view rotation $vpr,
 * distance $vpd and field of view $vpf used when nothing else is given. */
#define CAM_DEFAULT_RX 55.0
#define CAM_DEFAULT_RY 0.0
#define CAM_DEFAULT_RZ 25.0
#define CAM_DEFAULT_DISTANCE 140.0
#define CAM_DEFAULT_FOV 22.5

/* A camera placement before the image is known. The eye is
 * center - distance * forward. The gimbal form takes its distance as given;
 * cam_init rejects a distance that is not positive (OpenSCAD draws nothing
 * then: its near and far planes become negative), unless viewall has
 * replaced it. */
typedef struct cam_view {
    vec3 center;
    vec3 forward;    /* unit direction of the view rotation */
    double distance; /* from the centre back to the eye, see above */
    vec3 up;         /* up hint: +z, or the gimbal's rotated +z (never parallel to
                        forward in that case) */
} cam_view;

typedef struct camera {
    vec3 eye, center;
    vec3 f, r, u;    /* unit forward, right, up; right-handed: r x u = -f */
    double a;        /* tan(fov / 2) */
    double aspect;   /* W / H */
    double distance; /* |c - e|: the orthographic half-height is distance * a */
    int width, height;
    sc_projection projection;
    double lens_radius; /* thin lens: half the aperture; 0 for a pinhole */
    double focus;       /* thin lens: forward depth of the sharp plane */
} camera;

/* Sine and cosine of an angle in degrees, exact at multiples of 90 degrees
 * (so a top view looks exactly along -z) and symmetric around them. */
double cam_sin_deg(double deg);
double cam_cos_deg(double deg);

/* OpenSCAD's vector camera: eye p[0..2], centre p[3..5], up +z. Returns
 * SC_ERR_ARGUMENT when eye and centre coincide or a value is not finite. */
sc_status cam_view_lookat(const double p[6], cam_view *view, sc_error *error);

/* OpenSCAD's gimbal camera: translate p[0..2] ($vpt), rotate p[3..5] in
 * degrees ($vpr), distance p[6] ($vpd). Returns SC_ERR_ARGUMENT when a value
 * is not finite. */
sc_status cam_view_gimbal(const double p[7], cam_view *view, sc_error *error);

/* OpenSCAD's viewAll: keeps the direction; with autocenter the centre moves
 * to the centre of bounds; then the distance becomes
 * (|centre of bounds - centre| + half the diagonal) / sin(fov / 2). An empty
 * box puts the centre at the origin and the distance at 140. */
void cam_view_all(cam_view *view, const bbox *bounds, int autocenter, double fov_deg);

/* The view options ask for: the camera mode, then viewall (autocenter only
 * acts together with viewall, as in OpenSCAD 2021.01; the automatic camera
 * implies both). bounds are the world bounds of the solid (may be empty). */
sc_status cam_view_from_options(const sc_render_options *options, const bbox *bounds,
                                cam_view *view, sc_error *error);

/* Builds the camera for a view. Returns SC_ERR_ARGUMENT for a bad image size
 * or field of view (0 < fov < 180), or a distance that is not positive. */
sc_status cam_init(camera *cam, const cam_view *view, double fov_deg,
                   sc_projection projection, int width, int height, sc_error *error);

/* Gives cam a thin lens of diameter aperture focused at distance focus
 * from the eye (0: at the centre's). Returns SC_ERR_ARGUMENT for a
 * negative or non-finite aperture or focus. */
sc_status cam_set_lens(camera *cam, double aperture, double focus, sc_error *error);

/* Moves the pinhole ray (origin, direction) of cam to the lens point
 * (lx, ly) on the unit disc; see above. Leaves it as it is without a lens. */
void cam_lens_ray(const camera *cam, double lx, double ly, vec3 *origin, vec3 *direction);

/* The ray through pixel (i, j) at sample offset (sx, sy); see above. */
void cam_ray(const camera *cam, int i, int j, double sx, double sy, vec3 *origin,
             vec3 *direction);

#endif
