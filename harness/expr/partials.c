/*
 * A function expression's partial derivatives in its inputs (evaluate.h),
 * exact, over the same ops as its value, by two methods:
 *
 *  - the adjoint sweep (hx_expr_eval_partials): the ops are evaluated once,
 *    each value's local partials in its arguments written down as it is
 *    computed (a tape of the ops IF took), then one backward pass carries
 *    d(result)/d(value) to the inputs;
 *  - forward accumulation (hx_expr_eval_partials_forward): every stack value
 *    carries its gradient in all the inputs.
 *
 * The adjoint costs one pass whatever the count of inputs; forward costs a
 * gradient's length per op. Measured on the harness's expressions in
 * docs/performance.md ("Function expressions").
 */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "expr/evaluate.h"
#include "expr/operands.h"
#include "model/expr/apply.h"
#include "model/expr/functions.h"

/* One op that pushes a value: the value and its partials in its arguments
 * (partials[0 .. op->nargs - 1]); the fault with its place on failure.
 * Constants and inputs are the caller's. */
static int compute(const hx_expr_program *p, const hx_expr_context *c, int pc, double *args,
                   double *value, double *partials, hx_expr_fault *fault)
{
    const hx_expr_op *op = &p->ops[pc];
    if (op->code == HX_OP_CALL) { /* + - * done here, as the value's loop does them */
        double r = NAN;
        switch (op->function) {
        case HX_FN_ADD: r = args[0] + args[1], partials[0] = 1.0, partials[1] = 1.0; break;
        case HX_FN_SUB: r = args[0] - args[1], partials[0] = 1.0, partials[1] = -1.0; break;
        case HX_FN_MUL: r = args[0] * args[1], partials[0] = args[1], partials[1] = args[0];
            break;
        case HX_FN_NEG: r = -args[0], partials[0] = -1.0; break;
        default: break;
        }
        if (isfinite(r)) {
            *value = r;
            return 0;
        }
    }
    const int status = op->code == HX_OP_CALL
                           ? hx_expr_apply(op->function, args, op->nargs, value, partials, fault)
                           : hx_expr_operand_model(p, op, args, value, partials, fault);
    return status != 0 ? hx_expr_operand_fault(p, c, pc, fault) : 0;
}

/* A partial that is not finite where its argument depends on an input. */
static int partial_fault(const hx_expr_program *p, const hx_expr_context *c, int pc,
                         double partial, hx_expr_fault *fault)
{
    fault->kind = HX_EXPR_FAULT_PARTIAL;
    fault->function = hx_expr_function_at(p->ops[pc].function)->name;
    fault->what = "its partial derivative is not finite here";
    fault->has_argument = 1, fault->argument = partial;
    return hx_expr_operand_fault(p, c, pc, fault);
}

/* The partials summed over an input's uses may overflow where each term is
 * finite: 0, or -1 with the fault at the input's first place. */
static int partials_finite(const hx_expr_program *p, const hx_expr_context *c,
                           const double *partials, hx_expr_fault *fault)
{
    for (int k = 0; k < p->ninputs; ++k)
        if (!isfinite(partials[k])) {
            const hx_expr_input *in = &p->inputs[k];
            fault->kind = HX_EXPR_FAULT_PARTIAL;
            fault->function = in->kind == HX_EXPR_INPUT_TIME
                                  ? "TIME" : hx_expr_function_at(in->function)->name;
            fault->what = "the partial derivative in it is not finite (an overflow)";
            fault->has_argument = 1, fault->argument = partials[k];
            fault->line = in->line, fault->column = in->column, fault->time = c->frames->time;
            return -1;
        }
    return 0;
}

/* The adjoint's tape in scratch: per value pushed, its adjoint, where its
 * local partials start and how many (those in arguments that depend on an
 * input), and the input it is (-1 for others); per such argument, its
 * partial and the tape entry of the argument. */
typedef struct tape {
    double *adjoint;  /* values */
    double *partial;  /* arguments */
    int32_t *operand; /* arguments */
    int32_t *first;   /* values */
    int32_t *count;   /* values */
    int32_t *input;   /* values */
} tape;

static size_t int_doubles(size_t ints)
{
    return (ints * sizeof(int32_t) + sizeof(double) - 1) / sizeof(double);
}

static size_t tape_size(const hx_expr_program *p)
{
    const size_t values = (size_t)p->values, arguments = (size_t)p->arguments;
    return values + arguments + int_doubles(arguments) + 3 * int_doubles(values);
}

static tape tape_in(const hx_expr_program *p, double *scratch)
{
    const size_t values = (size_t)p->values, arguments = (size_t)p->arguments;
    tape t;
    t.adjoint = scratch;
    t.partial = t.adjoint + values;
    t.operand = (int32_t *)(t.partial + arguments);
    t.first = (int32_t *)((double *)t.operand + int_doubles(arguments));
    t.count = (int32_t *)((double *)t.first + int_doubles(values));
    t.input = (int32_t *)((double *)t.count + int_doubles(values));
    return t;
}

size_t hx_expr_scratch_size(const hx_expr_program *p)
{
    const size_t forward = (size_t)p->depth * (size_t)p->ninputs, adjoint = tape_size(p);
    return forward > adjoint ? forward : adjoint;
}

int hx_expr_eval_partials(const hx_expr_program *p, const hx_expr_context *c, double *value,
                          double *partials, double *scratch, hx_expr_fault *fault)
{
    if (!hx_expr_operands_ready(p, c, fault))
        return -1;
    tape t = tape_in(p, scratch);
    double stack[HX_EXPR_MAX_DEPTH], inputs[HX_EXPR_MAX_INPUTS], local[HX_EXPR_MAX_ARGUMENTS];
    int32_t entry[HX_EXPR_MAX_DEPTH];   /* the tape entry of each stack value */
    unsigned char varies[HX_EXPR_MAX_DEPTH]; /* whether it depends on an input */
    uint64_t have = 0;
    int sp = 0, entries = 0, used = 0;
    for (int pc = 0; pc < p->nops;) {
        const hx_expr_op *op = &p->ops[pc];
        switch ((hx_expr_opcode)op->code) {
        case HX_OP_IF: {
            const double condition = stack[--sp];
            if (condition != 0.0) {
                if (condition > 0.0) {
                    pc = op->b;
                    continue;
                }
                break;
            }
            pc = op->a;
            continue;
        }
        case HX_OP_JUMP: pc = op->a; continue;
        case HX_OP_CONST:
            stack[sp] = p->constants[op->a], varies[sp] = 0;
            t.input[entries] = -1, t.count[entries] = 0;
            entry[sp++] = entries++;
            break;
        case HX_OP_INPUT:
            if (!(have >> op->a & 1u)) {
                if (hx_expr_operand_input(p, c, op->a, &inputs[op->a], fault) != 0)
                    return hx_expr_operand_fault(p, c, pc, fault);
                have |= (uint64_t)1 << op->a;
            }
            stack[sp] = inputs[op->a], varies[sp] = 1;
            t.input[entries] = op->a, t.count[entries] = 0;
            entry[sp++] = entries++;
            break;
        default: { /* a call, a spline, a curve */
            sp -= op->nargs;
            double r;
            if (compute(p, c, pc, stack + sp, &r, local, fault) != 0)
                return -1;
            int count = 0;
            t.first[entries] = used;
            for (int i = 0; i < op->nargs; ++i) {
                if (!varies[sp + i])
                    continue;
                if (!isfinite(local[i]))
                    return partial_fault(p, c, pc, local[i], fault);
                t.partial[used + count] = local[i], t.operand[used + count] = entry[sp + i];
                ++count;
            }
            used += count;
            t.input[entries] = -1, t.count[entries] = count;
            stack[sp] = r, varies[sp] = count > 0;
            entry[sp++] = entries++;
            break;
        }
        }
        ++pc;
    }
    *value = stack[0];
    for (int k = 0; k < p->ninputs; ++k)
        partials[k] = 0.0;
    if (!varies[0])
        return 0;
    for (int e = 0; e < entries; ++e)
        t.adjoint[e] = 0.0;
    t.adjoint[entry[0]] = 1.0;
    for (int e = entry[0]; e >= 0; --e) { /* arguments come before the values made of them */
        const double a = t.adjoint[e];
        if (a == 0.0)
            continue;
        if (t.input[e] >= 0) {
            partials[t.input[e]] += a;
            continue;
        }
        for (int i = t.first[e], end = t.first[e] + t.count[e]; i < end; ++i)
            t.adjoint[t.operand[i]] += t.partial[i] * a;
    }
    return partials_finite(p, c, partials, fault);
}

int hx_expr_eval_partials_forward(const hx_expr_program *p, const hx_expr_context *c,
                                  double *value, double *partials, double *scratch,
                                  hx_expr_fault *fault)
{
    if (!hx_expr_operands_ready(p, c, fault))
        return -1;
    const int n = p->ninputs;
    double *gradient = scratch; /* depth x n: the gradient of each stack value */
    double stack[HX_EXPR_MAX_DEPTH], inputs[HX_EXPR_MAX_INPUTS], local[HX_EXPR_MAX_ARGUMENTS];
    unsigned char varies[HX_EXPR_MAX_DEPTH];
    uint64_t have = 0;
    int sp = 0;
    for (int pc = 0; pc < p->nops;) {
        const hx_expr_op *op = &p->ops[pc];
        switch ((hx_expr_opcode)op->code) {
        case HX_OP_IF: {
            const double condition = stack[--sp];
            if (condition != 0.0) {
                if (condition > 0.0) {
                    pc = op->b;
                    continue;
                }
                break;
            }
            pc = op->a;
            continue;
        }
        case HX_OP_JUMP: pc = op->a; continue;
        case HX_OP_CONST: stack[sp] = p->constants[op->a], varies[sp++] = 0; break;
        case HX_OP_INPUT: {
            if (!(have >> op->a & 1u)) {
                if (hx_expr_operand_input(p, c, op->a, &inputs[op->a], fault) != 0)
                    return hx_expr_operand_fault(p, c, pc, fault);
                have |= (uint64_t)1 << op->a;
            }
            double *g = gradient + (size_t)sp * (size_t)n;
            for (int j = 0; j < n; ++j)
                g[j] = 0.0;
            g[op->a] = 1.0;
            stack[sp] = inputs[op->a], varies[sp++] = 1;
            break;
        }
        default: {
            sp -= op->nargs;
            double r;
            if (compute(p, c, pc, stack + sp, &r, local, fault) != 0)
                return -1;
            /* the result's gradient, over the first argument's: each of its
             * components is read from every argument before it is written */
            int first = -1;
            for (int i = 0; i < op->nargs; ++i) {
                if (!varies[sp + i])
                    continue;
                if (!isfinite(local[i]))
                    return partial_fault(p, c, pc, local[i], fault);
                if (first < 0)
                    first = i;
            }
            if (first >= 0) {
                double *out = gradient + (size_t)sp * (size_t)n;
                for (int j = 0; j < n; ++j) {
                    double sum = 0.0;
                    for (int i = first; i < op->nargs; ++i)
                        if (varies[sp + i])
                            sum += local[i] * gradient[(size_t)(sp + i) * (size_t)n + (size_t)j];
                    out[j] = sum;
                }
            }
            stack[sp] = r, varies[sp++] = first >= 0;
            break;
        }
        }
        ++pc;
    }
    *value = stack[0];
    for (int k = 0; k < n; ++k)
        partials[k] = varies[0] ? gradient[k] : 0.0;
    return partials_finite(p, c, partials, fault);
}
