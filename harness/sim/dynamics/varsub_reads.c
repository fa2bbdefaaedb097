/* What a VARSUB declared it reads (varsub_reads.h). */
#include "sim/dynamics/varsub_reads.h"

int hx_varsub_reads(const hx_dynamics *d, int k, enum hx_query_reads reads, int *out, int max)
{
    const hx_model *m = d->m;
    const hx_variable *v = &m->variables[k];
    const hx_binding *b = v->varsub ? d->routine_binding[v->routine] : NULL;
    int n = 0;
    for (int i = 0; b != NULL && i < b->deps.count; ++i) {
        const hx_query *q = &b->deps.query[i];
        if (hx_query_reads(q) != (int)reads)
            continue;
        if (reads == HX_READS_DIFF) {
            const int r = hx_model_routine(m, HX_ROUTINE_DIFF, q->ipar[0]);
            if (r >= 0 && n < max)
                out[n++] = m->routines[r].slot;
            continue;
        }
        for (int j = 0; j < q->nsize && j < 4; ++j) {
            const int marker = q->ipar[j] != 0 ? hx_model_marker(m, q->ipar[j]) : -1;
            if (marker >= 0 && n < max)
                out[n++] = marker;
        }
    }
    return n;
}
