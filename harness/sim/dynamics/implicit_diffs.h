/*
 * The implicit Control_Diff elements by expression (docs/interface.md §7.10):
 * each a residual F_i(DIF1, DIF, ..., TIME) = 0 whose rates, the DIF1 of
 * every implicit one, are solved together at each evaluation by Newton's
 * method, dF/dDIF1 exact from the expressions' partials (expr/evaluate.h).
 * Newton starts from the rates of the last step the integrator accepted,
 * kept in the evaluation's own data (dd->implicit_start), which only the
 * run's accept hook moves (an evaluation never does, so a rejected step's
 * never count); at the start of a run from ic_dot where written, else 0.
 */
#ifndef HX_SIM_DYNAMICS_IMPLICIT_DIFFS_H
#define HX_SIM_DYNAMICS_IMPLICIT_DIFFS_H

#include <stddef.h>

#include "sim/dynamics/dynamics.h"

/* Sets d->implicit, d->nimplicit and the doubles a data's Newton work takes
 * (hx_implicit_diffs_work_size). 0, or -1 with msg. */
int hx_implicit_diffs_init(hx_dynamics *d, hx_message *msg);
void hx_implicit_diffs_free(hx_dynamics *d);
size_t hx_implicit_diffs_work_size(const hx_dynamics *d);

/* dd->implicit_start at a run's start: ic_dot where written, else 0. */
void hx_implicit_diffs_restart(const hx_dynamics *d, hx_dynamics_data *dd);

/* The implicit rates solved at dd->frames (the kinematics, the variables and
 * the DIFSUB rates set there) from dd->implicit_start, into dd->frames's DIF1 and, when
 * ydot is not NULL, into ydot. 0, or -1 with "file:line: Control_Diff ID:
 * ..." (the residual, and why: Newton did not converge, dF/dDIF1 singular)
 * in dd->message. */
int hx_implicit_diffs_solve(const hx_dynamics *d, hx_dynamics_data *dd, double *ydot);

/* The rates of dd->frames (DIF1, from the last evaluation) become where
 * Newton starts next: an accepted step's (the run's accept hook, after the
 * step's last evaluation), or the Jacobian's data at the build's state. */
void hx_implicit_diffs_keep(const hx_dynamics *d, hx_dynamics_data *dd);

#endif
