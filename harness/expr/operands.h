/*
 * What an evaluation takes from its context and the model (evaluate.h):
 * the inputs' values (TIME, the measures, VARVAL, DIF, DIF1, ARYVAL), the
 * splines' and curves' values with their partials, and the faults' places.
 * Shared by the value's evaluation and the partials'.
 */
#ifndef HX_EXPR_OPERANDS_H
#define HX_EXPR_OPERANDS_H

#include "expr/evaluate.h"
#include "model/expr/program.h"

/* 1 when p may be evaluated at c (linked against c's model), else 0 with
 * the fault. */
int hx_expr_operands_ready(const hx_expr_program *p, const hx_expr_context *c,
                           hx_expr_fault *fault);

/* Input k's value; 0, or -1 with the fault (not its place). */
int hx_expr_operand_input(const hx_expr_program *p, const hx_expr_context *c, int k,
                          double *value, hx_expr_fault *fault);

/* AKISPL, CUBSPL (op's args x, z) or CURVE (alpha) of the op's model call:
 * the value, and with partials != NULL its partials in the args; 0, or -1
 * with the fault (not its place). */
int hx_expr_operand_model(const hx_expr_program *p, const hx_expr_op *op, const double *args,
                          double *value, double *partials, hx_expr_fault *fault);

/* Puts op pc's place and c's time on a fault; returns -1. */
int hx_expr_operand_fault(const hx_expr_program *p, const hx_expr_context *c, int pc,
                          hx_expr_fault *fault);

#endif
