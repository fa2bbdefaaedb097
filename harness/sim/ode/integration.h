/*
 * One integration in progress, shared by the integrators (integrator.c,
 * dopri5.c, bdf.c, arkode_dopri5.c): the problem, the options, the counters,
 * and the bookkeeping of output times and divergence.
 */
#ifndef HX_SIM_ODE_INTEGRATION_H
#define HX_SIM_ODE_INTEGRATION_H

#include "sim/ode/integrator.h"

typedef struct hx_integration {
    const hx_ode *ode;
    const hx_integrator_options *opt;
    hx_integrator_stats *stats;
    double limit; /* unstable above this norm */
    double t0;
    long outputs; /* output times emitted: the next is t0 + (outputs + 1) interval */
} hx_integration;

double hx_integration_norm(const double *y, int n);
/* The next output time (counted, not summed, so that the last one lands on
 * the end however many there are). */
double hx_integration_next_output(const hx_integration *r);
/* One right-hand side, counted. */
int hx_integration_evaluate(hx_integration *r, double t, const double *y, double *ydot);
/* Positions and velocities finite and not grown without bound. */
int hx_integration_finite_and_bounded(const hx_integration *r, const double *y);

hx_status hx_integrate_dopri5(hx_integration *r, double t0, double *y);
hx_status hx_integrate_bdf(hx_integration *r, double t0, double *y);
hx_status hx_integrate_arkode_dopri5(hx_integration *r, double t0, double *y);

#endif
