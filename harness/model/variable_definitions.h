/*
 * A set of definitions of a model's Reference_Variable elements
 * (docs/interface.md §9.9): the program each is computed by (the model's own,
 * or one a command file's VARIABLE/id, FUNCTION= gave for some segments) and
 * the order they are computed in, each after those it reads, found again for
 * the set, a cycle of VARVALs refused naming each variable of it. A run puts
 * a set in force in the model between its segments (and the model's own back
 * however it ends), so that every reader of the variables (their values, the
 * bodies a load reads through them) reads the segment's.
 */
#ifndef HX_MODEL_VARIABLE_DEFINITIONS_H
#define HX_MODEL_VARIABLE_DEFINITIONS_H

#include "base/message.h"
#include "model/model.h"

typedef struct hx_variable_definitions {
    int n;                     /* the model's nvariables */
    hx_expr_program **program; /* per variable: its program (NULL: its measure or number) */
    int *order;                /* the variables' indices, each after those it reads */
    const char **file;         /* per variable: where it is defined (for a cycle's message) */
    int *line;
    const int *read_start;     /* the model's varsub_read_start and varsub_reads (model.h): */
    const int *reads;          /* what the VARSUBs read, which no redefinition changes */
} hx_variable_definitions;

/* The definitions in force in m now (the model's own, before a run); 0 or -1. */
int hx_variable_definitions_of(hx_variable_definitions *v, const hx_model *m, hx_message *msg);
/* A copy of from into to; 0 or -1. */
int hx_variable_definitions_copy(hx_variable_definitions *to, const hx_variable_definitions *from,
                                 hx_message *msg);
/* Variable index k defined by p (linked against m; not taken over), written
 * at file:line; the order found again. 0, or -1 with why in msg: p reads a
 * rate (DIF1), or a cycle of VARVALs, each variable of it with its file:line
 * ("run.acf:4: Reference_Variable 1 reads VARVAL(2), m.adm:7:
 * Reference_Variable 2 reads VARVAL(1)"); v then keeps its order before. */
int hx_variable_definitions_redefine(hx_variable_definitions *v, const hx_model *m, int k,
                                     hx_expr_program *p, const char *file, int line,
                                     hx_message *msg);
/* The order of v's variables into order (v->n of them), each after those it
 * reads (the model reader's and a run's alike); 0, or -1 with why in msg (a
 * cycle of VARVALs, each variable of it with its file:line) and the index of
 * the cycle's first named variable in *first (-1 if out of memory first). */
int hx_variable_definitions_order(const hx_variable_definitions *v, const hx_model *m, int *order,
                                  int *first, hx_message *msg);
/* Puts v in force in m (its variables' programs and order): between a run's
 * segments only, when nothing evaluates. */
void hx_variable_definitions_apply(const hx_variable_definitions *v, const hx_model *m);
void hx_variable_definitions_free(hx_variable_definitions *v);

#endif
