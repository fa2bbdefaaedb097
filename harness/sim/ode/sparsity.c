/* Column-compressed sparsity patterns (sparsity.h). */
#include "sim/ode/sparsity.h"

#include <stdlib.h>
#include <string.h>

static int by_column_then_row(const void *a, const void *b)
{
    const long x = *(const long *)a, y = *(const long *)b;
    return (x > y) - (x < y);
}

int hx_sparsity_from_pairs(hx_sparsity *s, int n, const int *rows, const int *cols, long count)
{
    memset(s, 0, sizeof *s);
    s->n = n;
    /* one key per entry, column major: sorting the keys sorts the pattern */
    long *keys = malloc(sizeof(long) * (size_t)(count + n + 1));
    s->colptr = calloc((size_t)n + 1, sizeof(int));
    if (keys == NULL || s->colptr == NULL) {
        free(keys);
        hx_sparsity_free(s);
        return -1;
    }
    long m = 0;
    for (long k = 0; k < count; ++k)
        keys[m++] = (long)cols[k] * n + rows[k];
    for (int c = 0; c < n; ++c)
        keys[m++] = (long)c * n + c;
    qsort(keys, (size_t)m, sizeof *keys, by_column_then_row);
    long unique = 0;
    for (long k = 0; k < m; ++k)
        if (k == 0 || keys[k] != keys[k - 1])
            keys[unique++] = keys[k];
    s->rowind = malloc(sizeof(int) * (size_t)(unique + 1));
    if (s->rowind == NULL) {
        free(keys);
        hx_sparsity_free(s);
        return -1;
    }
    for (long k = 0; k < unique; ++k) {
        s->rowind[k] = (int)(keys[k] % n);
        s->colptr[keys[k] / n + 1]++;
    }
    for (int c = 0; c < n; ++c)
        s->colptr[c + 1] += s->colptr[c];
    s->nnz = (int)unique;
    free(keys);
    return 0;
}

void hx_sparsity_free(hx_sparsity *s)
{
    free(s->colptr);
    free(s->rowind);
    memset(s, 0, sizeof *s);
}

int hx_sparsity_find(const hx_sparsity *s, int row, int col)
{
    int lo = s->colptr[col], hi = s->colptr[col + 1];
    while (lo < hi) {
        const int mid = (lo + hi) / 2;
        if (s->rowind[mid] < row)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo < s->colptr[col + 1] && s->rowind[lo] == row ? lo : -1;
}
