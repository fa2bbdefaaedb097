/* Bookkeeping shared by the integrators (integration.h). */
#include "sim/ode/integration.h"

#include <math.h>

double hx_integration_norm(const double *y, int n)
{
    double s = 0.0;
    for (int k = 0; k < n; ++k)
        s += y[k] * y[k];
    return sqrt(s);
}



/* The next output time (counted, not summed, so that the last one lands on
 * the end however many there are). */
double hx_integration_next_output(const hx_integration *r)
{
    const double t = r->t0 + (double)(r->outputs + 1) * r->opt->output_interval;
    return fabs(t - r->opt->t_end) <= 1e-9 * r->opt->output_interval ? r->opt->t_end : t;
}

int hx_integration_evaluate(hx_integration *r, double t, const double *y, double *ydot)
{
    r->stats->evaluations++;
    return r->ode->rhs(r->ode->ctx, t, y, ydot);
}

/* Positions and velocities finite and not grown without bound (the other
 * components, such as accumulated work, may grow legitimately). */
int hx_integration_finite_and_bounded(const hx_integration *r, const double *y)
{
    const int m = r->ode->nq + r->ode->nu > 0 ? r->ode->nq + r->ode->nu : r->ode->n;
    if (!isfinite(hx_integration_norm(y, r->ode->n)))
        return 0;
    return hx_integration_norm(y, m) <= r->limit;
}

