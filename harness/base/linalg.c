/* Dense solve and norms (linalg.h). */
#include "base/linalg.h"

#include <math.h>

int hx_solve(int n, double *A, double *b)
{
    double scale = 0.0;
    for (int k = 0; k < n * n; ++k)
        scale = fmax(scale, fabs(A[k]));
    return hx_solve_pivot(n, A, b, 1e-14 * scale);
}

int hx_solve_pivot(int n, double *A, double *b, double min_pivot)
{
    for (int c = 0; c < n; ++c) {
        int p = c;
        for (int r = c + 1; r < n; ++r)
            if (fabs(A[r * n + c]) > fabs(A[p * n + c]))
                p = r;
        if (!(fabs(A[p * n + c]) > min_pivot))
            return -1;
        if (p != c) {
            for (int k = 0; k < n; ++k) {
                const double t = A[c * n + k];
                A[c * n + k] = A[p * n + k];
                A[p * n + k] = t;
            }
            const double t = b[c];
            b[c] = b[p];
            b[p] = t;
        }
        for (int r = c + 1; r < n; ++r) {
            const double f = A[r * n + c] / A[c * n + c];
            if (f == 0.0)
                continue;
            for (int k = c; k < n; ++k)
                A[r * n + k] -= f * A[c * n + k];
            b[r] -= f * b[c];
        }
    }
    for (int r = n - 1; r >= 0; --r) {
        double s = b[r];
        for (int k = r + 1; k < n; ++k)
            s -= A[r * n + k] * b[k];
        b[r] = s / A[r * n + r];
    }
    return 0;
}

double hx_max_abs(const double *x, int n)
{
    double m = 0.0;
    for (int k = 0; k < n; ++k)
        m = fmax(m, fabs(x[k]));
    return m;
}
