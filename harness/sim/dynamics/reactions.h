/*
 * The joints' reactions (docs/interface.md §7.14, reactions): for each joint
 * of the model (Constraint_Joint and Constraint_Jprim alike, model order),
 * the force and torque the joint puts on its I marker's body, at the I
 * marker's origin, in world axes, at an evaluated state. A joint held as
 * rows of the constraint system (constraints.h) gives them from its rows'
 * multipliers; a reduced joint (the body's one coordinate, no rows) from
 * its body's Newton-Euler balance. What J's body gets is their opposite,
 * moved to J's origin (the JOINT function's jflag = 1: expr/operands.c).
 */
#ifndef HX_SIM_DYNAMICS_REACTIONS_H
#define HX_SIM_DYNAMICS_REACTIONS_H

#include "sim/dynamics/dynamics.h"

/* The six values of joint k (fx, fy, fz, tx, ty, tz: on I, at I, world) into
 * out, from dd's evaluation: ydot = hx_dynamics_rhs(d, dd, t, y, ydot) just
 * before (dd's frames, loads and multipliers and ydot's accelerations are
 * read). */
void hx_reactions_joint(const hx_dynamics *d, const hx_dynamics_data *dd, const double *ydot,
                        int k, double out[6]);

/* What reduced joint k and whatever drives or couples its coordinate put on
 * its body (six values as above): the body's balance less the general
 * constraints' forces on it, along the joint's axis too (the torque about a
 * revolute's, the force along a translational's: a motion's and the
 * couplers' share, which hx_reactions_joint leaves out). */
void hx_reactions_balance(const hx_dynamics *d, const hx_dynamics_data *dd, const double *ydot,
                          int k, double out[6]);

/* The same for every joint: 6 * njoints values. */
void hx_reactions_all(const hx_dynamics *d, const hx_dynamics_data *dd, const double *ydot,
                      double *out);

#endif
