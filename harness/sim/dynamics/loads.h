/* Gravity and the model's loads on the bodies. */
#ifndef HX_SIM_DYNAMICS_LOADS_H
#define HX_SIM_DYNAMICS_LOADS_H

#include "sim/dynamics/dynamics.h"

/* What one load puts on the bodies at a state: a force F at a world point
 * and a couple T (world axes) on each of one or two bodies (the second the
 * reaction). */
typedef struct hx_load_share {
    int count;
    int body[2];
    double point[2][3], F[2][3], T[2][3];
} hx_load_share;

/* Load k at state s and time t. */
void hx_load_share_at(const hx_dynamics *d, const hx_frames *s, double t, int k,
                      hx_load_share *share);

/* Gravity and the model's loads at time t at d->frames; returns their power. */
double hx_loads_apply(hx_dynamics *d, double t);

#endif
