/*
 * The utilities that are functions of their arguments alone (docs/interface.md
 * §5.2): STEP, STEP5, HAVSIN, IMPACT, BISTOP, POLY, CHEBY, FORCOS, FORSIN and
 * SHF, with their first and second derivatives. Written from the functions'
 * definitions; nothing of the library they serve.
 */
#include <math.h>

#include "host/utilities.h"
#include "usrsub/solver_abi.h"

#define MAX_COEFFICIENTS 31 /* a0 .. a30, as the expression functions allow */

/* The order of the derivative asked for: 0, 1 or 2. */
static int order_ok(hx_utility u, int iord, int *errflg)
{
    if (iord >= 0 && iord <= 2)
        return 1;
    hx_utility_refused(u, "iord = %d (0, 1 or 2: the value or its derivative)", iord);
    *errflg = 1;
    return 0;
}

/* A smooth transition from (x0, h0) to (x1, h1): the shape s(u) on u in
 * [0, 1] with its two derivatives, scaled to x. */
typedef void shape_fn(double u, double s[3]);

static void cubic(double u, double s[3])
{
    s[0] = u * u * (3.0 - 2.0 * u), s[1] = 6.0 * u * (1.0 - u), s[2] = 6.0 - 12.0 * u;
}

static void quintic(double u, double s[3])
{
    s[0] = u * u * u * (10.0 + u * (-15.0 + 6.0 * u));
    s[1] = 30.0 * u * u * (1.0 - u) * (1.0 - u);
    s[2] = 60.0 * u * (1.0 - u) * (1.0 - 2.0 * u);
}

static void haversine(double u, double s[3])
{
    s[0] = 0.5 * (1.0 - cos(M_PI * u)), s[1] = 0.5 * M_PI * sin(M_PI * u);
    s[2] = 0.5 * M_PI * M_PI * cos(M_PI * u);
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

static void transition(hx_utility u, shape_fn *shape, double x, double x0, double h0, double x1,
                       double h1, int iord, double *value, int *errflg)
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
    double s[3] = {0.0, 0.0, 0.0};
    if (x >= x1)
        s[0] = 1.0;
    else if (x > x0)
        shape((x - x0) / (x1 - x0), s);
    const double length = x1 - x0;
    *value = iord == 0 ? h0 + (h1 - h0) * s[0]
                       : (h1 - h0) * s[iord] / (iord == 1 ? length : length * length);
}

void c_step(double x, double x0, double h0, double x1, double h1, int iord, double *value,
            int *errflg)
{
    transition(HX_UTILITY_STEP, cubic, x, x0, h0, x1, h1, iord, value, errflg);
}

void c_step5(double x, double x0, double h0, double x1, double h1, int iord, double *value,
             int *errflg)
{
    transition(HX_UTILITY_STEP5, quintic, x, x0, h0, x1, h1, iord, value, errflg);
}

void c_havsin(double x, double x0, double h0, double x1, double h1, int iord, double *value,
              int *errflg)
{
    transition(HX_UTILITY_HAVSIN, haversine, x, x0, h0, x1, h1, iord, value, errflg);
}

/* One side of a stop, the penetration p >= 0 growing as x moves by dp_dx = -1
 * (a lower stop) or +1 (an upper one); the damping rises as a cubic STEP over
 * the first d of penetration. f[0] the force's size, f[1..2] its slopes in x
 * and dxdt, f[3..5] the second derivatives (x x, x dxdt, dxdt dxdt), all zero
 * where the size would be negative (the stop only pushes). */
static void stop_side(double p, double dp_dx, double dxdt, double k, double e, double cmax,
                      double d, double f[6])
{
    for (int i = 0; i < 6; ++i)
        f[i] = 0.0;
    if (!(p > 0.0))
        return;
    double s[3] = {1.0, 0.0, 0.0};
    if (p < d)
        cubic(p / d, s);
    const double c = cmax * s[0], dc_dx = cmax * s[1] / d * dp_dx;
    const double d2c_dx2 = cmax * s[2] / (d * d);
    /* the damping opposes the penetration's rate, dp/dt = dp_dx dxdt */
    const double rate = dp_dx * dxdt;
    const double size = k * pow(p, e) + c * rate;
    if (!(size > 0.0))
        return;
    f[0] = size;
    f[1] = k * e * pow(p, e - 1.0) * dp_dx + dc_dx * rate;
    f[2] = c * dp_dx;
    f[3] = k * e * (e - 1.0) * pow(p, e - 2.0) + d2c_dx2 * rate;
    f[4] = dc_dx * dp_dx;
    f[5] = 0.0;
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
    stop_side(x1 - x, -1.0, dxdt, k, e, cmax, d, f);
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
        stop_side(x1 - x, -1.0, dxdt, k, e, cmax, d, f);
        stop_output(f, 1.0, iord, vec);
    } else {
        stop_side(x - x2, 1.0, dxdt, k, e, cmax, d, f); /* pushes back: negative */
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
    const double u = x - x0;
    double sum = 0.0;
    for (int j = npar - 1; j >= iord; --j) { /* Horner on the derivative's coefficients */
        const double factor = iord == 0 ? 1.0 : iord == 1 ? j : (double)j * (j - 1);
        sum = sum * u + factor * par[j];
    }
    *value = sum;
}

/* sum a_j T_j(x - x0), T_0 = 1, T_1 = u, T_j = 2 u T_(j-1) - T_(j-2) */
void c_cheby(double x, double x0, const double *par, int npar, int iord, double *value,
             int *errflg)
{
    *errflg = 0;
    if (!order_ok(HX_UTILITY_CHEBY, iord, errflg) ||
        !coefficients_ok(HX_UTILITY_CHEBY, par, npar, errflg))
        return;
    const double u = x - x0;
    double t[3] = {1.0, 0.0, 0.0}, t1[3] = {u, 1.0, 0.0}; /* T, T', T'' */
    double sum = par[0] * t[iord] + (npar > 1 ? par[1] * t1[iord] : 0.0);
    for (int j = 2; j < npar; ++j) {
        const double next[3] = {2.0 * u * t1[0] - t[0], 2.0 * t1[0] + 2.0 * u * t1[1] - t[1],
                                4.0 * t1[1] + 2.0 * u * t1[2] - t[2]};
        for (int i = 0; i < 3; ++i)
            t[i] = t1[i], t1[i] = next[i];
        sum += par[j] * t1[iord];
    }
    *value = sum;
}

/* a_0 + sum a_j f(j w (x - x0)), f = cos or sin */
static void fourier(hx_utility u, int cosine, double x, double x0, double w, const double *par,
                    int npar, int iord, double *value, int *errflg)
{
    *errflg = 0;
    if (!order_ok(u, iord, errflg) || !coefficients_ok(u, par, npar, errflg))
        return;
    double sum = iord == 0 ? par[0] : 0.0;
    for (int j = 1; j < npar; ++j) {
        const double a = j * w * (x - x0), c = cos(a), s = sin(a), f = j * w;
        const double term = cosine ? (iord == 0 ? c : iord == 1 ? -f * s : -f * f * c)
                                   : (iord == 0 ? s : iord == 1 ? f * c : -f * f * s);
        sum += par[j] * term;
    }
    *value = sum;
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
    const double angle = w * (x - x0) - phi;
    *value = iord == 0 ? a * sin(angle) + b
             : iord == 1 ? a * w * cos(angle)
                         : -a * w * w * sin(angle);
}
