/* Helpers of the function-expression tests (test_expr_*.c). */
#ifndef EXPR_SUPPORT_H
#define EXPR_SUPPORT_H

#include "expr/evaluate.h"
#include "frames/frames.h"
#include "model/expr/expr.h"
#include "test_support.h"

/* A model and its frames, and the values of its variables by index: the
 * context expressions are linked against and evaluated at. */
typedef struct expr_fixture {
    hx_model *model;
    hx_frames frames;
    double variables[16];
} expr_fixture;

/* The model of the function tests: ground with marker 10, Reference_Variables
 * 1 .. 9 (index = id - 1), IC array 30 (1.5, -2, 7), U array 31 (variables
 * 2 and 3), X array 32, Reference_Spline 101 (the six points of
 * docs/interface.md §7.11, on the line y = -1000 x) and 102 (y = x^2 at x = 0
 * .. 4), Control_Diff 7 (ic 0.25, ic_dot -1.5). Variable k starts at k. */
extern const char *const expr_function_model;

void expr_open(expr_fixture *f, const char *name, const char *xml);
void expr_close(expr_fixture *f);
hx_expr_context expr_context(expr_fixture *f);

/* Parsed at "test.xml":1:1 and linked; the test fails on an error. */
hx_expr_program *expr_compile(expr_fixture *f, const char *text);
/* The value of text at f; the test fails on a fault. Also checks that both
 * partial methods give the same value. */
double expr_value(expr_fixture *f, const char *text);
/* The fault of evaluating text at f (it must fault); its message in msg. */
hx_expr_fault expr_fault(expr_fixture *f, const char *text, hx_message *msg);
/* The message of parsing text at "m.xml":10:5 (it must fail). */
const char *expr_parse_error(const char *text, hx_message *msg);
/* The message of linking text against f's model (it must fail). */
const char *expr_link_error(expr_fixture *f, const char *text, hx_message *msg);

/* The partials of text at f by both methods against central differences in
 * its VARVAL inputs and TIME (the others are not varied): the largest
 * relative error, printed with what when above tolerance, and the test
 * fails then. */
double expr_check_partials(expr_fixture *f, const char *text, double tolerance);

#endif
