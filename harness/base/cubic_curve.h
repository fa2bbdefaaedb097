/*
 * Piecewise cubic curves through knots (x_k, y_k), x strictly increasing,
 * each piece the cubic with the knots' values and slopes at its ends
 * (docs/interface.md §7.11): the knot slopes by Akima's rule or those of the
 * natural cubic spline, and the curve's value with its first and second
 * derivatives anywhere, beyond the knots too.
 */
#ifndef HX_BASE_CUBIC_CURVE_H
#define HX_BASE_CUBIC_CURVE_H

/* Akima (1970): at each knot the mean of the secant slopes on either side,
 * each weighted by how much the two secants beyond the other side differ;
 * two secants extrapolated at each end (sec(-1) = 2 sec(0) - sec(1), ...);
 * the plain mean where both weights vanish. n >= 2. */
void hx_akima_slopes(const double *x, const double *y, int n, double *slope);

/* The slopes of the natural cubic spline (continuous second derivative, zero
 * at both ends). n >= 2; 0, or -1 when out of memory. */
int hx_natural_cubic_slopes(const double *x, const double *y, int n, double *slope);

/* The curve's value, first and second derivative at u into out[0..2].
 * Beyond the knots: the end piece continued (linear == 0), or the straight
 * line with the end knot's value and slope (linear != 0). */
void hx_cubic_curve(const double *x, const double *y, const double *slope, int n, int linear,
                    double u, double out[3]);

/* The curve's third derivative at u: the piece's (6 times its cubic
 * coefficient), 0 on a straight continuation. */
double hx_cubic_curve_third(const double *x, const double *y, const double *slope, int n,
                            int linear, double u);

#endif
