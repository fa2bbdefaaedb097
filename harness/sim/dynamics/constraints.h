/*
 * The couplers in the equations of motion: one Lagrange multiplier each, with
 * COUSUB/COUXX for the constraint and its Jacobian and COUXX2 for the
 * velocity-squared term; after a step, positions and velocities are
 * projected back onto phi = 0 and its rate.
 */
#ifndef HX_SIM_DYNAMICS_CONSTRAINTS_H
#define HX_SIM_DYNAMICS_CONSTRAINTS_H

#include "sim/dynamics/dynamics.h"

/* The couplers' multipliers into the accelerations udot (those of the
 * loads alone on entry). */
int hx_constraints_apply(hx_dynamics *d, double t, const double *y, double *udot);

/* Normalizes quaternions and projects onto the couplers; returns 0 or -1. */
int hx_constraints_project(hx_dynamics *d, double t, double *y);

/* Largest |phi| and |dphi/dt| of the couplers at a state. */
int hx_constraints_residuals(hx_dynamics *d, double t, const double *y, double *phi,
                             double *phidot);

/* Generalized force coupler puts on joint `joint` of its list: G_kj lambda_k. */
double hx_constraints_coupler_force(hx_dynamics *d, double t, const double *y, int coupler,
                                    int joint);

#endif
