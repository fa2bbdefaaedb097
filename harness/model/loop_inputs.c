/* The inputs of a model's algebraic loop (loop_inputs.h). */
#include "model/loop_inputs.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int is_loop_input(const hx_expr_input *in)
{
    return in->kind == HX_EXPR_INPUT_ACCELERATION || in->kind == HX_EXPR_INPUT_REACTION ||
           in->kind == HX_EXPR_INPUT_LOAD || in->kind == HX_EXPR_INPUT_MARKER_FORCE;
}

static int same(const hx_expr_input *a, const hx_expr_input *b)
{
    return a->kind == b->kind && a->function == b->function && a->measure == b->measure &&
           memcmp(a->ids, b->ids, sizeof a->ids) == 0;
}

/* What slot li stands for. */
static const hx_expr_input *input_of(const hx_loop_input *li)
{
    return li->program != NULL ? &hx_expr_inputs(li->program)[li->input] : &li->query;
}

/* Program p's loop inputs given their slots, new ones listed; 0 or -1. */
static int add_program(hx_model *m, hx_expr_program *p, const char *element, int id,
                       int *capacity)
{
    if (p == NULL)
        return 0;
    const hx_expr_input *in = hx_expr_inputs(p);
    for (int k = 0; k < hx_expr_input_count(p); ++k) {
        if (!is_loop_input(&in[k]))
            continue;
        int slot = 0;
        while (slot < m->nloop_inputs && !same(input_of(&m->loop_inputs[slot]), &in[k]))
            ++slot;
        if (slot == m->nloop_inputs) {
            if (m->nloop_inputs == *capacity) {
                const int grown = *capacity ? 2 * *capacity : 4;
                hx_loop_input *more = realloc(m->loop_inputs, sizeof *more * (size_t)grown);
                if (more == NULL)
                    return -1;
                m->loop_inputs = more, *capacity = grown;
            }
            hx_loop_input *li = &m->loop_inputs[m->nloop_inputs++];
            li->program = p, li->input = k;
            snprintf(li->element, sizeof li->element, "%s %d", element, id);
        }
        hx_expr_set_loop(p, k, slot);
    }
    return 0;
}

int hx_draft_find_loop_inputs(hx_draft *d)
{
    hx_model *m = d->m;
    int capacity = 0, status = 0;
    for (int k = 0; k < m->nloads && status == 0; ++k) {
        hx_load *l = &m->loads[k];
        hx_expr_program *programs[7] = {l->value,     l->force[0],  l->force[1], l->force[2],
                                        l->torque[0], l->torque[1], l->torque[2]};
        for (int i = 0; i < 7 && status == 0; ++i)
            status = add_program(m, programs[i], hx_load_element_name(l), l->id, &capacity);
    }
    for (int k = 0; k < m->nvariables && status == 0; ++k)
        status = add_program(m, m->variables[k].program, "Reference_Variable",
                             m->variables[k].id, &capacity);
    for (int k = 0; k < m->nroutines && status == 0; ++k)
        if (m->routines[k].kind == HX_ROUTINE_DIFF)
            status = add_program(m, m->routines[k].program, "Control_Diff", m->routines[k].id,
                                 &capacity);
    if (status != 0)
        hx_draft_fail(d, 0, "out of memory");
    return status;
}

int hx_model_loop_query(hx_model *m, const hx_expr_input *in, const char *text,
                        const char *element)
{
    for (int slot = 0; slot < m->nloop_inputs; ++slot)
        if (same(input_of(&m->loop_inputs[slot]), in))
            return slot;
    /* a few, once per session: grown one at a time */
    hx_loop_input *more =
        realloc(m->loop_inputs, sizeof *more * (size_t)(m->nloop_inputs + 1));
    if (more == NULL)
        return -1;
    m->loop_inputs = more;
    hx_loop_input *li = &m->loop_inputs[m->nloop_inputs];
    memset(li, 0, sizeof *li);
    li->query = *in;
    snprintf(li->text, sizeof li->text, "%s", text);
    snprintf(li->element, sizeof li->element, "%s", element);
    return m->nloop_inputs++;
}

int hx_model_output_query(hx_model *m, const hx_expr_input *in)
{
    for (int slot = 0; slot < m->noutput_queries; ++slot)
        if (same(&m->output_queries[slot], in))
            return slot;
    hx_expr_input *more =
        realloc(m->output_queries, sizeof *more * (size_t)(m->noutput_queries + 1));
    if (more == NULL)
        return -1;
    m->output_queries = more;
    m->output_queries[m->noutput_queries] = *in;
    return m->noutput_queries++;
}

const char *hx_loop_input_text(const hx_model *m, int k, char *text, size_t size)
{
    const hx_loop_input *li = &m->loop_inputs[k];
    char what[96];
    if (li->program != NULL)
        hx_expr_input_text(&hx_expr_inputs(li->program)[li->input], what, sizeof what);
    else
        snprintf(what, sizeof what, "%s", li->text);
    snprintf(text, size, "%s (%s)", what, li->element);
    return text;
}
