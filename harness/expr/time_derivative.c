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
    double r[4]; /* f' at t + h, t - h, t + 2h, t - 2h */
    const double at[4] = {t + h, t - h, t + 2.0 * h, t - 2.0 * h};
    for (int k = 0; k < 4; ++k)
        if (rate_at(p, fr, at[k], &r[k], fault) != 0)
            return -1;
    const double d1 = (r[0] - r[1]) / (2.0 * h), d2 = (r[2] - r[3]) / (4.0 * h);
    *value = (4.0 * d1 - d2) / 3.0;
    return 0;
}
