/*
 * The Newton matrix's rows of the user routines that are not forces
 * (sim/dynamics/routines.h): a Control_Diff's row by central differences of
 * DIFSUB in its own state and in the columns its declared queries read (the
 * bodies of the markers they name, the Control_Diff states they name); a
 * driven joint's rows, functions of time alone, are zero.
 */
#include <stdlib.h>

#include "host/queries.h"
#include "sim/dynamics/routines.h"
#include "sim/dynamics/stage_failure.h"
#include "sim/newton/newton_parts.h"

static void add_column(int *cols, int *n, int max, int c)
{
    for (int k = 0; k < *n; ++k)
        if (cols[k] == c)
            return;
    if (*n < max)
        cols[(*n)++] = c;
}

int hx_diff_columns(const hx_dynamics *d, int routine, int *cols, int max)
{
    const hx_model *m = d->m;
    int n = 0;
    add_column(cols, &n, max, d->diffs + m->routines[routine].slot);
    const hx_binding *b = d->routine_binding[routine];
    for (int q = 0; b != NULL && q < b->deps.count; ++q) {
        const hx_query *dq = &b->deps.query[q];
        const int reads = hx_query_reads(dq);
        for (int i = 0; i < dq->nsize && i < 4; ++i) {
            if (reads == HX_READS_DIFF) {
                const int k = hx_model_routine(m, HX_ROUTINE_DIFF, dq->ipar[i]);
                if (k >= 0)
                    add_column(cols, &n, max, d->diffs + m->routines[k].slot);
                break; /* DIF names one element */
            }
            const int marker = reads == HX_READS_MARKERS && dq->ipar[i] != 0
                                   ? hx_model_marker(m, dq->ipar[i]) : -1;
            if (marker < 0)
                continue;
            int body_cols[13];
            const int nb = hx_newton_body_columns(d, m->markers[marker].body, body_cols);
            for (int j = 0; j < nb; ++j)
                add_column(cols, &n, max, body_cols[j]);
        }
    }
    return n;
}

/* DIFSUB of routine k at (t, y); 0 or -1 (d->message). */
static int diff_rate(hx_newton_matrix *nm, int k, double t, const double *y, double *rate)
{
    hx_dynamics *d = nm->d;
    hx_dynamics_set_state(d, t, y);
    hx_binding *b = d->routine_binding[k];
    hx_invoke_routine(b, &d->frames, 1, 0, rate, NULL); /* dflag: a difference */
    nm->partial_calls++;
    return hx_dynamics_check_stop(d, b);
}

int hx_routine_blocks(hx_newton_matrix *nm, double t, const double *y)
{
    hx_dynamics *d = nm->d;
    const hx_model *m = d->m;
    if (m->nroutines == 0)
        return 0;
    if (m->nroutines_of[HX_ROUTINE_MOTION] > 0) {
        int *driven = malloc(sizeof(int) * (2 * (size_t)m->nroutines_of[HX_ROUTINE_MOTION] + 1));
        unsigned char *is_driven = calloc((size_t)nm->n, 1);
        if (driven == NULL || is_driven == NULL) {
            free(driven), free(is_driven);
            return hx_dynamics_fail(d, "out of memory");
        }
        const int ndriven = hx_routines_driven_rows(d, driven);
        for (int i = 0; i < ndriven; ++i)
            is_driven[driven[i]] = 1;
        for (int p = 0; p < nm->pattern.nnz; ++p)
            if (is_driven[nm->pattern.rowind[p]])
                nm->values[p] = 0.0;
        free(driven), free(is_driven);
    }
    double *yp = nm->y;
    int cols[DIFF_COLUMNS_MAX];
    for (int k = 0; k < m->nroutines; ++k) {
        if (m->routines[k].kind != HX_ROUTINE_DIFF)
            continue;
        const int row = d->diffs + m->routines[k].slot;
        const int nc = hx_diff_columns(d, k, cols, DIFF_COLUMNS_MAX);
        for (int j = 0; j < nc; ++j) {
            const int c = cols[j];
            const double h = hx_newton_step(y, c);
            double plus, minus;
            yp[c] = y[c] + h;
            const int status = diff_rate(nm, k, t, yp, &plus);
            yp[c] = y[c] - h;
            const int status2 = status == 0 ? diff_rate(nm, k, t, yp, &minus) : -1;
            yp[c] = y[c];
            if (status2 != 0)
                return -1;
            const double slope = (plus - minus) / (2.0 * h);
            hx_newton_add(nm, row, 1, c, &slope);
        }
    }
    /* back to the build's state, which is the last evaluation's */
    hx_dynamics_set_state(d, t, y);
    d->evaluated = 1;
    return 0;
}
