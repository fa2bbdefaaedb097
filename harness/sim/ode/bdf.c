/*
 * Variable-order (1 to 5), variable-step BDF through SUNDIALS CVODE, with
 * Newton iterations on a dense matrix: the Newton matrix I - gamma J from the
 * ode's jacobian (the elements' own partials, newton_matrix.c), or from
 * CVODE's difference quotients of the whole right-hand side. Constraints stay
 * as the explicit methods have them: couplers through their multipliers in
 * the right-hand side, and after each step CVODE's projection interface puts
 * the state back on phi = 0, dphi/dt = 0 and the quaternions on unit length.
 */
#include <cvode/cvode.h>
#include <cvode/cvode_proj.h>
#include <limits.h>
#include <math.h>
#include <string.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include "base/finite.h"
#include "sim/ode/sundials_common.h"

static int newton_jacobian(double t, N_Vector y, N_Vector fy, SUNMatrix J, void *user_data,
                           N_Vector tmp1, N_Vector tmp2, N_Vector tmp3)
{
    (void)fy, (void)tmp1, (void)tmp2, (void)tmp3;
    hx_sundials *s = user_data;
    const hx_ode *o = s->r->ode;
    const double *state = NV_DATA_S(y);
    if (!hx_all_finite(state, o->n))
        return 1; /* recoverable: CVODE retries with a smaller step */
    /* SUNDenseMatrix stores its n x n entries column by column, as J is built */
    return o->jacobian(o->ctx, t, state, SM_DATA_D(J)) == 0 ? 0 : -1;
}

static int projection(double t, N_Vector ycur, N_Vector corr, double eps, N_Vector err,
                      void *user_data)
{
    (void)eps, (void)err; /* projection of the error estimate is off */
    return hx_sundials_correction(user_data, t, NV_DATA_S(ycur), NV_DATA_S(corr));
}

static int advance(void *solver, double tout, N_Vector y, double *t, int one_step)
{
    const int flag = CVode(solver, tout, y, t, one_step ? CV_ONE_STEP : CV_NORMAL);
    return flag;
}

static hx_status status_of(int flag)
{
    switch (flag) {
    case CV_TOO_MUCH_WORK: return HX_INTEGRATION_TOO_MANY_STEPS;
    case CV_TOO_MUCH_ACC:
    case CV_ERR_FAILURE: return HX_INTEGRATION_STEP_TOO_SMALL;
    case CV_CONV_FAILURE:
    case CV_LSETUP_FAIL:
    case CV_LSOLVE_FAIL: return HX_INTEGRATION_NO_CONVERGENCE;
    default: return HX_INTEGRATION_FAILED;
    }
}

static long steps_of(void *solver)
{
    long steps = 0;
    CVodeGetNumSteps(solver, &steps);
    return steps;
}

static void collect_stats(void *solver, hx_integrator_stats *st)
{
    long steps = 0, fails = 0, iterations = 0, conv_fails = 0, jacobians = 0, fd_evals = 0;
    int order = 0;
    double last = 0.0;
    CVodeGetNumSteps(solver, &steps);
    CVodeGetNumErrTestFails(solver, &fails);
    CVodeGetNumNonlinSolvIters(solver, &iterations);
    CVodeGetNumNonlinSolvConvFails(solver, &conv_fails);
    CVodeGetNumJacEvals(solver, &jacobians);
    CVodeGetNumLinRhsEvals(solver, &fd_evals);
    CVodeGetLastOrder(solver, &order);
    CVodeGetLastStep(solver, &last);
    st->steps = steps;
    st->rejected = fails + conv_fails;
    st->error_test_failures = fails;
    st->convergence_failures = conv_fails;
    st->newton_iterations = iterations;
    st->jacobians = jacobians;
    st->fd_jacobian_evaluations = fd_evals;
    st->last_order = order;
    st->last_step = last;
}

hx_status hx_integrate_bdf(hx_integration *r, double t0, double *y)
{
    const hx_ode *o = r->ode;
    const hx_integrator_options *opt = r->opt;
    hx_sundials s;
    if (hx_sundials_open(&s, r, y) != 0)
        return HX_INTEGRATION_FAILED;
    void *solver = CVodeCreate(CV_BDF, s.context);
    SUNMatrix A = SUNDenseMatrix(o->n, o->n, s.context);
    SUNLinearSolver ls = A != NULL ? SUNLinSol_Dense(s.y, A, s.context) : NULL;
    int ok = solver != NULL && ls != NULL;
    ok = ok && CVodeInit(solver, hx_sundials_rhs, t0, s.y) == CV_SUCCESS;
    ok = ok && CVodeSetErrHandlerFn(solver, hx_sundials_message, &s) == CV_SUCCESS;
    ok = ok && CVodeSetUserData(solver, &s) == CV_SUCCESS;
    ok = ok && CVodeSStolerances(solver, opt->rtol, opt->atol) == CV_SUCCESS;
    ok = ok && CVodeSetLinearSolver(solver, ls, A) == CV_SUCCESS;
    /* fd: NULL keeps CVODE's own difference quotients of the whole right-hand side */
    ok = ok && CVodeSetJacFn(solver, opt->jacobian == HX_JACOBIAN_ANALYTIC && o->jacobian != NULL
                                         ? newton_jacobian : NULL) == CV_SUCCESS;
    ok = ok && CVodeSetStopTime(solver, opt->t_end) == CV_SUCCESS;
    ok = ok && CVodeSetMaxNumSteps(solver, opt->max_steps > 0 ? opt->max_steps : LONG_MAX / 2) ==
                   CV_SUCCESS;
    ok = ok && CVodeSetMaxHnilWarns(solver, 1) == CV_SUCCESS; /* t + h == t: said once */
    /* BDF of order 3 to 5 is unstable on a lightly damped fast mode at large
     * steps (A(alpha)-stable only): the detection lowers the order there */
    ok = ok && CVodeSetStabLimDet(solver, SUNTRUE) == CV_SUCCESS;
    if (ok && opt->max_order > 0)
        ok = CVodeSetMaxOrd(solver, opt->max_order) == CV_SUCCESS;
    if (ok && opt->step > 0.0)
        ok = CVodeSetInitStep(solver, opt->step) == CV_SUCCESS;
    if (ok && opt->max_step > 0.0)
        ok = CVodeSetMaxStep(solver, opt->max_step) == CV_SUCCESS;
    if (ok && opt->min_step > 0.0)
        ok = CVodeSetMinStep(solver, opt->min_step) == CV_SUCCESS;
    if (ok && o->project != NULL)
        ok = CVodeSetProjFn(solver, projection) == CV_SUCCESS &&
             CVodeSetProjErrEst(solver, SUNFALSE) == CV_SUCCESS;
    hx_status status = HX_INTEGRATION_FAILED;
    if (ok)
        status = hx_sundials_drive(&s, solver, advance, status_of, steps_of);
    if (solver != NULL)
        collect_stats(solver, r->stats);
    CVodeFree(&solver);
    if (ls != NULL)
        SUNLinSolFree(ls);
    if (A != NULL)
        SUNMatDestroy(A);
    hx_sundials_close(&s);
    return status;
}
