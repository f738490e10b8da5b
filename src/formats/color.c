/* The sRGB transfer function (IEC 61966-2-1): a linear toe below 0.04045
 * (display) / 0.0031308 (linear), a 2.4 power curve above. See color.h for
 * where the pipeline applies it. */
#include "formats/color.h"

#include <math.h>

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
