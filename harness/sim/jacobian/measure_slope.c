/* The slopes of the measures of markers (measure_slope.h). Each line's
 * formula is the derivative of hx_measure_value's (measure_functions.c),
 * with R_X' = (1 + [dth_X]x) R_X for a marker's axes. */
#include "sim/jacobian/measure_slope.h"

#include <math.h>

#include "base/orientation_systems.h"
#include "base/vecmath.h"
#include "frames/measures.h"

static const hx_motion still;

/* d atan2(y, x) = (x dy - y dx) / (x^2 + y^2); 0 at the origin. */
static double atan2_slope(double y, double x, double dy, double dx)
{
    const double r2 = x * x + y * y;
    return r2 > 0.0 ? (x * dy - y * dx) / r2 : 0.0;
}

/* d sqrt(a^2 + b^2); 0 at the origin. */
static double hypot_slope(double a, double b, double da, double db)
{
    const double h = sqrt(a * a + b * b);
    return h > 0.0 ? (a * da + b * db) / h : 0.0;
}

/* The relative rotation R = R_J^T R_I and its change
 * dR = R_J^T [dth_I - dth_J]x R_I. */
static void rotation_slope(const hx_frame *I, const hx_frame *J, const hx_motion *mI,
                           const hx_motion *mJ, double R[9], double dR[9])
{
    double w[3], A[9];
    v3_sub(w, mI->dth, mJ->dth);
    for (int j = 0; j < 3; ++j) {
        const double axis[3] = {I->R[j], I->R[3 + j], I->R[6 + j]};
        double c[3];
        v3_cross(c, w, axis);
        A[j] = c[0], A[3 + j] = c[1], A[6 + j] = c[2];
    }
    m3_tmul(R, J->R, I->R);
    m3_tmul(dR, J->R, A);
}

/* The change of R_K^T x when x changes by dx and K turns by dth_K:
 * R_K^T (dx - dth_K x x). */
static void in_axes_slope(const hx_frame *K, const hx_motion *mK, const double x[3],
                          const double dx[3], double out[3])
{
    double t[3], u[3];
    v3_cross(t, mK->dth, x);
    v3_sub(u, dx, t);
    m3_tapply(out, K->R, u);
}

/* The velocity of I relative to J differentiated in L (world axes) and its
 * change: v = v_I - v_J - w_L x r, r = p_I - p_J. */
static void rate_slope(const hx_frame *const f[3], const hx_motion *const mo[3], double v[3],
                       double dv[3], double r[3], double dr[3])
{
    double t[3];
    v3_sub(r, f[0]->p, f[1]->p);
    v3_sub(dr, mo[0]->dp, mo[1]->dp);
    v3_sub(v, f[0]->v, f[1]->v);
    v3_cross(t, f[2]->w, r);
    v3_sub(v, v, t);
    v3_sub(dv, mo[0]->dv, mo[1]->dv);
    v3_cross(t, mo[2]->dw, r);
    v3_sub(dv, dv, t);
    v3_cross(t, f[2]->w, dr);
    v3_sub(dv, dv, t);
}

/* The 3-1-3 angles' slopes (measures.c, hx_euler313). */
static double euler313_slope(const double R[9], const double d[9], int which)
{
    const double s = sqrt(R[2] * R[2] + R[5] * R[5]);
    const double ds = hypot_slope(R[2], R[5], d[2], d[5]);
    if (which == 1)
        return atan2_slope(s, R[8], ds, d[8]);
    const double psi = s > 0.0 ? atan2_slope(R[2], -R[5], d[2], -d[5])
                       : R[8] >= 0.0 ? atan2_slope(R[3] - R[1], R[0] + R[4], d[3] - d[1], d[0] + d[4])
                                     : atan2_slope(R[3] + R[1], R[0] - R[4], d[3] + d[1], d[0] - d[4]);
    if (which == 0)
        return psi;
    if (R[8] >= 0.0)
        return atan2_slope(R[3] - R[1], R[0] + R[4], d[3] - d[1], d[0] + d[4]) - psi;
    return psi - atan2_slope(R[3] + R[1], R[0] - R[4], d[3] + d[1], d[0] - d[4]);
}

/* The 3-2-1 angles' slopes (measures.c, hx_euler321). */
static double euler321_slope(const double R[9], const double d[9], int which)
{
    const double c = sqrt(R[0] * R[0] + R[3] * R[3]);
    if (which == 1)
        return atan2_slope(-R[6], c, -d[6], hypot_slope(R[0], R[3], d[0], d[3]));
    const int up = R[6] <= 0.0;
    const double defined = up ? atan2_slope(R[1] - R[5], R[4] + R[2], d[1] - d[5], d[4] + d[2])
                              : atan2_slope(-(R[1] + R[5]), R[4] - R[2], -(d[1] + d[5]),
                                            d[4] - d[2]);
    const double yaw = c > 0.0 ? atan2_slope(R[3], R[0], d[3], d[0]) : up ? -defined : defined;
    if (which == 0)
        return yaw;
    return up ? defined + yaw : defined - yaw;
}

/* The projection angle about J's axis (measures.c, hx_projection_angle). */
static double projection_slope(const double R[9], const double d[9], int axis)
{
    switch (axis) {
    case 0: return atan2_slope(R[7], R[4], d[7], d[4]);
    case 1: return atan2_slope(R[2], R[8], d[2], d[8]);
    default: return atan2_slope(R[3], R[0], d[3], d[0]);
    }
}

/* ORIENT's measure `code` (measure_functions.c) of the relative rotation R
 * changing by dR = [w]x R, w the turn of I relative to J in J's axes. */
static double orientation_slope(int code, const double R[9], const double dR[9])
{
    const int system = code / HX_ORIENTATION_COMPONENTS + 1;
    const int k = code % HX_ORIENTATION_COMPONENTS;
    const hx_orientation_system *s = hx_orientation_system_at(system);
    switch (s->kind) {
    case HX_ORIENTATION_BODY:
    case HX_ORIENTATION_SPACE: {
        const int space = s->kind == HX_ORIENTATION_SPACE;
        const int axes[3] = {s->axes[space ? 2 : 0], s->axes[1], s->axes[space ? 0 : 2]};
        const int which = space ? 2 - k : k;
        double C[9], dC[9], sign;
        if (hx_euler_canonical(axes, R, C, &sign)) {
            hx_euler_canonical(axes, dR, dC, &sign);
            return euler313_slope(C, dC, which);
        }
        hx_euler_canonical(axes, dR, dC, &sign);
        return (which == 2 ? sign : 1.0) * euler321_slope(C, dC, which);
    }
    case HX_ORIENTATION_PROJECTION:
        return projection_slope(R, dR, k);
    case HX_ORIENTATION_YPR:
        return (k == 1 ? -1.0 : 1.0) * euler321_slope(R, dR, k);
    case HX_ORIENTATION_PARAMETERS:
    case HX_ORIENTATION_RODRIGUES: {
        /* e' = (0, w) e / 2, w from dR R^T = [w]x */
        double e[4], W[9], de[4];
        hx_euler_parameters(R, e);
        m3_mult(W, dR, R);
        const double w[4] = {0.0, W[7], W[2], W[3]};
        quat_mul(de, w, e);
        for (int i = 0; i < 4; ++i)
            de[i] *= 0.5;
        if (s->kind == HX_ORIENTATION_PARAMETERS)
            return de[k];
        return e[0] > 0.0 ? (de[k + 1] * e[0] - e[k + 1] * de[0]) / (e[0] * e[0]) : 0.0;
    }
    default: /* HX_ORIENTATION_COSINES */
        return dR[3 * (k % 3) + k / 3];
    }
}

double hx_measure_slope(hx_measure m, const hx_frame *const f[4], const hx_motion *const mo[4])
{
    const hx_motion *const M[4] = {mo[0] ? mo[0] : &still, mo[1] ? mo[1] : &still,
                                   mo[2] ? mo[2] : &still, mo[3] ? mo[3] : &still};
    const hx_frame *I = f[0], *J = f[1];
    double r[3], dr[3], v[3], dv[3], out[3], R[9], dR[9];
    v3_sub(r, I->p, J->p);
    v3_sub(dr, M[0]->dp, M[1]->dp);
    if (m >= HX_MEASURE_ORIENT) {
        rotation_slope(I, J, M[0], M[1], R, dR);
        return orientation_slope(m - HX_MEASURE_ORIENT, R, dR);
    }
    switch (m) {
    case HX_MEASURE_DX:
    case HX_MEASURE_DY:
    case HX_MEASURE_DZ: /* R_K^T r */
        in_axes_slope(f[2], M[2], r, dr, out);
        return out[m - HX_MEASURE_DX];
    case HX_MEASURE_DM: {
        const double len = v3_norm(r);
        return len > 0.0 ? v3_dot(r, dr) / len : 0.0;
    }
    case HX_MEASURE_AX:
    case HX_MEASURE_AY:
    case HX_MEASURE_AZ:
        rotation_slope(I, J, M[0], M[1], R, dR);
        return projection_slope(R, dR, m - HX_MEASURE_AX);
    case HX_MEASURE_YAW:
    case HX_MEASURE_PITCH: /* the second angle negated */
    case HX_MEASURE_ROLL:
        rotation_slope(I, J, M[0], M[1], R, dR);
        return (m == HX_MEASURE_PITCH ? -1.0 : 1.0) * euler321_slope(R, dR, m - HX_MEASURE_YAW);
    case HX_MEASURE_PSI:
    case HX_MEASURE_THETA:
    case HX_MEASURE_PHI:
        rotation_slope(I, J, M[0], M[1], R, dR);
        return euler313_slope(R, dR, m - HX_MEASURE_PSI);
    case HX_MEASURE_INCANG: { /* atan2(|r x b|, r . b), b = p_K - p_J */
        double b[3], db[3], c[3], dc[3], t[3];
        v3_sub(b, f[2]->p, J->p);
        v3_sub(db, M[2]->dp, M[1]->dp);
        v3_cross(c, r, b);
        v3_cross(dc, dr, b);
        v3_cross(t, r, db);
        v3_add(dc, dc, t);
        const double len = v3_norm(c);
        const double dlen = len > 0.0 ? v3_dot(c, dc) / len : 0.0;
        if (len == 0.0 && v3_dot(r, b) == 0.0)
            return 0.0; /* J on I or K: the value is 0 there */
        return atan2_slope(len, v3_dot(r, b), dlen, v3_dot(dr, b) + v3_dot(r, db));
    }
    case HX_MEASURE_VX:
    case HX_MEASURE_VY:
    case HX_MEASURE_VZ: { /* R_K^T v, v differentiated in L */
        const hx_frame *const g[3] = {I, J, f[3]};
        const hx_motion *const n[3] = {M[0], M[1], M[3]};
        rate_slope(g, n, v, dv, r, dr);
        in_axes_slope(f[2], M[2], v, dv, out);
        return out[m - HX_MEASURE_VX];
    }
    case HX_MEASURE_VM:
    case HX_MEASURE_VR: { /* |v|; v . r / |r| */
        const hx_frame *const g[3] = {I, J, f[2]};
        const hx_motion *const n[3] = {M[0], M[1], M[2]};
        rate_slope(g, n, v, dv, r, dr);
        if (m == HX_MEASURE_VM) {
            const double speed = v3_norm(v);
            return speed > 0.0 ? v3_dot(v, dv) / speed : 0.0;
        }
        const double len = v3_norm(r);
        if (!(len > 0.0))
            return 0.0;
        const double vr = v3_dot(v, r);
        return (v3_dot(dv, r) + v3_dot(v, dr)) / len - vr * v3_dot(r, dr) / (len * len * len);
    }
    case HX_MEASURE_WX:
    case HX_MEASURE_WY:
    case HX_MEASURE_WZ: /* R_K^T (w_I - w_J) */
        v3_sub(v, I->w, J->w);
        v3_sub(dv, M[0]->dw, M[1]->dw);
        in_axes_slope(f[2], M[2], v, dv, out);
        return out[m - HX_MEASURE_WX];
    case HX_MEASURE_WM: {
        v3_sub(v, I->w, J->w);
        v3_sub(dv, M[0]->dw, M[1]->dw);
        const double spin = v3_norm(v);
        return spin > 0.0 ? v3_dot(v, dv) / spin : 0.0;
    }
    default:
        return 0.0;
    }
}
