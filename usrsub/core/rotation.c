/* Rotations of I relative to J (rotation.h). */
#include "usrsub/core/rotation.h"

#include <math.h>
#include <string.h>

#include "usrsub/core/trig.h"

void usrsub_euler313_rotation(const double e[3], double R[9])
{
    double sp, cp, st, ct, sf, cf;
    usrsub_sincos(e[0], &sp, &cp);
    usrsub_sincos(e[1], &st, &ct);
    usrsub_sincos(e[2], &sf, &cf);
    R[0] = cp * cf - sp * ct * sf, R[1] = -cp * sf - sp * ct * cf, R[2] = sp * st;
    R[3] = sp * cf + cp * ct * sf, R[4] = -sp * sf + cp * ct * cf, R[5] = -cp * st;
    R[6] = st * sf, R[7] = st * cf, R[8] = ct;
}

void usrsub_projection_angles(const double R[9], double a[3])
{
    a[0] = usrsub_atan2(R[7], R[4]); /* Y_I . Z_J, Y_I . Y_J */
    a[1] = usrsub_atan2(R[2], R[8]); /* Z_I . X_J, Z_I . Z_J */
    a[2] = usrsub_atan2(R[3], R[0]); /* X_I . Y_J, X_I . X_J */
}

double usrsub_rest_phi(double psi, double ct, double az)
{
    /* (R00, R10) = Rz(psi) (cos phi, cos theta sin phi): AZ - psi is the
     * angle of (cos phi, ct sin phi), so (cos phi, sin phi) lies along
     * (|ct| cos(AZ - psi), sign(ct) sin(AZ - psi)): near theta = pi too */
    double s, c;
    usrsub_sincos(az - psi, &s, &c);
    return usrsub_atan2(copysign(1.0, ct) * s, fabs(ct) * c);
}

static double det3(const double m[9])
{
    return m[0] * (m[4] * m[8] - m[5] * m[7]) - m[1] * (m[3] * m[8] - m[5] * m[6]) +
           m[2] * (m[3] * m[7] - m[4] * m[6]);
}

/* The inverse of a 3x3 row-major matrix; -1 when singular. */
static int invert3(const double m[9], double inv[9])
{
    const double d = det3(m);
    if (!(fabs(d) > 1e-300))
        return -1;
    inv[0] = (m[4] * m[8] - m[5] * m[7]) / d;
    inv[1] = (m[2] * m[7] - m[1] * m[8]) / d;
    inv[2] = (m[1] * m[5] - m[2] * m[4]) / d;
    inv[3] = (m[5] * m[6] - m[3] * m[8]) / d;
    inv[4] = (m[0] * m[8] - m[2] * m[6]) / d;
    inv[5] = (m[2] * m[3] - m[0] * m[5]) / d;
    inv[6] = (m[3] * m[7] - m[4] * m[6]) / d;
    inv[7] = (m[1] * m[6] - m[0] * m[7]) / d;
    inv[8] = (m[0] * m[4] - m[1] * m[3]) / d;
    return 0;
}

int usrsub_rotation_of_projection_angles(const double a[3], double R[9], double *A)
{
    double sx, cx, sy, cy, sz, cz;
    usrsub_sincos(a[0], &sx, &cx);
    usrsub_sincos(a[1], &sy, &cy);
    usrsub_sincos(a[2], &sz, &cz);
    /* I's axes up to their lengths: x ~ (cz, sz, p), y ~ (q, cx, sx), z ~ (sy, s, cy);
     * their three dot products vanish: linear in p, q, s */
    const double M[9] = {sx, cz, 0.0, 0.0, sy, cx, cy, 0.0, sz};
    const double rhs[3] = {-sz * cx, -sx * cy, -cz * sy};
    double Minv[9];
    if (invert3(M, Minv) != 0)
        return -1;
    double pqs[3];
    for (int i = 0; i < 3; ++i)
        pqs[i] = Minv[3 * i] * rhs[0] + Minv[3 * i + 1] * rhs[1] + Minv[3 * i + 2] * rhs[2];
    const double x[3] = {cz, sz, pqs[0]}, y[3] = {pqs[1], cx, sx}, z[3] = {sy, pqs[2], cy};
    const double nx = sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
    const double ny = sqrt(y[0] * y[0] + y[1] * y[1] + y[2] * y[2]);
    const double nz = sqrt(z[0] * z[0] + z[1] * z[1] + z[2] * z[2]);
    for (int i = 0; i < 3; ++i) {
        R[3 * i] = x[i] / nx;
        R[3 * i + 1] = y[i] / ny;
        R[3 * i + 2] = z[i] / nz;
    }
    if (!(det3(R) > 0.5))
        return -1; /* not a proper rotation near these angles */
    if (A == NULL)
        return 0;
    /* d angles / d theta for a small rotation theta in J (dR = [theta]x R), then
     * its inverse */
    const double dx = R[4] * R[4] + R[7] * R[7], dy = R[2] * R[2] + R[8] * R[8],
                 dz = R[0] * R[0] + R[3] * R[3];
    const double D[9] = {1.0, -R[4] * R[1] / dx, -R[7] * R[1] / dx,
                         -R[2] * R[5] / dy, 1.0, -R[8] * R[5] / dy,
                         -R[0] * R[6] / dz, -R[3] * R[6] / dz, 1.0};
    return invert3(D, A);
}

void usrsub_rotation_vector(const double R[9], double r[3])
{
    /* the quaternion by Shepperd's method (w >= 0), then 2 atan2(|v|, w) v/|v| */
    const double tr = R[0] + R[4] + R[8];
    double w, v[3];
    if (tr >= R[0] && tr >= R[4] && tr >= R[8]) {
        w = 0.5 * sqrt(fmax(1.0 + tr, 0.0));
        const double f = 0.25 / w;
        v[0] = (R[7] - R[5]) * f, v[1] = (R[2] - R[6]) * f, v[2] = (R[3] - R[1]) * f;
    } else {
        const int i = R[0] >= R[4] && R[0] >= R[8] ? 0 : R[4] >= R[8] ? 1 : 2;
        const int j = (i + 1) % 3, k = (i + 2) % 3;
        v[i] = 0.5 * sqrt(fmax(1.0 + R[4 * i] - R[4 * j] - R[4 * k], 0.0));
        const double f = 0.25 / v[i];
        w = (R[3 * k + j] - R[3 * j + k]) * f;
        v[j] = (R[3 * j + i] + R[3 * i + j]) * f;
        v[k] = (R[3 * k + i] + R[3 * i + k]) * f;
        if (w < 0.0)
            w = -w, v[0] = -v[0], v[1] = -v[1], v[2] = -v[2];
    }
    const double n = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    /* 2 atan2(n, w) / n, which tends to 2 / w */
    const double f = n > 1e-8 ? 2.0 * atan2(n, w) / n : 2.0 / w;
    r[0] = f * v[0], r[1] = f * v[1], r[2] = f * v[2];
}

/* c(t) = (1 - (t/2) cot(t/2)) / t^2 and g = c'(t) / t: series below 0.5 (where
 * the closed forms cancel), Bernoulli numbers' coefficients */
static void tangent_coefficients(double t, double *c, double *g)
{
    if (t < 0.5) {
        static const double cs[] = {8.333333333333333e-02, 1.388888888888889e-03,
                                    3.306878306878307e-05, 8.267195767195768e-07,
                                    2.087675698786810e-08, 5.284190138687493e-10,
                                    1.338253653068468e-11, 3.389680296322583e-13};
        static const double gs[] = {2.777777777777778e-03, 1.322751322751323e-04,
                                    4.960317460317460e-06, 1.670140559029448e-07,
                                    5.284190138687493e-09, 1.605904383682161e-10,
                                    4.745552414851616e-12, 1.373769929004455e-13};
        const double t2 = t * t;
        double sc = 0.0, sg = 0.0;
        for (int k = 7; k >= 0; --k) {
            sc = sc * t2 + cs[k];
            sg = sg * t2 + gs[k];
        }
        *c = sc, *g = sg;
        return;
    }
    double s, co;
    usrsub_sincos(0.5 * t, &s, &co);
    const double cot = co / s;
    *c = 1.0 / (t * t) - cot / (2.0 * t);
    const double dc = -2.0 / (t * t * t) + cot / (2.0 * t * t) + 1.0 / (4.0 * t * s * s);
    *g = dc / t;
}

void usrsub_tangent_inverse(const double r[3], double Jinv[9], double *dJinv)
{
    const double t = sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
    double c, g;
    tangent_coefficients(t, &c, &g);
    /* K = [r]x, K^2 = r r^T - t^2 I */
    const double K[9] = {0.0, -r[2], r[1], r[2], 0.0, -r[0], -r[1], r[0], 0.0};
    double K2[9];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            K2[3 * i + j] = r[i] * r[j] - (i == j ? t * t : 0.0);
    for (int n = 0; n < 9; ++n)
        Jinv[n] = (n % 4 == 0 ? 1.0 : 0.0) - 0.5 * K[n] + c * K2[n];
    if (dJinv == NULL)
        return;
    /* d/dr_k: -[e_k]x / 2 + g r_k K^2 + c (e_k r^T + r e_k^T - 2 r_k I) */
    for (int k = 0; k < 3; ++k) {
        double *D = dJinv + 9 * k;
        double E[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
        const int a = (k + 1) % 3, b = (k + 2) % 3; /* [e_k]x has +1 at (b, a), -1 at (a, b) */
        E[3 * b + a] = 1.0, E[3 * a + b] = -1.0;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) {
                const double dK2 = (i == k ? r[j] : 0.0) + (j == k ? r[i] : 0.0) -
                                   (i == j ? 2.0 * r[k] : 0.0);
                D[3 * i + j] = -0.5 * E[3 * i + j] + g * r[k] * K2[3 * i + j] + c * dK2;
            }
    }
}

static void mat3_vec(const double *M, const double *v, double *out)
{
    for (int i = 0; i < 3; ++i)
        out[i] = M[3 * i] * v[0] + M[3 * i + 1] * v[1] + M[3 * i + 2] * v[2];
}

void usrsub_rotation_map_make(usrsub_rotation_map *m, const double R[9], const double omega[3],
                              const double *A)
{
    usrsub_rotation_vector(R, m->r);
    usrsub_tangent_inverse(m->r, m->Jinv, A != NULL ? m->dJinv : NULL);
    mat3_vec(m->Jinv, omega, m->rdot);
    if (A == NULL)
        return;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            m->dr_da[3 * i + j] = m->Jinv[3 * i] * A[j] + m->Jinv[3 * i + 1] * A[3 + j] +
                                  m->Jinv[3 * i + 2] * A[6 + j];
    double dw[3][3]; /* (dJinv/dr_k) omega */
    for (int k = 0; k < 3; ++k)
        mat3_vec(m->dJinv + 9 * k, omega, dw[k]);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            m->drdot_da[3 * i + j] = dw[0][i] * m->dr_da[j] + dw[1][i] * m->dr_da[3 + j] +
                                     dw[2][i] * m->dr_da[6 + j];
}

void usrsub_rotation_map_forces(const usrsub_rotation_map *m, const double Q[6],
                                const double *dQdd, const double *dQdv, double F[6],
                                double *dFdd, double *dFdv)
{
    const double *Ji = m->Jinv;
    F[0] = Q[0], F[1] = Q[1], F[2] = Q[2];
    for (int i = 0; i < 3; ++i) /* T = J^-T Q_r */
        F[3 + i] = Ji[i] * Q[3] + Ji[3 + i] * Q[4] + Ji[6 + i] * Q[5];
    if (dFdd == NULL || dQdd == NULL)
        return;
    /* dQ/d(angles) and dQ/d(omega) through r(angles) and rdot(angles, omega) */
    double dQa[18], dQw[18]; /* [i + 6 j], j = 0..2 */
    for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 3; ++j) {
            double sa = 0.0, sw = 0.0;
            for (int k = 0; k < 3; ++k) {
                sa += dQdd[i + 6 * (3 + k)] * m->dr_da[3 * k + j] +
                      dQdv[i + 6 * (3 + k)] * m->drdot_da[3 * k + j];
                sw += dQdv[i + 6 * (3 + k)] * Ji[3 * k + j];
            }
            dQa[i + 6 * j] = sa, dQw[i + 6 * j] = sw;
        }
    /* (dJ^-T / dr_k Q_r) for the torque's own dependence on r */
    double dT[3][3];
    for (int k = 0; k < 3; ++k)
        for (int i = 0; i < 3; ++i) {
            const double *D = m->dJinv + 9 * k;
            dT[k][i] = D[i] * Q[3] + D[3 + i] * Q[4] + D[6 + i] * Q[5];
        }
    for (int j = 0; j < 6; ++j) {
        /* the inputs: x (j < 3) or the angles; v or omega */
        double cd[6], cv[6];
        for (int i = 0; i < 6; ++i) {
            cd[i] = j < 3 ? dQdd[i + 6 * j] : dQa[i + 6 * (j - 3)];
            cv[i] = j < 3 ? dQdv[i + 6 * j] : dQw[i + 6 * (j - 3)];
        }
        for (int i = 0; i < 3; ++i) {
            dFdd[i + 6 * j] = cd[i];
            dFdv[i + 6 * j] = cv[i];
            double td = Ji[i] * cd[3] + Ji[3 + i] * cd[4] + Ji[6 + i] * cd[5];
            if (j >= 3)
                for (int k = 0; k < 3; ++k)
                    td += dT[k][i] * m->dr_da[3 * k + (j - 3)];
            dFdd[3 + i + 6 * j] = td;
            dFdv[3 + i + 6 * j] = Ji[i] * cv[3] + Ji[3 + i] * cv[4] + Ji[6 + i] * cv[5];
        }
    }
}
