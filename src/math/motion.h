/* Interpolation between two affine transforms, as a motion: the linear part
 * of each is split by the polar decomposition L = R S (R a rotation, S
 * symmetric: the stretch), and the transform at s in [0, 1] is
 *
 *   R(s) = slerp(R0, R1, s)   (unit quaternions, the shorter arc),
 *   S(s) = (1 - s) S0 + s S1,  t(s) = (1 - s) t0 + s t1,
 *   M(s) = [R(s) S(s) | t(s)],
 *
 * so a turning object turns at a constant angular speed about a fixed axis
 * and its points move along arcs, not along the chords a blend of the two
 * matrices would take (Shoemake and Duff 1992, "Matrix animation and polar
 * decomposition"). M(0) and M(1) are the two transforms up to rounding. A
 * mirroring transform (det L < 0) is written R S with R = -Q, Q a rotation;
 * both ends must agree on mirroring.
 */
#ifndef SPANCAST_MATH_MOTION_H
#define SPANCAST_MATH_MOTION_H

#include "math/vec.h"

typedef struct motion {
    double q0[4], q1[4];       /* unit quaternions (w, x, y, z), q0 . q1 >= 0 */
    double s0[3][3], s1[3][3]; /* stretches */
    vec3 t0, t1;               /* translations */
    double sign;               /* -1 for mirroring transforms, else 1 */
} motion;

/* Splits a and b into *m. Returns 1, or 0 when a linear part is singular
 * or the two disagree on mirroring. */
int motion_init(motion *m, const affine *a, const affine *b);

/* The transform at s (0: a, 1: b). */
affine motion_at(const motion *m, double s);

#endif
