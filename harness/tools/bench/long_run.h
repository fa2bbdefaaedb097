/*
 * Long runs: many fixed steps of a model, with the energy error over the
 * first and the last tenth of the run and its drift rate (least squares),
 * and the largest constraint residuals. A symplectic method keeps the energy
 * error of a conservative model bounded; RK4 lets it drift slowly.
 */
#ifndef HX_TOOLS_BENCH_LONG_RUN_H
#define HX_TOOLS_BENCH_LONG_RUN_H

#include <stdio.h>

#include "sim/ode/integrator.h"
#include "session/session.h"

typedef struct hx_long_run {
    hx_method method;
    long steps;
    double step;
    double error_first, error_last; /* largest |E - E0| / scale over the first, last tenth */
    double drift;                   /* slope of (E - E0) / scale per time unit */
    double scale;                   /* max(|E0|, largest kinetic energy) */
    double max_phi, max_phidot;
    double seconds;
    hx_status status;
} hx_long_run;

int hx_long_run_measure(hx_session *s, hx_method method, long steps, double step,
                        hx_long_run *out, hx_message *msg);
void hx_long_run_print(FILE *f, const hx_long_run *runs, int count);

#endif
