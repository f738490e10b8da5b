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

/* The same codes for a whole image without a power per value: code k
 * (1..255) begins at the float thresholds[k - 1], the smallest float
 * whose color_linear_to_srgb8 is k or more, found by bisection on the
 * float's bits (positive floats order as their bit patterns), 255 * 31
 * evaluations. The encoding is monotone, so the code of v is the number
 * of thresholds at or below v: color_srgb8_code, 8 comparisons, the
 * very byte color_linear_to_srgb8 gives (NaN and v <= 0 give 0, v >= 1
 * gives 255). */
#define COLOR_SRGB8_THRESHOLDS 255
void color_srgb8_thresholds(float thresholds[COLOR_SRGB8_THRESHOLDS]);

static inline unsigned char color_srgb8_code(const float *thresholds, float v)
{
    unsigned k = 0;
    for (unsigned step = 128; step; step >>= 1)
        if (k + step <= COLOR_SRGB8_THRESHOLDS && v >= thresholds[k + step - 1])
            k += step;
    return (unsigned char)k;
}

#ifdef __cplusplus
}
#endif

#endif
