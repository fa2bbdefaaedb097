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
 * project() (optional) runs after every accepted step.
 */
#ifndef HX_INTEGRATOR_H
#define HX_INTEGRATOR_H

typedef int hx_rhs_fn(void *ctx, double t, const double *y, double *ydot);
/* Returns 0, 1 when it changed the state (DOPRI5 then re-evaluates f), or -1. */
typedef int hx_project_fn(void *ctx, double t, double *y);
typedef void hx_advance_fn(void *ctx, double *y, double h);
/* The Newton matrix's J = df/dy at (t, y), column-major n x n; 0 or -1. */
typedef int hx_jacobian_fn(void *ctx, double t, const double *y, double *J);
/* Returns 0 to go on, non-zero to stop the integration. */
typedef int hx_output_fn(void *ctx, double t, const double *y);

typedef struct hx_ode {
    int n, nq, nu;
    hx_rhs_fn *rhs;
    hx_project_fn *project;
    hx_advance_fn *advance;
    void *ctx;
    hx_jacobian_fn *jacobian; /* BDF's analytic Newton matrix (NULL: differences) */
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
 * partials), or CVODE's difference quotients of the whole right-hand side
 * (what a user gets without partials). */
typedef enum hx_jacobian { HX_JACOBIAN_ANALYTIC, HX_JACOBIAN_FD } hx_jacobian;

typedef struct hx_integrator_options {
    hx_method method;
    double t_end;
    double step;            /* fixed step; adaptive methods: first step (0: automatic) */
    double rtol, atol;      /* adaptive methods' tolerances (defaults 1e-6 and 1e-9) */
    double max_step;        /* adaptive methods: largest step (0: no limit) */
    double min_step;        /* BDF: smallest step (0: none; = max_step: fixed steps) */
    int max_order;          /* BDF: highest order, 1 to 5 (0: 5) */
    hx_jacobian jacobian;   /* BDF's Newton matrix */
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
    long fd_jacobian_evaluations; /* of evaluations, inside CVODE's difference quotients */
    long frozen_evaluations;  /* harness-only evaluations of the analytic Newton matrix */
    long partial_calls;       /* element calls for the analytic Newton matrix's partials */
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
int hx_jacobian_parse(const char *name, hx_jacobian *jacobian);

#endif
