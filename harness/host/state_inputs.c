/* A Force_StateEqn's inputs at a state (state_inputs.h). */
#include "host/state_inputs.h"

#include "host/queries.h"

int hx_variable_value(const hx_state *s, const hx_variable *v, double *value)
{
    if (v->function[0] == '\0') {
        *value = v->number;
        return 0;
    }
    double answer;
    if (hx_answer_query(s, v->function, v->marker_ids, v->nmarkers, 0, &answer) != 1)
        return -1;
    *value = v->sign * answer;
    return 0;
}

int hx_state_eqn_inputs(const hx_state *s, int element, double *u)
{
    const hx_model *m = s->model;
    const hx_state_eqn *f = &m->state_eqns[element];
    for (int i = 0; i < f->ninput; ++i)
        if (hx_variable_value(s, &m->variables[f->inputs[i]], &u[i]) != 0)
            return -1;
    return 0;
}

int hx_variable_is_angle(const hx_variable *v)
{
    return v->function[0] == 'A';
}
