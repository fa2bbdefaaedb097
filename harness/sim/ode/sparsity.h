/*
 * Where a Jacobian J = df/dy can be nonzero, column-compressed (CSC, the
 * layout of SUNDIALS' sparse matrices and of KLU): the rows of column c are
 * rowind[colptr[c] .. colptr[c + 1]), ascending, the diagonal among them.
 */
#ifndef HX_SIM_ODE_SPARSITY_H
#define HX_SIM_ODE_SPARSITY_H

typedef struct hx_sparsity {
    int n;
    int nnz;
    int *colptr;  /* n + 1 */
    int *rowind;  /* nnz */
} hx_sparsity;

/* From (row, column) pairs in any order, repeats allowed; the diagonal is
 * added. Takes over nothing; 0, or -1 (out of memory). */
int hx_sparsity_from_pairs(hx_sparsity *s, int n, const int *rows, const int *cols, long count);
void hx_sparsity_free(hx_sparsity *s);

/* Where (row, col) sits in the values, or -1 when outside the pattern. */
int hx_sparsity_find(const hx_sparsity *s, int row, int col);

#endif
