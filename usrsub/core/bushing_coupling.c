/*
 * Coupled force of a group of bushing directions (docs/interface.md §3.3), with
 * its analytic partials. For the group deformation q (r = |q|, e = q/r) and
 * rate qd (v_r = qd.e, v_t = qd - v_r e, u = v_t/|v_t|), with G_i = -(g_i + C_i qdot):
 *   F = -E e - a v_r e - b v_t - h u
 *   E = sum e_i|e_i| g_i(sign(e_i) r),  a = sum C_i e_i^2,
 *   b = sum C_i u_i^2,                  h = sum u_i|u_i| g_i(0),
 * which is F_r e_r + F_n e_n of the contract. Below r = EPSILON the uncoupled
 * force is used, blended into the coupled one by a cubic STEP over
 * [EPSILON, 2 EPSILON]. Partials are column-major: [i + m j] = dF_i/dq_j.
 *
 * The group has 2 (cylindrical) or 3 (spherical) members: the plane has its
 * own closed form (below), the sphere the general loops unrolled for 3.
 */
#include <math.h>
#include <string.h>

#include "usrsub/core/bushing.h"
#include "usrsub/core/step.h"

#define MAXM 3
#define INLINE static inline __attribute__((always_inline))

INLINE void uncoupled(const usrsub_bushing_direction *const dirs[], const int m, const double *q,
                      const double *qd, double *F, double *J, double *Jv)
{
    for (int i = 0; i < m; ++i) {
        double slope;
        F[i] = -(usrsub_characteristic(dirs[i], q[i], J != NULL ? &slope : NULL) + dirs[i]->c * qd[i]);
        if (J != NULL)
            for (int j = 0; j < m; ++j) {
                J[i + m * j] = i == j ? -slope : 0.0;
                Jv[i + m * j] = i == j ? -dirs[i]->c : 0.0;
            }
    }
}

INLINE void coupled(const usrsub_bushing_direction *const dirs[], const int m, const double *q,
                    const double *qd, double r, double *F, double *J, double *Jv)
{
    double e[MAXM], g[MAXM], gs[MAXM], C[MAXM];
    double E = 0.0, kappa = 0.0, a = 0.0, vr = 0.0;
    const double inv_r = 1.0 / r;
    for (int i = 0; i < m; ++i) {
        e[i] = q[i] * inv_r;
        const double s = e[i] < 0.0 ? -1.0 : 1.0;
        g[i] = usrsub_characteristic(dirs[i], s * r, J != NULL ? &gs[i] : NULL);
        C[i] = dirs[i]->c;
        E += e[i] * fabs(e[i]) * g[i];
        if (J != NULL)
            kappa += e[i] * e[i] * gs[i];
        a += C[i] * e[i] * e[i];
        vr += qd[i] * e[i];
    }
    double vt[MAXM], vn2 = 0.0;
    for (int i = 0; i < m; ++i) {
        vt[i] = qd[i] - vr * e[i];
        vn2 += vt[i] * vt[i];
    }
    double u[MAXM] = {0, 0, 0}, g0[MAXM] = {0, 0, 0}, b = 0.0, h = 0.0, vn = 0.0, inv_vn = 0.0;
    if (vn2 > 0.0) {
        vn = sqrt(vn2);
        inv_vn = 1.0 / vn;
        for (int i = 0; i < m; ++i) {
            u[i] = vt[i] * inv_vn;
            g0[i] = dirs[i]->g_at_zero;
            b += C[i] * u[i] * u[i];
            h += u[i] * fabs(u[i]) * g0[i];
        }
    }
    for (int i = 0; i < m; ++i)
        F[i] = -E * e[i] - a * vr * e[i] - b * vt[i] - h * u[i];
    if (J == NULL)
        return;

    double P[MAXM * MAXM], T[MAXM * MAXM], dvt[MAXM * MAXM]; /* all symmetric or [i + m j] */
    for (int i = 0; i < m; ++i)
        for (int j = 0; j < m; ++j)
            P[i + m * j] = (i == j) - e[i] * e[j];
    /* grad E = P gamma / r + kappa e with gamma_i = 2|e_i| g_i; grad a = P (2 C e) / r */
    double gradE[MAXM], grada[MAXM];
    for (int i = 0; i < m; ++i) {
        double pg = 0.0, pa = 0.0;
        for (int k = 0; k < m; ++k) {
            pg += P[i + m * k] * 2.0 * fabs(e[k]) * g[k];
            pa += P[i + m * k] * 2.0 * C[k] * e[k];
        }
        gradE[i] = pg * inv_r + kappa * e[i];
        grada[i] = pa * inv_r;
    }
    /* T = d(-b v_t - h u)/d v_t */
    if (vn > 0.0) {
        for (int i = 0; i < m; ++i)
            for (int j = 0; j < m; ++j) {
                double t = -b * (i == j) - 2.0 * u[i] * (C[j] * u[j] - b * u[j]);
                double hterm = 0.0; /* (u grad h^T + h I)(I - u u^T) / vn */
                for (int k = 0; k < m; ++k)
                    hterm += (u[i] * 2.0 * fabs(u[k]) * g0[k] + h * (i == k)) *
                             ((k == j) - u[k] * u[j]);
                T[i + m * j] = t - hterm * inv_vn;
            }
    } else { /* no tangential rate: the tangential damping, linearized */
        for (int i = 0; i < m; ++i)
            for (int j = 0; j < m; ++j) {
                double s = 0.0;
                for (int k = 0; k < m; ++k)
                    s += P[i + m * k] * C[k] * P[k + m * j];
                T[i + m * j] = -s;
            }
    }
    /* d v_t / d q = -e v_t^T / r - v_r P / r */
    for (int i = 0; i < m; ++i)
        for (int j = 0; j < m; ++j)
            dvt[i + m * j] = -(e[i] * vt[j] + vr * P[i + m * j]) * inv_r;
    for (int i = 0; i < m; ++i)
        for (int j = 0; j < m; ++j) {
            double tp = 0.0, td = 0.0;
            for (int k = 0; k < m; ++k) {
                tp += T[i + m * k] * P[k + m * j];
                td += T[i + m * k] * dvt[k + m * j];
            }
            const double gradvr = vt[j] * inv_r;
            J[i + m * j] = -(e[i] * gradE[j] + E * P[i + m * j] * inv_r) -
                           (e[i] * (vr * grada[j] + a * gradvr) + a * vr * P[i + m * j] * inv_r) + td;
            Jv[i + m * j] = -a * e[i] * e[j] + tp;
        }
}

/* The plane group (cylindrical) in polar form: with e = q/r and t = e turned
 * a quarter, (-e1, e0), the tangent u of the general form is sign(w) t, so
 *   F = Fr e + Ft t,  Fr = -(E + a v_r),  Ft = -(b w + H [w != 0]),
 *   v_r = qd.e,  w = qd.t,  b = sum C_i t_i^2,  H = sum t_i|t_i| g_i(0),
 * with no root but r's; the partials from d/dq = e d/dr + t d/(r dtheta),
 * where de/dtheta = t and dt/dtheta = -e. */
INLINE void coupled_plane(const usrsub_bushing_direction *const dirs[], const double *q,
                          const double *qd, double r, double *F, double *J, double *Jv)
{
    const double inv_r = 1.0 / r;
    const double e0 = q[0] * inv_r, e1 = q[1] * inv_r, t0 = -e1, t1 = e0;
    double gs0 = 0.0, gs1 = 0.0;
    const double g0 = usrsub_characteristic(dirs[0], e0 < 0.0 ? -r : r, J != NULL ? &gs0 : NULL);
    const double g1 = usrsub_characteristic(dirs[1], e1 < 0.0 ? -r : r, J != NULL ? &gs1 : NULL);
    const double C0 = dirs[0]->c, C1 = dirs[1]->c, z0 = dirs[0]->g_at_zero, z1 = dirs[1]->g_at_zero;
    const double E = e0 * fabs(e0) * g0 + e1 * fabs(e1) * g1;
    const double a = C0 * e0 * e0 + C1 * e1 * e1, b = C0 * t0 * t0 + C1 * t1 * t1;
    const double vr = qd[0] * e0 + qd[1] * e1, w = qd[0] * t0 + qd[1] * t1;
    const int sliding = w != 0.0;
    const double H = sliding ? t0 * fabs(t0) * z0 + t1 * fabs(t1) * z1 : 0.0;
    const double Fr = -(E + a * vr), Ft = -(b * w + H);
    F[0] = Fr * e0 + Ft * t0;
    F[1] = Fr * e1 + Ft * t1;
    if (J == NULL)
        return;
    const double kappa = e0 * e0 * gs0 + e1 * e1 * gs1; /* dE/dr */
    /* d/dtheta of E, a, b, H; dv_r/dtheta = w, dw/dtheta = -v_r */
    const double dE = 2.0 * (fabs(e0) * t0 * g0 + fabs(e1) * t1 * g1);
    const double da = 2.0 * (C0 * e0 * t0 + C1 * e1 * t1), db = -da;
    const double dH = sliding ? -2.0 * (fabs(t0) * e0 * z0 + fabs(t1) * e1 * z1) : 0.0;
    const double dFr_dth = -(dE + da * vr + a * w), dFt_dth = -(db * w - b * vr + dH);
    /* dF/dq = -kappa e e^T + ((dFr/dtheta - Ft) e + (Fr + dFt/dtheta) t) t^T / r */
    const double ce = (dFr_dth - Ft) * inv_r, ct = (Fr + dFt_dth) * inv_r;
    const double n0 = ce * e0 + ct * t0, n1 = ce * e1 + ct * t1;
    J[0] = -kappa * e0 * e0 + n0 * t0;
    J[1] = -kappa * e1 * e0 + n1 * t0;
    J[2] = -kappa * e0 * e1 + n0 * t1;
    J[3] = -kappa * e1 * e1 + n1 * t1;
    /* dF/dqd = -a e e^T - b t t^T */
    Jv[0] = -a * e0 * e0 - b * t0 * t0;
    Jv[1] = Jv[2] = -a * e0 * e1 - b * t0 * t1;
    Jv[3] = -a * e1 * e1 - b * t1 * t1;
}

INLINE void group_force(const usrsub_bushing_direction *const dirs[], const int m, double epsilon,
                        const double *q, const double *qd, double *F, double *dFdq,
                        double *dFdqd)
{
    double r2 = 0.0;
    for (int i = 0; i < m; ++i)
        r2 += q[i] * q[i];
    const double r = sqrt(r2);
    if (__builtin_expect(r >= 2.0 * epsilon, 1)) {
        if (m == 2)
            coupled_plane(dirs, q, qd, r, F, dFdq, dFdqd);
        else
            coupled(dirs, m, q, qd, r, F, dFdq, dFdqd);
        return;
    }
    if (!(r > epsilon)) { /* at and near r = 0 the direction e is undefined */
        uncoupled(dirs, m, q, qd, F, dFdq, dFdqd);
        return;
    }
    const usrsub_jet w = usrsub_step(r, epsilon, 0.0, 2.0 * epsilon, 1.0);
    double Fu[MAXM], Ju[MAXM * MAXM], Jvu[MAXM * MAXM];
    double Fc[MAXM], Jc[MAXM * MAXM], Jvc[MAXM * MAXM];
    double *pu = dFdq != NULL ? Ju : NULL, *pvu = dFdq != NULL ? Jvu : NULL;
    double *pc = dFdq != NULL ? Jc : NULL, *pvc = dFdq != NULL ? Jvc : NULL;
    uncoupled(dirs, m, q, qd, Fu, pu, pvu);
    if (m == 2)
        coupled_plane(dirs, q, qd, r, Fc, pc, pvc);
    else
        coupled(dirs, m, q, qd, r, Fc, pc, pvc);
    for (int i = 0; i < m; ++i)
        F[i] = (1.0 - w.value) * Fu[i] + w.value * Fc[i];
    if (dFdq == NULL)
        return;
    for (int i = 0; i < m; ++i)
        for (int j = 0; j < m; ++j) {
            dFdq[i + m * j] = (1.0 - w.value) * Ju[i + m * j] + w.value * Jc[i + m * j] +
                              (Fc[i] - Fu[i]) * w.d1 * q[j] / r;
            dFdqd[i + m * j] = (1.0 - w.value) * Jvu[i + m * j] + w.value * Jvc[i + m * j];
        }
}

void usrsub_bushing_coupling_force(const usrsub_bushing_direction *const dirs[], int m,
                                   double epsilon, const double *q, const double *qd, double *F,
                                   double *dFdq, double *dFdqd)
{
    if (m == 2)
        group_force(dirs, 2, epsilon, q, qd, F, dFdq, dFdqd);
    else
        group_force(dirs, 3, epsilon, q, qd, F, dFdq, dFdqd);
}
