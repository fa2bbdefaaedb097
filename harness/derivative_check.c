/* Analytic partials against central differences (derivative_check.h). */
#include "derivative_check.h"

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

double hx_check_column(hx_sample_fn *f, void *ctx, double *x, int i, int nout,
                       const double *analytic, const double *floor, double h)
{
    double plus[64], minus[64], best[64];
    const double x0 = x[i];
    if (nout > 64)
        nout = 64;
    for (int j = 0; j < nout; ++j)
        best[j] = INFINITY;
    for (int refine = 0; refine < 3; ++refine) {
        const double step = h * pow(0.1, refine);
        x[i] = x0 + step;
        const int ok_plus = f(ctx, x, plus) == 0;
        x[i] = x0 - step;
        const int ok_minus = f(ctx, x, minus) == 0;
        x[i] = x0;
        if (!ok_plus || !ok_minus)
            return INFINITY;
        int all_pass = 1;
        for (int j = 0; j < nout; ++j) {
            const double fd = (plus[j] - minus[j]) / (2.0 * step);
            /* never ask for more than the difference's rounding noise */
            const double noise = 4.0 * DBL_EPSILON * fmax(fabs(plus[j]), fabs(minus[j])) / step;
            const double bound = fmax(floor[j], noise / HX_DERIVATIVE_TOLERANCE);
            best[j] = fmin(best[j], hx_relative_error(analytic[j], fd, bound));
            all_pass = all_pass && best[j] <= HX_DERIVATIVE_TOLERANCE;
        }
        if (all_pass)
            break;
    }
    double worst = 0.0;
    for (int j = 0; j < nout; ++j)
        worst = fmax(worst, best[j]);
    return worst;
}
