/* Envelope (profile) Cholesky (envelope.h). Row i's values sit at
 * v[start[i]] for column first[i] on: L_ij is v[start[i] + j - first[i]]. */
#include <math.h>

#include "base/envelope.h"

void hx_envelope_layout(int n, const int *first, size_t *start)
{
    start[0] = 0;
    for (int i = 0; i < n; ++i)
        start[i + 1] = start[i] + (size_t)(i - first[i] + 1);
}

int hx_envelope_factor(int n, const int *first, const size_t *start, double *v)
{
    for (int i = 0; i < n; ++i) {
        double *li = v + start[i];
        for (int j = first[i]; j <= i; ++j) {
            const double *lj = v + start[j];
            const int k0 = first[i] > first[j] ? first[i] : first[j];
            double s = li[j - first[i]];
            for (int k = k0; k < j; ++k)
                s -= li[k - first[i]] * lj[k - first[j]];
            if (j < i) {
                li[j - first[i]] = s / lj[j - first[j]];
            } else {
                if (!(s > 0.0))
                    return -1;
                li[i - first[i]] = sqrt(s);
            }
        }
    }
    return 0;
}

void hx_envelope_solve(int n, const int *first, const size_t *start, const double *v,
                       double *b)
{
    for (int i = 0; i < n; ++i) { /* L y = b */
        const double *li = v + start[i];
        double s = b[i];
        for (int k = first[i]; k < i; ++k)
            s -= li[k - first[i]] * b[k];
        b[i] = s / li[i - first[i]];
    }
    for (int i = n - 1; i >= 0; --i) { /* L^T x = y */
        const double *li = v + start[i];
        b[i] /= li[i - first[i]];
        for (int k = first[i]; k < i; ++k)
            b[k] -= li[k - first[i]] * b[i];
    }
}
