/*
 * What the integrators taken from SUNDIALS (bdf.c: CVODE; arkode_dopri5.c:
 * ARKODE) share: one SUNDIALS context per integration, the state as an
 * N_Vector over the caller's array, the right-hand side and the projection
 * through hx_integration (counted as the other integrators count them), the solvers'
 * messages kept for the summary instead of printed, and the loop over the
 * output times.
 */
#ifndef HX_SIM_ODE_SUNDIALS_COMMON_H
#define HX_SIM_ODE_SUNDIALS_COMMON_H

#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>

#include "sim/ode/integration.h"

typedef struct hx_sundials {
    hx_integration *r;
    SUNContext context;
    N_Vector y;       /* over the caller's y: the solver writes its outputs there */
    double *scratch;  /* n values */
} hx_sundials;

/* 0, or -1 (out of memory). */
int hx_sundials_open(hx_sundials *s, hx_integration *r, double *y);
void hx_sundials_close(hx_sundials *s);

/* f(t, y) for CVODE and ARKODE (one signature): 0; 1 (recoverable: the solver
 * retries with a smaller step) on a non-finite trial state; -1 when the model
 * failed. */
int hx_sundials_rhs(double t, N_Vector y, N_Vector ydot, void *user_data);

/* The ode's projection as a correction: corr = P(y) - y; 0 or -1. */
int hx_sundials_correction(hx_sundials *s, double t, const double *y, double *corr);

/* Keeps a solver message in the run's stats (error handler of both). */
void hx_sundials_message(int error_code, const char *module, const char *function, char *msg,
                         void *user_data);

/* Advances the solver by one step towards tout, its state into s->y, the
 * time reached into *t; returns the solver's flag. */
typedef int hx_sundials_advance_fn(void *solver, double tout, N_Vector y, double *t);
/* The solver's interpolated state at t (within its last step) into y; 0 or
 * the solver's flag. */
typedef int hx_sundials_interpolate_fn(void *solver, double t, N_Vector y);
/* The status of a solver flag (negative: a failure). */
typedef hx_status hx_sundials_status_fn(int flag);

/* Runs the solver to the end time one step at a time, calling the ode's
 * accept after every step and the output at the output times (projected
 * copies of the solver's interpolated states) or after every step; the
 * state at the end is left in the caller's y. */
hx_status hx_sundials_drive(hx_sundials *s, void *solver, hx_sundials_advance_fn *advance,
                            hx_sundials_interpolate_fn *interpolate,
                            hx_sundials_status_fn *status_of, long (*steps_of)(void *solver));

#endif
