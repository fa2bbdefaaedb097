/*
 * Nonlinear joint coupler (docs/interface.md §2):
 *   phi(M) = G_1(M_1) + G_2(M_2) [+ G_3(M_3)]
 * USER(term_1, term_2 [, term_3]), a term being a code and its numbers:
 *   1 s                      G = s*M
 *   2 n a0..an (0<=n<=6)     G = a0 + a1 M + ... + an M^n
 *   3 n x1 y1 .. xn yn       G = natural cubic spline through the points
 *   4 string_id scale        G = scale * spline through the file's "x y" rows
 *   5 a w p                  G = a sin(w M + p)
 */
#ifndef USRSUB_COUPLER_H
#define USRSUB_COUPLER_H

#include "usrsub/core/jet.h"
#include "usrsub/core/message.h"
#include "usrsub/core/polynomial.h"
#include "usrsub/core/spline.h"

#ifdef __cplusplus
extern "C" {
#endif

#define USRSUB_COUPLER_MAX_TERMS 3

enum usrsub_coupler_code {
    USRSUB_COUPLER_LINEAR = 1,
    USRSUB_COUPLER_POLYNOMIAL = 2,
    USRSUB_COUPLER_SPLINE = 3,
    USRSUB_COUPLER_SPLINE_FILE = 4,
    USRSUB_COUPLER_SINE = 5
};

typedef struct usrsub_coupler_term {
    int code;
    double slope;              /* code 1 */
    usrsub_polynomial poly;    /* code 2 */
    usrsub_spline spline;      /* codes 3 and 4 */
    double scale;              /* codes 3 (1) and 4 */
    double amplitude, frequency, phase; /* code 5 */
} usrsub_coupler_term;

typedef struct usrsub_coupler {
    int nterms;
    usrsub_coupler_term term[USRSUB_COUPLER_MAX_TERMS];
} usrsub_coupler;


/* G, G', G'' of one term. */
usrsub_jet usrsub_coupler_term_eval(const usrsub_coupler_term *t, double m);

/* The interval of M a term has data for (the knots of a spline): returns 1 and
 * the bounds, or 0 for analytic terms defined everywhere. */
int usrsub_coupler_term_range(const usrsub_coupler_term *t, double *lo, double *hi);

double usrsub_coupler_phi(const usrsub_coupler *c, const double *disp);
void usrsub_coupler_gradient(const usrsub_coupler *c, const double *disp, double *dfda);
/* Full nterms x nterms matrix, column-major; diagonal G_i'', rest 0. */
void usrsub_coupler_hessian(const usrsub_coupler *c, const double *disp, double *d2fda2);

/* Frees the splines of its terms. */
void usrsub_coupler_free(usrsub_coupler *c);

#ifdef __cplusplus
}
#endif

#endif
