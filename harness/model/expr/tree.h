/*
 * The parse tree of a function expression, built by the parser
 * (parser.c) and turned into the compact program (compile.c); it lives only
 * while a text is parsed. Constants are folded as the tree is built.
 */
#ifndef HX_MODEL_EXPR_TREE_H
#define HX_MODEL_EXPR_TREE_H

#include "model/expr/expr.h"

typedef enum hx_expr_node_kind {
    HX_NODE_NUMBER,     /* value */
    HX_NODE_TIME,
    HX_NODE_CALL,       /* an operator or pure function of its children */
    HX_NODE_IF,         /* IF of its four children */
    HX_NODE_INPUT,      /* a measure, VARVAL, DIF, DIF1 or ARYVAL of ids */
    HX_NODE_SPLINE,     /* AKISPL or CUBSPL of children x, z; ids: the spline, iord */
    HX_NODE_CURVE       /* CURVE of child alpha; ids: iord, comp, the curve */
} hx_expr_node_kind;

typedef struct hx_expr_node {
    hx_expr_node_kind kind;
    int function;     /* model/expr/functions.h's code */
    double value;
    int first, count; /* the children: kids[first .. first + count - 1] */
    int ids[4], nids; /* the whole-number arguments */
    int depth;        /* 1 plus its deepest child's */
    int line, column; /* the operator's or the function name's place */
} hx_expr_node;

/* The deepest tree the parser builds (a sum of 4000 terms that do not fold);
 * the program is emitted from it by recursion. */
#define HX_EXPR_MAX_TREE_DEPTH 4000

typedef struct hx_expr_tree {
    hx_expr_node *nodes;
    int nnodes, node_capacity;
    int *kids;
    int nkids, kid_capacity;
    int root;
} hx_expr_tree;

/* Parses text into tree (freed with hx_expr_tree_free whatever happens).
 * Returns 0, or -1 with "file:line:column: what" in msg. */
int hx_expr_tree_parse(hx_expr_tree *tree, const char *text, size_t length,
                       const hx_expr_source *where, hx_message *msg);
void hx_expr_tree_free(hx_expr_tree *tree);

#endif
