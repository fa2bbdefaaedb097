/*
 * The constraint system's rows written on joint coordinates
 * (joint_coordinate.h): a coupler's (COUSUB/COUXX/COUXX2 or the built-in
 * scales) and a Motion_Joint's on a joint that is not reduced
 * (docs/architecture.md, the constraint system). constraints.c assembles
 * them with the joints' rows.
 */
#ifndef HX_SIM_DYNAMICS_COORDINATE_ROWS_H
#define HX_SIM_DYNAMICS_COORDINATE_ROWS_H

#include "sim/dynamics/dynamics.h"

/* Coupler k's row at (t, y): phi, its values added into G (the row's
 * d->row_values, zeroed by the caller) and gamma (G u_dot = gamma; may be
 * NULL). 0, or -1 (dd->message). */
int hx_coordinate_rows_coupler(const hx_dynamics *d, hx_dynamics_data *dd, int k, double t,
                               const double *y, double *phi, double *G, double *gamma);

/* The generalized force coupler `coupler` puts on its joint `joint`:
 * dphi/dM_joint times the coupler's multiplier in dd; NAN on a failure. */
double hx_coordinate_rows_force(const hx_dynamics *d, hx_dynamics_data *dd, double t,
                                const double *y, int coupler, int joint);

/* Motion row k (d->motion_routine[k]): phi = a(q) - f(t), G (12 values: I's
 * body block, J's) and gamma = f''(t) - c (may be NULL); for a velocity
 * motion (val_type V) phi = 0 and gamma = f'(t) - c; for an acceleration
 * motion (A) phi = a(q) - s, s its displacement state in y
 * (d->motion_state[k]), and gamma = f(t) - c. 0 or -1. */
int hx_coordinate_rows_motion(const hx_dynamics *d, hx_dynamics_data *dd, int k, double t,
                              const double *y, double *phi, double G[12], double *gamma);

/* What G u is held to at motion row i (an index among all rows) at (t, y):
 * f'(t), f(t) for a velocity motion, the velocity state for an acceleration
 * motion. */
int hx_coordinate_rows_rate(const hx_dynamics *d, hx_dynamics_data *dd, int i, double t,
                            const double *y, double *rate);

/* The rate G u of joint `joint`'s coordinate in freedom at y. */
double hx_coordinate_rows_joint_rate(const hx_dynamics *d, int joint, char freedom,
                                     const double *y);

#endif
