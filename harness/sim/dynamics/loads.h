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

/* Load k at frames fr and time t. */
void hx_load_share_at(const hx_model *m, const hx_frames *fr, double t, int k,
                      hx_load_share *share);

/* The forces stage's gravity and loads at time t at dd->frames, onto the
 * bodies; returns their power. */
double hx_loads_apply(const hx_dynamics *d, hx_dynamics_data *dd, double t);

#endif
