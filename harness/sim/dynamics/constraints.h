/*
 * The couplers in the equations of motion: one Lagrange multiplier each, with
 * COUSUB/COUXX for the constraint and its Jacobian and COUXX2 for the
 * velocity-squared term; after a step, positions and velocities are
 * projected back onto phi = 0 and its rate.
 */
#ifndef HX_SIM_DYNAMICS_CONSTRAINTS_H
#define HX_SIM_DYNAMICS_CONSTRAINTS_H

#include "sim/dynamics/dynamics.h"

/* The constraints stage: the couplers' multipliers (dd->lambda) into the
 * accelerations udot (those of the loads alone on entry). */
int hx_constraints_apply(const hx_dynamics *d, hx_dynamics_data *dd, double t, const double *y,
                         double *udot);

/* The velocities (indices into u) the couplers join, each once; returns
 * their count (at most nu). */
int hx_constraints_coupled(const hx_dynamics *d, int *index);

/* The couplers' share of the accelerations is udot = P udot_free + c(q, u),
 * with P = I - M^-1 G^T (G M^-1 G^T)^-1 G: P over the coupled velocities
 * (index, count, from hx_constraints_coupled), column-major count x count;
 * work holds nc (nc + 1) values. 0, or -1 (dd->message). */
int hx_constraints_projector(const hx_dynamics *d, hx_dynamics_data *dd, double t,
                             const double *y, const int *index, int count, double *work,
                             double *P);

/* Normalizes quaternions and projects onto the couplers, the largest
 * residuals left kept in dd->max_phi, max_phidot; returns 0 or -1. */
int hx_constraints_project(const hx_dynamics *d, hx_dynamics_data *dd, double t, double *y);

/* Largest |phi| and |dphi/dt| of the couplers at a state. */
int hx_constraints_residuals(const hx_dynamics *d, hx_dynamics_data *dd, double t,
                             const double *y, double *phi, double *phidot);

/* Generalized force coupler puts on joint `joint` of its list: G_kj lambda_k,
 * with the multipliers of dd's evaluation. */
double hx_constraints_coupler_force(const hx_dynamics *d, hx_dynamics_data *dd, double t,
                                    const double *y, int coupler, int joint);

#endif
