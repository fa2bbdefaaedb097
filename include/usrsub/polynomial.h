/* Polynomial a0 + a1 x + ... + an x^n (0 <= n <= 6) with derivatives. */
#ifndef USRSUB_POLYNOMIAL_H
#define USRSUB_POLYNOMIAL_H

#include "usrsub/jet.h"

#ifdef __cplusplus
extern "C" {
#endif

#define USRSUB_POLYNOMIAL_MAX_DEGREE 6

typedef struct usrsub_polynomial {
    int degree;
    double a[USRSUB_POLYNOMIAL_MAX_DEGREE + 1];
} usrsub_polynomial;

usrsub_jet usrsub_polynomial_eval(const usrsub_polynomial *p, double x);

#ifdef __cplusplus
}
#endif

#endif
