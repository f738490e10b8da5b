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

void color_srgb8_thresholds(float thresholds[COLOR_SRGB8_THRESHOLDS])
{
    const uint32_t one = 0x3f800000u; /* 1.0f, whose code is 255 */
    for (unsigned k = 1; k <= COLOR_SRGB8_THRESHOLDS; k++) {
        /* code(lo) < k <= code(hi) throughout */
        uint32_t lo = 0, hi = one;
        while (hi - lo > 1) {
            uint32_t mid = lo + (hi - lo) / 2;
            if (color_linear_to_srgb8(float_of_bits(mid)) >= k)
                hi = mid;
            else
                lo = mid;
        }
        thresholds[k - 1] = float_of_bits(hi);
    }
}
