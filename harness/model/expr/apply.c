/* The operators and pure functions computed (apply.h). */
#include "model/expr/apply.h"

#include <math.h>
#include <string.h>

#include "base/impact.h"
#include "base/series.h"
#include "base/transition.h"
#include "model/expr/functions.h"

static int fail(hx_expr_fault *f, int fn, hx_expr_fault_kind kind, const char *what,
                int has_argument, double argument)
{
    f->kind = kind;
    f->function = hx_expr_function_at(fn)->name;
    f->what = what;
    f->has_argument = has_argument;
    f->argument = argument;
    return -1;
}

static int domain(hx_expr_fault *f, int fn, const char *what, double argument)
{
    return fail(f, fn, HX_EXPR_FAULT_DOMAIN, what, 1, argument);
}

/* -1, 0, 1: the slope of ABS, and the sign SIGN gives its first argument */
static double sign_of(double x)
{
    return x > 0.0 ? 1.0 : x < 0.0 ? -1.0 : 0.0;
}

/* MIN and MAX: the first argument when it wins, the mean at a tie */
static double pick(double a, double b, int first_wins, int tie, double *partials)
{
    if (partials != NULL) {
        partials[0] = tie ? 0.5 : first_wins ? 1.0 : 0.0;
        partials[1] = 1.0 - partials[0];
    }
    return first_wins ? a : b;
}

static int transition(int fn, hx_transition_shape shape, const double *a, double *value,
                      double *partials, hx_expr_fault *f)
{
    if (a[3] < a[1])
        return domain(f, fn, "its x1 is below its x0", a[3]);
    if (shape == HX_TRANSITION_HAVSIN && !(a[3] > a[1]))
        return domain(f, fn, "its x1 equals its x0 (a jump the haversine cannot make)", a[3]);
    *value = hx_transition(shape, a[0], a[1], a[2], a[3], a[4], 0);
    if (partials != NULL)
        hx_transition_partials(shape, a[0], a[1], a[2], a[3], a[4], partials);
    return 0;
}

/* k, e, cmax, d of IMPACT and BISTOP (k >= 0, e > 0, cmax >= 0, d > 0) */
static int stop_parameters(int fn, const double *p, hx_expr_fault *f)
{
    if (!(p[0] >= 0.0))
        return domain(f, fn, "its stiffness k is negative", p[0]);
    if (!(p[1] > 0.0))
        return domain(f, fn, "its exponent e is not positive", p[1]);
    if (!(p[2] >= 0.0))
        return domain(f, fn, "its damping cmax is negative", p[2]);
    if (!(p[3] > 0.0))
        return domain(f, fn, "its penetration d is not positive", p[3]);
    return 0;
}

/* POLY, CHEBY (x, x0, a...) and FORCOS, FORSIN (x, x0, w, a...) */
static void series(int fn, const double *a, int nargs, double *value, double *partials)
{
    const int fourier = fn == HX_FN_FORCOS || fn == HX_FN_FORSIN, first = fourier ? 3 : 2;
    const int cosine = fn == HX_FN_FORCOS, n = nargs - first;
    const double *c = a + first;
    double slope;
    if (fn == HX_FN_POLY)
        *value = hx_poly(a[0], a[1], c, n, 0), slope = hx_poly(a[0], a[1], c, n, 1);
    else if (fn == HX_FN_CHEBY)
        *value = hx_cheby(a[0], a[1], c, n, 0), slope = hx_cheby(a[0], a[1], c, n, 1);
    else
        *value = hx_fourier(cosine, a[0], a[1], a[2], c, n, 0),
        slope = hx_fourier(cosine, a[0], a[1], a[2], c, n, 1);
    if (partials == NULL)
        return;
    partials[0] = slope, partials[1] = -slope;
    if (fn == HX_FN_POLY)
        hx_poly_coefficient_partials(a[0], a[1], n, partials + 2);
    else if (fn == HX_FN_CHEBY)
        hx_cheby_coefficient_partials(a[0], a[1], n, partials + 2);
    else
        hx_fourier_partials(cosine, a[0], a[1], a[2], c, n, partials + 2, partials + 3);
}

/* The functions of one argument with their slope; 0, or -1 with the fault. */
static int unary(int fn, double x, double *value, double *slope, hx_expr_fault *f)
{
    switch (fn) {
    case HX_FN_NEG: *value = -x, *slope = -1.0; return 0;
    case HX_FN_ABS: *value = fabs(x), *slope = sign_of(x); return 0;
    case HX_FN_SQRT:
        if (x < 0.0)
            return domain(f, fn, "its argument is negative", x);
        *value = sqrt(x), *slope = 0.5 / *value;
        return 0;
    case HX_FN_EXP: *value = exp(x), *slope = *value; return 0;
    case HX_FN_LOG:
    case HX_FN_LOG10:
        if (!(x > 0.0))
            return domain(f, fn, "its argument is not above 0", x);
        *value = fn == HX_FN_LOG ? log(x) : log10(x);
        *slope = fn == HX_FN_LOG ? 1.0 / x : 1.0 / (x * M_LN10);
        return 0;
    case HX_FN_SIN: *value = sin(x), *slope = cos(x); return 0;
    case HX_FN_COS: *value = cos(x), *slope = -sin(x); return 0;
    case HX_FN_TAN: *value = tan(x), *slope = 1.0 + *value * *value; return 0;
    case HX_FN_ASIN:
    case HX_FN_ACOS:
        if (!(fabs(x) <= 1.0))
            return domain(f, fn, "its argument is outside [-1, 1]", x);
        *value = fn == HX_FN_ASIN ? asin(x) : acos(x);
        *slope = (fn == HX_FN_ASIN ? 1.0 : -1.0) / sqrt(1.0 - x * x);
        return 0;
    case HX_FN_ATAN: *value = atan(x), *slope = 1.0 / (1.0 + x * x); return 0;
    case HX_FN_SINH: *value = sinh(x), *slope = cosh(x); return 0;
    case HX_FN_COSH: *value = cosh(x), *slope = sinh(x); return 0;
    case HX_FN_TANH: *value = tanh(x), *slope = 1.0 - *value * *value; return 0;
    case HX_FN_AINT: *value = trunc(x), *slope = 0.0; return 0;
    default: /* HX_FN_ANINT: half away from zero, int(x + 0.5) or int(x - 0.5) */
        *value = round(x), *slope = 0.0;
        return 0;
    }
}

/* a ** b: a negative a takes whole powers only; 0 takes no negative power */
static int power(const double *a, double *value, double *partials, hx_expr_fault *f)
{
    const double x = a[0], y = a[1];
    if (x < 0.0 && y != trunc(y))
        return domain(f, HX_FN_POW, "a negative number raised to a power that is not whole", x);
    if (x == 0.0 && y < 0.0)
        return fail(f, HX_FN_POW, HX_EXPR_FAULT_DIVISION_BY_ZERO,
                    "division by zero (0 raised to a negative power)", 0, 0.0);
    *value = pow(x, y);
    if (partials != NULL) {
        partials[0] = y == 0.0 ? 0.0 : y * pow(x, y - 1.0);
        /* in the exponent only where the base is positive: elsewhere the power
         * exists at whole exponents alone */
        partials[1] = x > 0.0 ? *value * log(x) : 0.0;
    }
    return 0;
}

static int binary(int fn, const double *a, double *value, double *partials, hx_expr_fault *f)
{
    double local[2];
    double *d = partials != NULL ? partials : local;
    const double x = a[0], y = a[1];
    switch (fn) {
    case HX_FN_ADD: *value = x + y, d[0] = 1.0, d[1] = 1.0; return 0;
    case HX_FN_SUB: *value = x - y, d[0] = 1.0, d[1] = -1.0; return 0;
    case HX_FN_MUL: *value = x * y, d[0] = y, d[1] = x; return 0;
    case HX_FN_DIV:
        if (y == 0.0)
            return fail(f, fn, HX_EXPR_FAULT_DIVISION_BY_ZERO, "division by zero", 0, 0.0);
        *value = x / y, d[0] = 1.0 / y, d[1] = -*value / y;
        return 0;
    case HX_FN_POW: return power(a, value, partials, f);
    case HX_FN_SIGN:
        *value = y >= 0.0 ? fabs(x) : -fabs(x);
        d[0] = (y >= 0.0 ? 1.0 : -1.0) * sign_of(x), d[1] = 0.0;
        return 0;
    case HX_FN_MIN: *value = pick(x, y, x < y, x == y, partials); return 0;
    case HX_FN_MAX: *value = pick(x, y, x > y, x == y, partials); return 0;
    case HX_FN_MOD:
        if (y == 0.0)
            return fail(f, fn, HX_EXPR_FAULT_DIVISION_BY_ZERO, "division by zero (MOD by 0)", 0,
                        0.0);
        /* a1 - AINT(a1/a2) a2, exactly */
        *value = fmod(x, y), d[0] = 1.0, d[1] = -trunc(x / y);
        return 0;
    case HX_FN_DIM:
        *value = x > y ? x - y : 0.0;
        d[0] = x > y ? 1.0 : x == y ? 0.5 : 0.0, d[1] = -d[0];
        return 0;
    default: { /* HX_FN_ATAN2 (y, x): here x holds y and y holds x */
        if (x == 0.0 && y == 0.0)
            return domain(f, fn, "both its arguments are 0", 0.0);
        *value = atan2(x, y);
        const double r2 = x * x + y * y;
        d[0] = y / r2, d[1] = -x / r2;
        return 0;
    }
    }
}

int hx_expr_apply(int fn, const double *args, int nargs, double *value, double *partials,
                  hx_expr_fault *fault)
{
    /* the result apart from the arguments, which it may be written over */
    double result = 0.0, *value_out = value;
    value = &result;
    int status = 0;
    switch (fn) {
    case HX_FN_STEP:
        status = transition(fn, HX_TRANSITION_STEP, args, value, partials, fault);
        break;
    case HX_FN_STEP5:
        status = transition(fn, HX_TRANSITION_STEP5, args, value, partials, fault);
        break;
    case HX_FN_HAVSIN:
        status = transition(fn, HX_TRANSITION_HAVSIN, args, value, partials, fault);
        break;
    case HX_FN_IMPACT:
        if ((status = stop_parameters(fn, args + 3, fault)) == 0)
            *value = hx_impact(args[0], args[1], args[2], args[3], args[4], args[5], args[6],
                               partials);
        break;
    case HX_FN_BISTOP:
        if (args[3] < args[2])
            status = domain(fault, fn, "its x2 is below its x1", args[3]);
        else if ((status = stop_parameters(fn, args + 4, fault)) == 0)
            *value = hx_bistop(args[0], args[1], args[2], args[3], args[4], args[5], args[6],
                               args[7], partials);
        break;
    case HX_FN_POLY:
    case HX_FN_CHEBY:
    case HX_FN_FORCOS:
    case HX_FN_FORSIN: series(fn, args, nargs, value, partials); break;
    case HX_FN_SHF:
        *value = hx_shf(args[0], args[1], args[2], args[3], args[4], args[5], 0);
        if (partials != NULL)
            hx_shf_partials(args[0], args[1], args[2], args[3], args[4], args[5], partials);
        break;
    default:
        if (nargs == 2) {
            status = binary(fn, args, value, partials, fault);
        } else {
            double slope;
            status = unary(fn, args[0], value, &slope, fault);
            if (status == 0 && partials != NULL)
                partials[0] = slope;
        }
        break;
    }
    if (status != 0)
        return -1;
    if (!isfinite(result))
        return fail(fault, fn, HX_EXPR_FAULT_NOT_FINITE, "its result is not finite", 0, 0.0);
    *value_out = result;
    return 0;
}
