/* The variables' values at frames (variable_values.h). */
#include "host/variable_values.h"

#include <stdio.h>

#include "expr/evaluate.h"
#include "host/state_inputs.h"

int hx_variables_values(const hx_frames *fr, double *values, hx_message *msg)
{
    const hx_model *m = fr->model;
    const hx_expr_context c = {fr, values, NULL};
    for (int i = 0; i < m->nvariables; ++i) {
        const int k = m->variable_order != NULL ? m->variable_order[i] : i;
        const hx_variable *v = &m->variables[k];
        if (v->program == NULL) {
            if (hx_variable_value(fr, v, &values[k]) != 0)
                return hx_fail(msg, "%s:%d: Reference_Variable %d: not answered", m->path,
                               v->line, v->id);
            continue;
        }
        hx_expr_fault fault;
        if (hx_expr_eval(v->program, &c, &values[k], &fault) != 0) {
            char element[48];
            snprintf(element, sizeof element, "Reference_Variable %d", v->id);
            return hx_expr_fail(msg, v->program, &fault, element);
        }
    }
    return 0;
}
