/*
 * Natural cubic spline (second derivative zero at both ends) through n >= 2
 * points with strictly increasing x, extended linearly with the end slopes
 * outside the data, so that the curve is C2 everywhere.
 */
#ifndef USRSUB_SPLINE_H
#define USRSUB_SPLINE_H

#include "usrsub/core/jet.h"
#include "usrsub/core/message.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct usrsub_spline {
    int n;          /* number of points */
    double *x;      /* n knots */
    double *coef;   /* 4 per interval: value, slope, c2, c3 at the left knot */
    double y_end;   /* value at the last knot */
    double slope_end; /* slope at the last knot */
    /* Interval look-up in O(1): the knot range cut into nbuckets equal
     * buckets, bucket[b] the interval holding the bucket's left edge. */
    int nbuckets;
    double bucket_scale;
    int *bucket;
    /* knots equally spaced (to 1e-12 of the spacing): the interval is
     * (x - x0) / h itself, with no table and no search */
    int uniform;
    double inverse_spacing;
} usrsub_spline;

/* Builds the spline; x and y are copied. On error (n < 2, a non-finite value,
 * x not strictly increasing) writes msg naming the point and returns -1. */
int usrsub_spline_init(usrsub_spline *s, int n, const double *x, const double *y,
                       usrsub_message *msg);
void usrsub_spline_free(usrsub_spline *s);

/* Value, first and second derivative at x (linear extension outside). */
usrsub_jet usrsub_spline_eval(const usrsub_spline *s, double x);

/* Value at x alone. */
double usrsub_spline_value(const usrsub_spline *s, double x);

/* Value and slope at x with one interval look-up. */
double usrsub_spline_value_slope(const usrsub_spline *s, double x, double *slope);

/* One derivative (order 0, 1 or 2) at x. */
double usrsub_spline_derivative(const usrsub_spline *s, double x, int order);

#ifdef __cplusplus
}
#endif

#endif
