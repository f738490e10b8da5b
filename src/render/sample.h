/* Deterministic random numbers and stratified pixel samples.
 *
 * Every sample's random numbers come from a generator seeded by the pixel's
 * position in the full image and the sample's index alone, never from a
 * stream shared between pixels, so the image does not depend on the thread
 * count, the tile order or a --region crop (pbrt's StartPixelSample). The
 * generator is splitmix64 (Steele, Lea and Flood 2014): a 64-bit counter
 * stepped by the golden-ratio constant and passed through a bijective
 * mixer; the seed is the same mixer applied to the packed coordinates.
 *
 * Sample s of n in a pixel lies in cell (s mod kx, s div kx) of a kx x ky
 * grid, kx * ky = n, kx the largest divisor of n not above sqrt(n), at a
 * uniformly jittered point in its cell (stratified jittered sampling). One
 * sample per pixel is the pixel's centre, unjittered, as the camera
 * contract says.
 */
#ifndef SPANCAST_RENDER_SAMPLE_H
#define SPANCAST_RENDER_SAMPLE_H

#include <stdint.h>

typedef struct sample_rng {
    uint64_t state;
} sample_rng;

static inline uint64_t sample_mix(uint64_t z)
{
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

/* The generator of sample s in pixel (x, y) of the full image. */
static inline sample_rng sample_rng_for(uint32_t x, uint32_t y, uint32_t s)
{
    uint64_t key =
        ((uint64_t)x << 32 | y) ^ sample_mix((uint64_t)s + 0x632be59bd9b4e019ull);
    sample_rng r = {sample_mix(key)};
    return r;
}

/* A uniform double in [0, 1). */
static inline double sample_next(sample_rng *r)
{
    r->state += 0x9e3779b97f4a7c15ull;
    return (double)(sample_mix(r->state) >> 11) * 0x1.0p-53;
}

/* The grid width for n samples (see above). */
static inline int sample_grid_width(int n)
{
    int kx = 1;
    for (int k = 1; k * k <= n; k++)
        if (n % k == 0)
            kx = k;
    return kx;
}

/* The offset inside the pixel of sample s of n, kx = sample_grid_width(n). */
static inline void sample_offset(int s, int n, int kx, sample_rng *r, double *sx,
                                 double *sy)
{
    if (n == 1) {
        *sx = *sy = 0.5;
        return;
    }
    int ky = n / kx;
    *sx = ((s % kx) + sample_next(r)) / kx;
    *sy = ((s / kx) + sample_next(r)) / ky;
}

#endif
