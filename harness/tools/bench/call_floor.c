/* The floor under an entry's cost (call_floor.h). */
#include "tools/bench/call_floor.h"

#include <dlfcn.h>

void STDCALL hx_floor_empty_entry(int *id, double *time, double *par, int *npar, int *dflag,
                                  int *iflag, double *result)
{
    (void)id, (void)time, (void)par, (void)npar, (void)dflag, (void)iflag, (void)result;
    __asm__ volatile("" ::: "memory"); /* a call the compiler cannot see through */
}

int hx_empty_call_init(hx_empty_call *e, hx_message *msg)
{
    void *self = dlopen(NULL, RTLD_NOW);
    void *fn = self != NULL ? dlsym(self, "hx_floor_empty_entry") : NULL;
    if (fn == NULL)
        return hx_fail(msg, "bench: the empty entry of the floor is not exported (%s)",
                       dlerror() != NULL ? "dlsym failed" : "no handle");
    e->fn = (usrsub_gfosub_fn *)fn;
    return 0;
}

void hx_run_empty_call(void *ctx, long calls)
{
    hx_empty_call *e = ctx;
    int id = 1, npar = 0, dflag = 0, iflag = 0;
    double time = 0.0;
    for (long k = 0; k < calls; ++k)
        e->fn(&id, &time, NULL, &npar, &dflag, &iflag, e->out);
}

void hx_host_replay_init(hx_host_replay *r, hx_call *evaluation)
{
    r->call = evaluation;
    r->count = 0;
    r->sink = 0.0;
    const hx_dependencies *d = evaluation->declared;
    for (int k = 0; d != NULL && k < d->count; ++k)
        if (evaluation->used & (1u << k))
            r->query[r->count++] = d->query[k];
}

void hx_run_host_replay(void *ctx, long calls)
{
    hx_host_replay *r = ctx;
    double values[6], sink = 0.0;
    int n, failed;
    hx_host_bind(r->call);
    for (long k = 0; k < calls; ++k)
        for (int q = 0; q < r->count; ++q) {
            const hx_query *query = &r->query[q];
            if (query->is_array)
                c_sysary(query->fnc, query->ipar, query->nsize, values, &n, &failed);
            else
                c_sysfnc(query->fnc, query->ipar, query->nsize, values, &failed);
            sink += values[0];
        }
    hx_host_unbind();
    r->sink += sink;
}
