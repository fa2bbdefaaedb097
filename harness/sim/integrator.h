/*
 * Small explicit integrators over one right-hand side, one options struct and
 * one status code: explicit Euler, symplectic (semi-implicit) Euler, classical
 * RK4 (fixed steps), and adaptive Dormand-Prince 5(4) with FSAL, PI step-size
 * control, dense output and the standard stiffness detection.
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
/* Returns 0 to go on, non-zero to stop the integration. */
typedef int hx_output_fn(void *ctx, double t, const double *y);

typedef struct hx_ode {
    int n, nq, nu;
    hx_rhs_fn *rhs;
    hx_project_fn *project;
    hx_advance_fn *advance;
    void *ctx;
} hx_ode;

typedef enum hx_method {
    HX_METHOD_EULER,
    HX_METHOD_SYMPLECTIC_EULER,
    HX_METHOD_RK4,
    HX_METHOD_DOPRI5
} hx_method;

typedef struct hx_integrator_options {
    hx_method method;
    double t_end;
    double step;            /* fixed step; DOPRI5: first step (0: automatic) */
    double rtol, atol;      /* DOPRI5 tolerances (defaults 1e-6 and 1e-9) */
    double max_step;        /* DOPRI5: largest step (0: no limit) */
    long max_steps;         /* 0: no limit */
    double output_interval; /* 0: output after every step */
    hx_output_fn *output;   /* may be NULL */
    double growth_limit;    /* |(q,u)| > growth_limit * (1 + |(q0,u0)|) is unstable (0: 1e12) */
} hx_integrator_options;

typedef enum hx_status {
    HX_INTEGRATION_OK = 0,
    HX_INTEGRATION_FAILED,         /* the right-hand side or projection failed */
    HX_INTEGRATION_UNSTABLE,       /* the state became non-finite or grew without bound */
    HX_INTEGRATION_STEP_TOO_SMALL, /* DOPRI5 could not meet the tolerance */
    HX_INTEGRATION_TOO_MANY_STEPS,
    HX_INTEGRATION_STOPPED         /* the output callback asked to stop */
} hx_status;

typedef struct hx_integrator_stats {
    long steps, rejected, evaluations;
    double last_step;
    double t_reached;
    int stiff;        /* DOPRI5's stiffness detector fired */
    double t_stiff;
} hx_integrator_stats;

void hx_integrator_defaults(hx_integrator_options *opt);
hx_status hx_integrate(const hx_ode *ode, double t0, double *y, const hx_integrator_options *opt,
                       hx_integrator_stats *stats);

const char *hx_method_name(hx_method method);
int hx_method_parse(const char *name, hx_method *method);
const char *hx_status_text(hx_status status);
/* Order of accuracy (5 for DOPRI5). */
int hx_method_order(hx_method method);

#endif
