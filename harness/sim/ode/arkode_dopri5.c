/*
 * ARKODE's explicit Dormand-Prince 5(4) (ERKStep with its
 * ARKODE_DORMAND_PRINCE_7_4_5 table) on the same right-hand side, tolerances,
 * output times and projection as the harness's own DOPRI5 (dopri5.c): the
 * well-kept implementation ours is measured against (bench --work-precision).
 * The projection runs after each step through ERKStep's post-processing hook.
 */
#include <arkode/arkode_erkstep.h>
#include <limits.h>
#include <string.h>

#include "sim/ode/sundials_common.h"

static int project_step(double t, N_Vector y, void *user_data)
{
    hx_sundials *s = user_data;
    const hx_ode *o = s->r->ode;
    return o->project(o->ctx, t, NV_DATA_S(y)) < 0 ? -1 : 0;
}

static int advance(void *solver, double tout, N_Vector y, double *t)
{
    return ERKStepEvolve(solver, tout, y, t, ARK_ONE_STEP);
}

static int interpolate(void *solver, double t, N_Vector y)
{
    return ERKStepGetDky(solver, t, 0, y);
}

static hx_status status_of(int flag)
{
    switch (flag) {
    case ARK_TOO_MUCH_WORK: return HX_INTEGRATION_TOO_MANY_STEPS;
    case ARK_TOO_MUCH_ACC:
    case ARK_ERR_FAILURE: return HX_INTEGRATION_STEP_TOO_SMALL;
    default: return HX_INTEGRATION_FAILED;
    }
}

static long steps_of(void *solver)
{
    long steps = 0;
    ERKStepGetNumSteps(solver, &steps);
    return steps;
}

hx_status hx_integrate_arkode_dopri5(hx_integration *r, double t0, double *y)
{
    const hx_ode *o = r->ode;
    const hx_integrator_options *opt = r->opt;
    hx_sundials s;
    if (hx_sundials_open(&s, r, y) != 0)
        return HX_INTEGRATION_FAILED;
    void *solver = ERKStepCreate(hx_sundials_rhs, t0, s.y, s.context);
    int ok = solver != NULL;
    ok = ok && ERKStepSetTableNum(solver, ARKODE_DORMAND_PRINCE_7_4_5) == ARK_SUCCESS;
    ok = ok && ERKStepSetErrHandlerFn(solver, hx_sundials_message, &s) == ARK_SUCCESS;
    ok = ok && ERKStepSetUserData(solver, &s) == ARK_SUCCESS;
    ok = ok && ERKStepSStolerances(solver, opt->rtol, opt->atol) == ARK_SUCCESS;
    ok = ok && ERKStepSetStopTime(solver, opt->t_end) == ARK_SUCCESS;
    ok = ok && ERKStepSetMaxNumSteps(solver, opt->max_steps > 0 ? opt->max_steps : LONG_MAX / 2) ==
                   ARK_SUCCESS;
    ok = ok && ERKStepSetMaxHnilWarns(solver, -1) == ARK_SUCCESS;
    if (ok && opt->step > 0.0)
        ok = ERKStepSetInitStep(solver, opt->step) == ARK_SUCCESS;
    if (ok && opt->max_step > 0.0)
        ok = ERKStepSetMaxStep(solver, opt->max_step) == ARK_SUCCESS;
    if (ok && o->project != NULL)
        ok = ERKStepSetPostprocessStepFn(solver, project_step) == ARK_SUCCESS;
    hx_status status = HX_INTEGRATION_FAILED;
    if (ok)
        status = hx_sundials_drive(&s, solver, advance, interpolate, status_of, steps_of);
    if (solver != NULL) {
        long steps = 0, fails = 0;
        double last = 0.0;
        ERKStepGetNumSteps(solver, &steps);
        ERKStepGetNumErrTestFails(solver, &fails);
        ERKStepGetLastStep(solver, &last);
        r->stats->steps = steps;
        r->stats->rejected = fails;
        r->stats->last_step = last;
    }
    ERKStepFree(&solver);
    hx_sundials_close(&s);
    return status;
}
