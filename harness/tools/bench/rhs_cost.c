/* The harness's own cost per right-hand side (rhs_cost.h). */
#include "tools/bench/rhs_cost.h"

#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "host/invoke.h"
#include "host/state_inputs.h"
#include "sim/dynamics/stateeqns.h"
#include "frames/measures.h"

/* ---- stand-in entries: replay what the real entry returned -------------------- */

/* A stand-in finds its recorded outputs through the USER list it is handed:
 * during the stand-in runs the binding's par points into this record, which
 * keeps the ABI's signatures and needs no table of its own. */
typedef struct standin {
    double out[3][81];  /* per function (a coupler's three; one otherwise) */
    int values;         /* a force routine's: how many it returns (hx_force_routine_values) */
    double par[];       /* a copy of the binding's USER list */
} standin;

static const standin *standin_of(const double *par)
{
    return (const standin *)(const void *)((const char *)par - offsetof(standin, par));
}

#define COUPLER_STANDIN(WHICH, COUNT)                                                            \
    static void STDCALL standin_coupler##WHICH(int *id, double *time, double *par, int *npar,   \
                                               double *disp, int *ndisp, int *iflag, double *out) \
    {                                                                                            \
        (void)id, (void)time, (void)npar, (void)disp, (void)iflag, (void)ndisp;                   \
        memcpy(out, standin_of(par)->out[WHICH], sizeof(double) * (size_t)(COUNT));              \
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
    const standin *st = standin_of(par);
    memcpy(result, st->out[0], sizeof(double) * (size_t)st->values);
}

static void STDCALL standin_fiesub(int *id, double *time, double *par, int *npar, double *disp,
                                   double *velo, int *dflag, int *iflag, double *field,
                                   double *dfddis, double *dfdvel)
{
    (void)id, (void)time, (void)npar, (void)disp, (void)velo, (void)dflag, (void)iflag;
    const double *out = standin_of(par)->out[0];
    memcpy(field, out, 6 * sizeof(double));
    memcpy(dfddis, out + 6, 36 * sizeof(double));
    memcpy(dfdvel, out + 42, 36 * sizeof(double));
}

/* A Force_StateEqn's: its state rates, then its outputs. */
static void STDCALL standin_yfosub(int *id, double *time, double *par, int *npar, int *dflag,
                                   int *iflag, int *nstate, double *states, int *ninput,
                                   double *input, int *noutpt, double *stated, double *output)
{
    (void)id, (void)time, (void)npar, (void)dflag, (void)iflag, (void)states, (void)ninput;
    (void)input, (void)noutpt;
    const double *out = standin_of(par)->out[0];
    memcpy(stated, out, sizeof(double) * (size_t)*nstate);
    memcpy(output, out + *nstate, 6 * sizeof(double));
}

/* The real entries and USER list of a binding, kept while stand-ins run. */
typedef struct saved_entries {
    hx_binding_functions fn;
    double *par;
} saved_entries;

/* A Force_StateEqn's rates and outputs at d's state, states from y, into out. */
static int record_stateeqn(const hx_dynamics *d, const hx_dynamics_data *dd, hx_binding *b,
                           const double *y, double *out)
{
    const hx_stateeqn *f = &d->m->stateeqns[b->index];
    if (f->nstate + 6 > 81)
        return -1; /* more states than a stand-in replays */
    double *work = malloc(sizeof(double) * (size_t)(f->nstate + f->ninput + 1));
    if (work == NULL)
        return -1;
    memcpy(work, y + d->stateeqns->offset[b->index], sizeof(double) * (size_t)f->nstate);
    hx_stateeqn_inputs(&dd->frames, b->index, work + f->nstate);
    hx_invoke_stateeqn(b, &dd->frames, work, work + f->nstate, 0, 0, out, out + f->nstate, NULL);
    free(work);
    return 0;
}

/* One stand-in per binding, recording each entry's outputs at the state of y. */
static int record_standins(hx_session *s, const hx_dynamics *d, hx_dynamics_data *dd,
                           const double *y, standin **records)
{
    double *ydot = calloc((size_t)d->n, sizeof(double));
    if (ydot == NULL || hx_dynamics_rhs(d, dd, 0.0, y, ydot) != 0) { /* dd->frames is y's */
        free(ydot);
        return -1;
    }
    free(ydot);
    for (int k = 0; k < s->bindings.count; ++k) {
        hx_binding *b = &s->bindings.items[k];
        standin *st = calloc(1, sizeof *st + sizeof(double) * (size_t)(b->npar + 1));
        if (st == NULL)
            return -1;
        records[k] = st;
        memcpy(st->par, b->par, sizeof(double) * (size_t)b->npar);
        if (b->kind == HX_BIND_COUPLER) {
            const hx_coupler *c = &s->model->couplers[b->index];
            double disp[3];
            for (int i = 0; i < c->njoints; ++i)
                disp[i] = hx_joint_coordinate(&dd->frames, c->joint[i], c->freedom[i]);
            for (int which = 0; which < 3; ++which)
                hx_invoke_coupler(b, which, &dd->frames, disp, c->njoints, 0, st->out[which], NULL);
        } else if (b->kind == HX_BIND_FORCE) {
            st->values = hx_force_routine_values(b->part);
            hx_invoke_force(b, &dd->frames, 0, 0, st->out[0], NULL);
        } else if (b->kind == HX_BIND_STATEEQN) {
            if (record_stateeqn(d, dd, b, y, st->out[0]) != 0)
                return -1;
        } else {
            double disp[6], velo[6];
            hx_force_deformation(&dd->frames, b->index, disp, velo);
            hx_invoke_field(b, &dd->frames, disp, velo, 0, 0, st->out[0], st->out[0] + 6,
                           st->out[0] + 42, NULL);
        }
    }
    return 0;
}

static void swap_in_standins(hx_session *s, standin **records, saved_entries *saved)
{
    for (int k = 0; k < s->bindings.count; ++k) {
        hx_binding *b = &s->bindings.items[k];
        saved[k] = (saved_entries){b->fn, b->par};
        b->par = records[k]->par;
        if (b->kind == HX_BIND_COUPLER)
            memcpy(b->fn.coupler, standin_coupler, sizeof b->fn.coupler);
        else if (b->kind == HX_BIND_FORCE)
            b->fn.force = standin_gfosub;
        else if (b->kind == HX_BIND_STATEEQN)
            b->fn.stateeqn.rates = standin_yfosub;
        else
            b->fn.field = standin_fiesub;
    }
}

static void restore_entries(hx_session *s, const saved_entries *saved)
{
    for (int k = 0; k < s->bindings.count; ++k) {
        hx_binding *b = &s->bindings.items[k];
        b->fn = saved[k].fn;
        b->par = saved[k].par;
    }
}

/* ---- the timed evaluations ----------------------------------------------------------- */

typedef struct rhs_bench {
    hx_session *s;
    const hx_dynamics *d;
    hx_dynamics_data *dd;
    double *y, *ydot;
    standin **records;     /* non-NULL: evaluate with the stand-ins */
    saved_entries *saved;
    double sink;
} rhs_bench;

static void run_rhs(void *ctx, long calls)
{
    rhs_bench *b = ctx;
    if (b->records != NULL)
        swap_in_standins(b->s, b->records, b->saved);
    double sink = 0.0;
    for (long k = 0; k < calls; ++k) {
        hx_dynamics_rhs(b->d, b->dd, 0.0, b->y, b->ydot);
        sink += b->ydot[0];
    }
    if (b->records != NULL)
        restore_entries(b->s, b->saved);
    b->sink += sink;
}

/* The stand-ins alone, called as one evaluation calls them: what replaying
 * costs, to be taken out of the harness's share. */
typedef struct standin_bench {
    hx_session *s;
    standin **records;
    double sink;
} standin_bench;

static void run_standins(void *ctx, long calls)
{
    standin_bench *b = ctx;
    double out[81], disp[6] = {0}, velo[6] = {0}, states[81] = {0}, t = 0.0, sink = 0.0;
    for (long k = 0; k < calls; ++k)
        for (int e = 0; e < b->s->bindings.count; ++e) {
            hx_binding *bd = &b->s->bindings.items[e];
            double *par = b->records[e]->par;
            int id = bd->id, npar = bd->npar, nd = 3, flag = 0;
            if (bd->kind == HX_BIND_COUPLER)
                for (int which = 0; which < 3; ++which)
                    standin_coupler[which](&id, &t, par, &npar, disp, &nd, &flag, out);
            else if (bd->kind == HX_BIND_FORCE)
                standin_gfosub(&id, &t, par, &npar, &flag, &flag, out);
            else if (bd->kind == HX_BIND_STATEEQN) {
                const hx_stateeqn *f = &b->s->model->stateeqns[bd->index];
                int ns = f->nstate, ni = 0, no = 6;
                standin_yfosub(&id, &t, par, &npar, &flag, &flag, &ns, states, &ni, disp, &no,
                               out, out + ns);
            } else
                standin_fiesub(&id, &t, par, &npar, disp, velo, &flag, &flag, out, out + 6,
                               out + 42);
            sink += out[0];
        }
    b->sink += sink;
}

int hx_rhs_cost_supported(const hx_session *s, hx_message *msg)
{
    /* the stand-ins replay the classic forms of the force, coupler and state
     * equation routines (and nothing else calls the library in a run) */
    for (int k = 0; k < s->bindings.count; ++k) {
        const hx_binding *b = &s->bindings.items[k];
        if (b->kind >= HX_BIND_REQUEST || b->record != NULL)
            return hx_fail(msg, "%s %d (%s): bench splits the cost of force elements, couplers"
                           " and state equations in the classic form only", b->element, b->id,
                           hx_binding_routine(b, 0));
    }
    return 0;
}

int hx_measure_rhs_cost(hx_session *s, int repeats, hx_entry_cost *costs, int capacity,
                        int *ncosts, hx_rhs_cost *out, hx_message *msg)
{
    memset(out, 0, sizeof *out);
    *ncosts = 0;
    if (hx_rhs_cost_supported(s, msg) != 0)
        return -1;
    hx_dynamics d;
    hx_dynamics_data dd;
    if (hx_dynamics_init(&d, s, msg) != 0)
        return -1;
    if (hx_dynamics_data_init(&dd, &d, msg) != 0) {
        hx_dynamics_free(&d);
        return -1;
    }
    const int nb = s->bindings.count;
    double *y = calloc((size_t)d.n, sizeof(double)), *ydot = calloc((size_t)d.n, sizeof(double));
    double *rounds = calloc(5 * (size_t)repeats, sizeof(double));
    saved_entries *saved = calloc((size_t)nb + 1, sizeof *saved);
    standin **records = calloc((size_t)nb + 1, sizeof *records);
    int status = y && ydot && rounds && saved && records ? 0 : hx_fail(msg, "out of memory");
    if (status == 0 &&
        (hx_dynamics_initial_state(&d, &dd, y) != 0 ||
         record_standins(s, &d, &dd, y, records) != 0))
        status = hx_fail(msg, "the model's right-hand side failed: %s", dd.message);
    if (status == 0) {
        double *real = rounds, *replay = rounds + repeats, *alone_ns = rounds + 2 * repeats;
        rhs_bench as_is = {s, &d, &dd, y, ydot, NULL, saved, 0.0};
        rhs_bench replayed = {s, &d, &dd, y, ydot, records, saved, 0.0};
        standin_bench alone = {s, records, 0.0};
        hx_timed_body bodies[3] = {{run_rhs, &as_is, real},
                                   {run_rhs, &replayed, replay},
                                   {run_standins, &alone, alone_ns}};
        *ncosts = hx_measure_entry_costs_with(s, repeats, costs, capacity, bodies, 3);
        if (*ncosts < 0) {
            *ncosts = 0;
            status = hx_fail(msg, "out of memory");
        }
    }
    if (status == 0) {
        double *real = rounds, *replay = rounds + repeats, *alone_ns = rounds + 2 * repeats;
        double *harness = rounds + 3 * repeats, *user = rounds + 4 * repeats;
        for (int k = 0; k < *ncosts; ++k)
            out->user_calls += costs[k].in_rhs;
        for (int r = 0; r < repeats; ++r) {
            harness[r] = replay[r] - alone_ns[r];
            user[r] = real[r] - harness[r];
        }
        out->rhs_ns = hx_median(real, repeats);
        out->harness_ns = hx_median(harness, repeats);
        out->user_ns = hx_median(user, repeats);
    }
    for (int k = 0; records != NULL && k < nb; ++k)
        free(records[k]);
    free(records);
    free(y);
    free(ydot);
    free(rounds);
    free(saved);
    hx_dynamics_data_free(&dd);
    hx_dynamics_free(&d);
    return status;
}

void hx_rhs_cost_text(const hx_rhs_cost *rc, char *text, size_t size)
{
    if (rc->user_calls == 0) {
        snprintf(text, size, "right-hand side: %.1f ns per evaluation (no user entries)",
                 rc->rhs_ns);
        return;
    }
    const char *noise = "below the noise of the timings (a loaded machine: measure again)";
    char user[96], harness[160];
    if (rc->user_ns > 0.0)
        snprintf(user, sizeof user, "%.1f ns", rc->user_ns);
    else
        snprintf(user, sizeof user, "%s", noise);
    if (rc->harness_ns <= 0.0)
        snprintf(harness, sizeof harness, "%s", noise);
    else if (rc->user_ns > 0.0)
        snprintf(harness, sizeof harness, "%.1f ns (%.0f %% of the user entries)", rc->harness_ns,
                 100.0 * rc->harness_ns / rc->user_ns);
    else
        snprintf(harness, sizeof harness, "%.1f ns", rc->harness_ns);
    snprintf(text, size, "right-hand side: %.1f ns per evaluation: the %d user entry calls in it"
             " %s, the harness's own share %s", rc->rhs_ns, rc->user_calls, user, harness);
}
