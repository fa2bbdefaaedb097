/* Cost per call of the user entries (entry_cost.h). */
#define _GNU_SOURCE /* sched_setaffinity, sched_getcpu */
#include "tools/bench/entry_cost.h"

#include <sched.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "base/clock.h"

#include "host/invoke.h"
#include "host/state_inputs.h"
#include "frames/measures.h"
#include "tools/bench/call_floor.h"
#include "tools/check/coupler_ranges.h"

#define SAMPLE_POINTS 256
#define BATCH_NS 2e6 /* aim for batches of about 2 ms */


static int compare_doubles(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

double hx_median(double *v, int n)
{
    qsort(v, (size_t)n, sizeof *v, compare_doubles);
    return v[n / 2];
}

/* ---- the timed bodies ------------------------------------------------------------ */

typedef struct coupler_bench {
    usrsub_coupler_fn *fn;
    int id, npar, ndisp;
    double *par;
    double disp[SAMPLE_POINTS][3];
    double out[9];
    double sink;
} coupler_bench;

static void run_coupler(void *ctx, long calls)
{
    coupler_bench *b = ctx;
    int id = b->id, npar = b->npar, ndisp = b->ndisp, iflag = 0;
    double time = 0.0, sink = 0.0;
    for (long k = 0; k < calls; ++k) {
        b->fn(&id, &time, b->par, &npar, b->disp[k & (SAMPLE_POINTS - 1)], &ndisp, &iflag, b->out);
        sink += b->out[0];
    }
    b->sink += sink;
}

typedef struct gfosub_bench {
    usrsub_gfosub_fn *fn;
    hx_call *call;
    int id, npar;
    double *par;
    double out[6];
    double sink;
} gfosub_bench;

static void run_gfosub(void *ctx, long calls)
{
    gfosub_bench *b = ctx;
    int id = b->id, npar = b->npar, dflag = 0, iflag = 0;
    double time = 0.0, sink = 0.0;
    hx_host_bind(b->call);
    for (long k = 0; k < calls; ++k) {
        b->fn(&id, &time, b->par, &npar, &dflag, &iflag, b->out);
        sink += b->out[0];
    }
    hx_host_unbind();
    b->sink += sink;
}

typedef struct fiesub_bench {
    usrsub_fiesub_fn *fn;
    int id, npar;
    double *par;
    double disp[SAMPLE_POINTS][6], velo[SAMPLE_POINTS][6];
    double field[6], dfd[36], dfv[36];
    double sink;
} fiesub_bench;

static void run_fiesub(void *ctx, long calls)
{
    fiesub_bench *b = ctx;
    int id = b->id, npar = b->npar, dflag = 0, iflag = 0;
    double time = 0.0, sink = 0.0;
    for (long k = 0; k < calls; ++k) {
        const int s = (int)(k & (SAMPLE_POINTS - 1));
        b->fn(&id, &time, b->par, &npar, b->disp[s], b->velo[s], &dflag, &iflag, b->field,
              b->dfd, b->dfv);
        sink += b->field[0] + b->dfd[0];
    }
    b->sink += sink;
}

/* YFOSUB (partial NULL) or one of its partial routines at sampled states
 * and inputs; data holds SAMPLE_POINTS rows of states, then of inputs, then
 * the rates and the output or matrix. */
typedef struct state_bench {
    usrsub_yfosub_fn *fn;
    usrsub_state_partial_fn *partial;
    int id, npar, nstate, ninput;
    double *par;
    double sink;
    double data[];
} state_bench;

static void run_state(void *ctx, long calls)
{
    state_bench *b = ctx;
    int id = b->id, npar = b->npar, ns = b->nstate, ni = b->ninput, no = 6, flag = 0;
    double time = 0.0, sink = 0.0;
    double *states = b->data, *input = states + SAMPLE_POINTS * ns;
    double *stated = input + SAMPLE_POINTS * ni, *out = stated + ns;
    for (long k = 0; k < calls; ++k) {
        const int s = (int)(k & (SAMPLE_POINTS - 1));
        if (b->fn != NULL)
            b->fn(&id, &time, b->par, &npar, &flag, &flag, &ns, states + s * ns, &ni,
                  input + s * ni, &no, stated, out);
        else
            b->partial(&id, &time, b->par, &npar, &flag, &ns, states + s * ns, &ni,
                       input + s * ni, &no, out);
        sink += out[0];
    }
    b->sink += sink;
}

/* A Force_StateEqn's routine `which` (0 YFOSUB, 1.. its partials) at its
 * initial states and its inputs at the model's state, each wobbled a little. */
static state_bench *state_points(hx_session *s, hx_binding *b, int which)
{
    const hx_stateeqn *f = &s->model->stateeqns[b->index];
    const int ns = f->nstate, ni = f->ninput;
    const size_t columns = (size_t)(ns + ni);
    const size_t size = (size_t)SAMPLE_POINTS * columns + (size_t)(ns + 6) * columns + 7;
    state_bench *sb = calloc(1, sizeof *sb + sizeof(double) * size);
    if (sb == NULL)
        return NULL;
    *sb = (state_bench){which == 0 ? b->fn.stateeqn.rates : NULL,
                        which > 0 ? b->fn.stateeqn.partial[which - 1] : NULL, b->id, b->npar, ns, ni,
                        b->par, 0.0};
    double *input = sb->data + SAMPLE_POINTS * ns;
    hx_stateeqn_inputs(&s->frames, b->index, input);
    for (int k = 0; k < SAMPLE_POINTS; ++k) {
        for (int i = 0; i < ns; ++i)
            sb->data[k * ns + i] = f->initial[i] * (1.0 + 1e-3 * ((k * 5 + i) % 11));
        for (int i = 0; i < ni; ++i)
            input[k * ni + i] = input[i] * (1.0 + 1e-3 * ((k * 7 + i) % 13));
    }
    return sb;
}

/* Calls per batch so that a batch takes about BATCH_NS. */
static long calibrate(void (*fn)(void *, long), void *ctx)
{
    long calls = 1000;
    for (;;) {
        const double start = hx_seconds();
        fn(ctx, calls);
        const double ns = 1e9 * (hx_seconds() - start);
        if (ns > 0.2 * BATCH_NS || calls > 100000000L)
            return (long)fmax(1000.0, (double)calls * BATCH_NS / fmax(ns, 1.0));
        calls *= 4;
    }
}

/* Coupler inputs across each term's data (as check samples them). */
static void coupler_points(hx_session *s, hx_binding *b, int n, coupler_bench *cb)
{
    const hx_coupler *c = &s->model->couplers[b->index];
    double q0[3] = {0}, lo[3] = {0}, hi[3] = {0};
    for (int i = 0; i < n; ++i)
        q0[i] = hx_joint_coordinate(&s->frames, c->joint[i], c->freedom[i]);
    hx_coupler_ranges(s->model, b->par, b->npar, n, q0, lo, hi);
    for (int i = 0; i < n; ++i)
        for (int k = 0; k < SAMPLE_POINTS; ++k)
            cb->disp[k][i] = lo[i] + (hi[i] - lo[i]) * ((k * 37 + i * 11) % SAMPLE_POINTS + 0.5) / SAMPLE_POINTS;
}

static void field_points(hx_session *s, hx_binding *b, fiesub_bench *fb)
{
    double disp[6], velo[6];
    hx_force_deformation(&s->frames, b->index, disp, velo);
    for (int k = 0; k < SAMPLE_POINTS; ++k)
        for (int i = 0; i < 6; ++i) {
            const double wobble = 1.0 + 1e-3 * ((k * 7 + i) % 13);
            fb->disp[k][i] = disp[i] * wobble;
            fb->velo[k][i] = velo[i] * wobble;
        }
}

/* Busy work until the processor has left its idle clock (about 0.3 s). */
static void spin_up(void)
{
    volatile double x = 1.0;
    const double until = hx_seconds() + 0.3;
    while (hx_seconds() < until)
        for (int k = 0; k < 10000; ++k)
            x = x * 1.0000001 + 1e-9;
}

/* Stays on the processor it runs on: moving between cores (of different
 * clocks, or shared with a neighbour) doubled timings on our 2-core machines. */
static void pin_to_this_cpu(void)
{
    const int cpu = sched_getcpu();
    if (cpu < 0)
        return;
    cpu_set_t set;
    CPU_ZERO(&set);
    CPU_SET(cpu, &set);
    sched_setaffinity(0, sizeof set, &set);
}

/* One timed entry: its batch body, context and batch size. */
typedef struct timed_entry {
    void (*run)(void *ctx, long calls);
    void *ctx;
    long calls;
    double *ns; /* one per round */
} timed_entry;

/* The median over rounds of an entry's cost divided by its floor's in the
 * same round: a slow spell falls on both. */
static double median_ratio(const double *ns, const double *empty, const double *host, int repeats)
{
    double *r = malloc(sizeof(double) * (size_t)repeats);
    if (r == NULL)
        return NAN;
    for (int k = 0; k < repeats; ++k)
        r[k] = ns[k] / (empty[k] + (host != NULL ? host[k] : 0.0));
    const double median = hx_median(r, repeats);
    free(r);
    return median;
}

static double median_of(const double *ns, int repeats)
{
    double *sorted = malloc(sizeof(double) * (size_t)repeats);
    if (sorted == NULL)
        return NAN;
    memcpy(sorted, ns, sizeof(double) * (size_t)repeats);
    const double median = hx_median(sorted, repeats);
    free(sorted);
    return median;
}

int hx_measure_entry_costs_with(hx_session *s, int repeats, hx_entry_cost *costs, int capacity,
                               hx_timed_body *extra, int nextra)
{
    /* the entries, the empty call, the host replays (one per GFOSUB row), the extras */
    enum { MAX_ROWS = 256, MAX_EXTRA = 4 };
    timed_entry entries[2 * MAX_ROWS + 1 + MAX_EXTRA];
    int replay_of[MAX_ROWS]; /* the row's host replay among entries, or -1 */
    if (nextra > MAX_EXTRA)
        nextra = MAX_EXTRA;
    void *contexts[2 * MAX_ROWS + 1];
    int rows = 0, ncontexts = 0;
    if (capacity > MAX_ROWS)
        capacity = MAX_ROWS;
    hx_empty_call empty;
    hx_message msg;
    const int has_floor = hx_empty_call_init(&empty, &msg) == 0;
    hx_host_replay *replays = calloc(MAX_ROWS, sizeof *replays);
    int nreplays = 0;
    pin_to_this_cpu();
    for (int k = 0; k < s->bindings.count; ++k) {
        hx_binding *b = &s->bindings.items[k];
        if (b->kind >= HX_BIND_REQUEST || b->record != NULL)
            continue; /* timed through their classic forms' calls only */
        if (b->kind == HX_BIND_COUPLER) {
            const hx_coupler *c = &s->model->couplers[b->index];
            for (int fn = 0; fn < 3 && rows < capacity; ++fn) {
                coupler_bench *cb = calloc(1, sizeof *cb);
                if (cb == NULL)
                    goto out_of_memory;
                cb->id = b->id, cb->npar = b->npar, cb->ndisp = c->njoints, cb->par = b->par;
                cb->fn = b->fn.coupler[fn];
                coupler_points(s, b, c->njoints, cb);
                contexts[ncontexts++] = cb;
                replay_of[rows] = -1;
                entries[rows] = (timed_entry){run_coupler, cb, 0, NULL};
                hx_entry_cost *r = &costs[rows++];
                snprintf(r->element, sizeof r->element, "%s %d", b->element, b->id);
                snprintf(r->function, sizeof r->function, "%s", b->names[fn]);
                r->host_calls = r->dependency_calls = 0;
                r->force_index = -1;
                r->in_rhs = 1;
            }
        } else if (b->kind == HX_BIND_FORCE && rows < capacity) {
            hx_call dep, *eval = calloc(1, sizeof *eval);
            if (eval == NULL)
                goto out_of_memory;
            contexts[ncontexts++] = eval;
            double out[6];
            hx_binding_call_init(b, &dep, 0, &s->frames, 1);
            hx_invoke_force(b, &s->frames, 0, 1, out, &dep);
            hx_binding_call_init(b, eval, 0, &s->frames, 0);
            hx_invoke_force(b, &s->frames, 0, 0, out, eval);
            gfosub_bench *gb = calloc(1, sizeof *gb);
            if (gb == NULL)
                goto out_of_memory;
            *gb = (gfosub_bench){b->fn.force, eval, b->id, b->npar, b->par, {0}, 0.0};
            contexts[ncontexts++] = gb;
            if (replays != NULL) {
                hx_host_replay_init(&replays[nreplays], eval);
                replay_of[rows] = nreplays++;
            } else {
                replay_of[rows] = -1;
            }
            entries[rows] = (timed_entry){run_gfosub, gb, 0, NULL};
            hx_entry_cost *r = &costs[rows++];
            snprintf(r->element, sizeof r->element, "%s %d", b->element, b->id);
            snprintf(r->function, sizeof r->function, "%s", b->names[0]);
            r->dependency_calls = dep.host_calls;
            r->host_calls = eval->host_calls;
            r->force_index = b->index;
            r->in_rhs = 1;
        } else if (b->kind == HX_BIND_FIELD && rows < capacity) {
            fiesub_bench *fb = calloc(1, sizeof *fb);
            if (fb == NULL)
                goto out_of_memory;
            fb->fn = b->fn.field, fb->id = b->id, fb->npar = b->npar, fb->par = b->par;
            field_points(s, b, fb);
            contexts[ncontexts++] = fb;
            replay_of[rows] = -1;
            entries[rows] = (timed_entry){run_fiesub, fb, 0, NULL};
            hx_entry_cost *r = &costs[rows++];
            snprintf(r->element, sizeof r->element, "%s %d", b->element, b->id);
            snprintf(r->function, sizeof r->function, "%s", b->names[0]);
            r->host_calls = r->dependency_calls = 0;
            r->force_index = b->index;
            r->in_rhs = 1;
        } else if (b->kind == HX_BIND_STATEEQN) {
            for (int which = 0; which < 5 && rows < capacity; ++which) {
                state_bench *sb = which == 0 || b->fn.stateeqn.partial[which - 1] != NULL
                                      ? state_points(s, b, which) : NULL;
                if (sb == NULL && (which == 0 || b->fn.stateeqn.partial[which - 1] != NULL))
                    goto out_of_memory;
                if (sb == NULL)
                    continue; /* a partial routine the library does not export */
                contexts[ncontexts++] = sb;
                replay_of[rows] = -1;
                entries[rows] = (timed_entry){run_state, sb, 0, NULL};
                hx_entry_cost *r = &costs[rows++];
                snprintf(r->element, sizeof r->element, "%s %d", b->element, b->id);
                snprintf(r->function, sizeof r->function, "%s", b->names[which]);
                r->host_calls = r->dependency_calls = 0;
                r->force_index = -1;
                r->in_rhs = which == 0;
            }
        }
    }
    int timed = rows;
    const int empty_index = has_floor ? timed++ : -1;
    if (has_floor)
        entries[empty_index] = (timed_entry){hx_run_empty_call, &empty, 0, NULL};
    const int first_replay = timed;
    for (int k = 0; k < nreplays; ++k)
        entries[timed++] = (timed_entry){hx_run_host_replay, &replays[k], 0, NULL};
    const int first_extra = timed;
    for (int k = 0; k < nextra; ++k)
        entries[timed++] = (timed_entry){extra[k].run, extra[k].ctx, 0, NULL};
    spin_up();
    for (int k = 0; k < timed; ++k)
        if ((entries[k].ns = malloc(sizeof(double) * (size_t)repeats)) == NULL) {
            while (k-- > 0)
                free(entries[k].ns);
            goto out_of_memory;
        }
    for (int k = 0; k < timed; ++k)
        entries[k].calls = calibrate(entries[k].run, entries[k].ctx);
    /* rounds of one batch per entry: a slow spell of the machine falls on all alike */
    for (int round = 0; round < repeats; ++round)
        for (int k = 0; k < timed; ++k) {
            const double start = hx_seconds();
            entries[k].run(entries[k].ctx, entries[k].calls);
            entries[k].ns[round] = 1e9 * (hx_seconds() - start) / (double)entries[k].calls;
        }
    for (int k = 0; k < nextra; ++k) {
        memcpy(extra[k].rounds, entries[first_extra + k].ns, sizeof(double) * (size_t)repeats);
        free(entries[first_extra + k].ns);
    }
    const double *empty_ns = has_floor ? entries[empty_index].ns : NULL;
    const double empty_median = has_floor ? median_of(empty_ns, repeats) : NAN;
    for (int k = 0; k < rows; ++k) {
        hx_entry_cost *c = &costs[k];
        c->rounds = entries[k].ns; /* the caller frees them */
        c->median_ns = median_of(entries[k].ns, repeats);
        c->min_ns = c->max_ns = entries[k].ns[0];
        for (int r = 1; r < repeats; ++r) {
            c->min_ns = fmin(c->min_ns, entries[k].ns[r]);
            c->max_ns = fmax(c->max_ns, entries[k].ns[r]);
        }
        const double *host = replay_of[k] >= 0 ? entries[first_replay + replay_of[k]].ns : NULL;
        c->empty_ns = empty_median;
        c->host_ns = host != NULL ? median_of(host, repeats) : 0.0;
        c->floor_ratio = has_floor ? median_ratio(entries[k].ns, empty_ns, host, repeats) : NAN;
    }
    for (int k = rows; k < first_extra; ++k)
        free(entries[k].ns);
    for (int k = 0; k < ncontexts; ++k)
        free(contexts[k]);
    free(replays);
    return rows;
out_of_memory:
    for (int k = 0; k < ncontexts; ++k)
        free(contexts[k]);
    free(replays);
    return -1;
}

void hx_print_entry_costs(FILE *f, const hx_entry_cost *costs, int count)
{
    fprintf(f, "%-26s %-20s %10s %8s %8s %10s %9s %9s %9s %7s\n", "element", "function",
            "median ns", "min ns", "max ns", "host/eval", "host/dep", "host ns", "floor ns",
            "ratio");
    for (int k = 0; k < count; ++k) {
        const hx_entry_cost *c = &costs[k];
        fprintf(f, "%-26s %-20s %10.1f %8.1f %8.1f %10d %9d %9.1f %9.1f %7.2f\n", c->element,
                c->function, c->median_ns, c->min_ns, c->max_ns, c->host_calls,
                c->dependency_calls, c->host_ns, c->empty_ns + c->host_ns, c->floor_ratio);
    }
    if (count > 0)
        fprintf(f, "floor: an empty call through a dlsym'd pointer (%.1f ns) plus the host alone"
                " answering what one evaluation asks (host ns); ratio: median over rounds of the"
                " entry's cost over its floor's in the same round\n", costs[0].empty_ns);
}

void hx_entry_costs_free(hx_entry_cost *costs, int count)
{
    for (int k = 0; k < count; ++k) {
        free(costs[k].rounds);
        costs[k].rounds = NULL;
    }
}

double hx_added_cost(const hx_entry_cost *base, const hx_entry_cost *other, int repeats)
{
    double *d = malloc(sizeof(double) * (size_t)repeats);
    if (d == NULL)
        return NAN;
    for (int k = 0; k < repeats; ++k)
        d[k] = other->rounds[k] - base->rounds[k];
    const double median = hx_median(d, repeats);
    free(d);
    return median;
}
