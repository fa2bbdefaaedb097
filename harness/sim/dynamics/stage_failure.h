/*
 * How a stage of an evaluation (bodies.h, loads.h, element_forces.h,
 * stateeqns.h, routines.h, constraints.h) and the Newton matrix's
 * blocks fail: the first failure's text in d->message, and -1 up the calls.
 */
#ifndef HX_SIM_DYNAMICS_STAGE_FAILURE_H
#define HX_SIM_DYNAMICS_STAGE_FAILURE_H

#include "sim/dynamics/dynamics.h"

/* Records the first failure in d->message; returns -1. */
int hx_dynamics_fail(hx_dynamics *d, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
/* -1 when an element asked to stop the run (c_errmes STOP). */
int hx_dynamics_check_stop(hx_dynamics *d, const hx_binding *b);

#endif
