/*
 * The pieces of the constraint system that its stage (constraints.c) and its
 * projections (constraint_projection.c) share: the parts of a data's
 * constraint work, the rows at a state, and products with one row or with G^T.
 */
#ifndef HX_SIM_DYNAMICS_CONSTRAINT_PARTS_H
#define HX_SIM_DYNAMICS_CONSTRAINT_PARTS_H

#include "sim/dynamics/dynamics.h"

/* dd->constraint_work's parts (sized by hx_constraints_work_size). */
typedef struct hx_constraint_work {
  double *G, *W, *A, *phi, *gamma, *step, *x, *expression;
} hx_constraint_work;

hx_constraint_work hx_constraint_work_parts(const hx_dynamics *d,
                                            hx_dynamics_data *dd);

/* G (d->row_values a row), phi and, when gamma is not NULL, the right-hand
 * sides of G udot = gamma. 0, or -1 (dd->message). */
int hx_constraint_rows_eval(const hx_dynamics *d, hx_dynamics_data *dd,
                            double t, const double *y, double *G, double *phi,
                            double *gamma);

/* What row i's G u must equal: f'(t) of a motion (f of a velocity motion, the
 * velocity state of an acceleration motion), -df/dt of a general constraint,
 * else 0. 0, or -1 (dd->message). */
int hx_constraint_row_rate(const hx_dynamics *d, hx_dynamics_data *dd, int i,
                           double t, const double *y, double *rate);

/* start + G_i . v over u */
double hx_constraint_row_dot(const hx_dynamics *d, const double *G, int i,
                             const double *v, double start);

/* x = G^T z over u (zero where no row reaches), z over the active rows */
void hx_constraint_transpose_apply(const hx_dynamics *d, const double *G,
                                   const double *z, double *x);

#endif
