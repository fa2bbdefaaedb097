/*
 * G M^-1 G^T, the matrix of the constraint system's multipliers, over the
 * active rows (docs/architecture.md, the constraint system).
 */
#ifndef HX_SIM_DYNAMICS_CONSTRAINT_MATRIX_H
#define HX_SIM_DYNAMICS_CONSTRAINT_MATRIX_H

#include "sim/dynamics/dynamics.h"

/* After the redundant rows are known (again when a run changes them): from
 * HX_CONSTRAINT_MATRIX_ENVELOPE_ROWS active rows on, the matrix is kept and
 * factored by its envelope (d->envelope_first, envelope_start: each active
 * row from the first it shares a body with); below, solved by dense
 * elimination. 0 or -1 with msg. */
#define HX_CONSTRAINT_MATRIX_ENVELOPE_ROWS 32
int hx_constraint_matrix_plan(hx_dynamics *d, hx_message *msg);

/* out = M^-1 in over one body's block of velocities. */
void hx_constraint_matrix_inverse_mass(const hx_dynamics *d, int body, const double *in,
                                       double *out);

/* W = M^-1 G^T (12 a row, as G) and A = G M^-1 G^T over the active rows,
 * nactive x nactive row-major in d->active's order. */
void hx_constraint_matrix_gram(const hx_dynamics *d, const double *G, double *W, double *A);

/* The same over every row, active or not (nrows x nrows): the redundancy
 * test's (redundancy.h). */
void hx_constraint_matrix_gram_all(const hx_dynamics *d, const double *G, double *W, double *A);

/* The matrix at G for the solves that follow: dense into A (each solve takes
 * it apart: form it again before the next), or its envelope factored once.
 * 0, or -1 when the envelope's factorization finds it singular. */
int hx_constraint_matrix_form(const hx_dynamics *d, const double *G, double *W, double *A);
/* b becomes (G M^-1 G^T)^-1 b over the active rows; 0, or -1 when singular. */
int hx_constraint_matrix_solve(const hx_dynamics *d, double *A, double *b);

#endif
