/*
 * Differences of a right-hand side by column groups (Curtis, Powell and
 * Reid): columns that share no row of the sparsity are perturbed together,
 * so a Jacobian costs one right-hand side per group, not per column: on a
 * chain of bodies the group count stays the same however long the chain.
 */
#ifndef HX_SIM_ODE_COLUMN_GROUPS_H
#define HX_SIM_ODE_COLUMN_GROUPS_H

#include "sim/ode/integrator.h"

typedef struct hx_column_groups {
    int count;
    int *start;    /* count + 1: group g's columns are columns[start[g] .. start[g + 1]) */
    int *columns;  /* n */
} hx_column_groups;

/* Greedy grouping in column order; 0, or -1 (out of memory). */
int hx_column_groups_build(hx_column_groups *g, const hx_sparsity *s);
void hx_column_groups_free(hx_column_groups *g);

/* J's values (in s's order) by forward differences of f: column c perturbed
 * by h[c], with the others of its group; fy = f(t, y); work holds 2n values.
 * Rows from `first_left_out` on are left out (zero): a pattern that omits
 * what they depend on would have their changes land on the diagonal.
 * Returns 0, or the first non-zero status of f. */
int hx_grouped_differences(const hx_column_groups *g, const hx_sparsity *s, hx_rhs_fn *f,
                           void *ctx, double t, const double *y, const double *fy,
                           const double *h, int first_left_out, double *values, double *work);

#endif
