/* The framebuffer behind the public API's opaque sc_framebuffer: what
 * sc_render fills (src/render) and the image writers read (image_io.c).
 * Callers outside the library see it only through the sc_framebuffer_*
 * getters (src/render/framebuffer.c), so its fields may change freely. */
#ifndef SPANCAST_FORMATS_FRAMEBUFFER_H
#define SPANCAST_FORMATS_FRAMEBUFFER_H

#include "spancast/spancast.h"

struct sc_framebuffer {
    int width, height;
    float *color;  /* RGB, 3 floats per pixel, scene-linear (sRGB primaries), >= 0 */
    float *depth;  /* distance along the ray to the hit, +inf on a miss */
    uint8_t *mask; /* 255 where the camera ray hits, 0 elsewhere */
    float *normal; /* world normal, 3 floats per pixel, 0 on a miss */
    int32_t *id;   /* index of the leaf the camera ray hit (source order), -1 on a miss */
    int x0, y0;    /* where this image lies in the full image (--region), else 0 */
    char camera_info[256]; /* the camera in words, for the files' metadata */
    sc_render_stats stats; /* its size field is the library's own */
    const volatile sig_atomic_t *cancel; /* the render options' cancel flag */
};

#endif
