/*
 * The weighted root-mean-square norm sqrt(sum (x_i w_i)^2 / n) that CVODE and
 * ARKODE take of every correction and error estimate, several times a step.
 * SUNDIALS' serial vector sums in one chain of dependent additions, which the
 * adder's latency bounds; four partial sums run four times as many at once
 * (docs/performance.md, "The implicit step").
 */
#ifndef HX_SIM_ODE_WRMS_NORM_H
#define HX_SIM_ODE_WRMS_NORM_H

#include <nvector/nvector_serial.h>

/* 0 for n = 0 (SUNDIALS' own divides by n). */
double hx_wrms_norm(const double *x, const double *w, sunindextype n);

/* Makes v (and every vector SUNDIALS clones from it) take hx_wrms_norm. */
void hx_wrms_norm_install(N_Vector v);

#endif
