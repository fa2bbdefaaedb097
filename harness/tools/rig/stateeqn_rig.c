/* The rig for a Force_StateEqn (stateeqn_rig.h). */
#include "tools/rig/stateeqn_rig.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/finite.h"
#include "base/vecmath.h"
#include "host/invoke.h"
#include "host/state_inputs.h"
#include "sim/dynamics/element_at.h"

typedef struct state_rig {
    hx_rig *r;
    hx_binding *b;
    const hx_stateeqn *f;
    hx_stateeqn_rig_result *result;
    double *u, *copy, *rates, *rates_minus; /* scratch */
    double out[6], disp[6], velo[6];
    double last_t, last_power;              /* the previous row's, for the work */
    long rows;
} state_rig;

/* YFOSUB at time t of the path with states x: rates into xdot, the outputs
 * on I in J's axes into sr->out. 0, or -1 with the result's message. */
static int evaluate(state_rig *sr, double t, const double *x, int dflag, double *xdot)
{
    hx_rig *r = sr->r;
    const hx_stateeqn *f = sr->f;
    hx_rig_path_at(&r->path, t, r->end, sr->disp, sr->velo);
    hx_place_relative(&r->s->frames, &r->scratch, f->i_marker, f->j_marker, sr->disp, sr->velo);
    r->scratch.time = t;
    if (hx_stateeqn_inputs(&r->scratch, r->force, sr->u) != 0) {
        snprintf(sr->result->message, sizeof sr->result->message, "an input of Force_StateEqn"
                 " %d could not be measured at t = %g", f->id, t);
        return -1;
    }
    memcpy(sr->copy, x, sizeof(double) * (size_t)f->nstate); /* copies: it may write there */
    memcpy(sr->copy + f->nstate, sr->u, sizeof(double) * (size_t)f->ninput);
    double out[6];
    hx_invoke_stateeqn(sr->b, &r->scratch, sr->copy, sr->copy + f->nstate, dflag, 0, xdot, out, NULL);
    r->element_calls++;
    if (hx_messages_stopped(&r->s->messages) || !hx_all_finite(out, 6) ||
        !hx_all_finite(xdot, f->nstate)) {
        snprintf(sr->result->message, sizeof sr->result->message, "Force_StateEqn %d %s at t = %g",
                 f->id, hx_messages_stopped(&r->s->messages) ? "stopped the run (c_errmes STOP)"
                                                             : "returned a non-finite value", t);
        return -1;
    }
    /* the outputs are in the ref_marker's axes: the rig reports J's */
    hx_frame frames[2];
    const hx_frame *J = hx_frames_marker(&r->scratch, f->j_marker, &frames[0]);
    const hx_frame *ref = hx_frames_marker(&r->scratch, f->ref_marker, &frames[1]);
    double Rjr[9];
    m3_tmul(Rjr, J->R, ref->R);
    m3_apply(sr->out, Rjr, out);
    m3_apply(sr->out + 3, Rjr, out + 3);
    return 0;
}

static int rates(void *ctx, double t, const double *x, double *xdot)
{
    return evaluate(ctx, t, x, 0, xdot);
}

/* d xdot/dx for BDF's Newton matrix: YFOXX, or central differences. */
static int rate_jacobian(void *ctx, double t, const double *x, const double *fx, double *J)
{
    (void)fx;
    state_rig *sr = ctx;
    const int ns = sr->f->nstate;
    if (sr->b->fn.stateeqn.partial[0] != NULL) {
        if (evaluate(sr, t, x, 1, sr->rates) != 0) /* places I and measures the inputs */
            return -1;
        memcpy(sr->copy, x, sizeof(double) * (size_t)ns);
        memcpy(sr->copy + ns, sr->u, sizeof(double) * (size_t)sr->f->ninput);
        hx_invoke_stateeqn_partial(sr->b, 0, &sr->r->scratch, sr->copy, sr->copy + ns, J, NULL);
        return hx_all_finite(J, ns * ns) && !hx_messages_stopped(&sr->r->s->messages) ? 0 : -1;
    }
    double *xp = sr->rates + ns; /* past the rates: ns values */
    memcpy(xp, x, sizeof(double) * (size_t)ns);
    for (int j = 0; j < ns; ++j) {
        const double h = 1e-6 * fmax(fabs(x[j]), 1e-6);
        xp[j] = x[j] + h;
        int status = evaluate(sr, t, xp, 1, sr->rates);
        xp[j] = x[j] - h;
        status |= evaluate(sr, t, xp, 1, sr->rates_minus);
        xp[j] = x[j];
        if (status != 0)
            return -1;
        for (int i = 0; i < ns; ++i)
            J[i + ns * j] = (sr->rates[i] - sr->rates_minus[i]) / (2.0 * h);
    }
    return 0;
}

/* A CSV row at a rig step, the ranges and the work done on the element. */
static int row(void *ctx, double t, const double *x)
{
    state_rig *sr = ctx;
    hx_rig *r = sr->r;
    if (evaluate(sr, t, x, 0, sr->rates) != 0)
        return 1;
    double power = 0.0; /* of the force on I: the rig does its opposite */
    for (int k = 0; k < 6; ++k)
        power += sr->out[k] * sr->velo[k];
    if (sr->rows > 0)
        sr->result->work -= 0.5 * (power + sr->last_power) * (t - sr->last_t);
    sr->last_power = power, sr->last_t = t;
    hx_rig_track(r, sr->disp, sr->out, sr->rows++ == 0);
    if (r->csv != NULL) {
        fprintf(r->csv, "%.10g", t);
        for (int k = 0; k < 6; ++k)
            fprintf(r->csv, ",%.15g", sr->disp[k]);
        for (int k = 0; k < 6; ++k)
            fprintf(r->csv, ",%.15g", sr->velo[k]);
        for (int k = 0; k < 6; ++k)
            fprintf(r->csv, ",%.15g", sr->out[k]);
        for (int k = 0; k < sr->f->nstate; ++k)
            fprintf(r->csv, ",%.15g", x[k]);
        fprintf(r->csv, "\n");
    }
    return 0;
}

static int integrate_states(state_rig *sr, double *x)
{
    hx_rig *r = sr->r;
    hx_ode ode = {sr->f->nstate, 0, 0, 0, rates, NULL, NULL, sr, rate_jacobian, NULL, NULL};
    hx_integrator_options opt;
    hx_integrator_defaults(&opt);
    opt.method = HX_METHOD_BDF;
    opt.t_end = r->end;
    opt.output_interval = r->step;
    opt.max_step = r->step; /* the path's turns are not stepped over */
    opt.rtol = 1e-8;
    opt.atol = 1e-12;
    opt.output = row;
    const hx_status status = hx_integrate(&ode, 0.0, x, &opt, &sr->result->stats);
    if (status != HX_INTEGRATION_OK && sr->result->message[0] == '\0')
        snprintf(sr->result->message, sizeof sr->result->message, "the states' integration %s at"
                 " t = %g", hx_status_text(status), sr->result->stats.t_reached);
    return status == HX_INTEGRATION_OK ? 0 : -1;
}

int hx_stateeqn_rig_run(hx_rig *r, hx_stateeqn_rig_result *result)
{
    memset(result, 0, sizeof *result);
    const hx_stateeqn *f = &r->s->model->stateeqns[r->force];
    state_rig sr = {.r = r, .f = f, .result = result};
    sr.b = hx_bindings_find(&r->s->bindings, HX_FAMILY_STATEEQN, r->force);
    const int ns = f->nstate, ni = f->ninput;
    double *work = calloc((size_t)(5 * ns + 2 * ni + 1), sizeof(double));
    if (work == NULL) {
        snprintf(result->message, sizeof result->message, "out of memory");
        return -1;
    }
    double *x = work;
    sr.u = x + ns;
    sr.copy = sr.u + ni;
    sr.rates = sr.copy + ns + ni; /* then ns more for the differences' states */
    sr.rates_minus = sr.rates + 2 * ns;
    memcpy(x, f->initial, sizeof(double) * (size_t)ns);
    if (r->csv != NULL) {
        fprintf(r->csv, "t,x,y,z,ax,ay,az,vx,vy,vz,wx,wy,wz,fx,fy,fz,tx,ty,tz");
        for (int k = 0; k < ns; ++k)
            fprintf(r->csv, ",stateeqn%d.x%d", f->id, k + 1);
        fprintf(r->csv, "\n");
    }
    int status = row(&sr, 0.0, x) == 0 ? 0 : -1;
    if (status == 0 && ns > 0) {
        status = integrate_states(&sr, x);
    } else {
        const long n = lround(r->end / r->step);
        for (long i = 1; i <= n && status == 0; ++i)
            status = row(&sr, (double)i * r->step, x) == 0 ? 0 : -1;
    }
    free(work);
    return status;
}
