/* Motion between two transforms: see motion.h.
 *
 * Polar decomposition by Higham's iteration R <- (R + R^-T) / 2, which
 * converges quadratically to the orthogonal factor of a non-singular
 * matrix; 60 steps bound it, and it stops when an update changes no entry
 * by more than 1e-15 of the matrix's size. S = R^T L, symmetrised. The
 * quaternion of R is Shepperd's: from the largest of the four diagonal
 * combinations, so it never divides by a small number.
 */
#include "math/motion.h"

#include <math.h>
#include <string.h>

static double det3(const double a[3][3])
{
    return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
           a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
           a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
}

/* The inverse transpose of a (det d != 0). */
static void inverse_transpose(const double a[3][3], double d, double out[3][3])
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
            out[i][j] = (a[i1][j1] * a[i2][j2] - a[i1][j2] * a[i2][j1]) / d;
        }
}

/* R and S of l = R S with det R = sign; returns 0 when l is singular. */
static int polar(const double l[3][3], double sign, double r[3][3], double s[3][3])
{
    double size = 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            r[i][j] = sign * l[i][j];
            size = fmax(size, fabs(l[i][j]));
        }
    for (int step = 0; step < 60; step++) {
        double d = det3(r);
        if (!(fabs(d) > 0) || !isfinite(d))
            return 0;
        double it[3][3], change = 0;
        inverse_transpose(r, d, it);
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) {
                double next = 0.5 * (r[i][j] + it[i][j]);
                change = fmax(change, fabs(next - r[i][j]));
                r[i][j] = next;
            }
        if (change <= 1e-15 * fmax(1.0, size))
            break;
    }
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            double v = 0;
            for (int k = 0; k < 3; k++)
                v += r[k][i] * sign * l[k][j];
            s[i][j] = v;
        }
    for (int i = 0; i < 3; i++)
        for (int j = i + 1; j < 3; j++)
            s[i][j] = s[j][i] = 0.5 * (s[i][j] + s[j][i]);
    return 1;
}

static void to_quaternion(const double r[3][3], double q[4])
{
    double tr = r[0][0] + r[1][1] + r[2][2];
    double c[4] = {tr, r[0][0], r[1][1], r[2][2]};
    int big = 0;
    for (int k = 1; k < 4; k++)
        if (c[k] > c[big])
            big = k;
    if (big == 0) {
        double w = 0.5 * sqrt(fmax(0.0, 1 + tr));
        q[0] = w;
        q[1] = (r[2][1] - r[1][2]) / (4 * w);
        q[2] = (r[0][2] - r[2][0]) / (4 * w);
        q[3] = (r[1][0] - r[0][1]) / (4 * w);
    } else if (big == 1) {
        double x = 0.5 * sqrt(fmax(0.0, 1 + r[0][0] - r[1][1] - r[2][2]));
        q[1] = x;
        q[0] = (r[2][1] - r[1][2]) / (4 * x);
        q[2] = (r[0][1] + r[1][0]) / (4 * x);
        q[3] = (r[0][2] + r[2][0]) / (4 * x);
    } else if (big == 2) {
        double y = 0.5 * sqrt(fmax(0.0, 1 - r[0][0] + r[1][1] - r[2][2]));
        q[2] = y;
        q[0] = (r[0][2] - r[2][0]) / (4 * y);
        q[1] = (r[0][1] + r[1][0]) / (4 * y);
        q[3] = (r[1][2] + r[2][1]) / (4 * y);
    } else {
        double z = 0.5 * sqrt(fmax(0.0, 1 - r[0][0] - r[1][1] + r[2][2]));
        q[3] = z;
        q[0] = (r[1][0] - r[0][1]) / (4 * z);
        q[1] = (r[0][2] + r[2][0]) / (4 * z);
        q[2] = (r[1][2] + r[2][1]) / (4 * z);
    }
    double n = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    for (int k = 0; k < 4; k++)
        q[k] /= n;
}

static void from_quaternion(const double q[4], double r[3][3])
{
    double w = q[0], x = q[1], y = q[2], z = q[3];
    r[0][0] = 1 - 2 * (y * y + z * z);
    r[0][1] = 2 * (x * y - w * z);
    r[0][2] = 2 * (x * z + w * y);
    r[1][0] = 2 * (x * y + w * z);
    r[1][1] = 1 - 2 * (x * x + z * z);
    r[1][2] = 2 * (y * z - w * x);
    r[2][0] = 2 * (x * z - w * y);
    r[2][1] = 2 * (y * z + w * x);
    r[2][2] = 1 - 2 * (x * x + y * y);
}

int motion_init(motion *m, const affine *a, const affine *b)
{
    memset(m, 0, sizeof *m);
    double la[3][3], lb[3][3], ra[3][3], rb[3][3];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            la[i][j] = a->m[i][j];
            lb[i][j] = b->m[i][j];
        }
    double da = det3(la), db = det3(lb);
    if (!(da != 0 && db != 0) || (da < 0) != (db < 0))
        return 0;
    m->sign = da < 0 ? -1 : 1;
    if (!polar(la, m->sign, ra, m->s0) || !polar(lb, m->sign, rb, m->s1))
        return 0;
    to_quaternion(ra, m->q0);
    to_quaternion(rb, m->q1);
    double dot = 0;
    for (int k = 0; k < 4; k++)
        dot += m->q0[k] * m->q1[k];
    if (dot < 0) /* q and -q are one rotation: take the shorter arc */
        for (int k = 0; k < 4; k++)
            m->q1[k] = -m->q1[k];
    m->t0 = v3(a->m[0][3], a->m[1][3], a->m[2][3]);
    m->t1 = v3(b->m[0][3], b->m[1][3], b->m[2][3]);
    return 1;
}

affine motion_at(const motion *m, double s)
{
    double dot = 0;
    for (int k = 0; k < 4; k++)
        dot += m->q0[k] * m->q1[k];
    double wa = 1 - s, wb = s;
    if (dot < 0.9999995) { /* else the arc is so short that the blend is exact */
        double theta = acos(fmin(1.0, dot)), sn = sin(theta);
        wa = sin((1 - s) * theta) / sn;
        wb = sin(s * theta) / sn;
    }
    double q[4], n = 0;
    for (int k = 0; k < 4; k++) {
        q[k] = wa * m->q0[k] + wb * m->q1[k];
        n += q[k] * q[k];
    }
    n = sqrt(n);
    for (int k = 0; k < 4; k++)
        q[k] /= n;
    double r[3][3];
    from_quaternion(q, r);
    affine out;
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 3; j++) {
            double v = 0;
            for (int k = 0; k < 3; k++)
                v += r[i][k] * ((1 - s) * m->s0[k][j] + s * m->s1[k][j]);
            out.m[i][j] = m->sign * v;
        }
    }
    vec3 t = v3_add(v3_scale(m->t0, 1 - s), v3_scale(m->t1, s));
    out.m[0][3] = t.x;
    out.m[1][3] = t.y;
    out.m[2][3] = t.z;
    return out;
}
