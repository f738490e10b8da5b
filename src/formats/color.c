/* The sRGB transfer function (IEC 61966-2-1): a linear toe below 0.04045
 * (display) / 0.0031308 (linear), a 2.4 power curve above. See color.h for
 * where the pipeline applies it. */
#include "formats/color.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

double color_srgb_to_linear(double v)
{
    if (!(v > 0))
        return 0;
    if (v >= 1)
        return 1;
    return v <= 0.04045 ? v / 12.92 : pow((v + 0.055) / 1.055, 2.4);
}

double color_linear_to_srgb(double v)
{
    if (!(v > 0))
        return 0;
    if (v >= 1)
        return 1;
    return v <= 0.0031308 ? 12.92 * v : 1.055 * pow(v, 1 / 2.4) - 0.055;
}

unsigned char color_linear_to_srgb8(float v)
{
    return (unsigned char)lround(255.0 * color_linear_to_srgb(v));
}

static float float_of_bits(uint32_t bits)
{
    float v;
    memcpy(&v, &bits, sizeof v);
    return v;
}

static uint32_t bits_of_float(float v)
{
    uint32_t bits;
    memcpy(&bits, &v, sizeof bits);
    return bits;
}

void color_srgb8_thresholds(float thresholds[COLOR_SRGB8_THRESHOLDS])
{
    const uint32_t one = 0x3f800000u; /* 1.0f, whose code is 255 */
    for (unsigned k = 1; k <= COLOR_SRGB8_THRESHOLDS; k++) {
        /* The guess: where the curve crosses k - 1/2, a float or a few
         * away from where the rounded code becomes k. */
        float guess = (float)color_srgb_to_linear((k - 0.5) / 255);
        uint32_t at = bits_of_float(guess);
        if (at > one)
            at = one;
        /* Step down while the code below is k or more, up while the code
         * here is less than k: then code(at - 1) < k <= code(at). */
        while (at > 0 && color_linear_to_srgb8(float_of_bits(at - 1)) >= k)
            at--;
        while (at < one && color_linear_to_srgb8(float_of_bits(at)) < k)
            at++;
        thresholds[k - 1] = float_of_bits(at);
    }
}

void color_srgb8_table_init(color_srgb8_table *table)
{
    color_srgb8_thresholds(table->above);
    table->above[COLOR_SRGB8_THRESHOLDS] = INFINITY;
    /* The code of a bucket's smallest float is the number of thresholds
     * at or below it; both rise with the bucket. */
    unsigned code = 0;
    for (uint32_t b = 0; b < COLOR_SRGB8_BUCKETS; b++) {
        uint32_t lowest = b << 16;
        while (code < COLOR_SRGB8_THRESHOLDS &&
               bits_of_float(table->above[code]) <= lowest)
            code++;
        table->first[b] = (unsigned char)code;
    }
}
