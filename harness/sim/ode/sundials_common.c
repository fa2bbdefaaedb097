/* The SUNDIALS integrators' shared glue (sundials_common.h). */
#include "sim/ode/sundials_common.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/finite.h"
#include "sim/ode/vector_ops.h"

int hx_sundials_open(hx_sundials *s, hx_integration *r, double *y)
{
    memset(s, 0, sizeof *s);
    s->r = r;
    const int n = r->ode->n;
    s->scratch = malloc(sizeof(double) * (size_t)n);
    if (s->scratch == NULL || SUNContext_Create(NULL, &s->context) != 0) {
        free(s->scratch);
        s->scratch = NULL;
        return -1;
    }
    s->y = N_VMake_Serial(n, y, s->context);
    if (s->y == NULL) {
        hx_sundials_close(s);
        return -1;
    }
    hx_vector_ops_install(s->y);
    return 0;
}

void hx_sundials_close(hx_sundials *s)
{
    if (s->y != NULL)
        N_VDestroy(s->y);
    if (s->context != NULL)
        SUNContext_Free(&s->context);
    free(s->scratch);
    memset(s, 0, sizeof *s);
}

int hx_sundials_rhs(double t, N_Vector y, N_Vector ydot, void *user_data)
{
    hx_sundials *s = user_data;
    const double *state = NV_DATA_S(y);
    /* a Newton iterate or a rejected trial may be non-finite: the model
     * (whose elements stop the run on such a state) is not asked */
    if (!hx_all_finite(state, s->r->ode->n))
        return 1;
    return hx_integration_evaluate(s->r, t, state, NV_DATA_S(ydot)) == 0 ? 0 : -1;
}

int hx_sundials_correction(hx_sundials *s, double t, const double *y, double *corr)
{
    const hx_ode *o = s->r->ode;
    memcpy(s->scratch, y, sizeof(double) * (size_t)o->n);
    if (o->project(o->ctx, t, s->scratch) < 0)
        return -1;
    for (int i = 0; i < o->n; ++i)
        corr[i] = s->scratch[i] - y[i];
    return 0;
}

void hx_sundials_message(int error_code, const char *module, const char *function, char *msg,
                         void *user_data)
{
    hx_sundials *s = user_data;
    snprintf(s->r->stats->solver_message, sizeof s->r->stats->solver_message, "%s %s (%s): %s",
             module, error_code < 0 ? "error" : "warning", function, msg);
}

hx_status hx_sundials_drive(hx_sundials *s, void *solver, hx_sundials_advance_fn *advance,
                            hx_sundials_interpolate_fn *interpolate,
                            hx_sundials_status_fn *status_of, long (*steps_of)(void *solver))
{
    hx_integration *r = s->r;
    const hx_ode *o = r->ode;
    const hx_integrator_options *opt = r->opt;
    double *y = NV_DATA_S(s->y);
    const int at_intervals = opt->output != NULL && opt->output_interval > 0.0;
    double t = r->t0;
    while (t < opt->t_end) {
        /* one step at a time (the solvers stop at the end time): y is the
         * accepted step's state, the outputs are interpolated from the solver's */
        const int flag = advance(solver, opt->t_end, s->y, &t);
        r->stats->t_reached = t;
        if (flag < 0)
            return status_of(flag);
        if (opt->max_steps > 0 && steps_of(solver) >= opt->max_steps && t < opt->t_end)
            return HX_INTEGRATION_TOO_MANY_STEPS;
        if (!hx_integration_finite_and_bounded(r, y))
            return HX_INTEGRATION_UNSTABLE;
        if (o->accept != NULL && o->accept(o->ctx, t, y) != 0)
            return HX_INTEGRATION_FAILED;
        if (opt->output == NULL)
            continue;
        if (!at_intervals) {
            if (o->project != NULL && o->project(o->ctx, t, y) < 0)
                return HX_INTEGRATION_FAILED;
            if (opt->output(o->ctx, t, y) != 0)
                return HX_INTEGRATION_STOPPED;
            continue;
        }
        double to;
        while ((to = hx_integration_next_output(r)) <= t) {
            /* an interpolated state: projected like DOPRI5's dense output (the
             * solver keeps its own) */
            if (interpolate(solver, to, s->y) != 0)
                return HX_INTEGRATION_FAILED;
            r->outputs++;
            if (o->project != NULL && o->project(o->ctx, to, y) < 0)
                return HX_INTEGRATION_FAILED;
            if (opt->output(o->ctx, to, y) != 0)
                return HX_INTEGRATION_STOPPED;
        }
    }
    return HX_INTEGRATION_OK;
}
