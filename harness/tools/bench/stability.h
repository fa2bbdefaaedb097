/*
 * Stability limits of the integrators for a model: the fastest mode
 * of the dynamics linearized at a state (its eigenvalue lambda, by power
 * iteration on J^2 with J v from central differences of the right-hand side,
 * then a two-vector Arnoldi step for the pair it converged to; over every
 * state but the work accumulators: the bodies', the Force_StateEqn and the
 * Control_Diff states), and for each
 * method the largest fixed step h with h lambda inside its stability region
 * (BDF, A(alpha)-stable, has none: any step).
 */
#ifndef HX_TOOLS_BENCH_STABILITY_H
#define HX_TOOLS_BENCH_STABILITY_H

#include "sim/dynamics/dynamics.h"
#include "sim/ode/integrator.h"

typedef struct hx_stability {
    double magnitude;                 /* |lambda|, per time unit */
    double re, im;                    /* lambda = re + i im, im >= 0 */
    double max_step[HX_METHOD_COUNT]; /* by hx_method: 0 = no stable step, INFINITY = any */
    int evaluations;                  /* right-hand sides spent */
} hx_stability;

/* Estimates at state y and time t. Returns 0, or -1 with msg (the
 * right-hand side failed). */
int hx_estimate_stability(const hx_dynamics *d, double t, const double *y, hx_stability *out,
                          hx_message *msg);

/* Largest h with h lambda stable for the method (lambda = re + i im). */
double hx_stable_step(hx_method method, double re, double im);

/* One line: "|lambda| = ...; largest stable step: euler ..., ...". */
void hx_stability_text(const hx_stability *s, char *text, size_t size);

#endif
