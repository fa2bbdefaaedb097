/*
 * An expression of TIME and its derivatives in time (time_derivative.h).
 */
#include "expr/time_derivative.h"
#include "model/expr/program.h"

/* f'(t) exactly: the partial in TIME, 0 for a program that does not read it. */
static int rate_at(const hx_expr_program *p, const hx_frames *fr, double t, double *rate,
                   hx_expr_fault *fault)
{
    hx_frames at = *fr; /* a shallow copy: TIME is all the program reads */
    at.time = t;
    const hx_expr_context c = {&at, NULL, NULL};
    double value, partials[1] = {0.0}, scratch[HX_EXPR_MAX_DEPTH];
    if (hx_expr_input_count(p) == 0) {
        *rate = 0.0;
        return hx_expr_eval(p, &c, &value, fault);
    }
    /* one input: forward accumulation's scratch is the stack's depth */
    if (hx_expr_eval_partials_forward(p, &c, &value, partials, scratch, fault) != 0)
        return -1;
    *rate = partials[0];
    return 0;
}

int hx_time_derivative_eval(const hx_expr_program *p, const hx_frames *fr, int iord,
                            double *value, hx_expr_fault *fault)
{
    if (iord == 0) {
        const hx_expr_context c = {fr, NULL, NULL};
        return hx_expr_eval(p, &c, value, fault);
    }
    const double t = fr->time;
    if (iord == 1)
        return rate_at(p, fr, t, value, fault);
    const double h = HX_TIME_DERIVATIVE_STEP;
    double r[5];
    if (t >= 0.0 && t < 2.0 * h) {
        /* the run's start: no time before 0 (TIME**1.5 is not defined there);
         * forward, of the same order: f'' = (-25 r0 + 48 r1 - 36 r2 + 16 r3
         * - 3 r4) / (12 h), r_k = f'(t + k h) */
        for (int k = 0; k < 5; ++k)
            if (rate_at(p, fr, t + k * h, &r[k], fault) != 0)
                return -1;
        *value = (-25.0 * r[0] + 48.0 * r[1] - 36.0 * r[2] + 16.0 * r[3] - 3.0 * r[4]) /
                 (12.0 * h);
        return 0;
    }
    const double at[4] = {t + h, t - h, t + 2.0 * h, t - 2.0 * h}; /* f' there into r */
    for (int k = 0; k < 4; ++k)
        if (rate_at(p, fr, at[k], &r[k], fault) != 0)
            return -1;
    const double d1 = (r[0] - r[1]) / (2.0 * h), d2 = (r[2] - r[3]) / (4.0 * h);
    *value = (4.0 * d1 - d2) / 3.0;
    return 0;
}
