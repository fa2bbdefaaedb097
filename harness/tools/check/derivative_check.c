/* Analytic partials against central differences (derivative_check.h). */
#include "tools/check/derivative_check.h"

#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>

double hx_relative_error(double analytic, double fd, double floor)
{
    return fabs(analytic - fd) / fmax(fabs(fd), floor);
}

void hx_worst_update(hx_worst *w, double error, const char *fmt, ...)
{
    w->compared++;
    if (!(error <= HX_DERIVATIVE_TOLERANCE))
        w->failed++;
    if (!(error <= w->error) || w->compared == 1) {
        w->error = error;
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(w->where, sizeof w->where, fmt, ap);
        va_end(ap);
    }
}

/* Error of analytic against a difference quotient (never tighter than its noise). */
static double quotient_error(double analytic, double fd, double magnitude, double step,
                             double floor)
{
    const double noise = 4.0 * DBL_EPSILON * magnitude / step;
    return hx_relative_error(analytic, fd, fmax(floor, noise / HX_DERIVATIVE_TOLERANCE));
}

double hx_check_column(hx_sample_fn *f, void *ctx, double *x, int i, int nout,
                       const double *analytic, const double *floor, double h, int *worst_row)
{
    if (worst_row != NULL)
        *worst_row = 0;
    enum { MAX_OUT = 64 };
    double p1[MAX_OUT], m1[MAX_OUT], p2[MAX_OUT], m2[MAX_OUT], f0[MAX_OUT], best[MAX_OUT];
    const double x0 = x[i];
    if (nout > MAX_OUT)
        nout = MAX_OUT;
    for (int j = 0; j < nout; ++j)
        best[j] = INFINITY;
    if (f(ctx, x, f0) != 0)
        return INFINITY;
    for (int refine = 0; refine < 3; ++refine) {
        const double step = h * pow(0.1, refine);
        const double at[4] = {x0 + step, x0 - step, x0 + 2.0 * step, x0 - 2.0 * step};
        double *const out[4] = {p1, m1, p2, m2};
        for (int k = 0; k < 4; ++k) {
            x[i] = at[k];
            const int ok = f(ctx, x, out[k]) == 0;
            x[i] = x0;
            if (!ok)
                return INFINITY;
        }
        int all_pass = 1;
        for (int j = 0; j < nout; ++j) {
            const double size = fmax(fmax(fabs(p2[j]), fabs(m2[j])), fabs(f0[j]));
            const double central = (p1[j] - m1[j]) / (2.0 * step);
            const double forward = (-3.0 * f0[j] + 4.0 * p1[j] - p2[j]) / (2.0 * step);
            const double backward = (3.0 * f0[j] - 4.0 * m1[j] + m2[j]) / (2.0 * step);
            double e = quotient_error(analytic[j], central, size, step, floor[j]);
            /* one-sided quotients carry 4x the rounding noise of the central one */
            e = fmin(e, quotient_error(analytic[j], forward, 4.0 * size, step, floor[j]));
            e = fmin(e, quotient_error(analytic[j], backward, 4.0 * size, step, floor[j]));
            best[j] = fmin(best[j], e);
            all_pass = all_pass && best[j] <= HX_DERIVATIVE_TOLERANCE;
        }
        if (all_pass)
            break;
    }
    double worst = 0.0;
    for (int j = 0; j < nout; ++j)
        if (!(best[j] <= worst)) {
            worst = best[j];
            if (worst_row != NULL)
                *worst_row = j;
        }
    return worst;
}
