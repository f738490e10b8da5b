/* The getters of the public API's opaque sc_framebuffer (spancast.h): the
 * struct itself (formats/framebuffer.h) stays inside the library, so it
 * can change without breaking a program built against an older header.
 * sc_render (render.c) makes and frees it. */
#include <stddef.h>

#include "base/error.h"
#include "base/sized.h"
#include "formats/framebuffer.h"

int sc_framebuffer_width(const sc_framebuffer *fb)
{
    return fb ? fb->width : 0;
}

int sc_framebuffer_height(const sc_framebuffer *fb)
{
    return fb ? fb->height : 0;
}

void sc_framebuffer_offset(const sc_framebuffer *fb, int *x0, int *y0)
{
    if (x0)
        *x0 = fb ? fb->x0 : 0;
    if (y0)
        *y0 = fb ? fb->y0 : 0;
}

const float *sc_framebuffer_color(const sc_framebuffer *fb)
{
    return fb ? fb->color : NULL;
}

const float *sc_framebuffer_depth(const sc_framebuffer *fb)
{
    return fb ? fb->depth : NULL;
}

const uint8_t *sc_framebuffer_mask(const sc_framebuffer *fb)
{
    return fb ? fb->mask : NULL;
}

const float *sc_framebuffer_normal(const sc_framebuffer *fb)
{
    return fb ? fb->normal : NULL;
}

const int32_t *sc_framebuffer_id(const sc_framebuffer *fb)
{
    return fb ? fb->id : NULL;
}

const char *sc_framebuffer_camera_info(const sc_framebuffer *fb)
{
    return fb ? fb->camera_info : NULL;
}

void sc_render_stats_init_size(sc_render_stats *stats, size_t size)
{
    if (stats && size >= sizeof stats->size)
        sized_clear(stats, size);
}

sc_status sc_framebuffer_get_stats(const sc_framebuffer *fb, sc_render_stats *stats,
                                   sc_error *error)
{
    if (!fb || !stats)
        return err_set(error, SC_ERR_ARGUMENT, NULL,
                       "sc_framebuffer_get_stats needs a framebuffer and a result");
    return sized_write(stats, &fb->stats, sizeof fb->stats,
                       SIZED_MIN(sc_render_stats, threads), "sc_render_stats", error);
}
