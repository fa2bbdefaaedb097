/* The bushing's LuGre friction torque (lugre_friction.h). */
#include "usrsub/core/lugre_friction.h"

#include <math.h>
#include <string.h>

#include "usrsub/core/step.h"

/* half-width of the blend between the two torques, in (|tj| - |tp|) / (|tj| + |tp|) */
#define SWITCH_BAND 0.05

static double dot3(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* c = a b, 3x3 column-major */
static void mul3(const double *a, const double *b, double *c)
{
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i)
            c[i + 3 * j] = a[i] * b[3 * j] + a[i + 3] * b[1 + 3 * j] + a[i + 6] * b[2 + 3 * j];
}

void usrsub_friction_eval(const usrsub_friction *f, const double FN[3], const double z[3],
                          const double w[3], double tau[3], double zdot[3],
                          usrsub_friction_partials *p)
{
    const double rb = f->ball_radius, s0 = f->bristle_stiffness, s2 = f->slip_damping;
    /* the rate function, the bristle damping's fade, and their slopes in |w| */
    const double wm = sqrt(dot3(w, w)), a = rb * wm / f->transition_velocity;
    const double decay = exp(-a * a), ddecay = decay * (-2.0 * a * rb / f->transition_velocity);
    double g = f->mu_dynamic, dg = 0.0;
    if (f->stiction) {
        g += (f->mu_static - f->mu_dynamic) * decay;
        dg = (f->mu_static - f->mu_dynamic) * ddecay;
    }
    const double s1 = f->bristle_damping * decay, ds1 = f->bristle_damping * ddecay;
    const double C0 = rb * wm * s0 / g, dC0 = rb * s0 * (g - wm * dg) / (g * g);
    double mu[3], unit_w[3] = {0, 0, 0};
    for (int i = 0; i < 3; ++i) {
        zdot[i] = rb * w[i] - C0 * z[i];
        mu[i] = -(s0 * z[i] + s1 * zdot[i] + s2 * rb * w[i]);
        if (wm > 0.0)
            unit_w[i] = w[i] / wm;
    }
    /* the joint-force torque and the preload torque, blended where their sizes
     * cross (the vendor's switch is the band's zero-width limit) */
    const double N = sqrt(dot3(FN, FN)), kp = f->preload_torque / f->mu_static;
    double tj[3] = {0, 0, 0}, tp[3], n[3] = {0, 0, 0};
    if (N > 0.0)
        for (int i = 0; i < 3; ++i)
            n[i] = FN[i] / N;
    /* r_B N (mu - n (n . mu)): the part of mu across the load, with the unit
     * normal, so that the part along it cancels at the size of mu, not of N mu */
    const double nmu = dot3(n, mu);
    for (int i = 0; i < 3; ++i) {
        if (N > 0.0)
            tj[i] = rb * N * (mu[i] - n[i] * nmu);
        tp[i] = kp * mu[i];
    }
    const double aj = sqrt(dot3(tj, tj)), ap = sqrt(dot3(tp, tp));
    double weight = 1.0, dweight = 0.0; /* of the joint torque; dweight: d/d(ratio) */
    if (f->preload_torque > 0.0 && (N == 0.0 || aj + ap > 0.0)) {
        const double ratio = N > 0.0 ? (aj - ap) / (aj + ap) : -1.0;
        const usrsub_jet step = usrsub_step(ratio, -SWITCH_BAND, 0.0, SWITCH_BAND, 1.0);
        weight = step.value, dweight = step.d1;
    }
    for (int i = 0; i < 3; ++i)
        tau[i] = tp[i] + weight * (tj[i] - tp[i]);
    if (p == NULL)
        return;

    /* mu against z and w */
    double dmu_dz[9], dmu_dw[9];
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i) {
            const double id = i == j;
            p->dzdot_dz[i + 3 * j] = -C0 * id;
            p->dzdot_dw[i + 3 * j] = rb * id - z[i] * dC0 * unit_w[j];
            dmu_dz[i + 3 * j] = -(s0 * id + s1 * p->dzdot_dz[i + 3 * j]);
            dmu_dw[i + 3 * j] = -(s1 * p->dzdot_dw[i + 3 * j] + zdot[i] * ds1 * unit_w[j] +
                                  s2 * rb * id);
        }
    /* each torque against F, z and w: [F | z | w], 3 x 9 */
    double dtj[27] = {0}, dtp[27] = {0}, dtj_dmu[9] = {0};
    if (N > 0.0)
        for (int j = 0; j < 3; ++j)
            for (int i = 0; i < 3; ++i) {
                const double id = i == j, ni = n[i], nj = n[j];
                dtj_dmu[i + 3 * j] = rb * N * (id - ni * nj);
                dtj[i + 3 * j] = rb * (mu[i] * nj - nmu * id - ni * mu[j] + nmu * ni * nj);
            }
    mul3(dtj_dmu, dmu_dz, dtj + 9);
    mul3(dtj_dmu, dmu_dw, dtj + 18);
    for (int k = 0; k < 9; ++k) {
        dtp[9 + k] = kp * dmu_dz[k];
        dtp[18 + k] = kp * dmu_dw[k];
    }
    /* d ratio = 2 (ap d aj - aj d ap) / (aj + ap)^2, d aj = (tj / aj) . d tj */
    double dratio[9] = {0};
    if (dweight != 0.0)
        for (int c = 0; c < 9; ++c) {
            const double daj = aj > 0.0 ? dot3(tj, dtj + 3 * c) / aj : 0.0;
            const double dap = ap > 0.0 ? dot3(tp, dtp + 3 * c) / ap : 0.0;
            dratio[c] = 2.0 * (ap * daj - aj * dap) / ((aj + ap) * (aj + ap));
        }
    double *out[3] = {p->dtau_dF, p->dtau_dz, p->dtau_dw};
    for (int c = 0; c < 9; ++c)
        for (int i = 0; i < 3; ++i)
            out[c / 3][i + 3 * (c % 3)] = dtp[i + 3 * c] + weight * (dtj[i + 3 * c] - dtp[i + 3 * c]) +
                                          (tj[i] - tp[i]) * dweight * dratio[c];
}
