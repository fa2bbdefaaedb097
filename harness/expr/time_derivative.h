/*
 * An expression of TIME alone and its first two derivatives in time
 * (docs/interface.md §7.12, a Motion_Joint by expression): f exactly, f'
 * exactly as the program's partial in TIME (forward accumulation: one input),
 * f'' as the central difference of that exact f' over 1e-4 and 2e-4 time
 * units, extrapolated (Richardson):
 *   D(h) = (f'(t + h) - f'(t - h)) / (2h),   f'' = (4 D(h) - D(2h)) / 3,
 * whose truncation is h^4 |f^(6)| / 30 and whose rounding about
 * 2 DBL_EPSILON |f'| / h (0.1 sin(2 pi t): 2e-14 and 3e-12; 6.6e-12 measured in
 * tests/test_expr_motions.c). The same steps as check's test of a MOTSUB.
 * Within 2h of t = 0 no time before 0 is read: the forward difference of the
 * same order (h^4 |f^(6)| / 5) over f' at t .. t + 4h.
 */
#ifndef HX_EXPR_TIME_DERIVATIVE_H
#define HX_EXPR_TIME_DERIVATIVE_H

#include "expr/evaluate.h"

/* The step of f'''s difference, in the model's time unit (D(h) and D(2h)). */
#define HX_TIME_DERIVATIVE_STEP 1e-4

/* Order iord (0, 1 or 2) of p in time at fr's time; p reads TIME alone
 * (the model's reader refuses any other input: model/routine_elements.c). No allocation. 0, or -1 with the fault (its
 * time that of the evaluation that faulted). */
int hx_time_derivative_eval(const hx_expr_program *p, const hx_frames *fr, int iord,
                            double *value, hx_expr_fault *fault);

#endif
