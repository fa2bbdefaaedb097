/* Small dense linear algebra of the harness (row-major matrices). */
#ifndef HX_BASE_LINALG_H
#define HX_BASE_LINALG_H

/* Solves A x = b in place (b becomes x) by Gaussian elimination with partial
 * pivoting; A is destroyed. Returns 0, or -1 when A is singular. */
int hx_solve(int n, double *A, double *b);
/* The same, A counted singular when a pivot is not above min_pivot (an
 * absolute size, for a matrix whose scale the caller knows). */
int hx_solve_pivot(int n, double *A, double *b, double min_pivot);

/* Largest |x_i|. */
double hx_max_abs(const double *x, int n);

#endif
