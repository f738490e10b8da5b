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
 *
 * The other dimensions a sample draws (the lens, area lights, glossy
 * lobes: docs/distribution.md) are stratified over the same grid, each
 * dimension d on its own: sample s takes cell perm_d(s) of the kx x ky
 * grid, perm_d a permutation of 0..n-1 seeded by the pixel and d, and a
 * jittered point in it (pbrt's padded StratifiedSampler). So the n samples
 * of a pixel cover the lens, and each light, with one point per cell,
 * while the pairing of lens cells with pixel cells stays random. The
 * permutation is a bijection of 0..2^k-1 built from steps that are each
 * one (xor with a constant, multiplication by an odd constant and
 * addition modulo 2^k, xor with the value shifted right), walked until it
 * falls below n (cycle walking: the walk stays on the cycle of s, which
 * holds a value below n because s is one). Jitter comes from the sample's
 * generator, after the pixel offset, so a pixel's offsets do not change
 * with the dimensions a sample uses.
 */
#ifndef SPANCAST_RENDER_SAMPLE_H
#define SPANCAST_RENDER_SAMPLE_H

#include <math.h>
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

/* A bijection of 0..mask (mask = 2^k - 1) seeded by seed. */
static inline uint32_t sample_scramble(uint32_t i, uint32_t mask, uint64_t seed)
{
    uint32_t a = (uint32_t)seed, b = (uint32_t)(seed >> 32) | 1u;
    int bits = 0;
    while (bits < 32 && (mask >> bits))
        bits++;
    int shift = bits > 1 ? bits / 2 : 1;
    i = (i ^ a) & mask;
    i = (i * b) & mask;
    i ^= i >> shift;
    i = (i + (a >> 11)) & mask;
    i = (i * ((b ^ 0x5a5a5a5au) | 1u)) & mask;
    i ^= i >> shift;
    return i;
}

/* perm(s) for a permutation of 0..n-1 seeded by seed (see above). */
static inline uint32_t sample_permute(uint32_t s, uint32_t n, uint64_t seed)
{
    uint32_t mask = n - 1;
    mask |= mask >> 1;
    mask |= mask >> 2;
    mask |= mask >> 4;
    mask |= mask >> 8;
    mask |= mask >> 16;
    uint32_t i = s;
    do
        i = sample_scramble(i, mask, seed);
    while (i >= n);
    return i;
}

/* Where the samples of one pixel stand, for the stratified dimensions. */
typedef struct sample_pixel {
    uint32_t x, y; /* the pixel in the full image */
    int s, n, kx;  /* sample s of n, grid width kx */
    uint32_t dim;  /* the next dimension to hand out */
} sample_pixel;

/* The next 2D point in [0, 1)^2 of sample p->s: stratified over the
 * pixel's samples in dimension p->dim (see above), jittered with r; a
 * plain uniform point when the pixel has one sample. */
static inline void sample_2d(sample_pixel *p, sample_rng *r, double *u, double *v)
{
    uint32_t dim = p->dim++;
    if (p->n <= 1) {
        *u = sample_next(r);
        *v = sample_next(r);
        return;
    }
    uint64_t seed = sample_mix(((uint64_t)p->x << 32 | p->y) ^
                               sample_mix((uint64_t)dim * 0x9e3779b97f4a7c15ull + 1));
    uint32_t cell = sample_permute((uint32_t)p->s, (uint32_t)p->n, seed);
    int ky = p->n / p->kx;
    *u = ((int)cell % p->kx + sample_next(r)) / p->kx;
    *v = ((int)cell / p->kx + sample_next(r)) / ky;
}

/* A uniform point on the unit disc from a point in [0, 1)^2, by Shirley
 * and Chiu's concentric map, which keeps strata compact on the disc. */
static inline void sample_disc(double u, double v, double *x, double *y)
{
    double a = 2 * u - 1, b = 2 * v - 1;
    if (a == 0 && b == 0) {
        *x = *y = 0;
        return;
    }
    const double quarter = 0.7853981633974483;
    double r, phi;
    if (a * a > b * b) {
        r = a;
        phi = quarter * (b / a);
    } else {
        r = b;
        phi = 2 * quarter - quarter * (a / b);
    }
    *x = r * cos(phi);
    *y = r * sin(phi);
}

#endif
