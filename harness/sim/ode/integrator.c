/* The integrators' common entry, names and fixed-step methods (integrator.h). */
#include "sim/ode/integrator.h"
#include "sim/ode/integration.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* |(q,u)| > GROWTH_LIMIT (1 + |(q0,u0)|): the run is unstable */
#define GROWTH_LIMIT 1e12

void hx_integrator_defaults(hx_integrator_options *opt)
{
    memset(opt, 0, sizeof *opt);
    opt->method = HX_METHOD_RK4;
    opt->rtol = 1e-6;
    opt->atol = 1e-9;
}

const char *hx_method_name(hx_method method)
{
    switch (method) {
    case HX_METHOD_EULER: return "euler";
    case HX_METHOD_SYMPLECTIC_EULER: return "symplectic-euler";
    case HX_METHOD_RK4: return "rk4";
    case HX_METHOD_DOPRI5: return "dopri5";
    case HX_METHOD_BDF: return "bdf";
    case HX_METHOD_DOPRI5_ARKODE: return "dopri5-arkode";
    }
    return "?";
}

int hx_method_parse(const char *name, hx_method *method)
{
    for (int k = 0; k < HX_METHOD_COUNT; ++k)
        if (strcmp(name, hx_method_name((hx_method)k)) == 0) {
            *method = (hx_method)k;
            return 0;
        }
    return -1;
}

int hx_method_adaptive(hx_method method)
{
    return method == HX_METHOD_DOPRI5 || method == HX_METHOD_BDF ||
           method == HX_METHOD_DOPRI5_ARKODE;
}

int hx_jacobian_method_parse(const char *name, hx_jacobian_method *jacobian)
{
    if (strcmp(name, "analytic") == 0)
        *jacobian = HX_JACOBIAN_ANALYTIC;
    else if (strcmp(name, "fd") == 0)
        *jacobian = HX_JACOBIAN_FD;
    else
        return -1;
    return 0;
}

int hx_linear_solver_parse(const char *name, hx_linear_solver *solver)
{
    for (int k = HX_LINEAR_AUTO; k <= HX_LINEAR_KLU; ++k)
        if (strcmp(name, hx_linear_solver_name((hx_linear_solver)k)) == 0) {
            *solver = (hx_linear_solver)k;
            return 0;
        }
    return -1;
}

const char *hx_linear_solver_name(hx_linear_solver solver)
{
    switch (solver) {
    case HX_LINEAR_AUTO: return "auto";
    case HX_LINEAR_DENSE: return "dense";
    case HX_LINEAR_KLU: return "klu";
    }
    return "?";
}

const char *hx_status_text(hx_status status)
{
    switch (status) {
    case HX_INTEGRATION_OK: return "finished";
    case HX_INTEGRATION_FAILED: return "failed (the model reported an error)";
    case HX_INTEGRATION_UNSTABLE: return "unstable (the state diverged)";
    case HX_INTEGRATION_STEP_TOO_SMALL: return "step size too small";
    case HX_INTEGRATION_TOO_MANY_STEPS: return "too many steps";
    case HX_INTEGRATION_STOPPED: return "stopped";
    case HX_INTEGRATION_NO_CONVERGENCE: return "Newton iterations failed to converge";
    }
    return "?";
}

/* ---- fixed steps ----------------------------------------------------------------- */

static int fixed_step(hx_integration *r, hx_method method, double t, double h, double *y, double *work)
{
    const hx_ode *o = r->ode;
    const int n = o->n;
    double *k1 = work, *k2 = k1 + n, *k3 = k2 + n, *k4 = k3 + n, *tmp = k4 + n;
    if (hx_integration_evaluate(r, t, y, k1) != 0)
        return -1;
    switch (method) {
    case HX_METHOD_EULER:
        for (int i = 0; i < n; ++i)
            y[i] += h * k1[i];
        return 0;
    case HX_METHOD_SYMPLECTIC_EULER:
        /* velocities first, then positions with the new velocities */
        for (int i = o->nq; i < n; ++i)
            y[i] += h * k1[i];
        o->advance(o->ctx, y, h);
        return 0;
    case HX_METHOD_RK4:
        for (int i = 0; i < n; ++i)
            tmp[i] = y[i] + 0.5 * h * k1[i];
        if (hx_integration_evaluate(r, t + 0.5 * h, tmp, k2) != 0)
            return -1;
        for (int i = 0; i < n; ++i)
            tmp[i] = y[i] + 0.5 * h * k2[i];
        if (hx_integration_evaluate(r, t + 0.5 * h, tmp, k3) != 0)
            return -1;
        for (int i = 0; i < n; ++i)
            tmp[i] = y[i] + h * k3[i];
        if (hx_integration_evaluate(r, t + h, tmp, k4) != 0)
            return -1;
        for (int i = 0; i < n; ++i)
            y[i] += h * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]) / 6.0;
        return 0;
    default:
        return -1;
    }
}

static hx_status integrate_fixed(hx_integration *r, double t0, double *y)
{
    const hx_ode *o = r->ode;
    const hx_integrator_options *opt = r->opt;
    const double span = opt->t_end - t0;
    if (!(opt->step > 0.0) || !(span >= 0.0))
        return HX_INTEGRATION_FAILED;
    const long nsteps = span > 0.0 ? (long)ceil(span / opt->step - 1e-9) : 0;
    const double h = nsteps > 0 ? span / (double)nsteps : opt->step;
    long every = opt->output_interval > 0.0 ? lround(opt->output_interval / h) : 1;
    if (every < 1)
        every = 1;
    double *work = malloc(sizeof(double) * 5u * (size_t)o->n);
    if (work == NULL)
        return HX_INTEGRATION_FAILED;
    hx_status status = HX_INTEGRATION_OK;
    r->stats->last_step = h;
    for (long k = 0; k < nsteps; ++k) {
        if (opt->max_steps > 0 && k >= opt->max_steps) {
            status = HX_INTEGRATION_TOO_MANY_STEPS;
            break;
        }
        const double t = t0 + (double)k * h;
        if (fixed_step(r, opt->method, t, h, y, work) != 0) {
            status = HX_INTEGRATION_FAILED;
            break;
        }
        const double t1 = k + 1 == nsteps ? opt->t_end : t0 + (double)(k + 1) * h;
        if ((o->project != NULL && o->project(o->ctx, t1, y) < 0) ||
            (o->accept != NULL && o->accept(o->ctx, t1, y) != 0)) {
            status = HX_INTEGRATION_FAILED;
            break;
        }
        r->stats->steps++;
        r->stats->t_reached = t1;
        if (!hx_integration_finite_and_bounded(r, y)) {
            status = HX_INTEGRATION_UNSTABLE;
            break;
        }
        if (opt->output != NULL && ((k + 1) % every == 0 || k + 1 == nsteps) &&
            opt->output(o->ctx, t1, y) != 0) {
            status = HX_INTEGRATION_STOPPED;
            break;
        }
    }
    free(work);
    return status;
}

hx_status hx_integrate(const hx_ode *ode, double t0, double *y, const hx_integrator_options *opt,
                       hx_integrator_stats *stats)
{
    memset(stats, 0, sizeof *stats);
    stats->t_reached = t0;
    hx_integration r = {ode, opt, stats, 0.0, t0, 0};
    const int m = ode->nq + ode->nu > 0 ? ode->nq + ode->nu : ode->n;
    r.limit = GROWTH_LIMIT * (1.0 + hx_integration_norm(y, m));
    if (opt->method == HX_METHOD_SYMPLECTIC_EULER && ode->advance == NULL)
        return HX_INTEGRATION_FAILED;
    switch (opt->method) {
    case HX_METHOD_DOPRI5: return hx_integrate_dopri5(&r, t0, y);
    case HX_METHOD_BDF: return hx_integrate_bdf(&r, t0, y);
    case HX_METHOD_DOPRI5_ARKODE: return hx_integrate_arkode_dopri5(&r, t0, y);
    default: return integrate_fixed(&r, t0, y);
    }
}
