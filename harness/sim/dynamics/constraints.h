/*
 * The constraint system: the couplers (one Lagrange multiplier each, with
 * COUSUB/COUXX for the constraint and its Jacobian and COUXX2 for the
 * velocity-squared term, on the coordinates of joints between any bodies:
 * joint_coordinate.h) and the joints between free bodies (their equations
 * in joint_equations.h) in one G, rows couplers first then joint by joint;
 * after a step, positions and velocities are projected back onto phi = 0 and
 * G u = 0 (docs/architecture.md, the constraint system).
 */
#ifndef HX_SIM_DYNAMICS_CONSTRAINTS_H
#define HX_SIM_DYNAMICS_CONSTRAINTS_H

#include "sim/dynamics/dynamics.h"

/* The rows of the model (d->rows, d->joint_row); 0 or -1 with msg. */
int hx_constraints_init(hx_dynamics *d, hx_message *msg);
void hx_constraints_free(hx_dynamics *d);
/* The doubles of dd->constraint_work. */
size_t hx_constraints_work_size(const hx_dynamics *d);

/* phi, G (d->row_values a row: the blocks of d->rows[i] at their slots; a
 * free body's omega in body axes) and gamma (G udot = gamma; may be NULL)
 * at a state: for the tests. 0 or -1 (dd->message). */
int hx_constraints_rows(const hx_dynamics *d, hx_dynamics_data *dd, double t, const double *y,
                        double *phi, double *G, double *gamma);

/* The constraints stage: the couplers' multipliers (dd->lambda, a row each) into the
 * accelerations udot (those of the loads alone on entry); the power the
 * time-dependent rows (motions, general constraints of TIME) put in added to
 * *power (force * length / time; may be NULL: not wanted). */
int hx_constraints_apply(const hx_dynamics *d, hx_dynamics_data *dd, double t, const double *y,
                         double *udot, double *power);

/* The velocities (indices into u) the rows join, each once (a free body's six); returns
 * their count (at most nu). */
int hx_constraints_coupled(const hx_dynamics *d, int *index);

/* The couplers' share of the accelerations is udot = P udot_free + c(q, u),
 * with P = I - M^-1 G^T (G M^-1 G^T)^-1 G: P over the coupled velocities
 * (index, count, from hx_constraints_coupled), column-major count x count.
 * index lists them in ngroups groups (group_start, ngroups + 1 entries) no
 * row joins: P is zero between groups, so one solve gives a column of every
 * group (as many solves as the largest group has velocities; one group of
 * all: one a velocity). work holds nrows (nrows + 1) values. 0, or -1
 * (dd->message). */
int hx_constraints_projector(const hx_dynamics *d, hx_dynamics_data *dd, double t,
                             const double *y, const int *index, int count,
                             const int *group_start, int ngroups, double *work, double *P);

/* Normalizes quaternions and projects onto the constraints (positions by
 * Newton, mass-weighted, then velocities); fails when they cannot be met, the largest
 * residuals left kept in dd->max_phi, max_phidot; returns 0 or -1. */
int hx_constraints_project(const hx_dynamics *d, hx_dynamics_data *dd, double t, double *y);

/* The positions alone projected onto the active rows (quaternions made unit,
 * Newton as hx_constraints_project's), the removed rows not checked: the
 * set-up's assembly before the redundant rows are found again
 * (redundancy.h). 0, or -1 (dd->message) when the active rows are not met. */
int hx_constraints_assemble(const hx_dynamics *d, hx_dynamics_data *dd, double t, double *y);

/* Largest |phi| and |dphi/dt| of the rows at a state. */
int hx_constraints_residuals(const hx_dynamics *d, hx_dynamics_data *dd, double t,
                             const double *y, double *phi, double *phidot);

/* Generalized force coupler puts on joint `joint` of its list: G_kj lambda_k,
 * with the multipliers of dd's evaluation. */
double hx_constraints_coupler_force(const hx_dynamics *d, hx_dynamics_data *dd, double t,
                                    const double *y, int coupler, int joint);

#endif
