/*
 * The compact form of a function expression (docs/architecture.md, "Function
 * expressions"): a stack program of fixed-size ops, constants folded, the
 * source place of every op kept apart for faults, the inputs listed once,
 * the stack depth known. Shared by the parser, the linker and the evaluator
 * (expr/); callers see model/expr/expr.h only.
 */
#ifndef HX_MODEL_EXPR_PROGRAM_H
#define HX_MODEL_EXPR_PROGRAM_H

#include <stdint.h>

#include "model/expr/expr.h"

#define HX_EXPR_MAX_DEPTH 128  /* stack slots an expression may need */
#define HX_EXPR_MAX_INPUTS 64  /* distinct inputs an expression may read */
#define HX_EXPR_MAX_ARGUMENTS 40 /* arguments of one call (FORCOS takes 34) */

typedef enum hx_expr_opcode {
    HX_OP_CONST,      /* push constants[a] */
    HX_OP_INPUT,      /* push the value of inputs[a] */
    HX_OP_CALL,       /* pop nargs arguments, push function(arguments): operators and pure
                       * functions (model/expr/apply.h) */
    HX_OP_SPLINE,     /* pop x and z, push AKISPL or CUBSPL of calls[a] */
    HX_OP_CURVE,      /* pop alpha, push CURVE of calls[a] */
    HX_OP_IF,         /* pop c: c < 0 goes on, c == 0 jumps to a, c > 0 jumps to b */
    HX_OP_JUMP        /* go to a */
} hx_expr_opcode;

typedef struct hx_expr_op {
    uint8_t code;      /* hx_expr_opcode */
    uint8_t nargs;     /* the arguments it pops */
    uint16_t function; /* model/expr/functions.h's code */
    int32_t a, b;
} hx_expr_op;

typedef struct hx_expr_place {
    int line, column;
} hx_expr_place;

/* A spline or curve the program evaluates. */
typedef struct hx_expr_model_call {
    int function;  /* HX_FN_AKISPL, HX_FN_CUBSPL or HX_FN_CURVE */
    int id;        /* the Reference_Spline's or curve's id */
    int index;     /* its index in the model, after linking */
    int order;     /* the derivative asked for (iord): 0, 1 or 2 */
    int component; /* CURVE: 1, 2 or 3 (x, y, z) */
} hx_expr_model_call;

struct hx_expr_program {
    hx_expr_op *ops;
    hx_expr_place *places; /* one per op */
    int nops;
    double *constants;
    int nconstants;
    hx_expr_input *inputs;
    int ninputs;
    hx_expr_model_call *calls;
    int ncalls;
    int depth;             /* the most stack slots an evaluation uses */
    int values;            /* ops that push a value (at most as many on one path) */
    int arguments;         /* the arguments those ops pop, all together */
    char *file;
    const hx_model *model; /* the model it is linked against, NULL before */
};

#endif
