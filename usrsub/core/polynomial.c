/* Polynomial value and derivatives by Horner's rule. */
#include "usrsub/core/polynomial.h"

usrsub_jet usrsub_polynomial_eval(const usrsub_polynomial *p, double x)
{
    double v = 0.0, d1 = 0.0, d2 = 0.0;
    for (int k = p->degree; k >= 0; --k) {
        d2 = d2 * x + 2.0 * d1;
        d1 = d1 * x + v;
        v = v * x + p->a[k];
    }
    usrsub_jet j = {v, d1, d2};
    return j;
}

double usrsub_polynomial_derivative(const usrsub_polynomial *p, double x, int order)
{
    double v = 0.0;
    for (int k = p->degree; k >= order; --k) {
        const double factor = order == 0 ? 1.0 : order == 1 ? k : (double)k * (k - 1);
        v = v * x + factor * p->a[k];
    }
    return v;
}
