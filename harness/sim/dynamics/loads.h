/* Gravity and the model's loads on the bodies. */
#ifndef HX_SIM_DYNAMICS_LOADS_H
#define HX_SIM_DYNAMICS_LOADS_H

#include "sim/dynamics/dynamics.h"

/* Gravity and the model's loads at time t at d->state; returns their power. */
double hx_loads_apply(hx_dynamics *d, double t);

#endif
