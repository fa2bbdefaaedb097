/*
 * Integrators over one right-hand side, one options struct and one status
 * code: explicit Euler, symplectic (semi-implicit) Euler, classical RK4 (fixed
 * steps), and adaptive Dormand-Prince 5(4) with FSAL, PI step-size control,
 * dense output and the standard stiffness detection, all written here; and
 * two from SUNDIALS: variable-order, variable-step BDF with Newton iterations
 * (CVODE, bdf.c) for stiff models, and ARKODE's explicit Dormand-Prince
 * (arkode_dopri5.c), kept to measure ours against.
 *
 * The state is [positions (nq) | velocities (nu) | other (n - nq - nu)];
 * symplectic Euler needs advance() to move positions with the new velocities.
 * project() (optional) runs after every accepted step (and on DOPRI5's and
 * the SUNDIALS integrators' interpolated outputs, and inside CVODE's steps);
 * accept() (optional) runs after every accepted step alone, on its
 * projected state: never on a stage, a Newton iterate, a rejected step or an
 * interpolated output.
 */
#ifndef HX_SIM_ODE_INTEGRATOR_H
#define HX_SIM_ODE_INTEGRATOR_H

#include "sim/ode/sparsity.h"

typedef int hx_rhs_fn(void *ctx, double t, const double *y, double *ydot);
/* Returns 0, 1 when it changed the state (DOPRI5 then re-evaluates f), or -1. */
typedef int hx_project_fn(void *ctx, double t, double *y);
/* After an accepted step at t: 0, or -1 (the integration stops, failed). */
typedef int hx_accept_fn(void *ctx, double t, const double *y);
typedef void hx_advance_fn(void *ctx, double *y, double h);
/* The Newton matrix's J = df/dy at (t, y), given fy = f(t, y) as the
 * integrator has it: its values in the order of the ode's sparsity (or,
 * without one, column-major n x n); 0 or -1. */
typedef int hx_jacobian_fn(void *ctx, double t, const double *y, const double *fy,
                           double *values);
/* Returns 0 to go on, non-zero to stop the integration. */
typedef int hx_output_fn(void *ctx, double t, const double *y);

typedef struct hx_ode {
    int n, nq, nu;
    int quadratures;             /* the last ones of y: nothing depends on them; the
                                  * Newton matrix leaves their rows out */
    hx_rhs_fn *rhs;
    hx_project_fn *project;
    hx_advance_fn *advance;
    void *ctx;
    hx_jacobian_fn *jacobian;    /* BDF's analytic Newton matrix (NULL: differences) */
    const hx_sparsity *sparsity; /* J's nonzeros (NULL: dense): KLU, and differences by
                                  * column groups */
    hx_accept_fn *accept;        /* may be NULL */
} hx_ode;

typedef enum hx_method {
    HX_METHOD_EULER,
    HX_METHOD_SYMPLECTIC_EULER,
    HX_METHOD_RK4,
    HX_METHOD_DOPRI5,
    HX_METHOD_BDF,          /* CVODE */
    HX_METHOD_DOPRI5_ARKODE /* ARKODE's ERKStep, Dormand-Prince table */
} hx_method;

#define HX_METHOD_COUNT 6

/* Where BDF's Newton matrix comes from: the ode's jacobian (the elements' own
 * partials), or differences of the right-hand side (what a user gets without
 * partials): by column groups on the ode's sparsity (column_groups.h), or
 * CVODE's own column by column when there is none. */
typedef enum hx_jacobian_method { HX_JACOBIAN_ANALYTIC, HX_JACOBIAN_FD } hx_jacobian_method;

/* BDF's linear solver for the Newton systems: dense LU (SUNDIALS), or sparse
 * LU (SuiteSparse KLU through SUNDIALS) on the ode's sparsity; auto takes KLU
 * from HX_KLU_FROM states on (bdf.c says why). */
typedef enum hx_linear_solver { HX_LINEAR_AUTO, HX_LINEAR_DENSE, HX_LINEAR_KLU } hx_linear_solver;

typedef struct hx_integrator_options {
    hx_method method;
    double t_end;
    double step;            /* fixed step; adaptive methods: first step (0: automatic) */
    double rtol, atol;      /* adaptive methods' tolerances (defaults 1e-6 and 1e-9) */
    double max_step;        /* adaptive methods: largest step (0: no limit) */
    double min_step;        /* BDF: smallest step (0: none; = max_step: fixed steps) */
    int max_order;          /* BDF: highest order, 1 to 5 (0: 5) */
    hx_jacobian_method jacobian;   /* BDF's Newton matrix */
    hx_linear_solver linear_solver;
    long max_steps;         /* 0: no limit */
    double output_interval; /* 0: output after every step */
    hx_output_fn *output;   /* may be NULL */
} hx_integrator_options;

typedef enum hx_status {
    HX_INTEGRATION_OK = 0,
    HX_INTEGRATION_FAILED,         /* the right-hand side or projection failed */
    HX_INTEGRATION_UNSTABLE,       /* the state became non-finite or grew without bound */
    HX_INTEGRATION_STEP_TOO_SMALL, /* an adaptive method could not meet the tolerance */
    HX_INTEGRATION_TOO_MANY_STEPS,
    HX_INTEGRATION_STOPPED,        /* the output callback asked to stop */
    HX_INTEGRATION_NO_CONVERGENCE  /* BDF's Newton iterations failed at the smallest step */
} hx_status;

typedef struct hx_integrator_stats {
    long steps, rejected, evaluations;
    double last_step;
    double t_reached;
    int stiff;        /* DOPRI5's stiffness detector fired */
    double t_stiff;
    /* BDF (evaluations above count every full right-hand side, those of
     * CVODE's difference-quotient Jacobians included) */
    long newton_iterations, jacobians;
    long error_test_failures, convergence_failures;
    long fd_jacobian_evaluations; /* of evaluations, inside the difference quotients */
    long partial_calls;       /* element calls for the analytic Newton matrix's partials */
    double jacobian_seconds;  /* wall time in building Newton matrices */
    hx_linear_solver linear_solver; /* the one BDF used: dense or KLU */
    long nonzeros;            /* of the Newton matrix (n * n when dense) */
    int column_groups;        /* differences by column groups: their number */
    int last_order;
    char solver_message[256]; /* the SUNDIALS solver's last error, if any */
} hx_integrator_stats;

void hx_integrator_defaults(hx_integrator_options *opt);
hx_status hx_integrate(const hx_ode *ode, double t0, double *y, const hx_integrator_options *opt,
                       hx_integrator_stats *stats);

const char *hx_method_name(hx_method method);
int hx_method_parse(const char *name, hx_method *method);
const char *hx_status_text(hx_status status);
/* Chooses its own steps (tolerances) rather than taking fixed ones. */
int hx_method_adaptive(hx_method method);
int hx_jacobian_method_parse(const char *name, hx_jacobian_method *jacobian);
int hx_linear_solver_parse(const char *name, hx_linear_solver *solver);
const char *hx_linear_solver_name(hx_linear_solver solver);

#endif
