/*
 * The user routines that are not forces in the equations of motion
 * (docs/interface.md §7.12):
 *  - each Control_Diff's state is part of y (dynamics.h), its rate DIFSUB's
 *    value at the state, or its expression's (after every DIFSUB's, in the
 *    model's diff_order), which the host also answers DIF and DIF1 from;
 *  - a Motion_Joint drives its joint's coordinate: for val_type D, MOTSUB's
 *    value at iord 1 and 2 are the coordinate's rate and acceleration, and
 *    iord 0 and 1 its value and rate at t = 0; for V its rate is MOTSUB's
 *    value and its acceleration iord 1; for A its acceleration is the value.
 *    The joint's forces then do not move it: its reaction is the motion's.
 *    A motion by expression gives the same three values in time
 *    (expr/time_derivative.h).
 *    The coordinate follows the integrated rates, within the integrator's
 *    tolerance of MOTSUB's value (the CSV's motionID.error says how far).
 *    On a joint between bodies the motion is a row (coordinate_rows.h); one
 *    in acceleration has its displacement and velocity as two states of y
 *    (d->motion_state), integrated here from its value, started at ic_disp
 *    and ic_vel (or the joint's coordinate and rate as the model places it).
 *  - Post_Request (REQSUB) and USERSUB Reference_Variable (VARSUB) values are
 *    outputs: computed at the output times, for the CSV.
 */
#ifndef HX_SIM_DYNAMICS_ROUTINES_H
#define HX_SIM_DYNAMICS_ROUTINES_H

#include <stdio.h>

#include "expr/evaluate.h"
#include "sim/dynamics/dynamics.h"

/* Sets d->diff_offset and d->ndiffs (after the Force_StateEqn states), the
 * acceleration motions' states (after those), the driven bodies and the
 * implicit Control_Diffs (implicit_diffs.h); refuses an implicit Control_Diff
 * with DIFSUB and a motion on a coupled joint. 0, or -1 with msg. */
int hx_routines_init(hx_dynamics *d, hx_message *msg);
void hx_routines_free(hx_dynamics *d);

/* The kinematics stage's share: the Control_Diff states of y into
 * dd->frames (DIF answers them). */
void hx_routines_set_state(const hx_dynamics *d, hx_dynamics_data *dd, const double *y);

/* Initial values: ic of each Control_Diff, the driven joints' coordinates
 * and rates, an acceleration motion's states between bodies (y's bodies
 * set already); 0 or -1 (dd->message). */
int hx_routines_initial(const hx_dynamics *d, hx_dynamics_data *dd, double *y);

/* The routines stage, at dd->frames: the Control_Diff rates into ydot (and
 * dd->frames's DIF1), the driven joints' rates and accelerations over the
 * bodies', an acceleration motion's states' rates (v and f), and the drives'
 * power added to ydot[d->load_work]. 0 or -1. */
int hx_routines_apply(const hx_dynamics *d, hx_dynamics_data *dd, const double *y, double *ydot);

/* The rate of the Control_Diff by expression routine k at dd->frames (its
 * variables computed there when it reads one): 0, or -1 with
 * "file:line:column: Control_Diff ID: what at t = ..." (dd->message). */
int hx_routines_diff_expression(const hx_dynamics *d, hx_dynamics_data *dd, int k, double *rate);

/* The y rows whose rate is a function of time alone (driven joints):
 * their indices into rows (at most 2 per driven joint); their count. */
int hx_routines_driven_rows(const hx_dynamics *d, int *rows);

/* MOTSUB of routine k (a Motion_Joint) at iord 0, 1 or 2, at dd->frames's
 * time, or its expression's value, rate and acceleration in time
 * (expr/time_derivative.h): the reduced driver's and a motion row's
 * (constraints.c); 0 or -1 (dd->message). */
int hx_routines_motion(const hx_dynamics *d, hx_dynamics_data *dd, int k, int iord,
                       double *value);

/* The CSV's columns: diffID, motionID.error (coordinate less MOTSUB's
 * value; for V, rate less it), requestID.1 .. 8, variableID. A row at (t, y)
 * after the evaluation there, its outputs s answering the accelerations and
 * forces REQSUBs ask (host/loop_queries.h). */
void hx_routines_csv_header(FILE *f, const hx_dynamics *d);
int hx_routines_csv_row(FILE *f, const hx_dynamics *d, hx_dynamics_data *dd, const double *y,
                        const hx_expr_outputs *s);

#endif
