/*
 * Variable-order (1 to 5), variable-step BDF through SUNDIALS CVODE, with
 * Newton iterations on the Newton matrix I - gamma J: J from the ode's
 * jacobian (the elements' own partials), or by differences of the right-hand
 * side (by column groups on the ode's sparsity, else CVODE's own); the
 * linear systems by dense LU, or by sparse LU (KLU) on the sparsity. Constraints stay
 * as the explicit methods have them: couplers through their multipliers in
 * the right-hand side, and after each step CVODE's projection interface puts
 * the state back on phi = 0, dphi/dt = 0 and the quaternions on unit length.
 */
#include <cvode/cvode.h>
#include <cvode/cvode_proj.h>
#include <float.h>
#include <limits.h>
#include <math.h>
#include <string.h>
#include <stdlib.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunlinsol/sunlinsol_klu.h>
#include <sunmatrix/sunmatrix_dense.h>
#include <sunmatrix/sunmatrix_sparse.h>

#include "base/clock.h"
#include "base/finite.h"
#include "sim/ode/column_groups.h"
#include "sim/ode/sundials_common.h"

/* Dense LU below this many states, KLU from it on. Measured (median of three
 * BDF runs, rtol 1e-5): KLU is already faster at 41 states (stiff_powertrain
 * 0.015 s against 0.027 s) and 28 (a chain of 2 bodies, 0.020 s against
 * 0.036 s); on one body (15 states) the two are level (bench_bushing 0.023 s
 * against 0.024 s): dense stays for single bodies. */
#define HX_KLU_FROM 16

/* CVODE's own rule for a difference increment (its dense difference-quotient
 * Jacobian): the smallest increment in weighted norm */
#define MIN_INCREMENT_FACTOR 1000.0

typedef struct bdf_context {
    hx_sundials s;              /* first: the shared callbacks take the context as it */
    void *solver;
    int sparse;                 /* the matrix is CVODE's sparse (KLU) one */
    hx_column_groups groups;    /* differences on the sparsity */
    double *values;             /* nnz: J in the sparsity's order (dense matrix, and the
                                 * sparse one when own_system) */
    int own_system;             /* KLU: A = I - gamma J written here in one pass (linear_system) */
    int *diagonal;              /* own_system: where each column's diagonal is in values */
    double *increment, *work;   /* n and 2n: the differences' */
    long fd_evaluations;
    double seconds;
} bdf_context;

static int counted_rhs(void *ctx, double t, const double *y, double *ydot)
{
    bdf_context *c = ctx;
    c->fd_evaluations++;
    return hx_integration_evaluate(c->s.r, t, y, ydot);
}

/* J by column groups, each column's increment by CVODE's rule. */
static int grouped_jacobian(bdf_context *c, double t, const double *y, const double *fy,
                            N_Vector weights, double *values)
{
    const hx_ode *o = c->s.r->ode;
    const int n = o->n;
    double step = 0.0;
    CVodeGetErrWeights(c->solver, weights);
    CVodeGetCurrentStep(c->solver, &step);
    const double *w = NV_DATA_S(weights);
    double norm = 0.0;
    for (int i = 0; i < n; ++i)
        norm += (fy[i] * w[i]) * (fy[i] * w[i]);
    norm = sqrt(norm / n);
    const double root = sqrt(DBL_EPSILON);
    const double least = norm != 0.0 ? MIN_INCREMENT_FACTOR * fabs(step) * DBL_EPSILON * n * norm
                                     : 1.0;
    for (int i = 0; i < n; ++i)
        c->increment[i] = fmax(root * fabs(y[i]), least / w[i]);
    return hx_grouped_differences(&c->groups, o->sparsity, counted_rhs, c, t, y, fy,
                                  c->increment, n - o->quadratures, values, c->work);
}

static int newton_jacobian(double t, N_Vector y, N_Vector fy, SUNMatrix J, void *user_data,
                           N_Vector tmp1, N_Vector tmp2, N_Vector tmp3)
{
    (void)tmp2, (void)tmp3;
    bdf_context *c = user_data;
    const hx_ode *o = c->s.r->ode;
    const hx_sparsity *sp = o->sparsity;
    const double *state = NV_DATA_S(y);
    if (!hx_all_finite(state, o->n))
        return 1; /* recoverable: CVODE retries with a smaller step */
    const double start = hx_seconds();
    /* the sparse matrix takes the values in place (or they are kept for
     * linear_system); the dense one from them, or (no sparsity) column-major
     * as its own n x n entries are stored */
    double *values = c->own_system ? c->values
                     : c->sparse   ? SM_DATA_S(J)
                     : sp != NULL  ? c->values
                                   : SM_DATA_D(J);
    if (c->sparse && !c->own_system) {
        sunindextype *ptr = SM_INDEXPTRS_S(J), *ind = SM_INDEXVALS_S(J);
        for (int k = 0; k <= sp->n; ++k)
            ptr[k] = sp->colptr[k];
        for (int k = 0; k < sp->nnz; ++k)
            ind[k] = sp->rowind[k];
    }
    int status;
    if (c->s.r->opt->jacobian == HX_JACOBIAN_ANALYTIC)
        status = o->jacobian(o->ctx, t, state, NV_DATA_S(fy), values);
    else
        status = grouped_jacobian(c, t, state, NV_DATA_S(fy), tmp1, values);
    if (status == 0 && !c->sparse && sp != NULL) {
        double *dense = SM_DATA_D(J);
        memset(dense, 0, sizeof(double) * (size_t)sp->n * (size_t)sp->n);
        for (int col = 0; col < sp->n; ++col)
            for (int k = sp->colptr[col]; k < sp->colptr[col + 1]; ++k)
                dense[(size_t)col * (size_t)sp->n + (size_t)sp->rowind[k]] = values[k];
    }
    c->seconds += hx_seconds() - start;
    return status == 0 ? 0 : -1;
}

/* The Newton matrix A = I - gamma J in one pass over the sparsity, from J
 * evaluated anew when CVODE judges the kept one stale (jok false): what
 * CVODE would do in three (copy the kept J, zero, scale and add I). */
static int linear_system(double t, N_Vector y, N_Vector fy, SUNMatrix A, sunbooleantype jok,
                         sunbooleantype *jcur, double gamma, void *user_data, N_Vector tmp1,
                         N_Vector tmp2, N_Vector tmp3)
{
    bdf_context *c = user_data;
    const hx_sparsity *sp = c->s.r->ode->sparsity;
    *jcur = SUNFALSE;
    if (!jok) { /* false at the first step and after a failure: the kept values are whole */
        const int status = newton_jacobian(t, y, fy, A, user_data, tmp1, tmp2, tmp3);
        if (status != 0)
            return status;
        *jcur = SUNTRUE; /* CVODE counts it */
    }
    sunindextype *ptr = SM_INDEXPTRS_S(A), *ind = SM_INDEXVALS_S(A);
    double *a = SM_DATA_S(A);
    for (int k = 0; k <= sp->n; ++k)
        ptr[k] = sp->colptr[k];
    for (int k = 0; k < sp->nnz; ++k) {
        ind[k] = sp->rowind[k];
        a[k] = -gamma * c->values[k];
    }
    for (int col = 0; col < sp->n; ++col)
        a[c->diagonal[col]] += 1.0;
    return 0;
}

static int projection(double t, N_Vector ycur, N_Vector corr, double eps, N_Vector err,
                      void *user_data)
{
    (void)eps, (void)err; /* projection of the error estimate is off */
    return hx_sundials_correction(user_data, t, NV_DATA_S(ycur), NV_DATA_S(corr));
}

static int advance(void *solver, double tout, N_Vector y, double *t)
{
    return CVode(solver, tout, y, t, CV_ONE_STEP);
}

static int interpolate(void *solver, double t, N_Vector y)
{
    return CVodeGetDky(solver, t, 0, y);
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

static int uses_klu(const hx_ode *o, hx_linear_solver choice)
{
    if (o->sparsity == NULL)
        return 0;
    return choice == HX_LINEAR_KLU || (choice == HX_LINEAR_AUTO && o->n >= HX_KLU_FROM);
}

static void close_context(bdf_context *c)
{
    hx_column_groups_free(&c->groups);
    free(c->values);
    free(c->diagonal);
    free(c->increment);
    hx_sundials_close(&c->s);
}

hx_status hx_integrate_bdf(hx_integration *r, double t0, double *y)
{
    const hx_ode *o = r->ode;
    const hx_integrator_options *opt = r->opt;
    const hx_sparsity *sp = o->sparsity;
    bdf_context c;
    memset(&c, 0, sizeof c);
    if (hx_sundials_open(&c.s, r, y) != 0)
        return HX_INTEGRATION_FAILED;
    c.sparse = uses_klu(o, opt->linear_solver);
    const int ours = sp != NULL && (opt->jacobian == HX_JACOBIAN_FD || o->jacobian != NULL);
    const int grouped = sp != NULL && opt->jacobian == HX_JACOBIAN_FD;
    if (sp != NULL) {
        c.values = malloc(sizeof(double) * ((size_t)sp->nnz + 1));
        c.increment = malloc(sizeof(double) * 3 * ((size_t)o->n + 1));
        c.work = c.increment + o->n + 1;
        c.diagonal = malloc(sizeof(int) * ((size_t)o->n + 1));
        if (c.values == NULL || c.increment == NULL || c.diagonal == NULL ||
            (grouped && hx_column_groups_build(&c.groups, sp) != 0)) {
            close_context(&c);
            return HX_INTEGRATION_FAILED;
        }
        /* the sparsity always holds the diagonal (sparsity.h) */
        for (int col = 0; col < o->n; ++col)
            c.diagonal[col] = hx_sparsity_find(sp, col, col);
        c.own_system = c.sparse && ours;
    }
    void *solver = c.solver = CVodeCreate(CV_BDF, c.s.context);
    SUNMatrix A = c.sparse ? SUNSparseMatrix(o->n, o->n, sp->nnz, CSC_MAT, c.s.context)
                           : SUNDenseMatrix(o->n, o->n, c.s.context);
    SUNLinearSolver ls = A == NULL ? NULL
                         : c.sparse ? SUNLinSol_KLU(c.s.y, A, c.s.context)
                                    : SUNLinSol_Dense(c.s.y, A, c.s.context);
    int ok = solver != NULL && ls != NULL;
    /* AMD, KLU's own default, not SUNDIALS' COLAMD: on the full vehicle its
     * factors hold 16 869 nonzeros against 27 156, a quarter less time per run
     * (docs/performance.md, "The implicit step") */
    if (ok && c.sparse)
        ok = SUNLinSol_KLUSetOrdering(ls, 0) == SUNLS_SUCCESS;
    ok = ok && CVodeInit(solver, hx_sundials_rhs, t0, c.s.y) == CV_SUCCESS;
    ok = ok && CVodeSetErrHandlerFn(solver, hx_sundials_message, &c.s) == CV_SUCCESS;
    ok = ok && CVodeSetUserData(solver, &c) == CV_SUCCESS;
    ok = ok && CVodeSStolerances(solver, opt->rtol, opt->atol) == CV_SUCCESS;
    ok = ok && CVodeSetLinearSolver(solver, ls, A) == CV_SUCCESS;
    /* NULL: CVODE's own difference quotients, column by column (no sparsity) */
    ok = ok && CVodeSetJacFn(solver, ours ? newton_jacobian : NULL) == CV_SUCCESS;
    /* after CVodeSetJacFn, which clears a linear-system function */
    if (ok && c.own_system)
        ok = CVodeSetLinSysFn(solver, linear_system) == CV_SUCCESS;
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
        status = hx_sundials_drive(&c.s, solver, advance, interpolate, status_of, steps_of);
    if (solver != NULL)
        collect_stats(solver, r->stats);
    hx_integrator_stats *st = r->stats;
    st->linear_solver = c.sparse ? HX_LINEAR_KLU : HX_LINEAR_DENSE;
    st->nonzeros = c.sparse ? sp->nnz : (long)o->n * o->n;
    st->column_groups = c.groups.count;
    st->jacobian_seconds = c.seconds;
    if (ours)
        st->fd_jacobian_evaluations = c.fd_evaluations;
    CVodeFree(&solver);
    if (ls != NULL)
        SUNLinSolFree(ls);
    if (A != NULL)
        SUNMatDestroy(A);
    close_context(&c);
    return status;
}
