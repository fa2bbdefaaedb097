/*
 * The forces of the constraint elements that are not joints (docs/interface.md
 * §8.3, MOTION, COUPLER, GCON): what a Motion_Joint, a Constraint_Coupler (at
 * each of its joints) and a Constraint_General put on the bodies, from the
 * multipliers of their own rows (constraints.h), at an evaluated state; the
 * functions of the language and FX .. TM read them at output times
 * (expr/evaluate.h's hx_expr_outputs.constraints).
 */
#ifndef HX_SIM_DYNAMICS_CONSTRAINT_FORCES_H
#define HX_SIM_DYNAMICS_CONSTRAINT_FORCES_H

#include "sim/dynamics/dynamics.h"

/* The doubles hx_constraint_forces_all writes: twelve a slot
 * (expr/marker_forces.h's hx_marker_forces_slots). */
size_t hx_constraint_forces_size(const hx_dynamics *d);

/* Every slot's twelve values (on I's body at I's origin, then on J's body at
 * J's origin, world axes; zeros in a slot no element has) into out, from
 * dd's evaluation at (t, y): ydot = hx_dynamics_rhs(d, dd, t, y, ydot) just
 * before (or the algebraic loop's stages). 0, or -1 (dd->message) when a
 * coupler's routine fails. */
int hx_constraint_forces_all(const hx_dynamics *d, hx_dynamics_data *dd, double t,
                             const double *y, const double *ydot, double *out);

#endif
