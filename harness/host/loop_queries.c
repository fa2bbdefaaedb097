/* The accelerations and forces user routines ask, as loop inputs or, a
 * REQSUB's, as output queries (loop_queries.h). */
#include "host/loop_queries.h"

#include <stdio.h>
#include <string.h>

#include "model/expr/functions.h"
#include "model/loop_inputs.h"

/* Value `value` of query q (measure `measure`) as an expression's input. */
static void as_input(const hx_model *m, const hx_query *q, int measure, hx_expr_input *in)
{
    memset(in, 0, sizeof *in);
    in->kind = HX_EXPR_INPUT_ACCELERATION;
    in->function = HX_FN_ACCX + measure; /* the same order: ACCX .. WDTM */
    in->measure = measure;
    in->nids = q->nsize;
    for (int j = 0; j < 4; ++j) {
        in->ids[j] = q->ipar[j];
        in->index[j] = q->ipar[j] != 0 ? hx_model_marker(m, q->ipar[j]) : -1;
    }
    in->variable = in->loop = -1;
}

/* Force query q (function `function`) as an expression's input, linked;
 * 0, or -1 with why. */
static int as_force(const hx_model *m, const hx_query *q, int function, hx_expr_input *in,
                    char *why, size_t size)
{
    memset(in, 0, sizeof *in);
    const hx_expr_function_kind kind = hx_expr_function_at(function)->kind;
    in->kind = kind == HX_FK_REACTION ? HX_EXPR_INPUT_REACTION
               : kind == HX_FK_LOAD   ? HX_EXPR_INPUT_LOAD
                                      : HX_EXPR_INPUT_MARKER_FORCE;
    in->function = function;
    in->nids = q->nsize;
    for (int j = 0; j < 4; ++j)
        in->ids[j] = q->ipar[j];
    in->variable = in->loop = -1;
    return hx_expr_link_force(in, m, why, size);
}

/* Binding b's declared query k given its slots; 0 or -1 with msg. */
static int bind_query(hx_model *m, hx_binding *b, int k, hx_message *msg)
{
    const hx_query *q = &b->deps.query[k];
    int measures[6];
    const int force = hx_query_force(q);
    const int count = force >= 0 ? 1 : hx_query_accelerations(q, measures);
    if (count == 0)
        return 0;
    /* a request's REQSUB runs at output times, once the forces and accelerations are
     * known: what it reads closes no loop. Only routines that may query declare any
     * (a force, a request, a variable, a Control_Diff: host/binding.c) */
    const int at_output = b->kind == HX_BIND_REQUEST;
    const char *routine = hx_binding_routine(b, 0);
    char asked[40], text[64], element[64];
    hx_query_text(q, asked, sizeof asked);
    snprintf(element, sizeof element, "%s of %s %d", routine, b->element, b->id);
    for (int i = 0; i < count; ++i) {
        hx_expr_input in;
        char why[320];
        if (force < 0)
            as_input(m, q, measures[i], &in);
        else if (as_force(m, q, force, &in, why, sizeof why) != 0)
            return hx_fail(msg, "%s:%d: %s %d (%s) declares %s in its dependency pass: %s",
                           m->path, hx_binding_line(m, b), b->element, b->id, routine, asked,
                           why);
        if (count > 1)
            snprintf(text, sizeof text, "%s[%d]", asked, i + 1);
        else
            snprintf(text, sizeof text, "%s", asked);
        b->loop_slot[k][i] = at_output ? hx_model_output_query(m, &in)
                                       : hx_model_loop_query(m, &in, text, element);
        if (b->loop_slot[k][i] < 0)
            return hx_fail(msg, "out of memory");
    }
    return 0;
}

int hx_bind_loop_queries(hx_model *m, hx_bindings *bs, hx_message *msg)
{
    for (int n = 0; n < bs->count; ++n)
        for (int k = 0; k < bs->items[n].deps.count; ++k)
            if (bind_query(m, &bs->items[n], k, msg) != 0)
                return -1;
    return 0;
}
