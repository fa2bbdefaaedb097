/*
 * The bushing's friction torque (docs/interface.md §3.8), a LuGre model on
 * three bristle states z (a length at the ball's surface), driven by the slip
 * rate w (I relative to J, J axes) and loaded by the normal force F_N:
 *   g(|w|)  = mu_d + (mu_s - mu_d) exp(-(r_B |w| / v_s)^2)    (mu_d when SLIDING)
 *   C0(|w|) = r_B |w| sigma0 / g(|w|)
 *   zdot    = r_B w - C0 z
 *   mu      = -(sigma0 z + sigma1 exp(-(r_B |w| / v_s)^2) zdot + sigma2 r_B w)
 *   tau_jf  = r_B (|F_N| mu - F_N (F_N . mu) / |F_N|)        (r x (mu x F_N), r = r_B F_N/|F_N|)
 *   tau_pre = (T_pre / mu_s) mu
 *   tau     = tau_pre + W (tau_jf - tau_pre),  W = STEP(rho, -0.05, 0, 0.05, 1),
 *             rho = (|tau_jf| - |tau_pre|) / (|tau_jf| + |tau_pre|)
 * The vendor switches to the larger torque; the two point different ways when
 * mu has a part along F_N, so the switch is a jump: the blend keeps the torque
 * (and a series mount's balance through it) continuous. The bristle damping
 * fades with the slip, as is usual for LuGre, so that the friction never
 * pushes along the slip. Torques only; partials exact where the law is smooth;
 * at the kinks |w| = 0, F_N = 0 and |mu| = 0 they drop the terms through the
 * kink's unit vector (w/|w|, F_N/|F_N|, mu/|mu|): at |w| = 0 this is the
 * mean of the one-sided slopes along any line through rest.
 */
#ifndef USRSUB_LUGRE_FRICTION_H
#define USRSUB_LUGRE_FRICTION_H

#ifdef __cplusplus
extern "C" {
#endif

typedef struct usrsub_friction {
    int active;
    double mu_static, mu_dynamic;
    double transition_velocity; /* v_s, a length per time at the ball's surface */
    double bristle_stiffness;   /* sigma0, per length */
    double bristle_damping;     /* sigma1, time per length */
    double slip_damping;        /* sigma2, time per length */
    double ball_radius;         /* r_B */
    double preload_torque;      /* T_pre */
    int stiction;               /* EFFECT 'STICTION' (1) or 'SLIDING' (0: g = mu_d) */
} usrsub_friction;

/* The torque and the bristle rates, with their 3x3 partials (column-major,
 * [i + 3 j] = d out_i / d in_j; p may be NULL). */
typedef struct usrsub_friction_partials {
    double dtau_dF[9], dtau_dz[9], dtau_dw[9];
    double dzdot_dz[9], dzdot_dw[9];
} usrsub_friction_partials;

void usrsub_friction_eval(const usrsub_friction *f, const double FN[3], const double z[3],
                          const double w[3], double tau[3], double zdot[3],
                          usrsub_friction_partials *p);

#ifdef __cplusplus
}
#endif

#endif
