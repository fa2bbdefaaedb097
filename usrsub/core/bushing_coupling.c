/*
 * Coupled force of a group of bushing directions (docs/interface.md §3.3), with its
 * analytic partials. For the group deformation q (r = |q|, e = q/r) and rate
 * qd (v_r = qd.e, v_t = qd - v_r e, u = v_t/|v_t|), with G_i = -(g_i + C_i qdot):
 *   F = -E e - a v_r e - b v_t - h u
 *   E = sum e_i|e_i| g_i(sign(e_i) r),  a = sum C_i e_i^2,
 *   b = sum C_i u_i^2,                  h = sum u_i|u_i| g_i(0),
 * which is F_r e_r + F_n e_n of the contract. Below r = EPSILON the uncoupled
 * force is used, blended into the coupled one by a cubic STEP over
 * [EPSILON, 2 EPSILON].
 */
#include <math.h>
#include <string.h>

#include "usrsub/core/bushing.h"
#include "usrsub/core/step.h"

#define MAXM 3

static void uncoupled(const usrsub_bushing_direction *const dirs[], int m, const double *q,
                      const double *qd, double *F, double *J, double *Jv)
{
    for (int i = 0; i < m; ++i) {
        double slope;
        F[i] = -(usrsub_characteristic(dirs[i], q[i], J != NULL ? &slope : NULL) + dirs[i]->c * qd[i]);
        if (J != NULL)
            for (int j = 0; j < m; ++j) {
                J[i * m + j] = i == j ? -slope : 0.0;
                Jv[i * m + j] = i == j ? -dirs[i]->c : 0.0;
            }
    }
}

static void coupled(const usrsub_bushing_direction *const dirs[], int m, const double *q,
                    const double *qd, double r, double *F, double *J, double *Jv)
{
    double e[MAXM], g[MAXM], gs[MAXM], C[MAXM];
    double E = 0.0, kappa = 0.0, a = 0.0, vr = 0.0;
    for (int i = 0; i < m; ++i) {
        e[i] = q[i] / r;
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
    const double vn = sqrt(vn2);
    double u[MAXM] = {0, 0, 0}, g0[MAXM] = {0, 0, 0}, b = 0.0, h = 0.0;
    if (vn > 0.0)
        for (int i = 0; i < m; ++i) {
            u[i] = vt[i] / vn;
            g0[i] = dirs[i]->g_at_zero;
            b += C[i] * u[i] * u[i];
            h += u[i] * fabs(u[i]) * g0[i];
        }
    for (int i = 0; i < m; ++i)
        F[i] = -E * e[i] - a * vr * e[i] - b * vt[i] - h * u[i];
    if (J == NULL)
        return;

    double P[MAXM * MAXM], T[MAXM * MAXM], dvt[MAXM * MAXM];
    for (int i = 0; i < m; ++i)
        for (int j = 0; j < m; ++j)
            P[i * m + j] = (i == j) - e[i] * e[j];
    /* grad E = P gamma / r + kappa e with gamma_i = 2|e_i| g_i; grad a = P (2 C e) / r */
    double gradE[MAXM], grada[MAXM];
    for (int i = 0; i < m; ++i) {
        double pg = 0.0, pa = 0.0;
        for (int k = 0; k < m; ++k) {
            pg += P[i * m + k] * 2.0 * fabs(e[k]) * g[k];
            pa += P[i * m + k] * 2.0 * C[k] * e[k];
        }
        gradE[i] = pg / r + kappa * e[i];
        grada[i] = pa / r;
    }
    /* T = d(-b v_t - h u)/d v_t */
    for (int i = 0; i < m; ++i)
        for (int j = 0; j < m; ++j) {
            if (vn > 0.0) {
                T[i * m + j] = -b * (i == j) - 2.0 * u[i] * (C[j] * u[j] - b * u[j]);
                double hterm = 0.0; /* (u grad h^T + h I)(I - u u^T) / vn */
                for (int k = 0; k < m; ++k)
                    hterm += (u[i] * 2.0 * fabs(u[k]) * g0[k] + h * (i == k)) *
                             ((k == j) - u[k] * u[j]);
                T[i * m + j] -= hterm / vn;
            } else { /* no tangential rate: the tangential damping, linearized */
                double s = 0.0;
                for (int k = 0; k < m; ++k)
                    s += P[i * m + k] * C[k] * P[k * m + j];
                T[i * m + j] = -s;
            }
        }
    /* d v_t / d q = -e v_t^T / r - v_r P / r */
    for (int i = 0; i < m; ++i)
        for (int j = 0; j < m; ++j)
            dvt[i * m + j] = -e[i] * vt[j] / r - vr * P[i * m + j] / r;
    for (int i = 0; i < m; ++i)
        for (int j = 0; j < m; ++j) {
            double tp = 0.0, td = 0.0;
            for (int k = 0; k < m; ++k) {
                tp += T[i * m + k] * P[k * m + j];
                td += T[i * m + k] * dvt[k * m + j];
            }
            const double gradvr = vt[j] / r;
            J[i * m + j] = -(e[i] * gradE[j] + E * P[i * m + j] / r) -
                           (e[i] * (vr * grada[j] + a * gradvr) + a * vr * P[i * m + j] / r) + td;
            Jv[i * m + j] = -a * e[i] * e[j] + tp;
        }
}

void usrsub_bushing_group_force(const usrsub_bushing_direction *const dirs[], int m,
                                double epsilon, const double *q, const double *qd, double *F,
                                double *dFdq, double *dFdqd)
{
    double r2 = 0.0;
    for (int i = 0; i < m; ++i)
        r2 += q[i] * q[i];
    const double r = sqrt(r2);
    if (!(r > epsilon)) { /* at and near r = 0 the direction e is undefined */
        uncoupled(dirs, m, q, qd, F, dFdq, dFdqd);
        return;
    }
    if (r >= 2.0 * epsilon) {
        coupled(dirs, m, q, qd, r, F, dFdq, dFdqd);
        return;
    }
    const usrsub_jet w = usrsub_step(r, epsilon, 0.0, 2.0 * epsilon, 1.0);
    double Fu[MAXM], Ju[MAXM * MAXM], Jvu[MAXM * MAXM];
    double Fc[MAXM], Jc[MAXM * MAXM], Jvc[MAXM * MAXM];
    double *pu = dFdq != NULL ? Ju : NULL, *pvu = dFdq != NULL ? Jvu : NULL;
    double *pc = dFdq != NULL ? Jc : NULL, *pvc = dFdq != NULL ? Jvc : NULL;
    uncoupled(dirs, m, q, qd, Fu, pu, pvu);
    coupled(dirs, m, q, qd, r, Fc, pc, pvc);
    for (int i = 0; i < m; ++i)
        F[i] = (1.0 - w.value) * Fu[i] + w.value * Fc[i];
    if (dFdq == NULL)
        return;
    for (int i = 0; i < m; ++i)
        for (int j = 0; j < m; ++j) {
            dFdq[i * m + j] = (1.0 - w.value) * Ju[i * m + j] + w.value * Jc[i * m + j] +
                              (Fc[i] - Fu[i]) * w.d1 * q[j] / r;
            dFdqd[i * m + j] = (1.0 - w.value) * Jvu[i * m + j] + w.value * Jvc[i * m + j];
        }
}
