/*
 * The forces at a marker at an output time (docs/interface.md §7.13, §8.3):
 * each side of a joint's reaction and of a force element's force, and their
 * sum at a marker, the FX .. TM functions' and REQUEST/FORCE's, from what an
 * output time knows (evaluate.h's hx_expr_outputs).
 */
#ifndef HX_EXPR_MARKER_FORCES_H
#define HX_EXPR_MARKER_FORCES_H

#include "expr/evaluate.h"

/* The force and torque joint k puts on J's body at J's origin (world), from
 * the one on I at I (on_i: six values): -F and -(T + (x_I - x_J) x F). */
void hx_marker_forces_joint_on_j(const hx_frames *fr, int k, const double on_i[6],
                                 double on_j[6]);

/* The net force F and torque T (world axes) acting at marker i from every
 * force element and joint between i and j (j < 0: every one acting at i),
 * each at the point it acts: a joint's and a force element's on i's side
 * (docs/interface.md §7.13). action_only: only the action-only forces at i
 * (an action-only SFORCE, a Force_Vector_OneBody: REQUEST/FORCE without J).
 * 0, or -1 with the fault when s lacks what it reads. The caller has made
 * sure no element it does not sum acts there (hx_marker_unsummed). */
int hx_marker_forces_sum(const hx_frames *fr, const hx_expr_outputs *s, int i, int j,
                         int action_only, double F[3], double T[3], hx_expr_fault *fault);

#endif
