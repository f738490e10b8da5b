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

#include <stdint.h>
#include <string.h>

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
 * whose color_linear_to_srgb8 is k or more, found from the inverse
 * transfer function's guess by stepping one float at a time until the
 * code changes there (positive floats order as their bit patterns). The
 * encoding is monotone, so the code of v is the number of thresholds at
 * or below v. */
#define COLOR_SRGB8_THRESHOLDS 255
void color_srgb8_thresholds(float thresholds[COLOR_SRGB8_THRESHOLDS]);

/* The floats of (0, 1) by their top 16 bits (sign, exponent and 7 bits of
 * the fraction): 0x3f80 buckets, each 2^-7 of an octave wide. */
#define COLOR_SRGB8_BUCKETS 0x3f80

/* The encoder of a whole image: the thresholds, and the code of each
 * bucket's smallest float, from which the code of v is found by counting
 * the thresholds in v's bucket at or below v. A bucket spans at most one
 * threshold: its width is v / 128 to v / 256, and the code climbs
 * 255 * 12.92 a unit on the linear toe (0.05 codes a bucket there) and
 * 112 * v^(-7/12) on the power curve (0.44 codes a bucket just below 1,
 * the most). So color_srgb8_encode makes one comparison where a search
 * over the thresholds made eight; the loop only keeps it exact without
 * that bound. */
typedef struct color_srgb8_table {
    float above[COLOR_SRGB8_THRESHOLDS + 1];  /* the thresholds; above[255] infinite */
    unsigned char first[COLOR_SRGB8_BUCKETS]; /* code of each bucket's smallest float */
} color_srgb8_table;

void color_srgb8_table_init(color_srgb8_table *table);

/* color_linear_to_srgb8(v), the very byte: NaN and v <= 0 give 0, v >= 1
 * gives 255. */
static inline unsigned char color_srgb8_encode(const color_srgb8_table *table, float v)
{
    if (!(v > 0))
        return 0;
    if (v >= 1)
        return 255;
    uint32_t bits;
    memcpy(&bits, &v, sizeof bits);
    unsigned k = table->first[bits >> 16];
    while (v >= table->above[k])
        k++;
    return (unsigned char)k;
}

#ifdef __cplusplus
}
#endif

#endif
