/* Lines drawn over the shaded image: OpenSCAD's axes, scale marks,
 * crosshairs and small corner axes (GLView.cc, 2021.01), and a contact
 * sheet tile's label and border.
 *
 * OpenSCAD draws, in one pixel wide lines:
 *   axes:       from the origin to +-l along x, y and z, l the camera's
 *               distance, the negative halves stippled (3 pixels on, 3
 *               off), in the scheme's axes colour;
 *   scales:     a tick every l' / 10 along each half axis (l' = 10^floor(
 *               log10 l)), l / 60 long (every tenth one l / 30), pointing
 *               along -y from the x axis and along -x from the y and z
 *               axes, stippled on the negative halves;
 *   crosshairs: the four diagonals (+-1, +-1, 1) l / 8 long each way from
 *               the view's centre, in the scheme's crosshair colour;
 *   small axes: red, green and blue lines 10/90 of half the image height
 *               long from the point at 10 % of the width and 90 % of the
 *               height, turned with the view, with X, Y and Z drawn in
 *               strokes at 12/90, always on top.
 * Axes, scales and crosshairs are occluded by the model: a line's point is
 * drawn only when it is nearer than the surface the sample's ray sees. The
 * numbers OpenSCAD writes beside the scale marks are not drawn.
 *
 * The render of a 2D model adds its polygons' outlines, drawn after the
 * model and over it (the depth test off), as OpenSCAD's render draws a 2D
 * result (CGALRenderer::draw): 2 pixels wide in the scheme's 2D edge
 * colour, as OpenGL widens a line that is not antialiased, across its
 * major axis (a line nearer the horizontal covers the pixel centres up to
 * 1 pixel above and below it).
 *
 * Everything is decided per sample, at a point of the image, from the
 * lines projected once per render, so the lines do not depend on tiling
 * and are antialiased by the samples like the rest of the image.
 */
#ifndef SPANCAST_RENDER_OVERLAY_H
#define SPANCAST_RENDER_OVERLAY_H

#include "render/camera.h"
#include "spancast/spancast.h"

/* A line projected to the image: pixel coordinates and camera depths of
 * its ends (depth: distance along the view direction). */
typedef struct overlay_line {
    double x0, y0, x1, y1; /* pixels */
    double z0, z1;         /* depths along the forward axis, > 0 */
    int stipple;           /* drawn 3 pixels on, 3 off from (x0, y0) */
    int occluded;          /* hidden behind the model's surfaces */
    int color;             /* index into overlay.colors */
    int wide;              /* 2 pixels wide across its major axis, else 1
                              pixel about the line */
} overlay_line;

#define OVERLAY_COLORS 6 /* axes, crosshair, red, green, blue, 2D edges */

/* A 2D model's outlines (shading.h's flat_*): world points, 3 doubles
 * each; outline k is points start[k] to start[k + 1] - 1; drawn in color
 * (display values). */
typedef struct overlay_outlines {
    const double *points;
    const uint32_t *start;
    uint32_t count;
    const float *color;
} overlay_outlines;

typedef struct overlay {
    overlay_line *lines; /* malloc'd */
    int count;
    /* The lines by square cells of the image, OVERLAY_CELL pixels on a side,
     * row by row: those that may cover cell c are cell_lines[cell_start[c]]
     * to cell_lines[cell_start[c + 1] - 1], ascending. */
    int cells_x, cells_y;
    uint32_t *cell_start, *cell_lines; /* malloc'd */
    double colors[OVERLAY_COLORS][3];  /* linear */
    const camera *cam;
    const char *label; /* a sheet tile's name, or NULL */
    int border;        /* draw the tile's left and top edges (sheet grid) */
} overlay;

/* Projects the lines view asks for (SC_VIEW_AXES, _SCALES, _CROSSHAIRS)
 * for cam, and outlines (NULL: none); label and border as above. Returns
 * SC_OK or SC_ERR_NOMEM. */
sc_status overlay_prepare(overlay *ov, const camera *cam, unsigned view,
                          const sc_color_scheme *scheme, const overlay_outlines *outlines,
                          const char *label, int border, sc_error *error);
void overlay_release(overlay *ov);

/* Whether an overlay covers the image point (px, py) (pixels, in the
 * camera's own image) whose ray sees a surface at forward depth
 * surface_depth (INFINITY on a miss); when it does, out gets its linear
 * colour. */
int overlay_sample(const overlay *ov, double px, double py, double surface_depth,
                   double out[3]);

/* The forward depth of a point. */
double overlay_depth(const camera *cam, vec3 p);

#endif
