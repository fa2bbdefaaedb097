/* Differences by column groups (column_groups.h). */
#include "sim/ode/column_groups.h"

#include <stdlib.h>
#include <string.h>

int hx_column_groups_build(hx_column_groups *g, const hx_sparsity *s)
{
    memset(g, 0, sizeof *g);
    const int n = s->n;
    /* the rows as lists of columns (the pattern transposed) */
    int *rowptr = calloc((size_t)n + 1, sizeof(int)), *colind = malloc(sizeof(int) * (size_t)(s->nnz + 1));
    int *color = malloc(sizeof(int) * (size_t)(n + 1)), *seen = malloc(sizeof(int) * (size_t)(n + 1));
    int *fill = calloc((size_t)n + 1, sizeof(int));
    g->start = calloc((size_t)n + 2, sizeof(int));
    g->columns = malloc(sizeof(int) * (size_t)(n + 1));
    int status = -1;
    if (!rowptr || !colind || !color || !seen || !fill || !g->start || !g->columns)
        goto done;
    for (int k = 0; k < s->nnz; ++k)
        rowptr[s->rowind[k] + 1]++;
    for (int r = 0; r < n; ++r)
        rowptr[r + 1] += rowptr[r];
    for (int c = 0; c < n; ++c)
        for (int k = s->colptr[c]; k < s->colptr[c + 1]; ++k) {
            const int r = s->rowind[k];
            colind[rowptr[r] + fill[r]++] = c;
        }
    /* each column takes the lowest group none of its rows' earlier columns has */
    for (int c = 0; c < n; ++c)
        seen[c] = -1;
    for (int c = 0; c < n; ++c) {
        for (int k = s->colptr[c]; k < s->colptr[c + 1]; ++k) {
            const int r = s->rowind[k];
            for (int j = rowptr[r]; j < rowptr[r + 1] && colind[j] < c; ++j)
                seen[color[colind[j]]] = c;
        }
        int pick = 0;
        while (seen[pick] == c)
            ++pick;
        color[c] = pick;
        if (pick + 1 > g->count)
            g->count = pick + 1;
    }
    for (int c = 0; c < n; ++c)
        g->start[color[c] + 1]++;
    for (int k = 0; k < g->count; ++k)
        g->start[k + 1] += g->start[k];
    memset(fill, 0, sizeof(int) * (size_t)n);
    for (int c = 0; c < n; ++c)
        g->columns[g->start[color[c]] + fill[color[c]]++] = c;
    status = 0;
done:
    free(rowptr), free(colind), free(color), free(seen), free(fill);
    if (status != 0)
        hx_column_groups_free(g);
    return status;
}

void hx_column_groups_free(hx_column_groups *g)
{
    free(g->start);
    free(g->columns);
    memset(g, 0, sizeof *g);
}

int hx_grouped_differences(const hx_column_groups *g, const hx_sparsity *s, hx_rhs_fn *f,
                           void *ctx, double t, const double *y, const double *fy,
                           const double *h, int first_left_out, double *values, double *work)
{
    const int n = s->n;
    double *yp = work, *fp = work + n;
    memcpy(yp, y, sizeof(double) * (size_t)n);
    for (int k = 0; k < g->count; ++k) {
        for (int j = g->start[k]; j < g->start[k + 1]; ++j)
            yp[g->columns[j]] += h[g->columns[j]];
        const int status = f(ctx, t, yp, fp);
        for (int j = g->start[k]; j < g->start[k + 1]; ++j)
            yp[g->columns[j]] = y[g->columns[j]];
        if (status != 0)
            return status;
        /* no two columns of a group share a row: each row's change is its own */
        for (int j = g->start[k]; j < g->start[k + 1]; ++j) {
            const int c = g->columns[j];
            for (int p = s->colptr[c]; p < s->colptr[c + 1]; ++p)
                values[p] = s->rowind[p] < first_left_out
                                ? (fp[s->rowind[p]] - fy[s->rowind[p]]) / h[c] : 0.0;
        }
    }
    return 0;
}
