/* A Force_StateEqn's inputs at a state (state_inputs.h). */
#include "host/state_inputs.h"

#include <stdio.h>

#include "expr/evaluate.h"
#include "host/queries.h"

int hx_variable_value(const hx_frames *fr, const hx_variable *v, double *value)
{
    if (v->function[0] == '\0') {
        *value = v->number;
        return 0;
    }
    double answer;
    if (hx_answer_query(fr, v->function, v->marker_ids, v->nmarkers, 0, &answer) != 1)
        return -1;
    *value = v->sign * answer;
    return 0;
}

/* A measure family's three values at one set of markers, computed once for
 * the inputs that share them (the usual U array asks DX, DY, DZ of the same
 * markers, and so on): a twelfth of the frames and angles. */
typedef struct family_values {
    char family;
    int ids[4];
    double v[3];
} family_values;

static int component(const hx_variable *v)
{
    return v->function[1] == 'X' ? 0 : v->function[1] == 'Y' ? 1 : v->function[1] == 'Z' ? 2 : -1;
}

int hx_stateeqn_inputs(const hx_frames *fr, int element, double *u)
{
    const hx_model *m = fr->model;
    const hx_stateeqn *f = &m->stateeqns[element];
    family_values known[8];
    int nknown = 0;
    for (int i = 0; i < f->ninput; ++i) {
        const hx_variable *v = &m->variables[f->inputs[i]];
        if (v->varsub) { /* its VARSUB's, which the variables' stage computed at fr */
            u[i] = fr->variables[f->inputs[i]];
            continue;
        }
        if (v->program != NULL) { /* an expression of TIME and measures (§7.10) */
            const hx_expr_context c = {fr, NULL, NULL};
            hx_expr_fault fault;
            if (hx_expr_eval(v->program, &c, &u[i], &fault) != 0)
                return -1;
            continue;
        }
        const int axis = v->function[0] != '\0' ? component(v) : -1;
        if (axis < 0) { /* a number, or DM */
            if (hx_variable_value(fr, v, &u[i]) != 0)
                return -1;
            continue;
        }
        int k = 0;
        while (k < nknown && !(known[k].family == v->function[0] && known[k].ids[0] == v->marker_ids[0] &&
                               known[k].ids[1] == v->marker_ids[1] && known[k].ids[2] == v->marker_ids[2] &&
                               known[k].ids[3] == v->marker_ids[3]))
            ++k;
        if (k == nknown) {
            if (nknown == 8)
                k = 7; /* more families than expected: recompute in the last slot */
            else
                ++nknown;
            known[k].family = v->function[0];
            for (int j = 0; j < 4; ++j)
                known[k].ids[j] = v->marker_ids[j];
            if (hx_answer_family(fr, v->function[0], v->marker_ids, known[k].v) != 0)
                return -1;
        }
        u[i] = v->sign * known[k].v[axis];
    }
    return 0;
}

int hx_stateeqn_inputs_why(const hx_frames *fr, int element, hx_message *msg)
{
    const hx_model *m = fr->model;
    const hx_stateeqn *f = &m->stateeqns[element];
    for (int i = 0; i < f->ninput; ++i) {
        const hx_variable *v = &m->variables[f->inputs[i]];
        double value;
        if (v->program != NULL) {
            const hx_expr_context c = {fr, NULL, NULL};
            hx_expr_fault fault;
            if (hx_expr_eval(v->program, &c, &value, &fault) != 0) {
                char element_name[48];
                snprintf(element_name, sizeof element_name, "Reference_Variable %d", v->id);
                return hx_expr_fail(msg, v->program, &fault, element_name);
            }
        } else if (hx_variable_value(fr, v, &value) != 0)
            return hx_fail(msg, "%s:%d: Reference_Variable %d: not answered", m->path, v->line,
                           v->id);
    }
    return hx_fail(msg, "an input could not be measured");
}

int hx_variable_is_angle(const hx_variable *v)
{
    return v->function[0] == 'A';
}
