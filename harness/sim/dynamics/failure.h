/*
 * How a stage of an evaluation (dynamics.h) and the Jacobian's blocks fail:
 * the first failure's text in the evaluation's data, and -1 up the calls.
 */
#ifndef HX_SIM_DYNAMICS_FAILURE_H
#define HX_SIM_DYNAMICS_FAILURE_H

#include "sim/dynamics/dynamics.h"

/* Records the first failure in dd->message; returns -1. */
int hx_dynamics_fail(hx_dynamics_data *dd, const char *fmt, ...)
    __attribute__((format(printf, 2, 3)));

/* After a call of element b at time t: -1 (with the message) when it asked to
 * stop the run (c_errmes STOP), or when one of its n outputs in out is not
 * finite ("Force_Field 3 (FIESUB) returned a non-finite force at t = 0.1",
 * what naming the outputs); else 0. n may be 0 (the stop alone). */
int hx_dynamics_check_call(const hx_dynamics *d, hx_dynamics_data *dd, const hx_binding *b,
                           const double *out, int n, const char *what, double t);

#endif
