/*
 * A symmetric positive definite matrix kept by its envelope: row i from its
 * first nonzero column first[i] to the diagonal, rows one after the other
 * (row i at start[i], start[n] the whole). Cholesky's factor fills only
 * inside the envelope, so a banded matrix of band b costs n b^2 to factor and
 * n b to solve (docs/architecture.md, the constraint system).
 */
#ifndef HX_BASE_ENVELOPE_H
#define HX_BASE_ENVELOPE_H

#include <stddef.h>

/* start[0..n] from first (first[i] <= i). */
void hx_envelope_layout(int n, const int *first, size_t *start);

/* Row i, column j (first[i] <= j <= i) of the values v. */
static inline double *hx_envelope_at(const int *first, const size_t *start, double *v, int i,
                                     int j)
{
    return v + start[i] + (size_t)(j - first[i]);
}

/* v becomes L with A = L L^T, in place; returns 0, or -1 when A is not
 * positive definite (a pivot not above zero). */
int hx_envelope_factor(int n, const int *first, const size_t *start, double *v);

/* b becomes x with L L^T x = b (v from hx_envelope_factor). */
void hx_envelope_solve(int n, const int *first, const size_t *start, const double *v,
                       double *b);

#endif
