/* The variables user routines read by c_sysfnc VARVAL (variable_reads.h). */
#include "host/variable_reads.h"

#include <stdlib.h>

#include "host/queries.h"
#include "model/variable_definitions.h"

/* Binding b's declared query k, a VARVAL: a routine that runs after the
 * variables' stage may read it; 0, or -1 with msg. */
static int allowed(const hx_model *m, const hx_binding *b, int k, hx_message *msg)
{
    if (b->kind == HX_BIND_VARIABLE || b->kind == HX_BIND_DIFF)
        return 0;
    char asked[40];
    hx_query_text(&b->deps.query[k], asked, sizeof asked);
    return hx_fail(msg, "%s:%d: %s %d (%s) declares %s in its dependency pass, which the host"
                   " answers only to a VARSUB or a DIFSUB (docs/interface.md §5.1)", m->path,
                   hx_binding_line(m, b), b->element, b->id, hx_binding_routine(b, 0), asked);
}

/* The VARSUBs' declared VARVALs as m's varsub_reads (by variable), and
 * whether any routine reads one into *read; 0 or -1 with msg. */
static int collect(hx_model *m, const hx_bindings *bs, int *read, hx_message *msg)
{
    int total = 0;
    *read = 0;
    for (int n = 0; n < bs->count; ++n)
        for (int k = 0; k < bs->items[n].deps.count; ++k)
            if (hx_query_reads(&bs->items[n].deps.query[k]) == HX_READS_VARIABLE) {
                if (allowed(m, &bs->items[n], k, msg) != 0)
                    return -1;
                *read = 1;
                ++total;
            }
    m->varsub_read_start = calloc((size_t)m->nvariables + 1, sizeof(int));
    m->varsub_reads = malloc(sizeof(int) * ((size_t)total + 1));
    if (m->varsub_read_start == NULL || m->varsub_reads == NULL)
        return hx_fail(msg, "out of memory");
    int used = 0;
    for (int v = 0; v < m->nvariables; ++v) {
        m->varsub_read_start[v] = used;
        const hx_variable *var = &m->variables[v];
        const hx_binding *b = NULL;
        for (int n = 0; var->varsub && n < bs->count && b == NULL; ++n)
            if (bs->items[n].kind == HX_BIND_VARIABLE && bs->items[n].index == var->routine)
                b = &bs->items[n];
        for (int k = 0; b != NULL && k < b->deps.count; ++k)
            if (hx_query_reads(&b->deps.query[k]) == HX_READS_VARIABLE)
                m->varsub_reads[used++] = hx_model_variable(m, b->deps.query[k].ipar[0]);
    }
    m->varsub_read_start[m->nvariables] = used;
    return 0;
}

int hx_bind_variable_reads(hx_model *m, const hx_bindings *bs, hx_message *msg)
{
    int read = 0;
    if (collect(m, bs, &read, msg) != 0)
        return -1;
    if (!read)
        return 0;
    m->variables_read = 1; /* computed at every right-hand side, before the forces */
    hx_variable_definitions defs;
    if (hx_variable_definitions_of(&defs, m, msg) != 0)
        return -1;
    int first = -1;
    const int status = hx_variable_definitions_order(&defs, m, m->variable_order, &first, msg);
    hx_variable_definitions_free(&defs);
    return status;
}
