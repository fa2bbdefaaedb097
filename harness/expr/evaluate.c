/*
 * A function expression's value (evaluate.h): one loop over the program's
 * ops on a stack of fixed depth, each input computed at its first use and
 * kept, IF jumping over the branches it does not take, + - * / and the
 * sign done in the loop and every other function by the same code the
 * parser folds constants with (model/expr/apply.h).
 */
#include "expr/evaluate.h"

#include <math.h>
#include <stdint.h>

#include "expr/operands.h"
#include "model/expr/apply.h"
#include "model/expr/functions.h"

_Static_assert(HX_EXPR_MAX_INPUTS <= 64, "the inputs computed are kept as bits of a word");

/* A result of + - * / or the sign that is not finite (a division by zero
 * among them): the fault apply gives for it. */
static int arithmetic_fault(int fn, const double *args, int nargs, hx_expr_fault *fault)
{
    double value;
    hx_expr_apply(fn, args, nargs, &value, NULL, fault);
    return -1;
}

int hx_expr_eval(const hx_expr_program *p, const hx_expr_context *c, double *value,
                 hx_expr_fault *fault)
{
    if (!hx_expr_operands_ready(p, c, fault))
        return -1;
    double stack[HX_EXPR_MAX_DEPTH], inputs[HX_EXPR_MAX_INPUTS];
    uint64_t have = 0; /* the inputs computed so far */
    int sp = 0;
    for (int pc = 0; pc < p->nops;) {
        const hx_expr_op *op = &p->ops[pc];
        switch ((hx_expr_opcode)op->code) {
        case HX_OP_CONST: stack[sp++] = p->constants[op->a]; break;
        case HX_OP_INPUT:
            if (!(have >> op->a & 1u)) {
                if (hx_expr_operand_input(p, c, op->a, &inputs[op->a], fault) != 0)
                    return hx_expr_operand_fault(p, c, pc, fault);
                have |= (uint64_t)1 << op->a;
            }
            stack[sp++] = inputs[op->a];
            break;
        case HX_OP_CALL: {
            sp -= op->nargs;
            double *a = stack + sp, r;
            switch (op->function) {
            case HX_FN_ADD: r = a[0] + a[1]; break;
            case HX_FN_SUB: r = a[0] - a[1]; break;
            case HX_FN_MUL: r = a[0] * a[1]; break;
            case HX_FN_NEG: r = -a[0]; break;
            case HX_FN_DIV: r = a[0] / a[1]; break; /* by 0: not finite, and so named below */
            default:
                if (hx_expr_apply(op->function, a, op->nargs, &r, NULL, fault) != 0)
                    return hx_expr_operand_fault(p, c, pc, fault);
            }
            if (!isfinite(r)) {
                arithmetic_fault(op->function, a, op->nargs, fault);
                return hx_expr_operand_fault(p, c, pc, fault);
            }
            stack[sp++] = r;
            break;
        }
        case HX_OP_SPLINE:
        case HX_OP_CURVE:
            sp -= op->nargs;
            if (hx_expr_operand_model(p, op, stack + sp, &stack[sp], NULL, fault) != 0)
                return hx_expr_operand_fault(p, c, pc, fault);
            ++sp;
            break;
        case HX_OP_IF: {
            const double condition = stack[--sp];
            if (condition == 0.0) {
                pc = op->a;
                continue;
            }
            if (condition > 0.0) {
                pc = op->b;
                continue;
            }
            break;
        }
        case HX_OP_JUMP: pc = op->a; continue;
        }
        ++pc;
    }
    *value = stack[0];
    return 0;
}

int hx_expr_input_value(const hx_expr_program *p, const hx_expr_context *c, int k,
                        double *value, hx_expr_fault *fault)
{
    if (!hx_expr_operands_ready(p, c, fault))
        return -1;
    if (hx_expr_operand_input(p, c, k, value, fault) != 0) {
        fault->line = p->inputs[k].line, fault->column = p->inputs[k].column;
        fault->time = c->frames->time;
        return -1;
    }
    return 0;
}
