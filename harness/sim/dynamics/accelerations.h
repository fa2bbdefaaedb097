/*
 * The bodies' accelerations at an evaluated state (docs/interface.md §8.5,
 * §7.13): for each body, its frame origin's linear acceleration and its
 * angular acceleration, world axes, from the right-hand side's udot. What
 * requests' ACCX .. WDTZ and REQUEST/ACCELERATION read at output times.
 */
#ifndef HX_SIM_DYNAMICS_ACCELERATIONS_H
#define HX_SIM_DYNAMICS_ACCELERATIONS_H

#include "sim/dynamics/dynamics.h"

/* Six values a body (a of the frame origin, alpha; world; the ground's 0)
 * into out (6 * nbodies), from dd's frames and ydot = hx_dynamics_rhs(d, dd,
 * t, y, ydot) evaluated just before at the same state. */
void hx_accelerations_bodies(const hx_dynamics *d, const hx_dynamics_data *dd, const double *ydot,
                             double *out);

#endif
