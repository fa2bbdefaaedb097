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

/* The variable index program k reads through input j, or -1. */
static int read_variable(const hx_model *m, int k, int j)
{
    const hx_expr_program *p = m->variables[k].program;
    return p == NULL ? -1 : hx_expr_inputs(p)[j].variable;
}

static int count_inputs(const hx_model *m, int k)
{
    const hx_expr_program *p = m->variables[k].program;
    return p == NULL ? 0 : hx_expr_input_count(p);
}

static int link_one(hx_draft *d, hx_variable *v)
{
    hx_model *m = d->m;
    hx_message why;
    if (hx_expr_link(v->program, m, &why) != 0) {
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
        if (in[k].kind == HX_EXPR_INPUT_DIF)
            v->reads_diff = 1;
        if (in[k].kind == HX_EXPR_INPUT_MEASURE)
            for (int i = 0; i < in[k].nids && i < 4; ++i)
                if (in[k].index[i] >= 0)
                    m->markers[in[k].index[i]].tracked = 1;
    }
    return 0;
}

/* A cycle among the variables not ordered (each of which reads one not
 * ordered): walk from one until a variable repeats, and name that loop. */
static void refuse_cycle(hx_draft *d, const unsigned char *ordered)
{
    const hx_model *m = d->m;
    int start = 0;
    while (ordered[start])
        ++start;
    int *next = malloc(sizeof(int) * (size_t)m->nvariables);
    int *seen = calloc((size_t)m->nvariables, sizeof(int));
    if (next == NULL || seen == NULL) {
        free(next), free(seen);
        hx_draft_fail(d, m->variables[start].line, "out of memory");
        return;
    }
    int k = start, step = 0;
    while (!seen[k]) {
        seen[k] = ++step;
        for (int j = 0; j < count_inputs(m, k); ++j) {
            const int r = read_variable(m, k, j);
            if (r >= 0 && !ordered[r]) {
                next[k] = r;
                break;
            }
        }
        k = next[k];
    }
    char text[HX_MESSAGE_MAX] = "";
    size_t used = 0;
    const int first = k;
    do {
        const hx_variable *v = &m->variables[k];
        used += (size_t)snprintf(text + used, used < sizeof text ? sizeof text - used : 0,
                                 "%s%s:%d: Reference_Variable %d reads VARVAL(%d)",
                                 k == first ? "" : ", ", d->path, v->line, v->id,
                                 m->variables[next[k]].id);
        k = next[k];
    } while (k != first && used < sizeof text);
    hx_draft_fail(d, m->variables[first].line, "a cycle of variables (an algebraic loop, which"
                  " the harness does not solve): %s", text);
    free(next), free(seen);
}

int hx_draft_link_variables(hx_draft *d)
{
    hx_model *m = d->m;
    for (int k = 0; k < m->nvariables; ++k)
        if (m->variables[k].program != NULL && link_one(d, &m->variables[k]) != 0)
            return -1;
    m->variable_order = malloc(sizeof(int) * (size_t)(m->nvariables + 1));
    unsigned char *ordered = calloc((size_t)m->nvariables + 1, 1);
    if (m->variable_order == NULL || ordered == NULL) {
        free(ordered);
        hx_draft_fail(d, 0, "out of memory");
        return -1;
    }
    /* passes over the unordered until none is added: a variable joins once all it
     * reads have (the models' variables are few; this runs once) */
    int count = 0;
    for (int added = 1; added && count < m->nvariables;) {
        added = 0;
        for (int k = 0; k < m->nvariables; ++k) {
            if (ordered[k])
                continue;
            int ready = 1;
            for (int j = 0; j < count_inputs(m, k) && ready; ++j) {
                const int r = read_variable(m, k, j);
                ready = r < 0 || ordered[r];
            }
            if (!ready)
                continue;
            hx_variable *v = &m->variables[k];
            for (int j = 0; j < count_inputs(m, k); ++j) {
                const int r = read_variable(m, k, j);
                if (r >= 0 && m->variables[r].reads_diff)
                    v->reads_diff = 1;
            }
            ordered[k] = 1;
            m->variable_order[count++] = k;
            added = 1;
        }
    }
    if (count < m->nvariables)
        refuse_cycle(d, ordered);
    free(ordered);
    return d->failed ? -1 : 0;
}
