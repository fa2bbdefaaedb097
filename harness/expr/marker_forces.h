/*
 * The forces at a marker at an output time (docs/interface.md §7.13, §8.3):
 * each side of a joint's reaction and of a force element's force, where the
 * motions', couplers' and general constraints' forces are kept, and their
 * sum at a marker, the FX .. TM functions' and REQUEST/FORCE's, from what an
 * output time knows (evaluate.h's hx_expr_outputs).
 */
#ifndef HX_EXPR_MARKER_FORCES_H
#define HX_EXPR_MARKER_FORCES_H

#include "expr/evaluate.h"

/* The slots of hx_expr_outputs.constraints, twelve values each: one a
 * model routine (a Motion_Joint's at its index; the others' unused), three a
 * coupler (one for each joint it may couple), one a general constraint. */
int hx_marker_forces_slots(const hx_model *m);
/* The slot of element `index` (in m->routines, m->couplers, m->gcons) of the
 * function (model/expr/functions.h: HX_FN_MOTION, HX_FN_COUPLER, HX_FN_GCON);
 * joint: a coupler's joint in its list (0 for the others). */
int hx_marker_forces_slot(const hx_model *m, int function, int index, int joint);

/* The force and torque joint k puts on J's body at J's origin (world), from
 * the one on I at I (on_i: six values): -F and -(T + (x_I - x_J) x F). */
void hx_marker_forces_joint_on_j(const hx_frames *fr, int k, const double on_i[6],
                                 double on_j[6]);

/* The net force F and torque T (world axes) acting at marker i from every
 * force element and joint between i and j (j < 0: every one acting at i),
 * each at the point it acts: a joint's, a motion's, a coupler's (at each of
 * its joints) and a force element's on i's side, a general constraint's at
 * its I marker with j < 0 (docs/interface.md §7.13). action_only: only the action-only forces at i
 * (an action-only SFORCE, a Force_Vector_OneBody: REQUEST/FORCE without J).
 * 0, or -1 with the fault when s lacks what it reads. The caller has made
 * sure no element it does not sum acts there (hx_marker_unsummed). */
int hx_marker_forces_sum(const hx_frames *fr, const hx_expr_outputs *s, int i, int j,
                         int action_only, double F[3], double T[3], hx_expr_fault *fault);

#endif
