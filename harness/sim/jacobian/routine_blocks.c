/*
 * The Newton matrix's rows of the user routines that are not forces
 * (sim/dynamics/routines.h): a Control_Diff's row by central differences of
 * DIFSUB in its own state and in the columns its declared queries read (the
 * bodies of the markers they name, the Control_Diff states they name); a
 * driven joint's rows, functions of time alone, are zero.
 */
#include <stdlib.h>

#include "host/invoke.h"
#include "host/queries.h"
#include "sim/dynamics/routines.h"
#include "sim/dynamics/failure.h"
#include "sim/jacobian/jacobian_parts.h"

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
    add_column(cols, &n, max, d->diff_offset + m->routines[routine].slot);
    const hx_binding *b = d->routine_binding[routine];
    for (int q = 0; b != NULL && q < b->deps.count; ++q) {
        const hx_query *dq = &b->deps.query[q];
        const int reads = hx_query_reads(dq);
        for (int i = 0; i < dq->nsize && i < 4; ++i) {
            if (reads == HX_READS_DIFF) {
                const int k = hx_model_routine(m, HX_ROUTINE_DIFF, dq->ipar[i]);
                if (k >= 0)
                    add_column(cols, &n, max, d->diff_offset + m->routines[k].slot);
                break; /* DIF names one element */
            }
            const int marker = reads == HX_READS_MARKERS && dq->ipar[i] != 0
                                   ? hx_model_marker(m, dq->ipar[i]) : -1;
            if (marker < 0)
                continue;
            int body_cols[13];
            const int nb = hx_jacobian_body_columns(d, m->markers[marker].body, body_cols);
            for (int j = 0; j < nb; ++j)
                add_column(cols, &n, max, body_cols[j]);
        }
    }
    return n;
}

/* DIFSUB of routine k at (t, y), jac->dd's kinematics set there; 0 or -1
 * (jac->dd.message). */
static int diff_rate(hx_jacobian *jac, int k, double t, const double *y, double *rate)
{
    const hx_dynamics *d = jac->d;
    hx_dynamics_data *dd = &jac->dd;
    hx_dynamics_kinematics(d, dd, t, y);
    hx_binding *b = d->routine_binding[k];
    hx_invoke_routine(b, &dd->frames, 1, 0, rate, NULL); /* dflag: a difference */
    jac->partial_calls++;
    return hx_dynamics_check_call(d, dd, b, NULL, 0, "", t);
}

int hx_routine_blocks_init(hx_jacobian *jac, hx_message *msg)
{
    const hx_dynamics *d = jac->d;
    const int motions = d->m->nroutines_of[HX_ROUTINE_MOTION];
    int *rows = malloc(sizeof(int) * (2 * (size_t)motions + 1));
    if (rows == NULL)
        return hx_fail(msg, "out of memory");
    const int ndriven = hx_routines_driven_rows(d, rows);
    for (int i = 0; i < ndriven; ++i)
        jac->driven[rows[i]] = 1;
    free(rows);
    return 0;
}

int hx_routine_blocks(hx_jacobian *jac, double t, const double *y)
{
    const hx_dynamics *d = jac->d;
    hx_dynamics_data *dd = &jac->dd;
    const hx_model *m = d->m;
    if (m->nroutines == 0)
        return 0;
    if (m->nroutines_of[HX_ROUTINE_MOTION] > 0)
        for (int p = 0; p < jac->pattern.nnz; ++p)
            if (jac->driven[jac->pattern.rowind[p]])
                jac->values[p] = 0.0;
    double *yp = jac->y;
    int cols[DIFF_COLUMNS_MAX];
    for (int k = 0; k < m->nroutines; ++k) {
        if (m->routines[k].kind != HX_ROUTINE_DIFF)
            continue;
        const int row = d->diff_offset + m->routines[k].slot;
        const int nc = hx_diff_columns(d, k, cols, DIFF_COLUMNS_MAX);
        for (int j = 0; j < nc; ++j) {
            const int c = cols[j];
            const double h = hx_jacobian_step(y, c);
            double plus, minus;
            yp[c] = y[c] + h;
            const int status = diff_rate(jac, k, t, yp, &plus);
            yp[c] = y[c] - h;
            const int status2 = status == 0 ? diff_rate(jac, k, t, yp, &minus) : -1;
            yp[c] = y[c];
            if (status2 != 0)
                return -1;
            const double slope = (plus - minus) / (2.0 * h);
            hx_jacobian_add(jac, row, 1, c, &slope);
        }
    }
    /* jac->dd's kinematics back at the build's state */
    hx_dynamics_kinematics(d, dd, t, y);
    return 0;
}
