/* Call records (call.h); the binding itself lives with the utilities (abi.c). */
#include "host/call.h"

#include <string.h>

void hx_call_init(hx_call *c, const char *element, int id, const char *routine,
                  const hx_model *model, const hx_frames *fr, hx_messages *messages,
                  int dependency_pass, hx_dependencies *declared)
{
    /* field by field: the noted queries' arrays are read only up to their
     * counts, and clearing them would cost more than most calls */
    c->undeclared.count = c->undeclared.distinct = 0;
    c->refused.count = c->refused.distinct = 0;
    c->reported_undeclared = c->reported_refused = NULL;
    c->unoffered = c->misused = c->non_finite = 0;
    c->reported_unoffered = c->reported_misused = c->reported_non_finite = NULL;
    c->host_calls = 0;
    c->used = 0;
    c->next_declared = 0;
    c->perturb_component = 0;
    c->perturb_delta = 0.0;
    c->element = element;
    c->id = id;
    c->routine = routine;
    c->model = model;
    c->frames = fr;
    c->messages = messages;
    c->may_query = 1;
    c->dependency_pass = dependency_pass;
    c->declared = declared;
    c->perturb_query = -1;
    c->loop_slot = NULL;
    c->at_output = 0;
    c->answers = NULL;
    if (dependency_pass && declared != NULL)
        memset(declared, 0, sizeof *declared);
}

const char *hx_dependencies_text(const hx_dependencies *d, char *text, size_t size)
{
    if (d == NULL || d->count == 0) {
        snprintf(text, size, "none");
        return text;
    }
    size_t n = 0;
    text[0] = '\0';
    for (int k = 0; k < d->count && n < size; ++k) {
        char one[64];
        n += (size_t)snprintf(text + n, size - n, k ? " %s" : "%s",
                              hx_query_text(&d->query[k], one, sizeof one));
    }
    return text;
}

const char *hx_noted_text(const hx_noted_queries *q, char *text, size_t size)
{
    size_t n = 0;
    text[0] = '\0';
    for (int k = 0; k < q->distinct && n < size; ++k) {
        char one[64];
        n += (size_t)snprintf(text + n, size - n, k ? ", %s at t = %g" : "%s at t = %g",
                              hx_query_text(&q->query[k], one, sizeof one), q->time[k]);
    }
    if (q->count > 0 && q->distinct == HX_MAX_NOTED && n < size)
        snprintf(text + n, size - n, ", ...");
    return text;
}

int hx_note_query(hx_noted_queries *n, const hx_query *q, double time)
{
    n->count++;
    for (int k = 0; k < n->distinct; ++k)
        if (hx_query_same(&n->query[k], q))
            return 0;
    if (n->distinct < HX_MAX_NOTED) {
        n->query[n->distinct] = *q;
        n->time[n->distinct++] = time;
    }
    return 1;
}
