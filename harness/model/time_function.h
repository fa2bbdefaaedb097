/*
 * A load's value over time as the harness reads it from the model: a number,
 * or STEP(TIME, t0, h0, t1, h1) / STEP5(TIME, ...) (docs/interface.md §3.6).
 * The harness computes STEP itself: it shares no code with the library it
 * verifies.
 */
#ifndef HX_MODEL_TIME_FUNCTION_H
#define HX_MODEL_TIME_FUNCTION_H

typedef struct hx_time_function {
    int kind;    /* 0 constant, 1 STEP, 2 STEP5 */
    double a[5]; /* constant: a[0]; steps: t0 h0 t1 h1 */
} hx_time_function;

double hx_time_function_at(const hx_time_function *f, double t);

/* Parses a number or STEP/STEP5(TIME, t0, h0, t1, h1) with t1 >= t0; 0 or -1. */
int hx_parse_time_function(const char *text, hx_time_function *f);

/* STEP and STEP5 of x: h0 for x <= x0, h1 for x >= x1, the cubic
 * h0 + (h1 - h0) a^2 (3 - 2a) or the quintic a^3 (10 - 15a + 6a^2) between. */
double hx_step(double x, double x0, double h0, double x1, double h1);
double hx_step5(double x, double x0, double h0, double x1, double h1);

#endif
