/*
 * The rigid bodies of the dynamics: their degrees of freedom, their frames at
 * a state, the loads applied to them, and their Newton-Euler accelerations.
 */
#ifndef HX_SIM_DYNAMICS_BODIES_H
#define HX_SIM_DYNAMICS_BODIES_H

#include "sim/dynamics/dynamics.h"

int hx_bodies_init(hx_dynamics *d, hx_message *msg);
/* Every body's frame from y into dd->frames. */
void hx_bodies_set_frames(const hx_dynamics *d, hx_dynamics_data *dd, const double *y);
/* Body k's frame from y into f (only k moves: the Newton matrix's columns); the
 * ground's where the model puts it, at rest. */
void hx_bodies_frame(const hx_dynamics *d, int k, const double *y, hx_frame *f);
void hx_bodies_initial_state(const hx_dynamics *d, double *y);
/* From the loads gathered in dd->force, dd->torque at dd->frames: positions'
 * and velocities' rates of every body. */
void hx_bodies_accelerations(const hx_dynamics *d, const hx_dynamics_data *dd, const double *y,
                             double *ydot);
/* Adds F at a world point (and a couple T, may be NULL) to a body's force and
 * torque about its centre (dd->frames), with sign; returns their power (0 on
 * ground). */
double hx_bodies_apply_load(const hx_dynamics *d, hx_dynamics_data *dd, int body,
                            const double point[3], const double F[3], const double T[3],
                            double sign);
/* q <- q + h N(q) u (quaternions by their exact increment), for symplectic Euler. */
void hx_bodies_advance_positions(const hx_dynamics *d, double *y, double h);

#endif
