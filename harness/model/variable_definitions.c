/* A set of the variables' definitions (variable_definitions.h). */
#include "model/variable_definitions.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "model/expr/expr.h"

static int alloc(hx_variable_definitions *v, int n)
{
    memset(v, 0, sizeof *v);
    v->n = n;
    v->program = calloc((size_t)n + 1, sizeof *v->program);
    v->order = calloc((size_t)n + 1, sizeof(int));
    v->file = calloc((size_t)n + 1, sizeof *v->file);
    v->line = calloc((size_t)n + 1, sizeof(int));
    if (v->program == NULL || v->order == NULL || v->file == NULL || v->line == NULL) {
        hx_variable_definitions_free(v);
        return -1;
    }
    return 0;
}

int hx_variable_definitions_of(hx_variable_definitions *v, const hx_model *m, hx_message *msg)
{
    if (alloc(v, m->nvariables) != 0)
        return hx_fail(msg, "out of memory");
    for (int k = 0; k < m->nvariables; ++k) {
        v->program[k] = m->variables[k].program;
        v->order[k] = m->variable_order != NULL ? m->variable_order[k] : k;
        v->file[k] = m->path;
        v->line[k] = m->variables[k].line;
    }
    v->read_start = m->varsub_read_start;
    v->reads = m->varsub_reads;
    return 0;
}

int hx_variable_definitions_copy(hx_variable_definitions *to, const hx_variable_definitions *from,
                                 hx_message *msg)
{
    if (alloc(to, from->n) != 0)
        return hx_fail(msg, "out of memory");
    const size_t n = (size_t)from->n;
    memcpy(to->program, from->program, n * sizeof *to->program);
    memcpy(to->order, from->order, n * sizeof(int));
    memcpy(to->file, from->file, n * sizeof *to->file);
    memcpy(to->line, from->line, n * sizeof(int));
    to->read_start = from->read_start;
    to->reads = from->reads;
    return 0;
}

static int program_inputs(const hx_variable_definitions *v, int k)
{
    return v->program[k] == NULL ? 0 : hx_expr_input_count(v->program[k]);
}

/* The variable index variable k reads through its input j (its program's,
 * then its VARSUB's declared VARVALs), or -1. */
static int read_variable(const hx_variable_definitions *v, int k, int j)
{
    const int np = program_inputs(v, k);
    if (j < np)
        return hx_expr_inputs(v->program[k])[j].variable;
    return v->reads[v->read_start[k] + j - np];
}

static int count_inputs(const hx_variable_definitions *v, int k)
{
    const int declared = v->read_start != NULL ? v->read_start[k + 1] - v->read_start[k] : 0;
    return program_inputs(v, k) + declared;
}

/* A cycle among the variables not ordered (each of which reads one not
 * ordered): walk from one until a variable repeats, and name that loop into
 * msg, its first variable's index into *first; -1. */
static int refuse_cycle(const hx_variable_definitions *v, const hx_model *m,
                        const unsigned char *ordered, int *next, int *first, hx_message *msg)
{
    int k = 0;
    while (ordered[k])
        ++k;
    *first = k;
    unsigned char *seen = calloc((size_t)v->n + 1, 1);
    if (seen == NULL)
        return hx_fail(msg, "out of memory");
    while (!seen[k]) {
        seen[k] = 1;
        for (int j = 0; j < count_inputs(v, k); ++j) {
            const int r = read_variable(v, k, j);
            if (r >= 0 && !ordered[r]) {
                next[k] = r;
                break;
            }
        }
        k = next[k];
    }
    free(seen);
    char text[HX_MESSAGE_MAX] = "";
    size_t used = 0;
    *first = k;
    do {
        used += (size_t)snprintf(text + used, used < sizeof text ? sizeof text - used : 0,
                                 "%s%s:%d: Reference_Variable %d%s reads VARVAL(%d)",
                                 k == *first ? "" : ", ", v->file[k], v->line[k],
                                 m->variables[k].id, m->variables[k].varsub ? " (its VARSUB)" : "",
                                 m->variables[next[k]].id);
        k = next[k];
    } while (k != *first && used < sizeof text);
    return hx_fail(msg, "a cycle of variables (an algebraic loop, which the harness does not"
                   " solve): %s", text);
}

/* Passes over the unordered until none joins: a variable joins once all it
 * reads have (the variables are few; this runs before a run). */
int hx_variable_definitions_order(const hx_variable_definitions *v, const hx_model *m, int *order,
                                  int *first, hx_message *msg)
{
    *first = -1;
    unsigned char *ordered = calloc((size_t)v->n + 1, 1);
    int *next = calloc((size_t)v->n + 1, sizeof(int));
    if (ordered == NULL || next == NULL) {
        free(ordered), free(next);
        return hx_fail(msg, "out of memory");
    }
    int count = 0;
    for (int added = 1; added && count < v->n;) {
        added = 0;
        for (int k = 0; k < v->n; ++k) {
            if (ordered[k])
                continue;
            int ready = 1;
            for (int j = 0; j < count_inputs(v, k) && ready; ++j) {
                const int r = read_variable(v, k, j);
                ready = r < 0 || ordered[r];
            }
            if (ready) {
                ordered[k] = 1;
                order[count++] = k;
                added = 1;
            }
        }
    }
    const int status = count < v->n ? refuse_cycle(v, m, ordered, next, first, msg) : 0;
    free(ordered), free(next);
    return status;
}

int hx_variable_definitions_redefine(hx_variable_definitions *v, const hx_model *m, int k,
                                     hx_expr_program *p, const char *file, int line,
                                     hx_message *msg)
{
    const hx_expr_input *in = hx_expr_inputs(p);
    for (int j = 0; j < hx_expr_input_count(p); ++j)
        if (in[j].kind == HX_EXPR_INPUT_DIF1) {
            /* the rates are computed after the variables (docs/interface.md §7.10) */
            char name[64];
            return hx_fail(msg, "%s:%d:%d: %s: a variable reads a Control_Diff's state (DIF),"
                           " not its rate, which is computed after the variables", file,
                           in[j].line, in[j].column, hx_expr_input_text(&in[j], name, sizeof name));
        }
    int *order = malloc(sizeof(int) * ((size_t)v->n + 1));
    if (order == NULL)
        return hx_fail(msg, "out of memory");
    hx_expr_program *before = v->program[k];
    const char *before_file = v->file[k];
    const int before_line = v->line[k];
    v->program[k] = p;
    v->file[k] = file;
    v->line[k] = line;
    int first;
    if (hx_variable_definitions_order(v, m, order, &first, msg) != 0) {
        v->program[k] = before;
        v->file[k] = before_file;
        v->line[k] = before_line;
        free(order);
        return -1;
    }
    memcpy(v->order, order, sizeof(int) * (size_t)v->n);
    free(order);
    return 0;
}

void hx_variable_definitions_apply(const hx_variable_definitions *v, const hx_model *m)
{
    /* the model's variables and their order are arrays it points to: a run
     * changes them between segments as it does the loads' flags */
    for (int k = 0; k < v->n && k < m->nvariables; ++k)
        m->variables[k].program = v->program[k];
    if (m->variable_order != NULL)
        memcpy(m->variable_order, v->order, sizeof(int) * (size_t)v->n);
}

void hx_variable_definitions_free(hx_variable_definitions *v)
{
    free(v->program);
    free(v->order);
    free(v->file);
    free(v->line);
    memset(v, 0, sizeof *v);
}
