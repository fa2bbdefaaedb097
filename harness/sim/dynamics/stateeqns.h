/*
 * The Force_StateEqn elements in the equations of motion (docs/interface.md
 * §5): each element's states are part of y (dynamics.h); an evaluation
 * computes its inputs (its U array's variables, measured by the harness at
 * the bodies' state), calls YFOSUB with its states from y, writes their
 * rates into ydot, and applies its six outputs as a Force_Vector_TwoBody's:
 * on I at the I marker, the reaction on the J floating marker's body at the
 * same point, components in the ref_marker's axes. Their power joins the
 * force elements' work.
 */
#ifndef HX_SIM_DYNAMICS_STATEEQNS_H
#define HX_SIM_DYNAMICS_STATEEQNS_H

#include <stdio.h>

#include "sim/dynamics/dynamics.h"

/* The Force_StateEqn elements' place in the dynamics' model. */
typedef struct hx_stateeqns {
    int count;
    hx_binding **binding;
    int *offset;        /* y index of each element's first state */
} hx_stateeqns;

/* Sets d->stateeqn_offset and d->nstates (right after the velocities); 0, or
 * -1 with msg (out of memory). */
int hx_stateeqns_init(hx_dynamics *d, hx_message *msg);
void hx_stateeqns_free(hx_dynamics *d);
/* The doubles of hx_dynamics_data's stateeqn_work. */
int hx_stateeqns_work_size(const hx_dynamics *d);

/* The initial states (IC arrays) into y. */
void hx_stateeqns_initial(const hx_dynamics *d, double *y);

/* The forces stage's elements at dd->frames (set from y): state rates into
 * ydot, outputs into dd->stateeqn_outputs and applied to the bodies, their
 * power added to ydot[d->element_work]. Returns 0, or -1 (dd->message) when
 * an element stopped the run or returned a non-finite value. */
int hx_stateeqns_apply(const hx_dynamics *d, hx_dynamics_data *dd, const double *y,
                       double *ydot);

/* Element k at dd->frames with states x (its nstate) and inputs u (its
 * ninput), dflag as given: rates xdot and outputs out; 0 or -1 (dd->message). */
int hx_stateeqn_call(const hx_dynamics *d, hx_dynamics_data *dd, int k, const double *x,
                     const double *u, int dflag, double *xdot, double out[6]);

/* The run's CSV columns: the states (stateeqnID.x1 ..), the inputs
 * (stateeqnID.u1 .., at dd->frames) and the outputs (stateeqnID.fx .. tz, on I
 * in the ref_marker's axes, of dd's evaluation) of each element. */
void hx_stateeqns_csv_header(FILE *f, const hx_dynamics *d);
void hx_stateeqns_csv_row(FILE *f, const hx_dynamics *d, hx_dynamics_data *dd, const double *y);

#endif
