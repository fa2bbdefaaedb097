/*
 * The operators and pure functions of the expression language, computed
 * (docs/interface.md §8.4): the value of one call and its partials in each
 * argument. The parser folds constants with it and the evaluator (expr/)
 * evaluates with it, so a folded constant is what an evaluation would give.
 */
#ifndef HX_MODEL_EXPR_APPLY_H
#define HX_MODEL_EXPR_APPLY_H

#include "model/expr/expr.h"

/* Function fn (an operator or a pure function, model/expr/functions.h) of
 * its nargs arguments: *value, and with partials != NULL the partial in each
 * argument (at a kink, the mean of the one-sided slopes; where the function
 * is flat or jumps, 0). Returns 0, or -1 with the fault's kind, function and
 * what filled (not its place): a division by zero, an argument outside the
 * domain, a result that is not finite. */
int hx_expr_apply(int fn, const double *args, int nargs, double *value, double *partials,
                  hx_expr_fault *fault);

#endif
