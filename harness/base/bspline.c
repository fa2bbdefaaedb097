/* Uniform B-splines (bspline.h). */
#include "base/bspline.h"

#include <math.h>

/* Knot i of the unrolled curve: clamped uniform over [0, 1] for an open
 * curve of n points; the integers for a closed one (its n - 1 distinct
 * points continued by the first k - 1 again). */
static double knot(int k, int n, int closed, int i)
{
    if (closed)
        return (double)i;
    if (i < k)
        return 0.0;
    if (i >= n)
        return 1.0;
    return (double)(i - k + 1) / (double)(n - k + 1);
}

void hx_bspline_basis(int k, int n, int closed, double u, double basis[4][HX_BSPLINE_MAX_ORDER],
                      int *first)
{
    const int p = k - 1;            /* the degree */
    const int m = closed ? n - 1 : n; /* distinct control points */
    /* the parameter on the knots, and the span [t_span, t_span+1) holding it */
    double s, scale;
    int span;
    if (closed) {
        /* u modulo 1 over the m spans; an odd order starts half a span on, so
         * that its sites j/m (the middles of its spans) make interpolation
         * well posed */
        double t = (k % 2 ? 0.5 : 0.0) + (u - floor(u)) * m;
        if (t >= m)
            t -= m;
        s = p + t, scale = m;
        span = (int)floor(s);
        if (span > p + m - 1)
            span = p + m - 1;
    } else {
        s = u < 0.0 ? 0.0 : u > 1.0 ? 1.0 : u, scale = 1.0;
        span = p + (int)floor(s * (double)(n - p));
        if (span > n - 1)
            span = n - 1;       /* u = 1 lies in the last span */
    }
    double ndu[HX_BSPLINE_MAX_ORDER][HX_BSPLINE_MAX_ORDER];
    double left[HX_BSPLINE_MAX_ORDER], right[HX_BSPLINE_MAX_ORDER];
    ndu[0][0] = 1.0;
    for (int j = 1; j <= p; ++j) {
        left[j] = s - knot(k, n, closed, span + 1 - j);
        right[j] = knot(k, n, closed, span + j) - s;
        double saved = 0.0;
        for (int r = 0; r < j; ++r) {
            ndu[j][r] = right[r + 1] + left[j - r]; /* the knots' spans, below the diagonal */
            const double temp = ndu[r][j - 1] / ndu[j][r];
            ndu[r][j] = saved + right[r + 1] * temp;
            saved = left[j - r] * temp;
        }
        ndu[j][j] = saved;
    }
    for (int d = 0; d < 4; ++d)
        for (int i = 0; i < HX_BSPLINE_MAX_ORDER; ++i)
            basis[d][i] = 0.0;
    for (int j = 0; j <= p; ++j)
        basis[0][j] = ndu[j][p];
    /* the derivatives (Piegl and Tiller's algorithm A2.3) */
    const int orders = p < 3 ? p : 3;
    double a[2][HX_BSPLINE_MAX_ORDER];
    for (int r = 0; r <= p; ++r) {
        int s1 = 0, s2 = 1;
        a[0][0] = 1.0;
        for (int d = 1; d <= orders; ++d) {
            double sum = 0.0;
            const int rk = r - d, pk = p - d;
            if (r >= d) {
                a[s2][0] = a[s1][0] / ndu[pk + 1][rk];
                sum = a[s2][0] * ndu[rk][pk];
            }
            const int j1 = rk >= -1 ? 1 : -rk, j2 = r - 1 <= pk ? d - 1 : p - r;
            for (int j = j1; j <= j2; ++j) {
                a[s2][j] = (a[s1][j] - a[s1][j - 1]) / ndu[pk + 1][rk + j];
                sum += a[s2][j] * ndu[rk + j][pk];
            }
            if (r <= pk) {
                a[s2][d] = -a[s1][d - 1] / ndu[pk + 1][r];
                sum += a[s2][d] * ndu[r][pk];
            }
            basis[d][r] = sum;
            const int swap = s1;
            s1 = s2, s2 = swap;
        }
    }
    double factor = p, chain = scale; /* p!/(p-d)! and (ds/du)^d */
    for (int d = 1; d <= orders; ++d) {
        for (int j = 0; j <= p; ++j)
            basis[d][j] *= factor * chain;
        factor *= p - d, chain *= scale;
    }
    *first = closed ? (span - p) % m : span - p;
}

void hx_bspline_sites(int k, int n, int closed, double *u)
{
    if (closed) { /* the knots (even order) or the spans' middles (odd order) */
        for (int j = 0; j < n; ++j)
            u[j] = (double)j / (double)(n - 1);
        return;
    }
    for (int j = 0; j < n; ++j) {
        double sum = 0.0;
        for (int i = 1; i < k; ++i)
            sum += knot(k, n, 0, j + i);
        u[j] = sum / (k - 1);
    }
}
