/*
 * The static equilibrium's Newton matrix from the dynamics' Jacobian
 * (sim/jacobian/jacobian.h; docs/harness.md, static equilibrium): K = dh/dx
 * for h(q) = M udot(q, 0) / ucf in the velocity coordinates, from the rows
 * of d(udot)/dq the elements' partials and the constraint blocks give,
 * instead of 2 right-hand sides per unknown.
 */
#ifndef HX_SIM_SIMULATION_EQUILIBRIUM_MATRIX_H
#define HX_SIM_SIMULATION_EQUILIBRIUM_MATRIX_H

#include "sim/jacobian/jacobian.h"

/* The unknowns: nv velocities (var: indices into u), each over its length,
 * each load over its scale (the saddle system's units, equilibrium.c). */
typedef struct hx_equilibrium_unknowns {
    int nv;
    const int *var;
    const double *length, *scale;
} hx_equilibrium_unknowns;

/* The parts' generalized forces M a / ucf (nu) of accelerations a (nu): a
 * free part's m a and I alpha (body axes; at u = 0 no gyroscopic term), a
 * reduced joint's mass (or inertia about its axis) times its acceleration. */
void hx_equilibrium_generalized(const hx_dynamics *d, const double *a, double *gen);

/* Whether K from jac's build costs fewer evaluations than differences of h,
 * 2 per unknown (the unknowns: every velocity of a part not driven): no when
 * the model has an algebraic loop (the build differences all n states),
 * nor when the constraint stage's differences, 2 per column of the largest
 * group of coupled parts (positions and rates, coupler_blocks.c), reach as
 * many (a linkage; docs/performance.md, the static equilibrium's matrix). */
int hx_equilibrium_jacobian_pays(const hx_jacobian *jac);

/* K[i * stride + j] = dh_i/dx_j length[j] / scale[i] at (t, y), from
 * hx_jacobian_build into values (jac->pattern.nnz); work holds 2 nu doubles.
 * 0, or -1 (jac->dd.message). */
int hx_equilibrium_matrix(hx_jacobian *jac, double t, const double *y,
                          const hx_equilibrium_unknowns *x, double *values, double *work,
                          double *K, int stride);

#endif
