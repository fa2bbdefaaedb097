/* A parsed program's accessors, its inputs' names and its faults' text (expr.h). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "model/expr/functions.h"
#include "model/expr/program.h"

void hx_expr_free(hx_expr_program *p)
{
    if (p == NULL)
        return;
    free(p->ops);
    free(p->places);
    free(p->constants);
    free(p->inputs);
    free(p->calls);
    free(p->file);
    free(p);
}

int hx_expr_input_count(const hx_expr_program *p)
{
    return p->ninputs;
}

const hx_expr_input *hx_expr_inputs(const hx_expr_program *p)
{
    return p->inputs;
}

const char *hx_expr_input_text(const hx_expr_input *in, char *text, size_t size)
{
    if (in->kind == HX_EXPR_INPUT_TIME) {
        snprintf(text, size, "TIME");
        return text;
    }
    int n = snprintf(text, size, "%s(", hx_expr_function_at(in->function)->name);
    for (int k = 0; k < in->nids && n > 0 && (size_t)n < size; ++k)
        n += snprintf(text + n, size - (size_t)n, k ? ",%d" : "%d", in->ids[k]);
    if (n > 0 && (size_t)n < size)
        snprintf(text + n, size - (size_t)n, ")");
    return text;
}

int hx_expr_constant(const hx_expr_program *p, double *value)
{
    if (p->nops != 1 || p->ops[0].code != HX_OP_CONST)
        return 0;
    *value = p->constants[p->ops[0].a];
    return 1;
}

const char *hx_expr_file(const hx_expr_program *p)
{
    return p->file;
}

int hx_expr_op_count(const hx_expr_program *p)
{
    return p->nops;
}

int hx_expr_depth(const hx_expr_program *p)
{
    return p->depth;
}

int hx_expr_fail(hx_message *msg, const hx_expr_program *p, const hx_expr_fault *f,
                 const char *element)
{
    /* "element: 'op': what (value) at t = time", each part there when it is */
    char function[48] = "", argument[48] = "";
    const char *name = f->function != NULL ? f->function : "";
    if (name[0] != '\0')
        snprintf(function, sizeof function, strchr("+-*/", name[0]) != NULL ? "'%s': " : "%s: ",
                 name);
    if (f->has_argument)
        snprintf(argument, sizeof argument, " (%.12g)", f->argument);
    return hx_fail(msg, "%s:%d:%d: %s%s%s%s%s at t = %.12g", p->file, f->line, f->column,
                   element != NULL ? element : "", element != NULL ? ": " : "", function,
                   f->what, argument, f->time);
}
