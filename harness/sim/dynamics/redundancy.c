/*
 * Redundant constraint rows (redundancy.h). A row of G is redundant when it
 * is a combination of the rows before it: an in-order Cholesky of
 * A = G M^-1 G^T that skips a row whose pivot (the squared size of its part
 * independent of the rows kept, in the metric M^-1) is below tol^2 of its
 * diagonal (its own squared size), so the test is relative to each row's
 * scale and the later joint's equations are the ones removed, as Adams
 * removes them. It runs at set-up, at the model's placed configuration and
 * again at each configuration the set-up's assembly reaches until the set
 * holds (docs/architecture.md, the constraint system).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sim/dynamics/constraint_matrix.h"
#include "sim/dynamics/constraints.h"
#include "sim/dynamics/joint_equations.h"
#include "sim/dynamics/redundancy.h"

/* The rank test at y into kept and removed (d->nrows of room each, every row
 * taken as active); their counts in *nkept, *nremoved. 0, or -1 with msg. */
static int rank_at(const hx_dynamics *d, hx_dynamics_data *dd, double t, const double *y,
                   int *kept, int *nkept_, int *removed, int *nremoved_, hx_message *msg)
{
    const int n = d->nrows;
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
    if (hx_constraints_rows(d, dd, t, y, phi, G, NULL) != 0) {
        hx_fail(msg, "%s", dd->message);
        goto done;
    }
    hx_constraint_matrix_gram_all(d, G, W, A);
    const double tol2 = HX_REDUNDANCY_TOLERANCE * HX_REDUNDANCY_TOLERANCE;
    int nkept = 0, nremoved = 0;
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
            removed[nremoved++] = i;
            continue;
        }
        L[i * n + i] = sqrt(pivot);
        kept[nkept++] = i;
    }
    *nkept_ = nkept, *nremoved_ = nremoved;
    status = 0;
done:
    free(G), free(W), free(A), free(phi), free(L);
    return status;
}

int hx_redundancy_find(hx_dynamics *d, hx_dynamics_data *dd, const double *y, hx_message *msg)
{
    if (d->nrows == 0)
        return 0;
    return rank_at(d, dd, 0.0, y, d->active, &d->nactive, d->removed, &d->nremoved, msg);
}

/* Whether two ascending lists of rows differ. */
static int lists_differ(const int *a, int na, const int *b, int nb)
{
    if (na != nb)
        return 1;
    for (int k = 0; k < na; ++k)
        if (a[k] != b[k])
            return 1;
    return 0;
}

/* Whether the assembly moved a position of y from y0 beyond the rounding of
 * its projection. */
static int moved(const hx_dynamics *d, const double *y0, const double *y)
{
    for (int k = 0; k < d->nq; ++k)
        if (fabs(y[k] - y0[k]) > 1e-12 * (1.0 + fabs(y0[k])))
            return 1;
    return 0;
}

int hx_redundancy_reassess(hx_dynamics *d, hx_dynamics_data *dd, hx_message *msg)
{
    const size_t n = (size_t)d->nrows;
    d->nremoved_placed = d->nremoved;
    d->removed_placed = malloc(sizeof(int) * (n + 1));
    double *y = malloc(sizeof(double) * ((size_t)d->n + 1));
    double *y0 = malloc(sizeof(double) * ((size_t)d->n + 1));
    int *kept = malloc(sizeof(int) * (n + 1)), *removed = malloc(sizeof(int) * (n + 1));
    int status = -1;
    if (d->removed_placed == NULL || y == NULL || y0 == NULL || kept == NULL || removed == NULL) {
        hx_fail(msg, "out of memory");
        goto done;
    }
    memcpy(d->removed_placed, d->removed, sizeof(int) * (size_t)d->nremoved);
    status = 0;
    if (hx_dynamics_model_state(d, dd, y) != 0)
        goto done; /* the run's own start says why */
    int changed = 0;
    for (int pass = 0; pass < HX_REDUNDANCY_PASSES; ++pass) {
        memcpy(y0, y, sizeof(double) * (size_t)d->n);
        /* a pass that cannot meet the active rows leaves the set as it is: the run's
         * assembly names what fails */
        if (hx_constraints_assemble(d, dd, 0.0, y) != 0 || !moved(d, y0, y))
            break;
        int nkept, nremoved;
        if (rank_at(d, dd, 0.0, y, kept, &nkept, removed, &nremoved, msg) != 0) {
            status = -1;
            goto done;
        }
        if (!lists_differ(removed, nremoved, d->removed, d->nremoved))
            break;
        memcpy(d->active, kept, sizeof(int) * (size_t)nkept);
        memcpy(d->removed, removed, sizeof(int) * (size_t)nremoved);
        d->nactive = nkept, d->nremoved = nremoved;
        changed = 1;
    }
    if (changed) { /* the run starts from the configuration the set was found at */
        d->assembled_q = malloc(sizeof(double) * ((size_t)d->nq + 1));
        if (d->assembled_q == NULL) {
            status = hx_fail(msg, "out of memory");
            goto done;
        }
        memcpy(d->assembled_q, y, sizeof(double) * (size_t)d->nq);
    }
done:
    free(y), free(y0), free(kept), free(removed);
    return status;
}

/* Appends row's name to text (size in all) after a separator when text is not empty. */
static void append_row(const hx_dynamics *d, int row, char *text, size_t size)
{
    char name[160];
    const size_t used = strlen(text);
    snprintf(text + used, size - used, "%s%s", used > 0 ? ", " : "",
             hx_redundancy_name_row(d, row, name, sizeof name));
}

/* Whether row is in the ascending list. */
static int listed(const int *list, int n, int row)
{
    for (int k = 0; k < n; ++k)
        if (list[k] == row)
            return 1;
    return 0;
}

/* The rows of `before` not in d->removed into no_longer, those of d->removed
 * not in `before` into now; how many. */
static int name_changes(const hx_dynamics *d, const int *before, int nbefore, char *no_longer,
                        char *now, size_t size)
{
    no_longer[0] = now[0] = '\0';
    int count = 0;
    for (int k = 0; k < nbefore; ++k)
        if (!listed(d->removed, d->nremoved, before[k]))
            append_row(d, before[k], no_longer, size), count++;
    for (int k = 0; k < d->nremoved; ++k)
        if (!listed(before, nbefore, d->removed[k]))
            append_row(d, d->removed[k], now, size), count++;
    return count;
}

int hx_redundancy_change(const hx_dynamics *d, char *no_longer, char *now, size_t size)
{
    return name_changes(d, d->removed_placed, d->nremoved_placed, no_longer, now, size);
}

int hx_redundancy_use(hx_dynamics *d, const int *removed, int nremoved, hx_message *msg)
{
    if (removed != d->removed)
        memmove(d->removed, removed, sizeof(int) * (size_t)nremoved);
    d->nremoved = nremoved;
    d->nactive = 0;
    for (int i = 0; i < d->nrows; ++i)
        if (!listed(removed, nremoved, i))
            d->active[d->nactive++] = i;
    return hx_constraint_matrix_plan(d, msg); /* G M^-1 G^T's envelope over the new rows */
}

int hx_redundancy_reexamine(hx_dynamics *d, hx_dynamics_data *dd, double t, const double *y,
                            char *no_longer, char *now, size_t size, hx_message *msg)
{
    no_longer[0] = now[0] = '\0';
    if (d->nrows == 0)
        return 0;
    const size_t n = (size_t)d->nrows;
    int *kept = malloc(sizeof(int) * (n + 1)), *removed = malloc(sizeof(int) * (n + 1));
    int *before = malloc(sizeof(int) * (n + 1)), nkept, nremoved, count = -1;
    if (kept == NULL || removed == NULL || before == NULL)
        hx_fail(msg, "out of memory");
    else if (rank_at(d, dd, t, y, kept, &nkept, removed, &nremoved, msg) != 0)
        count = -1;
    else if (!lists_differ(removed, nremoved, d->removed, d->nremoved))
        count = 0;
    else {
        const int nbefore = d->nremoved;
        memcpy(before, d->removed, sizeof(int) * (size_t)nbefore);
        if (hx_redundancy_use(d, removed, nremoved, msg) == 0)
            count = name_changes(d, before, nbefore, no_longer, now, size);
    }
    free(kept), free(removed), free(before);
    return count;
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
