/*
 * Redundant constraint rows (redundancy.h). A row of G is redundant when it
 * is a combination of the rows before it: an in-order Cholesky of
 * A = G M^-1 G^T that skips a row whose pivot (the squared size of its part
 * independent of the rows kept, in the metric M^-1) is below tol^2 of its
 * diagonal (its own squared size), so the test is relative to each row's
 * scale and the later joint's equations are the ones removed, as Adams
 * removes them. It runs once, at set-up (docs/architecture.md, the
 * constraint system).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "sim/dynamics/constraint_matrix.h"
#include "sim/dynamics/constraints.h"
#include "sim/dynamics/joint_equations.h"
#include "sim/dynamics/redundancy.h"

int hx_redundancy_find(hx_dynamics *d, hx_dynamics_data *dd, const double *y, hx_message *msg)
{
    const int n = d->nrows;
    if (n == 0)
        return 0;
    const size_t nn = (size_t)n;
    const size_t v = (size_t)d->row_values;
    double *G = malloc(sizeof(double) * v * nn), *W = malloc(sizeof(double) * v * nn);
    double *A = malloc(sizeof(double) * nn * nn), *phi = malloc(sizeof(double) * nn);
    double *L = calloc(nn * nn, sizeof(double));
    int status = -1;
    if (G == NULL || W == NULL || A == NULL || phi == NULL || L == NULL) {
        hx_fail(msg, "out of memory");
        goto done;
    }
    if (hx_constraints_rows(d, dd, 0.0, y, phi, G, NULL) != 0) {
        hx_fail(msg, "%s", dd->message);
        goto done;
    }
    hx_constraint_matrix_gram(d, G, W, A); /* every row active here */
    const double tol2 = HX_REDUNDANCY_TOLERANCE * HX_REDUNDANCY_TOLERANCE;
    int nkept = 0, nremoved = 0;
    int *kept = d->active; /* filled in order as rows are kept */
    for (int i = 0; i < n; ++i) {
        /* L's row i against the kept rows, then its pivot */
        double pivot = A[i * n + i];
        for (int a = 0; a < nkept; ++a) {
            const int j = kept[a];
            double s = A[i * n + j];
            for (int b = 0; b < a; ++b)
                s -= L[i * n + kept[b]] * L[j * n + kept[b]];
            L[i * n + j] = s / L[j * n + j];
            pivot -= L[i * n + j] * L[i * n + j];
        }
        if (!(pivot > tol2 * A[i * n + i])) {
            d->removed[nremoved++] = i;
            continue;
        }
        L[i * n + i] = sqrt(pivot);
        kept[nkept++] = i;
    }
    d->nactive = nkept, d->nremoved = nremoved;
    status = 0;
done:
    free(G), free(W), free(A), free(phi), free(L);
    return status;
}

const char *hx_redundancy_name_row(const hx_dynamics *d, int row, char *text, size_t size)
{
    const hx_model *m = d->m;
    if (row < m->ncouplers) {
        snprintf(text, size, "COUPLER/%d", m->couplers[row].id);
        return text;
    }
    if (row >= d->gcon_first && row < d->gcon_first + m->ngcons) {
        snprintf(text, size, "GCON/%d", m->gcons[row - d->gcon_first].id);
        return text;
    }
    if (row >= d->motion_first && row < d->motion_first + d->nmotions) {
        snprintf(text, size, "MOTION/%d",
                 m->routines[d->motion_routine[row - d->motion_first]].id);
        return text;
    }
    for (int k = m->njoints - 1; k >= 0; --k)
        if (d->joint_row[k] >= 0 && d->joint_row[k] <= row) {
            const hx_joint *j = &m->joints[k];
            const int e = row - d->joint_row[k];
            char equation[32];
            snprintf(text, size, "JOINT/%d %s: equation %d (%s)", j->id,
                     hx_joint_type_name(j->type), e + 1,
                     hx_joint_equation_name(j->type, e, equation, sizeof equation));
            return text;
        }
    snprintf(text, size, "row %d", row + 1);
    return text;
}
