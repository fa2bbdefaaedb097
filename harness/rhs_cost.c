/* The harness's own cost per right-hand side (rhs_cost.h). */
#include "rhs_cost.h"

#include "element_probe.h"

#include <stdlib.h>
#include <string.h>

/* ---- stand-in entries: replay what the real entry returned ----------------------- */

#define MAX_STANDINS 256

typedef struct standin {
    const double *par; /* the binding's USER list: tells the elements apart */
    int which;         /* a coupler's function (0, 1, 2); 0 otherwise */
    double out[81];    /* outputs recorded from the real entry */
} standin;

static standin standins[MAX_STANDINS];
static int standin_count;

static const standin *find_standin(const double *par, int which)
{
    for (int k = 0; k < standin_count; ++k)
        if (standins[k].par == par && standins[k].which == which)
            return &standins[k];
    return NULL;
}

#define COUPLER_STANDIN(WHICH, COUNT)                                                            \
    static void STDCALL standin_coupler##WHICH(int *id, double *time, double *par, int *npar,   \
                                               double *disp, int *ndisp, int *iflag, double *out) \
    {                                                                                            \
        (void)id, (void)time, (void)npar, (void)disp, (void)iflag, (void)ndisp;                   \
        const standin *s = find_standin(par, WHICH);                                             \
        if (s != NULL)                                                                           \
            memcpy(out, s->out, sizeof(double) * (size_t)(COUNT));                               \
    }
COUPLER_STANDIN(0, 1)
COUPLER_STANDIN(1, *ndisp)
COUPLER_STANDIN(2, *ndisp **ndisp)
static usrsub_coupler_fn *const standin_coupler[3] = {standin_coupler0, standin_coupler1,
                                                      standin_coupler2};

static void STDCALL standin_gfosub(int *id, double *time, double *par, int *npar, int *dflag,
                                   int *iflag, double *result)
{
    (void)id, (void)time, (void)npar, (void)dflag, (void)iflag;
    const standin *s = find_standin(par, 0);
    if (s != NULL)
        memcpy(result, s->out, 6 * sizeof(double));
}

static void STDCALL standin_fiesub(int *id, double *time, double *par, int *npar, double *disp,
                                   double *velo, int *dflag, int *iflag, double *field,
                                   double *dfddis, double *dfdvel)
{
    (void)id, (void)time, (void)npar, (void)disp, (void)velo, (void)dflag, (void)iflag;
    const standin *s = find_standin(par, 0);
    if (s == NULL)
        return;
    memcpy(field, s->out, 6 * sizeof(double));
    memcpy(dfddis, s->out + 6, 36 * sizeof(double));
    memcpy(dfdvel, s->out + 42, 36 * sizeof(double));
}

/* The real entries of every binding, and their outputs at the frames of y. */
typedef struct saved_entries {
    usrsub_coupler_fn *coupler[3];
    usrsub_gfosub_fn *gfosub;
    usrsub_fiesub_fn *fiesub;
} saved_entries;

static int record_standins(hx_session *s, hx_dynamics *d, const double *y)
{
    double *ydot = calloc((size_t)d->n, sizeof(double));
    if (ydot == NULL || hx_dynamics_rhs(d, 0.0, y, ydot) != 0) { /* frames of y, host set */
        free(ydot);
        return -1;
    }
    free(ydot);
    standin_count = 0;
    for (int k = 0; k < s->bindings.count && standin_count + 3 <= MAX_STANDINS; ++k) {
        hx_binding *b = &s->bindings.items[k];
        if (b->kind == HX_BIND_COUPLER) {
            const hx_coupler *c = &s->model->couplers[b->index];
            double disp[3];
            for (int i = 0; i < c->njoints; ++i)
                disp[i] = y[d->dof[s->model->markers[s->model->joints[c->joint[i]].i_marker].body].q];
            for (int which = 0; which < 3; ++which) {
                standin *st = &standins[standin_count++];
                st->par = b->par, st->which = which;
                hx_call_coupler(b, which, 0.0, disp, c->njoints, 0, st->out, NULL);
            }
        } else {
            standin *st = &standins[standin_count++];
            st->par = b->par, st->which = 0;
            if (b->kind == HX_BIND_GFOSUB) {
                hx_call_gfosub(b, 0.0, 0, 0, st->out, NULL);
            } else {
                double disp[6], velo[6];
                hx_element_state(s, b->index, disp, velo);
                hx_call_fiesub(b, 0.0, disp, velo, 0, 0, st->out, st->out + 6, st->out + 42, NULL);
            }
        }
    }
    return 0;
}

static void swap_in_standins(hx_session *s, saved_entries *saved)
{
    for (int k = 0; k < s->bindings.count; ++k) {
        hx_binding *b = &s->bindings.items[k];
        saved[k] = (saved_entries){{b->coupler[0], b->coupler[1], b->coupler[2]}, b->gfosub, b->fiesub};
        if (b->kind == HX_BIND_COUPLER) {
            b->coupler[0] = standin_coupler0;
            b->coupler[1] = standin_coupler1;
            b->coupler[2] = standin_coupler2;
        } else if (b->kind == HX_BIND_GFOSUB) {
            b->gfosub = standin_gfosub;
        } else {
            b->fiesub = standin_fiesub;
        }
    }
}

static void restore_entries(hx_session *s, const saved_entries *saved)
{
    for (int k = 0; k < s->bindings.count; ++k) {
        hx_binding *b = &s->bindings.items[k];
        memcpy(b->coupler, saved[k].coupler, sizeof b->coupler);
        b->gfosub = saved[k].gfosub;
        b->fiesub = saved[k].fiesub;
    }
}

/* ---- the timed evaluations ----------------------------------------------------------- */

typedef struct rhs_bench {
    hx_session *s;
    hx_dynamics *d;
    double *y, *ydot;
    saved_entries *saved; /* non-NULL: evaluate with the stand-ins */
    double sink;
} rhs_bench;

static void run_rhs(void *ctx, long calls)
{
    rhs_bench *b = ctx;
    saved_entries *keep = NULL;
    if (b->saved != NULL) {
        keep = b->saved;
        swap_in_standins(b->s, keep);
    }
    double sink = 0.0;
    for (long k = 0; k < calls; ++k) {
        hx_dynamics_rhs(b->d, 0.0, b->y, b->ydot);
        sink += b->ydot[0];
    }
    if (keep != NULL)
        restore_entries(b->s, keep);
    b->sink += sink;
}

/* The stand-ins alone, called as one evaluation calls them: what replaying
 * costs, to be taken out of the harness's share. */
typedef struct standin_bench {
    hx_session *s;
    double sink;
} standin_bench;

static void run_standins(void *ctx, long calls)
{
    standin_bench *b = ctx;
    double out[81], disp[6] = {0}, velo[6] = {0}, t = 0.0, sink = 0.0;
    for (long k = 0; k < calls; ++k)
        for (int e = 0; e < b->s->bindings.count; ++e) {
            hx_binding *bd = &b->s->bindings.items[e];
            int id = bd->id, npar = bd->npar, nd = 3, flag = 0;
            if (bd->kind == HX_BIND_COUPLER)
                for (int which = 0; which < 3; ++which)
                    standin_coupler[which](&id, &t, bd->par, &npar, disp, &nd, &flag, out);
            else if (bd->kind == HX_BIND_GFOSUB)
                standin_gfosub(&id, &t, bd->par, &npar, &flag, &flag, out);
            else
                standin_fiesub(&id, &t, bd->par, &npar, disp, velo, &flag, &flag, out, out + 6,
                               out + 42);
            sink += out[0];
        }
    b->sink += sink;
}

int hx_measure_rhs_cost(hx_session *s, int repeats, hx_call_cost *costs, int capacity,
                        int *ncosts, hx_rhs_cost *out, usrsub_message *msg)
{
    memset(out, 0, sizeof *out);
    *ncosts = 0;
    hx_dynamics d;
    if (hx_dynamics_init(&d, s, msg) != 0)
        return -1;
    double *y = calloc((size_t)d.n, sizeof(double)), *ydot = calloc((size_t)d.n, sizeof(double));
    double *rounds = calloc(5 * (size_t)repeats, sizeof(double));
    saved_entries *saved = calloc((size_t)s->bindings.count + 1, sizeof *saved);
    int status = y && ydot && rounds && saved ? 0 : usrsub_fail(msg, "out of memory");
    if (status == 0 && (hx_dynamics_initial_state(&d, y) != 0 || record_standins(s, &d, y) != 0))
        status = usrsub_fail(msg, "the model's right-hand side failed: %s", d.message);
    if (status == 0) {
        double *real = rounds, *replay = rounds + repeats, *alone_ns = rounds + 2 * repeats;
        double *harness = rounds + 3 * repeats, *user = rounds + 4 * repeats;
        rhs_bench as_is = {s, &d, y, ydot, NULL, 0.0}, replayed = {s, &d, y, ydot, saved, 0.0};
        standin_bench alone = {s, 0.0};
        hx_timed_body bodies[3] = {{run_rhs, &as_is, real},
                                   {run_rhs, &replayed, replay},
                                   {run_standins, &alone, alone_ns}};
        *ncosts = hx_measure_call_costs_with(s, repeats, costs, capacity, bodies, 3);
        out->user_calls = *ncosts;
        for (int r = 0; r < repeats; ++r) {
            harness[r] = replay[r] - alone_ns[r];
            user[r] = real[r] - harness[r];
        }
        out->rhs_ns = hx_median(real, repeats);
        out->harness_ns = hx_median(harness, repeats);
        out->user_ns = hx_median(user, repeats);
    }
    free(y);
    free(ydot);
    free(rounds);
    free(saved);
    hx_dynamics_free(&d);
    return status;
}
