/* Coupler terms and phi with its first and second partials
 * (coupler.h; docs/interface.md §2). */
#include "usrsub/core/coupler.h"

#include <math.h>
#include <string.h>

void usrsub_coupler_free(usrsub_coupler *c)
{
    for (int k = 0; k < USRSUB_COUPLER_MAX_TERMS; ++k)
        if (c->term[k].spline.x != NULL)
            usrsub_spline_free(&c->term[k].spline);
    c->nterms = 0;
}

usrsub_jet usrsub_coupler_term_eval(const usrsub_coupler_term *t, double m)
{
    usrsub_jet j;
    switch (t->code) {
    case USRSUB_COUPLER_LINEAR:
        j.value = t->slope * m;
        j.d1 = t->slope;
        j.d2 = 0.0;
        return j;
    case USRSUB_COUPLER_POLYNOMIAL:
        return usrsub_polynomial_eval(&t->poly, m);
    case USRSUB_COUPLER_SPLINE:
    case USRSUB_COUPLER_SPLINE_FILE:
        j = usrsub_spline_eval(&t->spline, m);
        j.value *= t->scale;
        j.d1 *= t->scale;
        j.d2 *= t->scale;
        return j;
    default: {
        const double arg = t->frequency * m + t->phase;
        const double s = sin(arg), co = cos(arg);
        j.value = t->amplitude * s;
        j.d1 = t->amplitude * t->frequency * co;
        j.d2 = -t->amplitude * t->frequency * t->frequency * s;
        return j;
    }
    }
}

int usrsub_coupler_term_range(const usrsub_coupler_term *t, double *lo, double *hi)
{
    if (t->code != USRSUB_COUPLER_SPLINE && t->code != USRSUB_COUPLER_SPLINE_FILE)
        return 0;
    *lo = t->spline.x[0];
    *hi = t->spline.x[t->spline.n - 1];
    return 1;
}

/* One derivative (order 0, 1 or 2) of a term: what each entry needs, no more. */
static inline double term_derivative(const usrsub_coupler_term *t, double m, int order)
{
    switch (t->code) {
    case USRSUB_COUPLER_LINEAR:
        return order == 0 ? t->slope * m : order == 1 ? t->slope : 0.0;
    case USRSUB_COUPLER_POLYNOMIAL:
        return usrsub_polynomial_derivative(&t->poly, m, order);
    case USRSUB_COUPLER_SPLINE:
    case USRSUB_COUPLER_SPLINE_FILE:
        return t->scale * usrsub_spline_derivative(&t->spline, m, order);
    default: {
        const double arg = t->frequency * m + t->phase;
        if (order == 1)
            return t->amplitude * t->frequency * cos(arg);
        const double s = t->amplitude * sin(arg);
        return order == 0 ? s : -t->frequency * t->frequency * s;
    }
    }
}

double usrsub_coupler_phi(const usrsub_coupler *c, const double *disp)
{
    double phi = 0.0;
    for (int k = 0; k < c->nterms; ++k)
        phi += term_derivative(&c->term[k], disp[k], 0);
    return phi;
}

void usrsub_coupler_gradient(const usrsub_coupler *c, const double *disp, double *dfda)
{
    for (int k = 0; k < c->nterms; ++k)
        dfda[k] = term_derivative(&c->term[k], disp[k], 1);
}

void usrsub_coupler_hessian(const usrsub_coupler *c, const double *disp, double *d2fda2)
{
    const int n = c->nterms;
    memset(d2fda2, 0, sizeof(double) * (size_t)(n * n));
    for (int i = 0; i < n; ++i)
        d2fda2[i * (n + 1)] = term_derivative(&c->term[i], disp[i], 2);
}
