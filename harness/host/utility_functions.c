/*
 * The utilities that are functions of their arguments alone (docs/interface.md
 * §5.2): STEP, STEP5, HAVSIN, IMPACT, BISTOP, POLY, CHEBY, FORCOS, FORSIN and
 * SHF, with their first and second derivatives: the arguments checked and
 * reported here, the functions computed by the harness's one implementation
 * (base/transition.h, base/impact.h, base/series.h), which the function
 * expressions use too. Nothing of the library they serve.
 */
#include <math.h>

#include "base/impact.h"
#include "base/series.h"
#include "base/transition.h"
#include "host/utilities.h"
#include "usrsub/solver_abi.h"

#define MAX_COEFFICIENTS HX_SERIES_MAX_COEFFICIENTS

/* The order of the derivative asked for: 0, 1 or 2. */
static int order_ok(hx_utility u, int iord, int *errflg)
{
    if (iord >= 0 && iord <= 2)
        return 1;
    hx_utility_refused(u, "iord = %d (0, 1 or 2: the value or its derivative)", iord);
    *errflg = 1;
    return 0;
}

/* Every argument finite: a NaN would otherwise pass through a comparison
 * as one side of a transition. 1 when they are; else 0, with the out
 * values (iord + 1 of them) NaN and errflg clear in a dependency pass, or
 * errflg set (hx_utility_non_finite). */
static int finite_ok(hx_utility u, const double *args, int n, int iord, double *out, int *errflg)
{
    for (int k = 0; k < n; ++k)
        if (!isfinite(args[k])) {
            if (hx_utility_non_finite(u, "a non-finite argument (argument %d is %g)", k + 1,
                                      args[k]))
                for (int i = 0; i <= iord; ++i)
                    out[i] = NAN;
            else
                *errflg = 1;
            return 0;
        }
    return 1;
}

static void transition(hx_utility u, hx_transition_shape shape, double x, double x0, double h0,
                       double x1, double h1, int iord, double *value, int *errflg)
{
    *errflg = 0;
    if (!order_ok(u, iord, errflg) ||
        !finite_ok(u, (const double[]){x, x0, h0, x1, h1}, 5, 0, value, errflg))
        return;
    if (!(x1 > x0)) {
        hx_utility_refused(u, "x1 = %g not above x0 = %g", x1, x0);
        *errflg = 1;
        return;
    }
    *value = hx_transition(shape, x, x0, h0, x1, h1, iord);
}

void c_step(double x, double x0, double h0, double x1, double h1, int iord, double *value,
            int *errflg)
{
    transition(HX_UTILITY_STEP, HX_TRANSITION_STEP, x, x0, h0, x1, h1, iord, value, errflg);
}

void c_step5(double x, double x0, double h0, double x1, double h1, int iord, double *value,
             int *errflg)
{
    transition(HX_UTILITY_STEP5, HX_TRANSITION_STEP5, x, x0, h0, x1, h1, iord, value, errflg);
}

void c_havsin(double x, double x0, double h0, double x1, double h1, int iord, double *value,
              int *errflg)
{
    transition(HX_UTILITY_HAVSIN, HX_TRANSITION_HAVSIN, x, x0, h0, x1, h1, iord, value, errflg);
}

static int stop_parameters_ok(hx_utility u, double k, double e, double cmax, double d,
                              int *errflg)
{
    if (k >= 0.0 && e > 0.0 && cmax >= 0.0 && d > 0.0)
        return 1;
    hx_utility_refused(u, "k = %g, e = %g, cmax = %g, d = %g (k >= 0, e > 0, cmax >= 0, d > 0)",
                       k, e, cmax, d);
    *errflg = 1;
    return 0;
}

static void stop_output(const double f[6], double sign, int iord, double *vec)
{
    if (iord == 0)
        vec[0] = sign * f[0];
    else if (iord == 1)
        vec[0] = sign * f[1], vec[1] = sign * f[2];
    else
        vec[0] = sign * f[3], vec[1] = sign * f[4], vec[2] = sign * f[5];
}

void c_impact(double x, double dxdt, double x1, double k, double e, double cmax, double d,
              int iord, double *vec, int *errflg)
{
    *errflg = 0;
    if (!order_ok(HX_UTILITY_IMPACT, iord, errflg) ||
        !finite_ok(HX_UTILITY_IMPACT, (const double[]){x, dxdt, x1, k, e, cmax, d}, 7, iord, vec,
                   errflg) ||
        !stop_parameters_ok(HX_UTILITY_IMPACT, k, e, cmax, d, errflg))
        return;
    double f[6];
    hx_impact_side(x1 - x, -1.0, dxdt, k, e, cmax, d, f);
    stop_output(f, 1.0, iord, vec);
}

void c_bistop(double x, double dxdt, double x1, double x2, double k, double e, double cmax,
              double d, int iord, double *vec, int *errflg)
{
    *errflg = 0;
    if (!order_ok(HX_UTILITY_BISTOP, iord, errflg) ||
        !finite_ok(HX_UTILITY_BISTOP, (const double[]){x, dxdt, x1, x2, k, e, cmax, d}, 8, iord,
                   vec, errflg) ||
        !stop_parameters_ok(HX_UTILITY_BISTOP, k, e, cmax, d, errflg))
        return;
    if (!(x2 >= x1)) {
        hx_utility_refused(HX_UTILITY_BISTOP, "x2 = %g below x1 = %g", x2, x1);
        *errflg = 1;
        return;
    }
    double f[6];
    if (x < x1) {
        hx_impact_side(x1 - x, -1.0, dxdt, k, e, cmax, d, f);
        stop_output(f, 1.0, iord, vec);
    } else {
        hx_impact_side(x - x2, 1.0, dxdt, k, e, cmax, d, f); /* pushes back: negative */
        stop_output(f, -1.0, iord, vec);
    }
}

static int coefficients_ok(hx_utility u, const double *par, int npar, int *errflg)
{
    if (par != NULL && npar >= 1 && npar <= MAX_COEFFICIENTS)
        return 1;
    hx_utility_refused(u, "npar = %d coefficients (1 to %d)", npar, MAX_COEFFICIENTS);
    *errflg = 1;
    return 0;
}

/* sum a_j (x - x0)^j */
void c_poly(double x, double x0, const double *par, int npar, int iord, double *value,
            int *errflg)
{
    *errflg = 0;
    if (!order_ok(HX_UTILITY_POLY, iord, errflg) ||
        !coefficients_ok(HX_UTILITY_POLY, par, npar, errflg))
        return;
    *value = hx_poly(x, x0, par, npar, iord);
}

/* sum a_j T_j(x - x0), T_0 = 1, T_1 = u, T_j = 2 u T_(j-1) - T_(j-2) */
void c_cheby(double x, double x0, const double *par, int npar, int iord, double *value,
             int *errflg)
{
    *errflg = 0;
    if (!order_ok(HX_UTILITY_CHEBY, iord, errflg) ||
        !coefficients_ok(HX_UTILITY_CHEBY, par, npar, errflg))
        return;
    *value = hx_cheby(x, x0, par, npar, iord);
}

/* a_0 + sum a_j f(j w (x - x0)), f = cos or sin */
static void fourier(hx_utility u, int cosine, double x, double x0, double w, const double *par,
                    int npar, int iord, double *value, int *errflg)
{
    *errflg = 0;
    if (!order_ok(u, iord, errflg) || !coefficients_ok(u, par, npar, errflg))
        return;
    *value = hx_fourier(cosine, x, x0, w, par, npar, iord);
}

void c_forcos(double x, double x0, double w, const double *par, int npar, int iord,
              double *value, int *errflg)
{
    fourier(HX_UTILITY_FORCOS, 1, x, x0, w, par, npar, iord, value, errflg);
}

void c_forsin(double x, double x0, double w, const double *par, int npar, int iord,
              double *value, int *errflg)
{
    fourier(HX_UTILITY_FORSIN, 0, x, x0, w, par, npar, iord, value, errflg);
}

/* a sin(w (x - x0) - phi) + b */
void c_shf(double x, double x0, double a, double w, double phi, double b, int iord,
           double *value, int *errflg)
{
    *errflg = 0;
    if (!order_ok(HX_UTILITY_SHF, iord, errflg))
        return;
    *value = hx_shf(x, x0, a, w, phi, b, iord);
}
