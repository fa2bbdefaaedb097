/*
 * One integration in progress, shared by the integrators (integrator.c,
 * dopri5.c, bdf.c, arkode_dopri5.c): the problem, the options, the counters,
 * and the bookkeeping of output times and divergence.
 */
#ifndef HX_SIM_INTEGRATION_RUN_H
#define HX_SIM_INTEGRATION_RUN_H

#include "sim/integrator.h"

typedef struct hx_run {
    const hx_ode *ode;
    const hx_integrator_options *opt;
    hx_integrator_stats *stats;
    double limit; /* unstable above this norm */
    double t0;
    long outputs; /* output times emitted: the next is t0 + (outputs + 1) interval */
} hx_run;

double hx_run_norm(const double *y, int n);
/* The next output time (counted, not summed, so that the last one lands on
 * the end however many there are). */
double hx_run_next_output(const hx_run *r);
/* One right-hand side, counted. */
int hx_run_evaluate(hx_run *r, double t, const double *y, double *ydot);
/* Positions and velocities finite and not grown without bound. */
int hx_run_finite_and_bounded(const hx_run *r, const double *y);

hx_status hx_integrate_dopri5(hx_run *r, double t0, double *y);
hx_status hx_integrate_bdf(hx_run *r, double t0, double *y);
hx_status hx_integrate_arkode_dopri5(hx_run *r, double t0, double *y);

#endif
