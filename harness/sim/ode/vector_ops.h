/*
 * The serial vector's operations, compiled with the harness. CVODE and
 * ARKODE do all their work on the state through a vector's table of
 * operations (sums, scalings, norms); Debian's SUNDIALS 6.4 builds the serial
 * vector inside each solver's library without optimization (every loop index
 * kept in memory), which made those operations about a third of a BDF run's
 * time on a model of 834 states. The table is SUNDIALS' own means of giving a
 * vector other operations; these compute what SUNDIALS' do, bit for bit, but
 * the norm, which keeps four partial sums in place of one chain of dependent
 * additions (docs/performance.md, "The implicit step"). Installed: twelve
 * operations and the two fused sums CVODE and ARKODE take in every step; the
 * rest of the table (dot products, constraint tests, vector arrays), seldom
 * or never called, stays SUNDIALS'.
 */
#ifndef HX_SIM_ODE_VECTOR_OPS_H
#define HX_SIM_ODE_VECTOR_OPS_H

#include <nvector/nvector_serial.h>

/* sqrt(sum (x_i w_i)^2 / n); 0 for n = 0 (SUNDIALS' own divides by n). */
double hx_wrms_norm(const double *x, const double *w, sunindextype n);

/* Makes v (and every vector SUNDIALS clones from it) take these operations. */
void hx_vector_ops_install(N_Vector v);

#endif
