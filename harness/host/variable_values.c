/* The variables' values at frames (variable_values.h). */
#include "host/variable_values.h"

#include <math.h>
#include <stdio.h>

#include "expr/evaluate.h"
#include "host/invoke.h"
#include "host/state_inputs.h"

/* A USERSUB variable's value: its VARSUB called at fr, which reads the
 * values computed before it (the order puts those it declared first). */
static int varsub_value(const hx_frames *fr, hx_binding *const *routines, const hx_variable *v,
                        double *value, hx_message *msg)
{
    const hx_model *m = fr->model;
    hx_binding *b = routines != NULL ? routines[v->routine] : NULL;
    if (b == NULL)
        return hx_fail(msg, "%s:%d: Reference_Variable %d: its VARSUB is not bound here",
                       m->path, v->line, v->id);
    hx_invoke_routine(b, fr, 0, 0, value, NULL);
    if (!isfinite(*value))
        return hx_fail(msg, "%s:%d: Reference_Variable %d (%s) returned a non-finite value at"
                       " t = %g", m->path, v->line, v->id, hx_binding_routine(b, 0), fr->time);
    return 0;
}

int hx_variables_values(const hx_frames *fr, hx_binding *const *routines, double *values,
                        hx_message *msg)
{
    const hx_model *m = fr->model;
    const hx_expr_context c = {fr, values, NULL};
    for (int i = 0; i < m->nvariables; ++i) {
        const int k = m->variable_order != NULL ? m->variable_order[i] : i;
        const hx_variable *v = &m->variables[k];
        if (v->varsub) {
            if (varsub_value(fr, routines, v, &values[k], msg) != 0)
                return -1;
            continue;
        }
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
