/*
 * Analytic partials against central differences, with a relative error and an
 * absolute floor, and never tighter than the rounding noise of the difference
 * (4 eps max|f| / h). Near a kink (a spline knot's jump in the third
 * derivative) the central difference converges only like h: a value that fails
 * at h is retried at h/10 and h/100. At a switch point itself (a contact
 * closing, a damper clipped) the two sides have different slopes; there the
 * analytic value must match one of the one-sided limits (second-order forward
 * or backward differences).
 */
#ifndef HX_TOOLS_CHECK_DERIVATIVE_CHECK_H
#define HX_TOOLS_CHECK_DERIVATIVE_CHECK_H

#include <stddef.h>

#define HX_DERIVATIVE_TOLERANCE 1e-6

typedef struct hx_worst {
    double error;      /* largest relative error seen */
    char where[256];   /* description of where */
    int compared;      /* values compared */
    int failed;        /* values over the tolerance */
} hx_worst;

/* Relative error of an analytic value against a finite difference. */
double hx_relative_error(double analytic, double fd, double floor);

/* Records a comparison (keeping the worst). */
void hx_worst_update(hx_worst *w, double error, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

/* f(x) for the derivative check of one coordinate, returning n outputs. */
typedef int hx_sample_fn(void *ctx, const double *x, double *out);

/* Compares analytic[j] (d out_j / d x_i) for all j at x, by central differences
 * in x_i with steps h, h/10, h/100. Returns the largest relative error, and
 * in *worst_row (may be NULL) the output j it was found at. */
double hx_check_column(hx_sample_fn *f, void *ctx, double *x, int i, int nout,
                       const double *analytic, const double *floor, double h, int *worst_row);

#endif
