/*
 * The user force elements in the equations of motion: each is called with the
 * dynamics' state bound, its result turned into world axes and applied at I,
 * its reaction on J's body at the same point.
 */
#ifndef HX_SIM_DYNAMICS_ELEMENT_FORCES_H
#define HX_SIM_DYNAMICS_ELEMENT_FORCES_H

#include "sim/dynamics/dynamics.h"

/* The force elements at d->frames; *power receives the power of their forces. */
int hx_element_forces_apply(hx_dynamics *d, double *power);

#endif
