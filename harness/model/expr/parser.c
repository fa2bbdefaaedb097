/*
 * The parser of function expressions (tree.h): recursive descent over the
 * grammar of docs/interface.md §8.2, with Fortran's precedence and a sign
 * allowed after an operator,
 *
 *   expression := term { (+ | -) term }
 *   term       := signed { (* | /) signed }
 *   signed     := (+ | -) signed | power
 *   power      := primary [ ** signed ]           (right to left)
 *   primary    := number | name | name ( arguments ) | ( expression )
 *
 * so that -2**2 = -4, 2**3**2 = 512, 2*-3 = -6. Calls of operators and pure
 * functions whose arguments are all constants are folded as they are built
 * (unless folding faults: then the evaluation reports it, in its place).
 */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/orientation_systems.h"
#include "model/expr/apply.h"
#include "model/expr/functions.h"
#include "model/expr/lexer.h"
#include "model/expr/program.h"
#include "model/expr/tree.h"

#define MAX_NESTING 200 /* recursion of the descent: parentheses, signs, calls */

typedef struct parser {
    hx_expr_tree *tree;
    hx_expr_lexer lexer;
    hx_expr_token token;    /* the current token */
    hx_expr_token previous; /* the one consumed before it, when started */
    int started;
    int nesting;
    const hx_expr_source *where;
    hx_message *msg;
} parser;

static int fail_at(parser *p, int line, int column, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));

static int fail_at(parser *p, int line, int column, const char *fmt, ...)
{
    char what[HX_MESSAGE_MAX];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    return hx_fail(p->msg, "%s:%d:%d: %s", p->where->file != NULL ? p->where->file : "(text)",
                   line, column, what);
}

static void next(parser *p)
{
    p->previous = p->token, p->started = 1;
    hx_expr_lex(&p->lexer, &p->token);
}

/* A token the lexer refused fails where it stands. */
static int token_error(parser *p)
{
    return fail_at(p, p->token.line, p->token.column, "%s", p->token.error);
}

static int add_node(parser *p, hx_expr_node_kind kind, int function, int line, int column)
{
    hx_expr_tree *t = p->tree;
    if (t->nnodes == t->node_capacity) {
        const int capacity = t->node_capacity ? 2 * t->node_capacity : 32;
        hx_expr_node *grown = realloc(t->nodes, sizeof *grown * (size_t)capacity);
        if (grown == NULL)
            return hx_fail(p->msg, "out of memory");
        t->nodes = grown, t->node_capacity = capacity;
    }
    hx_expr_node *n = &t->nodes[t->nnodes];
    memset(n, 0, sizeof *n);
    n->kind = kind, n->function = function, n->line = line, n->column = column, n->depth = 1;
    return t->nnodes++;
}

static int add_number(parser *p, double value, int line, int column)
{
    const int k = add_node(p, HX_NODE_NUMBER, -1, line, column);
    if (k >= 0)
        p->tree->nodes[k].value = value;
    return k;
}

/* Node k's children become the count nodes in kids. */
static int set_children(parser *p, int k, const int *kids, int count)
{
    hx_expr_tree *t = p->tree;
    if (t->nkids + count > t->kid_capacity) {
        int capacity = t->kid_capacity ? 2 * t->kid_capacity : 64;
        while (capacity < t->nkids + count)
            capacity *= 2;
        int *grown = realloc(t->kids, sizeof *grown * (size_t)capacity);
        if (grown == NULL)
            return hx_fail(p->msg, "out of memory");
        t->kids = grown, t->kid_capacity = capacity;
    }
    memcpy(t->kids + t->nkids, kids, sizeof *kids * (size_t)count);
    hx_expr_node *n = &t->nodes[k];
    n->first = t->nkids, n->count = count;
    t->nkids += count;
    for (int i = 0; i < count; ++i)
        if (t->nodes[kids[i]].depth + 1 > n->depth)
            n->depth = t->nodes[kids[i]].depth + 1;
    if (n->depth > HX_EXPR_MAX_TREE_DEPTH)
        return fail_at(p, n->line, n->column, "the expression is longer than the harness reads"
                       " (a chain of more than %d operations)", HX_EXPR_MAX_TREE_DEPTH);
    return 0;
}

/* An operator or pure function of its arguments: folded when they are all
 * numbers and it does not fault. */
static int call(parser *p, int function, const int *args, int count, int line, int column)
{
    double values[HX_EXPR_MAX_ARGUMENTS];
    int constant = 1;
    for (int i = 0; i < count; ++i) {
        const hx_expr_node *a = &p->tree->nodes[args[i]];
        constant = constant && a->kind == HX_NODE_NUMBER;
        values[i] = a->value;
    }
    double value;
    hx_expr_fault fault;
    if (constant && hx_expr_apply(function, values, count, &value, NULL, &fault) == 0)
        return add_number(p, value, line, column);
    const int k = add_node(p, HX_NODE_CALL, function, line, column);
    if (k < 0 || set_children(p, k, args, count) != 0)
        return -1;
    return k;
}

static int expression(parser *p);

/* The place of what comes next and what it is, for "expected ... found". */
static int expected(parser *p, const char *what)
{
    if (p->token.kind == HX_TOKEN_ERROR)
        return token_error(p);
    char found[96], after[96];
    hx_expr_token_text(&p->token, found, sizeof found);
    if (!p->started)
        return fail_at(p, p->token.line, p->token.column, "expected %s, found %s", what, found);
    hx_expr_token_text(&p->previous, after, sizeof after);
    return fail_at(p, p->token.line, p->token.column, "expected %s after %s, found %s", what,
                   after, found);
}

/* The arguments of a call, after its '(' : expressions, or whole numbers
 * where the function takes ids. Returns their count, or -1. */
static int arguments(parser *p, const hx_expr_function *f, const hx_expr_token *name, int *args,
                     int *ids, int *id_places)
{
    int count = 0;
    if (p->token.kind == HX_TOKEN_CLOSE) { /* no arguments */
        next(p);
        return 0;
    }
    for (;;) {
        if (count == HX_EXPR_MAX_ARGUMENTS)
            return fail_at(p, name->line, name->column, "%s takes at most %d arguments %s%s",
                           f->name, f->most, f->name, f->arguments);
        if (count < 32 && (f->ids >> count & 1u)) {
            if (p->token.kind != HX_TOKEN_NUMBER || p->token.whole < 0) {
                if (p->token.kind == HX_TOKEN_ERROR)
                    return token_error(p);
                return fail_at(p, p->token.line, p->token.column,
                               "%s%s: argument %d must be written as a whole number (an id or"
                               " an option), not an expression", f->name, f->arguments,
                               count + 1);
            }
            ids[count] = (int)p->token.whole;
            id_places[2 * count] = p->token.line, id_places[2 * count + 1] = p->token.column;
            args[count] = -1;
            next(p);
            if (p->token.kind != HX_TOKEN_COMMA && p->token.kind != HX_TOKEN_CLOSE)
                return fail_at(p, p->token.line, p->token.column,
                               "%s%s: argument %d must be written as a whole number (an id or"
                               " an option), not an expression", f->name, f->arguments,
                               count + 1);
        } else if ((args[count] = expression(p)) < 0) {
            return -1;
        }
        ++count;
        if (p->token.kind == HX_TOKEN_CLOSE)
            break;
        if (p->token.kind != HX_TOKEN_COMMA)
            return expected(p, "',' or ')' in the arguments of a call");
        next(p);
    }
    next(p);
    return count;
}

static int wrong_count(parser *p, const hx_expr_function *f, const hx_expr_token *name,
                       int count)
{
    if (f->least == f->most)
        return fail_at(p, name->line, name->column, "%s takes %d argument%s %s%s, not %d",
                       f->name, f->least, f->least == 1 ? "" : "s", f->name, f->arguments,
                       count);
    return fail_at(p, name->line, name->column, "%s takes %d to %d arguments %s%s, not %d",
                   f->name, f->least, f->most, f->name, f->arguments, count);
}

/* IF(e1: e2, e3, e4), after its '(' (a ',' after e1 is read as the ':',
 * as MotionSolve's own examples write it). */
static int if_call(parser *p, const hx_expr_token *name)
{
    int args[4];
    for (int i = 0; i < 4; ++i) {
        if ((args[i] = expression(p)) < 0)
            return -1;
        const hx_expr_token_kind wanted = i == 3 ? HX_TOKEN_CLOSE : HX_TOKEN_COMMA;
        if (p->token.kind == wanted || (i == 0 && p->token.kind == HX_TOKEN_COLON)) {
            next(p);
            continue;
        }
        if (p->token.kind == HX_TOKEN_COMMA || p->token.kind == HX_TOKEN_CLOSE ||
            p->token.kind == HX_TOKEN_COLON)
            return fail_at(p, name->line, name->column,
                           "IF takes 4 expressions, IF(e1: e2, e3, e4): the value of e2 where"
                           " e1 < 0, e3 where e1 = 0, e4 where e1 > 0");
        return expected(p, i == 0 ? "':'" : i == 3 ? "')'" : "','");
    }
    const hx_expr_node *condition = &p->tree->nodes[args[0]];
    if (condition->kind == HX_NODE_NUMBER) /* the branch is known now */
        return args[condition->value < 0.0 ? 1 : condition->value == 0.0 ? 2 : 3];
    const int k = add_node(p, HX_NODE_IF, HX_FN_IF, name->line, name->column);
    if (k < 0 || set_children(p, k, args, 4) != 0)
        return -1;
    return k;
}

/* ORIENT(system, component, I[, J]) (docs/interface.md §8.5): a system of
 * base/orientation_systems.h, one of its components, and a marker for I. */
static int orient_arguments(parser *p, const int *ids, const int *places)
{
    const hx_orientation_system *s = hx_orientation_system_at(ids[0]);
    if (s == NULL)
        return fail_at(p, places[0], places[1], "ORIENT: system (argument 1) is %d: 1 to 12 the"
                       " body-fixed Euler angles, 13 to 24 the space-fixed ones, 25 AX AY AZ, 26"
                       " YAW PITCH ROLL, 27 the Euler parameters, 28 the Rodrigues parameters, 29"
                       " the direction cosines", ids[0]);
    if (ids[1] < 1 || ids[1] > s->components)
        return fail_at(p, places[2], places[3], "ORIENT: component (argument 2) is %d: system %d"
                       " (%s) has components 1 to %d", ids[1], ids[0], s->what, s->components);
    if (ids[2] == 0)
        return fail_at(p, places[4], places[5], "ORIENT: its I marker (argument 3) is 0: I names"
                       " a marker (0 stands for the ground's origin only for J)");
    return 0;
}

/* A call of a function the table knows, after its '('. */
static int known_call(parser *p, int code, const hx_expr_token *name)
{
    const hx_expr_function *f = hx_expr_function_at(code);
    if (f->kind == HX_FK_IF)
        return if_call(p, name);
    int args[HX_EXPR_MAX_ARGUMENTS], ids[HX_EXPR_MAX_ARGUMENTS] = {0};
    int places[2 * HX_EXPR_MAX_ARGUMENTS];
    const int count = arguments(p, f, name, args, ids, places);
    if (count < 0)
        return -1;
    if (count < f->least || count > f->most)
        return wrong_count(p, f, name, count);
    const int line = name->line, column = name->column;
    int k;
    switch (f->kind) {
    case HX_FK_OPERATOR:
    case HX_FK_PURE:
        return call(p, code, args, count, line, column);
    case HX_FK_SPLINE: { /* (x, z, id[, iord]) */
        const int order = count == 4 ? ids[3] : 0;
        if (order > 2)
            return fail_at(p, places[6], places[7], "%s: iord (argument 4) is %d: the value (0)"
                           " or its first (1) or second (2) derivative in x", f->name, order);
        if ((k = add_node(p, HX_NODE_SPLINE, code, line, column)) < 0 ||
            set_children(p, k, args, 2) != 0)
            return -1;
        p->tree->nodes[k].ids[0] = ids[2], p->tree->nodes[k].ids[1] = order;
        p->tree->nodes[k].nids = 2;
        return k;
    }
    case HX_FK_CURVE: /* (alpha, iord, comp, id) */
        if (ids[1] > 2)
            return fail_at(p, places[2], places[3], "CURVE: iord (argument 2) is %d: the"
                           " coordinate (0) or its first (1) or second (2) derivative", ids[1]);
        if (ids[2] < 1 || ids[2] > 3)
            return fail_at(p, places[4], places[5], "CURVE: comp (argument 3) is %d: 1, 2 or 3"
                           " (x, y or z)", ids[2]);
        if ((k = add_node(p, HX_NODE_CURVE, code, line, column)) < 0 ||
            set_children(p, k, args, 1) != 0)
            return -1;
        memcpy(p->tree->nodes[k].ids, ids + 1, 3 * sizeof(int));
        p->tree->nodes[k].nids = 3;
        return k;
    case HX_FK_LOAD:
    case HX_FK_REACTION: /* (id, jflag, comp, rm) */
        /* a coupler's jflag 2k, 2k + 1: the I and J markers of its joint k + 1 */
        if (code == HX_FN_COUPLER && ids[1] > 5)
            return fail_at(p, places[2], places[3], "COUPLER: jflag (argument 2) is %d: 0 to 5"
                           " (on the I or J marker of the coupler's first, second or third"
                           " joint, at it)", ids[1]);
        if (code == HX_FN_GCON && ids[1] != 0)
            return fail_at(p, places[2], places[3], "GCON: jflag (argument 2) is %d: 0 (on its"
                           " I marker, at it; a general constraint has no J marker)", ids[1]);
        if (code != HX_FN_COUPLER && ids[1] > 1)
            return fail_at(p, places[2], places[3], "%s: jflag (argument 2) is %d: 0 (on the I"
                           " marker, at it) or 1 (on the J marker, at it)", f->name, ids[1]);
        if (ids[2] < 1 || ids[2] > 8)
            return fail_at(p, places[4], places[5], "%s: comp (argument 3) is %d: 1 to 8 (FM, FX,"
                           " FY, FZ, TM, TX, TY, TZ)", f->name, ids[2]);
        if ((k = add_node(p, HX_NODE_INPUT, code, line, column)) < 0)
            return -1;
        memcpy(p->tree->nodes[k].ids, ids, 4 * sizeof(int));
        p->tree->nodes[k].nids = count;
        return k;
    case HX_FK_ACCELERATION:
    case HX_FK_MARKER_FORCE:
    case HX_FK_MEASURE:
        if (code == HX_FN_ORIENT && orient_arguments(p, ids, places) != 0)
            return -1;
        if (code != HX_FN_ORIENT && ids[0] == 0)
            return fail_at(p, places[0], places[1], "%s: its I marker is 0: I names a marker"
                           " (0 stands for the ground's origin only in the later places)",
                           f->name);
        /* fall through */
    case HX_FK_VARVAL:
    case HX_FK_DIF:
    case HX_FK_DIF1:
    case HX_FK_ARYVAL:
        if (f->kind == HX_FK_ARYVAL && ids[1] < 1)
            return fail_at(p, places[2], places[3], "ARYVAL: its component (argument 2) counts"
                           " from 1, not %d", ids[1]);
        if ((k = add_node(p, HX_NODE_INPUT, code, line, column)) < 0)
            return -1;
        memcpy(p->tree->nodes[k].ids, ids, 4 * sizeof(int));
        p->tree->nodes[k].nids = count;
        return k;
    case HX_FK_IF: /* if_call, above */
        break;
    }
    return -1;
}

/* A name: a constant, TIME, or a call. */
static int name(parser *p)
{
    const hx_expr_token n = p->token;
    next(p);
    const int code = hx_expr_function_find(n.name);
    const int long_name = n.length > HX_EXPR_NAME_MAX;
    if (p->token.kind == HX_TOKEN_OPEN) {
        if (strcmp(n.name, "USER") == 0 && !long_name)
            return fail_at(p, n.line, n.column, "USER(...) is not an expression: it is the list"
                           " of parameters of a user subroutine, which the model's reader"
                           " passes to the routine itself");
        if (code < 0 || long_name) {
            if (!long_name && (strcmp(n.name, "PI") == 0 || strcmp(n.name, "DTOR") == 0 ||
                               strcmp(n.name, "RTOD") == 0 || strcmp(n.name, "TIME") == 0))
                return fail_at(p, n.line, n.column, "%s is a constant, not a function", n.name);
            return fail_at(p, n.line, n.column, "unknown function %s%s", n.name,
                           long_name ? "..." : "");
        }
        next(p);
        return known_call(p, code, &n);
    }
    if (!long_name) {
        if (strcmp(n.name, "PI") == 0)
            return add_number(p, M_PI, n.line, n.column);
        if (strcmp(n.name, "DTOR") == 0)
            return add_number(p, M_PI / 180.0, n.line, n.column);
        if (strcmp(n.name, "RTOD") == 0)
            return add_number(p, 180.0 / M_PI, n.line, n.column);
        if (strcmp(n.name, "TIME") == 0)
            return add_node(p, HX_NODE_TIME, -1, n.line, n.column);
    }
    if (code >= 0) {
        const hx_expr_function *f = hx_expr_function_at(code);
        return fail_at(p, n.line, n.column, "%s is a function: write %s%s", f->name, f->name,
                       f->arguments);
    }
    return fail_at(p, n.line, n.column, "unknown name %s%s (the constants are PI, DTOR, RTOD"
                   " and TIME)", n.name, long_name ? "..." : "");
}

static int primary(parser *p)
{
    switch (p->token.kind) {
    case HX_TOKEN_NUMBER: {
        const int k = add_number(p, p->token.number, p->token.line, p->token.column);
        next(p);
        return k;
    }
    case HX_TOKEN_NAME: return name(p);
    case HX_TOKEN_OPEN: {
        const hx_expr_token open = p->token;
        next(p);
        const int k = expression(p);
        if (k < 0)
            return -1;
        if (p->token.kind != HX_TOKEN_CLOSE) {
            if (p->token.kind == HX_TOKEN_ERROR)
                return token_error(p);
            char found[96];
            return fail_at(p, p->token.line, p->token.column,
                           "missing ')' to close the '(' at %d:%d, found %s", open.line,
                           open.column, hx_expr_token_text(&p->token, found, sizeof found));
        }
        next(p);
        return k;
    }
    default: return expected(p, "a number, a name or '('");
    }
}

static int signed_power(parser *p);

static int power(parser *p)
{
    const int base = primary(p);
    if (base < 0 || p->token.kind != HX_TOKEN_POWER)
        return base;
    const hx_expr_token op = p->token;
    next(p);
    const int exponent = signed_power(p); /* right to left: 2**3**2 = 2**(3**2) */
    if (exponent < 0)
        return -1;
    const int args[2] = {base, exponent};
    return call(p, HX_FN_POW, args, 2, op.line, op.column);
}

static int signed_power(parser *p)
{
    if (++p->nesting > MAX_NESTING)
        return fail_at(p, p->token.line, p->token.column, "the expression nests deeper than %d"
                       " levels", MAX_NESTING);
    int k;
    if (p->token.kind == HX_TOKEN_MINUS || p->token.kind == HX_TOKEN_PLUS) {
        const hx_expr_token sign = p->token;
        next(p);
        k = signed_power(p); /* the sign takes the power after it: -2**2 = -(2**2) */
        if (k >= 0 && sign.kind == HX_TOKEN_MINUS)
            k = call(p, HX_FN_NEG, &k, 1, sign.line, sign.column);
    } else {
        k = power(p);
    }
    --p->nesting;
    return k;
}

static int term(parser *p)
{
    int k = signed_power(p);
    while (k >= 0 && (p->token.kind == HX_TOKEN_STAR || p->token.kind == HX_TOKEN_SLASH)) {
        const hx_expr_token op = p->token;
        next(p);
        const int right = signed_power(p);
        if (right < 0)
            return -1;
        const int args[2] = {k, right};
        k = call(p, op.kind == HX_TOKEN_STAR ? HX_FN_MUL : HX_FN_DIV, args, 2, op.line,
                 op.column);
    }
    return k;
}

static int expression(parser *p)
{
    int k = term(p);
    while (k >= 0 && (p->token.kind == HX_TOKEN_PLUS || p->token.kind == HX_TOKEN_MINUS)) {
        const hx_expr_token op = p->token;
        next(p);
        const int right = term(p);
        if (right < 0)
            return -1;
        const int args[2] = {k, right};
        k = call(p, op.kind == HX_TOKEN_PLUS ? HX_FN_ADD : HX_FN_SUB, args, 2, op.line,
                 op.column);
    }
    return k;
}

int hx_expr_tree_parse(hx_expr_tree *tree, const char *text, size_t length,
                       const hx_expr_source *where, hx_message *msg)
{
    memset(tree, 0, sizeof *tree);
    tree->root = -1;
    parser p = {.tree = tree, .where = where, .msg = msg};
    hx_expr_lexer_init(&p.lexer, text != NULL ? text : "", text != NULL ? length : 0,
                       where->line, where->column);
    hx_expr_lex(&p.lexer, &p.token);
    if (p.token.kind == HX_TOKEN_END)
        return fail_at(&p, p.token.line, p.token.column, "empty expression");
    const int root = expression(&p);
    if (root < 0)
        return -1;
    if (p.token.kind == HX_TOKEN_ERROR)
        return token_error(&p);
    if (p.token.kind == HX_TOKEN_CLOSE)
        return fail_at(&p, p.token.line, p.token.column, "')' without a '(' to close");
    if (p.token.kind == HX_TOKEN_COLON)
        return fail_at(&p, p.token.line, p.token.column, "':' belongs in IF(e1: e2, e3, e4)"
                       " only");
    if (p.token.kind != HX_TOKEN_END) {
        char found[96];
        return fail_at(&p, p.token.line, p.token.column, "%s where an operator or the end was"
                       " expected", hx_expr_token_text(&p.token, found, sizeof found));
    }
    tree->root = root;
    return 0;
}

void hx_expr_tree_free(hx_expr_tree *tree)
{
    free(tree->nodes);
    free(tree->kids);
    memset(tree, 0, sizeof *tree);
}
