/* Piecewise cubic curves through knots (cubic_curve.h). */
#include "base/cubic_curve.h"

#include <math.h>
#include <stdlib.h>

/* The slope of the secant from knot k to knot k + 1, for k in [0, n - 2];
 * beyond, two more at each end on the straight line of the secants' slopes
 * (as Akima extends the data: the end points on the parabola through the
 * last three). */
static double secant(const double *x, const double *y, int n, int k)
{
    if (k < 0) {
        const double s0 = secant(x, y, n, 0), s1 = secant(x, y, n, 1);
        return s0 + (double)(-k) * (s0 - s1); /* 2 s0 - s1, 3 s0 - 2 s1 */
    }
    if (k > n - 2) {
        const double a = secant(x, y, n, n - 2), b = secant(x, y, n, n - 3);
        return a + (double)(k - (n - 2)) * (a - b);
    }
    return (y[k + 1] - y[k]) / (x[k + 1] - x[k]);
}

void hx_akima_slopes(const double *x, const double *y, int n, double *slope)
{
    if (n == 2) { /* one secant: a straight line */
        slope[0] = slope[1] = secant(x, y, n, 0);
        return;
    }
    for (int i = 0; i < n; ++i) {
        const double m0 = secant(x, y, n, i - 2), m1 = secant(x, y, n, i - 1);
        const double m2 = secant(x, y, n, i), m3 = secant(x, y, n, i + 1);
        const double w1 = fabs(m3 - m2), w2 = fabs(m1 - m0); /* weights of m1 and m2 */
        slope[i] = w1 + w2 > 0.0 ? (w1 * m1 + w2 * m2) / (w1 + w2) : 0.5 * (m1 + m2);
    }
}

int hx_natural_cubic_slopes(const double *x, const double *y, int n, double *slope)
{
    /* continuity of the second derivative at the inner knots and zero at the
     * ends, in the slopes t (h_k = x_(k+1) - x_k, m_k the secants):
     *   2 t_0 + t_1 = 3 m_0,
     *   h_k t_(k-1) + 2 (h_(k-1) + h_k) t_k + h_(k-1) t_(k+1) = 3 (h_k m_(k-1) + h_(k-1) m_k),
     *   t_(n-2) + 2 t_(n-1) = 3 m_(n-2);
     * tridiagonal and diagonally dominant: eliminated without pivoting */
    double *upper = malloc(sizeof(double) * (size_t)n);
    if (upper == NULL)
        return -1;
    double previous_upper = 0.0, previous_rhs = 0.0;
    for (int k = 0; k < n; ++k) {
        double lower, diagonal, up, rhs;
        if (k == 0) {
            lower = 0.0, diagonal = 2.0, up = 1.0, rhs = 3.0 * secant(x, y, n, 0);
        } else if (k == n - 1) {
            lower = 1.0, diagonal = 2.0, up = 0.0, rhs = 3.0 * secant(x, y, n, n - 2);
        } else {
            const double h0 = x[k] - x[k - 1], h1 = x[k + 1] - x[k];
            lower = h1, diagonal = 2.0 * (h0 + h1), up = h0;
            rhs = 3.0 * (h1 * secant(x, y, n, k - 1) + h0 * secant(x, y, n, k));
        }
        const double pivot = diagonal - lower * previous_upper;
        upper[k] = up / pivot;
        slope[k] = (rhs - lower * previous_rhs) / pivot;
        previous_upper = upper[k], previous_rhs = slope[k];
    }
    for (int k = n - 2; k >= 0; --k)
        slope[k] -= upper[k] * slope[k + 1];
    free(upper);
    return 0;
}

/* The piece of knots k and k + 1 as a cubic about knot `about` (k or k + 1):
 * y_about + t d + c2 d^2 + c3 d^3, d = u - x_about; its value and two
 * derivatives at u. About knot k + 1, the curve is exact there. */
static void piece(const double *x, const double *y, const double *slope, int k, int about,
                  double u, double out[3])
{
    const double h = x[k + 1] - x[k], m = (y[k + 1] - y[k]) / h;
    const double t0 = slope[k], t1 = slope[k + 1];
    const double c3 = (t0 + t1 - 2.0 * m) / (h * h);
    double c2 = (3.0 * m - 2.0 * t0 - t1) / h; /* about knot k */
    if (about != k)
        c2 = (2.0 * t1 + t0 - 3.0 * m) / h; /* the half second derivative at knot k + 1 */
    const double d = u - x[about], t = slope[about];
    out[0] = y[about] + d * (t + d * (c2 + d * c3));
    out[1] = t + d * (2.0 * c2 + 3.0 * c3 * d);
    out[2] = 2.0 * c2 + 6.0 * c3 * d;
}

/* Where u falls: on a straight continuation (linear, beyond the knots):
 * 1, with the end knot in *k; else 0, with the piece in *k (x[k] <= u <
 * x[k + 1]; the first piece before the knots, the last from the last knot
 * on) and the knot to expand about in *about. */
static int locate(const double *x, int n, int linear, double u, int *k, int *about)
{
    const int end = u < x[0] ? 0 : u > x[n - 1] ? n - 1 : -1;
    if (end >= 0 && linear) {
        *k = end;
        return 1;
    }
    if (u >= x[n - 1]) { /* the last knot, or the last piece continued */
        *k = n - 2, *about = n - 1;
        return 0;
    }
    int lo = 0, hi = n - 1; /* x[lo] <= u < x[hi], or u before the first knot */
    while (hi - lo > 1) {
        const int mid = lo + (hi - lo) / 2;
        if (x[mid] <= u)
            lo = mid;
        else
            hi = mid;
    }
    *k = *about = lo;
    return 0;
}

void hx_cubic_curve(const double *x, const double *y, const double *slope, int n, int linear,
                    double u, double out[3])
{
    int piece_index, about;
    if (locate(x, n, linear, u, &piece_index, &about) != 0) {
        const int end = piece_index;
        out[0] = y[end] + slope[end] * (u - x[end]);
        out[1] = slope[end];
        out[2] = 0.0;
        return;
    }
    piece(x, y, slope, piece_index, about, u, out);
}

double hx_cubic_curve_third(const double *x, const double *y, const double *slope, int n,
                            int linear, double u)
{
    int k, about;
    if (locate(x, n, linear, u, &k, &about) != 0)
        return 0.0;
    const double h = x[k + 1] - x[k], m = (y[k + 1] - y[k]) / h;
    return 6.0 * (slope[k] + slope[k + 1] - 2.0 * m) / (h * h);
}
