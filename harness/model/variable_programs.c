/*
 * The Reference_Variable elements given by expressions (docs/interface.md
 * §7.10, §8): each program linked against the whole model, and the order the
 * variables are computed in, found once from what each reads (VARVAL, ARYVAL
 * of a U array), so that a right-hand side computes each once, after those it
 * reads. A cycle (an algebraic loop) is refused naming each variable in it.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "model/draft.h"
#include "model/expr/expr.h"
#include "model/load_elements.h"
#include "model/variable_definitions.h"

static int link_one(hx_draft *d, hx_variable *v)
{
    hx_model *m = d->m;
    hx_message why;
    if (hx_expr_link_loop(v->program, m, &why) != 0) {
        hx_draft_fail_expression(d, "Reference_Variable", v->id, "expr", why.text);
        return -1;
    }
    const hx_expr_input *in = hx_expr_inputs(v->program);
    for (int k = 0; k < hx_expr_input_count(v->program); ++k) {
        if (in[k].kind == HX_EXPR_INPUT_DIF1) {
            /* the rate is computed after the variables, by the routines stage */
            char name[64], what[HX_MESSAGE_MAX];
            snprintf(what, sizeof what, "%s:%d:%d: %s: a variable reads a Control_Diff's state"
                     " (DIF), not its rate, which is computed after the variables",
                     d->path, in[k].line, in[k].column,
                     hx_expr_input_text(&in[k], name, sizeof name));
            hx_draft_fail_expression(d, "Reference_Variable", v->id, "expr", what);
            return -1;
        }
        if (in[k].kind == HX_EXPR_INPUT_MEASURE)
            for (int i = 0; i < in[k].nids && i < 4; ++i)
                if (in[k].index[i] >= 0)
                    m->markers[in[k].index[i]].tracked = 1;
    }
    return 0;
}

/* The order the variables are computed in (model.h's variable_order),
 * found as a run finds a redefined set's (variable_definitions.c), a cycle
 * refused naming each variable of it at the model's path as given. */
static int find_order(hx_draft *d)
{
    hx_model *m = d->m;
    hx_variable_definitions defs;
    hx_message why;
    if (hx_variable_definitions_of(&defs, m, &why) != 0) {
        hx_draft_fail(d, 0, "%s", why.text);
        return -1;
    }
    for (int k = 0; k < m->nvariables; ++k)
        defs.file[k] = d->path;
    m->variable_order = malloc(sizeof(int) * (size_t)(m->nvariables + 1));
    int first = -1;
    if (m->variable_order == NULL)
        hx_draft_fail(d, 0, "out of memory");
    else if (hx_variable_definitions_order(&defs, m, m->variable_order, &first, &why) != 0)
        hx_draft_fail(d, first >= 0 ? m->variables[first].line : 0, "%s", why.text);
    hx_variable_definitions_free(&defs);
    return d->failed ? -1 : 0;
}

int hx_draft_link_variables(hx_draft *d)
{
    hx_model *m = d->m;
    for (int k = 0; k < m->nvariables; ++k)
        if (m->variables[k].program != NULL && link_one(d, &m->variables[k]) != 0)
            return -1;
    return find_order(d);
}
