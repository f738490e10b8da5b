/* The colour pipeline: display values in, linear light inside, encoded out.
 *
 * Colours in model files (OpenSCAD's color(), material(), light(),
 * background()) are display values, sRGB-encoded, as every colour picker and
 * OpenSCAD itself treat them. The renderer decodes them to linear light
 * with the sRGB transfer function (IEC 61966-2-1) once per render, shades in
 * linear light (so light adds, reflections and antialiasing average
 * correctly), and stores linear values in the framebuffer. Image output
 * encodes them again for 8-bit formats (PNG, JPEG: sRGB, tagged so) and
 * writes them unchanged to float formats (EXR, float TIFF: scene-linear with
 * sRGB primaries). Values above 1 are kept in float files and clipped in
 * 8-bit ones.
 */
#ifndef SPANCAST_FORMATS_COLOR_H
#define SPANCAST_FORMATS_COLOR_H

#ifdef __cplusplus
extern "C" {
#endif

/* sRGB decoding of a display value in 0..1 (clamped) to linear light. */
double color_srgb_to_linear(double v);

/* sRGB encoding of linear light (clamped to 0..1) to a display value. */
double color_linear_to_srgb(double v);

/* The 8-bit code of linear light: round(255 * encode(v)). */
unsigned char color_linear_to_srgb8(float v);

#ifdef __cplusplus
}
#endif

#endif
