/* Polynomial a0 + a1 x + ... + an x^n (0 <= n <= 6) with derivatives. */
#ifndef USRSUB_POLYNOMIAL_H
#define USRSUB_POLYNOMIAL_H

#include "usrsub/core/jet.h"

#ifdef __cplusplus
extern "C" {
#endif

#define USRSUB_POLYNOMIAL_MAX_DEGREE 6

typedef struct usrsub_polynomial {
    int degree;
    double a[USRSUB_POLYNOMIAL_MAX_DEGREE + 1];
} usrsub_polynomial;

usrsub_jet usrsub_polynomial_eval(const usrsub_polynomial *p, double x);

/* One derivative (order 0, 1 or 2) alone, by Horner's rule on its coefficients. */
double usrsub_polynomial_derivative(const usrsub_polynomial *p, double x, int order);

#ifdef __cplusplus
}
#endif

#endif
