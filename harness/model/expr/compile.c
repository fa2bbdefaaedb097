/*
 * A function expression parsed into its compact program (expr.h,
 * program.h): the parse tree (parser.c) emitted in postorder as stack ops,
 * IF as a conditional jump over branches that are not evaluated, each
 * distinct input and each spline or curve recorded once, the stack depth
 * counted as the ops are emitted.
 */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/orientation_systems.h"
#include "model/expr/functions.h"
#include "model/expr/program.h"
#include "model/expr/tree.h"

typedef struct emitter {
    const hx_expr_tree *tree;
    hx_expr_program *p;
    int op_capacity, constant_capacity, call_capacity;
    int depth;  /* the stack's depth after the ops so far */
    hx_message *msg;
} emitter;

static int fail_at(const emitter *e, const hx_expr_node *n, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

static int fail_at(const emitter *e, const hx_expr_node *n, const char *fmt, ...)
{
    char what[HX_MESSAGE_MAX];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    return hx_fail(e->msg, "%s:%d:%d: %s", e->p->file, n->line, n->column, what);
}

/* Room for one more of an array; 0 or -1 (out of memory). */
static int grow(void **items, int count, int *capacity, size_t size, hx_message *msg)
{
    if (count < *capacity)
        return 0;
    const int wanted = *capacity ? 2 * *capacity : 16;
    void *grown = realloc(*items, size * (size_t)wanted);
    if (grown == NULL)
        return hx_fail(msg, "out of memory");
    *items = grown, *capacity = wanted;
    return 0;
}

/* Appends an op at node n's place that pops nargs values and pushes pushes;
 * returns its index, or -1. */
static int emit(emitter *e, const hx_expr_node *n, hx_expr_opcode code, int nargs, int pushes,
                int function, int a)
{
    hx_expr_program *p = e->p;
    const int capacity = e->op_capacity;
    if (grow((void **)&p->ops, p->nops, &e->op_capacity, sizeof *p->ops, e->msg) != 0)
        return -1;
    if (e->op_capacity != capacity) { /* the places keep pace with the ops */
        hx_expr_place *grown = realloc(p->places, sizeof *grown * (size_t)e->op_capacity);
        if (grown == NULL)
            return hx_fail(e->msg, "out of memory");
        p->places = grown;
    }
    hx_expr_op *op = &p->ops[p->nops];
    op->code = (uint8_t)code, op->nargs = (uint8_t)nargs;
    op->function = (uint16_t)(function < 0 ? 0 : function);
    op->a = a, op->b = 0;
    p->places[p->nops].line = n->line, p->places[p->nops].column = n->column;
    e->depth += pushes - nargs;
    if (pushes) {
        ++p->values;
        p->arguments += nargs;
    }
    if (e->depth > p->depth)
        p->depth = e->depth;
    if (p->depth > HX_EXPR_MAX_DEPTH)
        return fail_at(e, n, "the expression needs a stack deeper than %d values (nest it less)",
                       HX_EXPR_MAX_DEPTH);
    return p->nops++;
}

static int constant(emitter *e, const hx_expr_node *n)
{
    hx_expr_program *p = e->p;
    if (grow((void **)&p->constants, p->nconstants, &e->constant_capacity,
             sizeof *p->constants, e->msg) != 0)
        return -1;
    p->constants[p->nconstants] = n->value;
    return emit(e, n, HX_OP_CONST, 0, 1, -1, p->nconstants++);
}

/* The input a node reads, listed once: its index, or -1. */
static int input(emitter *e, const hx_expr_node *n)
{
    hx_expr_program *p = e->p;
    hx_expr_input in;
    memset(&in, 0, sizeof in);
    in.function = n->kind == HX_NODE_TIME ? -1 : n->function;
    switch (n->kind == HX_NODE_TIME ? HX_FK_OPERATOR : hx_expr_function_at(n->function)->kind) {
    case HX_FK_MEASURE: /* in the order of frames/measure_functions.h, ORIENT's after */
        in.kind = HX_EXPR_INPUT_MEASURE, in.measure = n->function - HX_FN_DX;
        if (n->function == HX_FN_ORIENT)
            in.measure = HX_FN_WM + 1 - HX_FN_DX + hx_orientation_code(n->ids[0], n->ids[1]);
        break;
    case HX_FK_VARVAL: in.kind = HX_EXPR_INPUT_VARVAL; break;
    case HX_FK_DIF: in.kind = HX_EXPR_INPUT_DIF; break;
    case HX_FK_DIF1: in.kind = HX_EXPR_INPUT_DIF1; break;
    case HX_FK_ARYVAL: in.kind = HX_EXPR_INPUT_ARYVAL; break;
    case HX_FK_REACTION: in.kind = HX_EXPR_INPUT_REACTION; break;
    case HX_FK_LOAD: in.kind = HX_EXPR_INPUT_LOAD; break;
    case HX_FK_MARKER_FORCE: in.kind = HX_EXPR_INPUT_MARKER_FORCE; break;
    case HX_FK_ACCELERATION: /* in the order of frames/acceleration_measures.h */
        in.kind = HX_EXPR_INPUT_ACCELERATION, in.measure = n->function - HX_FN_ACCX;
        break;
    default: in.kind = HX_EXPR_INPUT_TIME; break;
    }
    if (n->kind != HX_NODE_TIME)
        memcpy(in.ids, n->ids, sizeof in.ids), in.nids = n->nids;
    for (int k = 0; k < p->ninputs; ++k) /* DX(1,2) and DX(1,2,0) read the same */
        if (p->inputs[k].kind == in.kind && p->inputs[k].function == in.function &&
            memcmp(p->inputs[k].ids, in.ids, sizeof in.ids) == 0)
            return k;
    if (p->ninputs == HX_EXPR_MAX_INPUTS)
        return fail_at(e, n, "the expression reads more than %d distinct inputs",
                       HX_EXPR_MAX_INPUTS);
    for (int k = 0; k < 4; ++k)
        in.index[k] = -1;
    in.variable = -1;
    in.line = n->line, in.column = n->column;
    p->inputs[p->ninputs] = in;
    return p->ninputs++;
}

static int model_call(emitter *e, const hx_expr_node *n)
{
    hx_expr_program *p = e->p;
    if (grow((void **)&p->calls, p->ncalls, &e->call_capacity, sizeof *p->calls, e->msg) != 0)
        return -1;
    hx_expr_model_call *c = &p->calls[p->ncalls];
    memset(c, 0, sizeof *c);
    c->function = n->function, c->index = -1;
    if (n->kind == HX_NODE_SPLINE)
        c->id = n->ids[0], c->order = n->ids[1];
    else
        c->order = n->ids[0], c->component = n->ids[1], c->id = n->ids[2];
    return p->ncalls++;
}

static int node(emitter *e, int k);

static int children(emitter *e, const hx_expr_node *n)
{
    for (int i = 0; i < n->count; ++i)
        if (node(e, e->tree->kids[n->first + i]) != 0)
            return -1;
    return 0;
}

/* IF: the condition, then a jump to the branch its sign picks; each branch
 * ends with a jump past the others. */
static int if_node(emitter *e, const hx_expr_node *n)
{
    const int *kids = e->tree->kids + n->first;
    if (node(e, kids[0]) != 0)
        return -1;
    const int test = emit(e, n, HX_OP_IF, 1, 0, HX_FN_IF, 0);
    if (test < 0)
        return -1;
    const int start = e->depth;
    int jumps[2];
    for (int branch = 1; branch <= 3; ++branch) {
        if (branch == 2)
            e->p->ops[test].a = e->p->nops;
        else if (branch == 3)
            e->p->ops[test].b = e->p->nops;
        e->depth = start;
        if (node(e, kids[branch]) != 0)
            return -1;
        if (branch < 3 && (jumps[branch - 1] = emit(e, n, HX_OP_JUMP, 0, 0, -1, 0)) < 0)
            return -1;
    }
    e->p->ops[jumps[0]].a = e->p->ops[jumps[1]].a = e->p->nops;
    return 0;
}

static int node(emitter *e, int k)
{
    const hx_expr_node *n = &e->tree->nodes[k];
    int index;
    switch (n->kind) {
    case HX_NODE_NUMBER: return constant(e, n) < 0 ? -1 : 0;
    case HX_NODE_TIME:
    case HX_NODE_INPUT:
        if ((index = input(e, n)) < 0)
            return -1;
        return emit(e, n, HX_OP_INPUT, 0, 1, n->function, index) < 0 ? -1 : 0;
    case HX_NODE_CALL:
        if (children(e, n) != 0)
            return -1;
        return emit(e, n, HX_OP_CALL, n->count, 1, n->function, 0) < 0 ? -1 : 0;
    case HX_NODE_IF: return if_node(e, n);
    case HX_NODE_SPLINE:
    case HX_NODE_CURVE:
        if (children(e, n) != 0 || (index = model_call(e, n)) < 0)
            return -1;
        return emit(e, n, n->kind == HX_NODE_SPLINE ? HX_OP_SPLINE : HX_OP_CURVE, n->count, 1,
                    n->function, index) < 0 ? -1 : 0;
    }
    return -1; /* every kind returns above */
}

hx_expr_program *hx_expr_parse(const char *text, size_t length, const hx_expr_source *where,
                               hx_message *msg)
{
    hx_expr_source at = {"(text)", 1, 1};
    if (where != NULL) {
        at = *where;
        if (at.file == NULL)
            at.file = "(text)";
        if (at.line < 1)
            at.line = 1;
        if (at.column < 1)
            at.column = 1;
    }
    hx_expr_program *p = calloc(1, sizeof *p);
    if (p == NULL || (p->file = strdup(at.file)) == NULL ||
        (p->inputs = malloc(sizeof *p->inputs * HX_EXPR_MAX_INPUTS)) == NULL) {
        hx_expr_free(p);
        hx_fail(msg, "out of memory");
        return NULL;
    }
    hx_expr_tree tree;
    emitter e = {.tree = &tree, .p = p, .msg = msg};
    if (hx_expr_tree_parse(&tree, text, length, &at, msg) != 0 || node(&e, tree.root) != 0) {
        hx_expr_tree_free(&tree);
        hx_expr_free(p);
        return NULL;
    }
    hx_expr_tree_free(&tree);
    return p;
}
