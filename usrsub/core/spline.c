/*
 * Natural cubic spline with linear extension (spline.h).
 * Set-up solves the tridiagonal system for the knot curvatures once; an
 * evaluation finds its interval (by division for equally spaced knots, else
 * a bucket and a step or two) and is a cubic in Horner form.
 */
#include "usrsub/core/spline.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

int usrsub_spline_init(usrsub_spline *s, int n, const double *x, const double *y,
                       usrsub_message *msg)
{
    memset(s, 0, sizeof *s);
    if (n < 2)
        return usrsub_fail(msg, "a spline needs at least 2 points, got %d", n);
    for (int i = 0; i < n; ++i) {
        if (!isfinite(x[i]) || !isfinite(y[i]))
            return usrsub_fail(msg, "point %d (%g, %g) is not finite", i + 1, x[i], y[i]);
        if (i > 0 && !(x[i] > x[i - 1]))
            return usrsub_fail(msg, "x of point %d (%g) is not greater than x of point %d (%g):"
                               " x must be strictly increasing", i + 1, x[i], i, x[i - 1]);
    }
    const int m = n - 1; /* intervals */
    /* Spacings whose span or reciprocal overflows would give infinite
     * coefficients or interval indices; such a table is not a curve. */
    if (!isfinite(x[m] - x[0]))
        return usrsub_fail(msg, "x spans %g to %g, a range too wide for double arithmetic",
                           x[0], x[m]);
    for (int i = 0; i < m; ++i)
        if (!isfinite(1.0 / (x[i + 1] - x[i])))
            return usrsub_fail(msg, "x of points %d and %d (%g, %g) are too close to tell apart",
                               i + 1, i + 2, x[i], x[i + 1]);
    const int nbuckets = 2 * m;
    double *xs = malloc(sizeof(double) * (size_t)n);
    double *coef = malloc(sizeof(double) * 4u * (size_t)m);
    int *bucket = malloc(sizeof(int) * (size_t)(nbuckets + 1));
    double *curv = calloc((size_t)n, sizeof(double)); /* second derivatives */
    double *work = calloc((size_t)n, sizeof(double));
    if (xs == NULL || coef == NULL || bucket == NULL || curv == NULL || work == NULL) {
        free(xs), free(coef), free(bucket), free(curv), free(work);
        return usrsub_fail(msg, "out of memory for a %d-point spline", n);
    }
    memcpy(xs, x, sizeof(double) * (size_t)n);

    /* Thomas algorithm on the interior knots; curv[0] = curv[n-1] = 0. */
    for (int i = 1; i < m; ++i) {
        const double h0 = x[i] - x[i - 1], h1 = x[i + 1] - x[i];
        const double rhs = 6.0 * ((y[i + 1] - y[i]) / h1 - (y[i] - y[i - 1]) / h0);
        const double diag = 2.0 * (h0 + h1) - h0 * work[i - 1];
        work[i] = h1 / diag;
        curv[i] = (rhs - h0 * curv[i - 1]) / diag;
    }
    for (int i = m - 1; i >= 1; --i)
        curv[i] -= work[i] * curv[i + 1];

    for (int i = 0; i < m; ++i) {
        const double h = x[i + 1] - x[i];
        double *c = coef + 4 * i;
        c[0] = y[i];
        c[1] = (y[i + 1] - y[i]) / h - h * (2.0 * curv[i] + curv[i + 1]) / 6.0;
        c[2] = 0.5 * curv[i];
        c[3] = (curv[i + 1] - curv[i]) / (6.0 * h);
    }
    const double h_last = x[m] - x[m - 1];
    s->y_end = y[m];
    s->slope_end = (y[m] - y[m - 1]) / h_last + h_last * (curv[m - 1] + 2.0 * curv[m]) / 6.0;
    s->n = n;
    s->x = xs;
    s->coef = coef;
    s->nbuckets = nbuckets;
    s->bucket_scale = nbuckets / (x[m] - x[0]);
    s->bucket = bucket;
    for (int b = 0, i = 0; b <= nbuckets; ++b) {
        const double edge = x[0] + b / s->bucket_scale;
        while (i < m - 1 && x[i + 1] <= edge)
            ++i;
        bucket[b] = i;
    }
    const double h0 = x[1] - x[0];
    s->uniform = 1;
    for (int i = 1; i < m && s->uniform; ++i)
        s->uniform = fabs((x[i + 1] - x[i]) - h0) <= 1e-12 * h0;
    s->inverse_spacing = 1.0 / h0;
    free(curv);
    free(work);
    int finite = isfinite(s->slope_end) && isfinite(s->bucket_scale);
    for (int k = 0; k < 4 * m && finite; ++k)
        finite = isfinite(coef[k]);
    if (!finite) {
        usrsub_spline_free(s);
        return usrsub_fail(msg, "the spline through these %d points overflows"
                           " (slopes beyond double range)", n);
    }
    return 0;
}

void usrsub_spline_free(usrsub_spline *s)
{
    free(s->x);
    free(s->coef);
    free(s->bucket);
    memset(s, 0, sizeof *s);
}

/* The interval holding x, for x0 < x < x_last: a bucket, then a step or two
 * (a bisection where knots cluster). */
static inline int interval_of(const usrsub_spline *s, double x)
{
    const double *xs = s->x;
    const int last = s->n - 1;
    if (s->uniform) { /* the quotient, then one step where rounding put x across a knot */
        const double q = (x - xs[0]) * s->inverse_spacing; /* clamped before the cast */
        int i = q > 0.0 ? (q < last - 1 ? (int)q : last - 1) : 0;
        if (i > 0 && xs[i] > x)
            --i;
        else if (i + 1 < last && xs[i + 1] <= x)
            ++i;
        return i;
    }
    const double q = (x - xs[0]) * s->bucket_scale; /* clamped before the cast */
    int b = q > 0.0 ? (q < s->nbuckets - 1 ? (int)q : s->nbuckets - 1) : 0;
    int lo = s->bucket[b], hi = s->bucket[b + 1] + 1; /* xs[lo] <= x < xs[hi] */
    while (lo > 0 && xs[lo] > x) /* x rounded into the next bucket */
        --lo;
    if (hi - lo > 4) {
        while (hi - lo > 1) {
            const int mid = (lo + hi) >> 1;
            if (xs[mid] <= x)
                lo = mid;
            else
                hi = mid;
        }
    } else {
        while (lo + 1 < last && xs[lo + 1] <= x)
            ++lo;
    }
    return lo;
}

usrsub_jet usrsub_spline_eval(const usrsub_spline *s, double x)
{
    usrsub_jet j;
    const double *xs = s->x;
    const int last = s->n - 1;
    if (x <= xs[0]) {
        j.value = s->coef[0] + s->coef[1] * (x - xs[0]);
        j.d1 = s->coef[1];
        j.d2 = 0.0;
    } else if (x >= xs[last]) {
        j.value = s->y_end + s->slope_end * (x - xs[last]);
        j.d1 = s->slope_end;
        j.d2 = 0.0;
    } else {
        const int i = interval_of(s, x);
        const double *c = s->coef + 4 * i;
        const double t = x - xs[i];
        j.value = c[0] + t * (c[1] + t * (c[2] + t * c[3]));
        j.d1 = c[1] + t * (2.0 * c[2] + 3.0 * t * c[3]);
        j.d2 = 2.0 * c[2] + 6.0 * t * c[3];
    }
    return j;
}

double usrsub_spline_value(const usrsub_spline *s, double x)
{
    const double *xs = s->x;
    const int last = s->n - 1;
    if (x <= xs[0])
        return s->coef[0] + s->coef[1] * (x - xs[0]);
    if (x >= xs[last])
        return s->y_end + s->slope_end * (x - xs[last]);
    const int i = interval_of(s, x);
    const double *c = s->coef + 4 * i;
    const double t = x - xs[i];
    return c[0] + t * (c[1] + t * (c[2] + t * c[3]));
}

double usrsub_spline_value_slope(const usrsub_spline *s, double x, double *slope)
{
    const double *xs = s->x;
    const int last = s->n - 1;
    if (x <= xs[0]) {
        *slope = s->coef[1];
        return s->coef[0] + s->coef[1] * (x - xs[0]);
    }
    if (x >= xs[last]) {
        *slope = s->slope_end;
        return s->y_end + s->slope_end * (x - xs[last]);
    }
    const int i = interval_of(s, x);
    const double *c = s->coef + 4 * i;
    const double t = x - xs[i];
    *slope = c[1] + t * (2.0 * c[2] + 3.0 * t * c[3]);
    return c[0] + t * (c[1] + t * (c[2] + t * c[3]));
}

double usrsub_spline_derivative(const usrsub_spline *s, double x, int order)
{
    const double *xs = s->x;
    const int last = s->n - 1;
    if (x <= xs[0])
        return order == 0 ? s->coef[0] + s->coef[1] * (x - xs[0]) : order == 1 ? s->coef[1] : 0.0;
    if (x >= xs[last])
        return order == 0 ? s->y_end + s->slope_end * (x - xs[last])
                          : order == 1 ? s->slope_end : 0.0;
    const int i = interval_of(s, x);
    const double *c = s->coef + 4 * i;
    const double t = x - xs[i];
    switch (order) {
    case 0: return c[0] + t * (c[1] + t * (c[2] + t * c[3]));
    case 1: return c[1] + t * (2.0 * c[2] + 3.0 * t * c[3]);
    default: return 2.0 * c[2] + 6.0 * t * c[3];
    }
}
