/*
 * POLY, CHEBY, FORCOS, FORSIN and SHF (docs/interface.md §5.2, §8.4): the
 * series in x - x0, their derivatives in x and their partials in the other
 * arguments. The one implementation behind the host's c_poly, c_cheby,
 * c_forcos, c_forsin and c_shf and the function expressions. n is the count
 * of coefficients a_0 .. a_(n-1), 1 to HX_SERIES_MAX_COEFFICIENTS (the
 * caller's to check).
 */
#ifndef HX_BASE_SERIES_H
#define HX_BASE_SERIES_H

#define HX_SERIES_MAX_COEFFICIENTS 31 /* a0 .. a30, as the expression functions allow */

/* sum a_j (x - x0)^j, or its iord-th derivative in x (iord 0, 1, 2) */
double hx_poly(double x, double x0, const double *a, int n, int iord);
/* Its partials in a_j: (x - x0)^j, j = 0 .. n - 1. */
void hx_poly_coefficient_partials(double x, double x0, int n, double *d);

/* sum a_j T_j(x - x0), T_0 = 1, T_1 = u, T_j = 2 u T_(j-1) - T_(j-2), or
 * its iord-th derivative in x */
double hx_cheby(double x, double x0, const double *a, int n, int iord);
/* Its partials in a_j: T_j(x - x0). */
void hx_cheby_coefficient_partials(double x, double x0, int n, double *d);

/* a_0 + sum_(j >= 1) a_j f(j w (x - x0)), f = cos (cosine != 0) or sin, or
 * its iord-th derivative in x */
double hx_fourier(int cosine, double x, double x0, double w, const double *a, int n, int iord);
/* Its partials in w (*d_dw) and in a_j (d_da[j]). */
void hx_fourier_partials(int cosine, double x, double x0, double w, const double *a, int n,
                         double *d_dw, double *d_da);

/* a sin(w (x - x0) - phi) + b, or its iord-th derivative in x */
double hx_shf(double x, double x0, double a, double w, double phi, double b, int iord);
/* Its partials in x, x0, a, w, phi and b (d[0..5]). */
void hx_shf_partials(double x, double x0, double a, double w, double phi, double b, double d[6]);

#endif
