/* The bushing's LuGre friction torque (include/usrsub/core/lugre_friction.h). */
#include "usrsub/core/lugre_friction.h"

#include <math.h>
#include <string.h>

static double dot3(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

void usrsub_friction_eval(const usrsub_friction *f, const double FN[3], const double z[3],
                          const double w[3], double tau[3], double zdot[3],
                          usrsub_friction_partials *p)
{
    const double rb = f->ball_radius, s0 = f->bristle_stiffness, s1 = f->bristle_damping,
                 s2 = f->slip_damping;
    /* the rate function and its slope in |w| */
    const double wm = sqrt(dot3(w, w));
    double g = f->mu_dynamic, dg = 0.0;
    if (f->stiction) {
        const double a = rb * wm / f->transition_velocity, decay = exp(-a * a);
        g += (f->mu_static - f->mu_dynamic) * decay;
        dg = (f->mu_static - f->mu_dynamic) * decay * (-2.0 * a * rb / f->transition_velocity);
    }
    const double C0 = rb * wm * s0 / g, dC0 = rb * s0 * (g - wm * dg) / (g * g);
    double mu[3], unit_w[3] = {0, 0, 0};
    for (int i = 0; i < 3; ++i) {
        zdot[i] = rb * w[i] - C0 * z[i];
        mu[i] = -(s0 * z[i] + s1 * zdot[i] + s2 * rb * w[i]);
        if (wm > 0.0)
            unit_w[i] = w[i] / wm;
    }
    /* the joint-force torque and the preload torque; the larger acts */
    const double N = sqrt(dot3(FN, FN)), Fmu = dot3(FN, mu);
    double tj[3] = {0, 0, 0}, tp[3];
    for (int i = 0; i < 3; ++i) {
        if (N > 0.0)
            tj[i] = rb * (N * mu[i] - FN[i] * Fmu / N);
        tp[i] = f->preload_torque / f->mu_static * mu[i];
    }
    const int joint = dot3(tj, tj) > dot3(tp, tp);
    memcpy(tau, joint ? tj : tp, sizeof tj);
    if (p == NULL)
        return;

    double dmu_dz[9], dmu_dw[9], dtau_dmu[9];
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i) {
            const double id = i == j;
            p->dzdot_dz[i + 3 * j] = -C0 * id;
            p->dzdot_dw[i + 3 * j] = rb * id - z[i] * dC0 * unit_w[j];
            dmu_dz[i + 3 * j] = -(s0 * id + s1 * p->dzdot_dz[i + 3 * j]);
            dmu_dw[i + 3 * j] = -(s1 * p->dzdot_dw[i + 3 * j] + s2 * rb * id);
            if (joint) { /* r_B (N I - F F^T / N), and d/dF of it applied to mu */
                const double ni = FN[i] / N, nj = FN[j] / N, nmu = Fmu / N;
                dtau_dmu[i + 3 * j] = rb * (N * id - FN[i] * FN[j] / N);
                p->dtau_dF[i + 3 * j] = rb * (mu[i] * nj - nmu * id - ni * mu[j] + nmu * ni * nj);
            } else {
                dtau_dmu[i + 3 * j] = f->preload_torque / f->mu_static * id;
                p->dtau_dF[i + 3 * j] = 0.0;
            }
        }
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i) {
            double tz = 0.0, tw = 0.0;
            for (int k = 0; k < 3; ++k) {
                tz += dtau_dmu[i + 3 * k] * dmu_dz[k + 3 * j];
                tw += dtau_dmu[i + 3 * k] * dmu_dw[k + 3 * j];
            }
            p->dtau_dz[i + 3 * j] = tz;
            p->dtau_dw[i + 3 * j] = tw;
        }
}
