/*
 * The user force elements in the equations of motion: each is called with the
 * dynamics' state bound, its result turned into world axes and applied at I,
 * its reaction on J's body at the same point.
 */
#ifndef HX_SIM_DYNAMICS_ELEMENT_FORCES_H
#define HX_SIM_DYNAMICS_ELEMENT_FORCES_H

#include "sim/dynamics/dynamics.h"

/* What the harness makes of a force routine's own values (hx_invoke_force,
 * hx_force_routine_values of them): the force and torque on I in the
 * element's output axes (hx_force_output_axes). A GFOSUB's six as they are;
 * a VFOSUB's force or a VTOSUB's torque, the other part zero; an SFOSUB's
 * value along the line from J to I, positive pushing I away (none where they
 * meet), or about J's z axis, in world axes (a Force_Scalar_TwoBody has no
 * reference marker). A value left unwritten (NaN in check's probe) stays NaN.
 * The dependency and history audits judge the values, never this load. */
void hx_force_routine_load(const hx_model *m, const hx_frames *fr, int force,
                           const double *values, double load[6]);

/* Force element `force`'s routine called at s (dflag as given, iflag 0) and
 * its values made a load in its output axes (hx_force_routine_load). */
void hx_force_routine_call(hx_binding *b, const hx_frames *fr, int dflag, double load[6]);

/* The forces stage's user force elements at dd->frames: their outputs and
 * loads into dd, the loads onto the bodies; with partials set a Force_Field
 * is asked for its partials too (dflag), kept in dd->element_partials. *power
 * receives the power of their forces. 0, or -1 (dd->message). */
int hx_element_forces_apply(const hx_dynamics *d, hx_dynamics_data *dd, int partials,
                            double *power);

#endif
