/*
 * The general constraints' rows (Constraint_General, GCON; docs/architecture.md,
 * the constraint system): phi = f(q, t), an expression of the markers'
 * displacements and rotations and of time, one row each after the motions'
 * (d->gcon_first). G is the expression's partials in its measures (the
 * expression engine's adjoint) times each measure's derivative in its
 * bodies' motions, on the blocks of the bodies its markers sit on; the
 * velocity level is G u + df/dt = 0.
 */
#ifndef HX_SIM_DYNAMICS_EXPRESSION_ROWS_H
#define HX_SIM_DYNAMICS_EXPRESSION_ROWS_H

#include "sim/dynamics/dynamics.h"

/* The rows' blocks and scales (length: the model's length, the scale of a row
 * that reads a displacement); may widen d->row_values. 0, or -1 with msg (a
 * constraint on ground alone, or on more bodies than a row holds). */
int hx_expression_rows_init(hx_dynamics *d, double length, hx_message *msg);
/* The doubles of work the functions below take. */
size_t hx_expression_rows_work_size(const hx_dynamics *d);

/* Constraint k's phi, its row G (d->row_values wide, its blocks' slots; G
 * zero on entry; dd->gcon_twist's too, world, whatever the body's
 * coordinates) and, when gamma is not NULL, its right-hand side of
 * G udot = gamma. 0, or -1 (dd->message: the expression faulted). */
int hx_expression_rows_eval(const hx_dynamics *d, hx_dynamics_data *dd, int k, double t,
                            const double *y, double *work, double *phi, double *G,
                            double *gamma);

/* Constraint k reads TIME: G u is held to a -df/dt that may not be 0. */
int hx_expression_rows_timed(const hx_dynamics *d, int k);

/* What G u of constraint k must equal: -df/dt at (t, y). 0, or -1. */
int hx_expression_rows_rate(const hx_dynamics *d, hx_dynamics_data *dd, int k, double t,
                            const double *y, double *work, double *rate);

#endif
