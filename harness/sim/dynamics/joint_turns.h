/*
 * The turns of the rotations couplers take between two moving bodies
 * (docs/interface.md §2, docs/architecture.md, the constraint system): a
 * REVOLUTE joint's AZ(I,J), or a CYLINDRICAL one's 'R' freedom, of a joint
 * that is not reduced; and a ROTATIONAL Force_SpringDamper's AZ(I,J), whose
 * full turns its torque counts, as Adams' does (docs/interface.md §7.17).
 * atan2 gives such a rotation in (-pi, pi] only; an evaluation unwraps it
 * against the angle its data holds for the joint or the load (dd->turn,
 * joints first): the model's placement in a new data (what check, rig and bench
 * sample against), and in a run the angle at the last accepted step, set by
 * hx_joint_turns_accept from the integrator's accept hook alone, so that
 * DOPRI5's stages, BDF's Newton iterations and a rejected step all read the
 * last accepted angle and never move it. The coordinate is then continuous
 * over any number of turns, as long as no one step turns more than pi.
 */
#ifndef HX_SIM_DYNAMICS_JOINT_TURNS_H
#define HX_SIM_DYNAMICS_JOINT_TURNS_H

#include "sim/dynamics/dynamics.h"

/* d->turn_joint and d->turn_coupler from the couplers (after
 * hx_constraints_init); 0 or -1 with msg. */
int hx_joint_turns_init(hx_dynamics *d, hx_message *msg);

/* dd->turn at the model's placement of every joint with a rotation (the
 * rates zero, the time 0): what a new data holds. */
void hx_joint_turns_placed(const hx_dynamics *d, hx_dynamics_data *dd);

/* A run's start (or a jump of its state, as a static equilibrium between
 * segments): dd->turn at y (each rotation unwrapped against the angle held),
 * the rates at y, the time t. */
void hx_joint_turns_start(const hx_dynamics *d, hx_dynamics_data *dd, double t, const double *y);

/* An accepted step to (t, y) from dd's time: each rotation unwrapped against
 * the angle held plus the turn its rates at both ends give (the trapezoid),
 * and held with its rate and t. 0, or -1 (dd->message, naming the coupler,
 * the joint and the step) when the step turned a rotation more than pi: the
 * step's stages could not tell which way it went. */
int hx_joint_turns_accept(const hx_dynamics *d, hx_dynamics_data *dd, double t, const double *y);

/* `from`'s turns into `to` (the Jacobian's data follows the run's). */
void hx_joint_turns_copy(const hx_dynamics *d, hx_dynamics_data *to, const hx_dynamics_data *from);

#endif
