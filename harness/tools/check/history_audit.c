/*
 * The history audit (checks.h): a solver calls an element in any order, at
 * trial states it throws away, differencing with dflag set, and again after
 * a restart; an element whose output depends on what it was called with
 * before (a value kept from an earlier call) breaks every implicit solver.
 * At two inputs A and B (different states and times), the outputs at A must
 * be bit-identical: repeated, after a call at B, after a dflag call at B,
 * and after a call at A at B's time. Whether the output depends on time is
 * said, not judged.
 */
#include <stdio.h>
#include <string.h>

#include "sim/element_probe.h"
#include "state/measures.h"
#include "tools/check/checks.h"
#include "tools/check/coupler_ranges.h"
#include "tools/check/element_samples.h"

#define MAX_OUT 81
#define MAX_IN 64

typedef struct probe {
    hx_session *s;
    hx_binding *b;
    hx_state state;
    /* A and B: joint displacements, deformation and rate, or a state
     * equation's states and inputs */
    double input[2][MAX_IN];
    double time[2];
} probe;

/* Every output of the element at input `which`, at time t; dflag as given. */
static int evaluate(probe *p, int which, double t, int dflag, double *out)
{
    hx_binding *b = p->b;
    memset(out, 0, sizeof(double) * MAX_OUT);
    if (b->kind == HX_BIND_COUPLER) {
        const int n = p->s->model->couplers[b->index].njoints;
        p->state.time = t;
        hx_call_coupler(b, 0, &p->state, p->input[which], n, 0, out, NULL);
        hx_call_coupler(b, 1, &p->state, p->input[which], n, 0, out + 1, NULL);
        hx_call_coupler(b, 2, &p->state, p->input[which], n, 0, out + 1 + n, NULL);
    } else if (b->kind == HX_BIND_FIESUB) {
        p->state.time = t;
        hx_call_fiesub(b, &p->state, p->input[which], p->input[which] + 6, dflag, 0, out,
                       out + 6, out + 42, NULL);
    } else if (b->kind == HX_BIND_YFOSUB) {
        /* the rates and outputs; copies of the arguments, which it may write */
        const int ns = p->s->model->state_eqns[b->index].nstate;
        double copy[MAX_IN];
        memcpy(copy, p->input[which], sizeof copy);
        p->state.time = t;
        hx_call_yfosub(b, &p->state, copy, copy + ns, dflag, 0, out, out + ns, NULL);
    } else {
        const hx_force *f = &p->s->model->forces[b->index];
        hx_place_relative(&p->s->state, &p->state, f->i_marker, f->j_marker, p->input[which],
                          p->input[which] + 6);
        p->state.time = t;
        hx_call_gfosub(b, &p->state, dflag, 0, out, NULL);
    }
    return hx_messages_stopped(b->messages) ? -1 : 0;
}

static int outputs(const hx_binding *b, const hx_model *m)
{
    if (b->kind == HX_BIND_COUPLER) {
        const int n = m->couplers[b->index].njoints;
        return 1 + n + n * n;
    }
    if (b->kind == HX_BIND_YFOSUB)
        return m->state_eqns[b->index].nstate + 6;
    return b->kind == HX_BIND_FIESUB ? 78 : 6;
}

static void choose_inputs(probe *p)
{
    const hx_model *m = p->s->model;
    hx_binding *b = p->b;
    p->time[0] = hx_sample_time(m, 3);
    p->time[1] = hx_sample_time(m, 8);
    if (b->kind == HX_BIND_COUPLER) {
        const hx_coupler *c = &m->couplers[b->index];
        double q0[3] = {0}, lo[3] = {0}, hi[3] = {0};
        for (int i = 0; i < c->njoints; ++i)
            q0[i] = hx_joint_coordinate(&p->s->state, c->joint[i]);
        hx_coupler_ranges(m, b->par, b->npar, c->njoints, q0, lo, hi);
        for (int i = 0; i < c->njoints; ++i) {
            p->input[0][i] = lo[i] + 0.31 * (hi[i] - lo[i]);
            p->input[1][i] = lo[i] + (0.77 - 0.1 * i) * (hi[i] - lo[i]);
        }
        return;
    }
    double scale[MAX_IN];
    if (b->kind == HX_BIND_YFOSUB) {
        const int ns = m->state_eqns[b->index].nstate;
        hx_sample_state_element(p->s, b->index, 3, p->input[0], p->input[0] + ns, scale);
        hx_sample_state_element(p->s, b->index, 8, p->input[1], p->input[1] + ns, scale);
        return;
    }
    hx_sample_element_state(p->s, b->index, 3, p->input[0], p->input[0] + 6, scale);
    hx_sample_element_state(p->s, b->index, 8, p->input[1], p->input[1] + 6, scale);
}

int hx_audit_history(hx_session *s, hx_binding *b, FILE *out)
{
    probe p = {.s = s, .b = b};
    if (b->kind == HX_BIND_YFOSUB) {
        const hx_state_eqn *f = &s->model->state_eqns[b->index];
        if (f->nstate + f->ninput > MAX_IN || f->nstate + 6 > MAX_OUT) {
            fprintf(out, "  %s %d: history audit: %d states and %d inputs are more than it"
                    " compares (%d): FAIL\n", b->element, b->id, f->nstate, f->ninput, MAX_IN);
            return 1;
        }
    }
    if (hx_state_clone(&p.state, &s->state) != 0)
        return 1;
    choose_inputs(&p);
    const int n = outputs(b, s->model);
    double first[MAX_OUT], again[MAX_OUT], other[MAX_OUT];
    static const char *const after[] = {"repeated at once", "after a call at B",
                                        "after a dflag call at B", "after a call at A at B's time"};
    int status = evaluate(&p, 0, p.time[0], 0, first);
    int time_dependent = 0, failed_step = -1, component = 0;
    for (int step = 0; step < 4 && status == 0 && failed_step < 0; ++step) {
        if (step == 1)
            status = evaluate(&p, 1, p.time[1], 0, other);
        else if (step == 2)
            status = b->kind == HX_BIND_COUPLER ? evaluate(&p, 1, p.time[1], 0, other)
                                                : evaluate(&p, 1, p.time[1], 1, other);
        else if (step == 3) {
            status = evaluate(&p, 0, p.time[1], 0, other);
            time_dependent = status == 0 && memcmp(other, first, sizeof(double) * (size_t)n) != 0;
        }
        if (status == 0)
            status = evaluate(&p, 0, p.time[0], 0, again);
        for (int k = 0; status == 0 && k < n && failed_step < 0; ++k)
            if (memcmp(&first[k], &again[k], sizeof first[k]) != 0)
                failed_step = step, component = k;
    }
    hx_state_free(&p.state);
    if (status != 0) {
        fprintf(out, "  %s %d: history audit: the element stopped the run\n", b->element, b->id);
        return 1;
    }
    if (failed_step >= 0) {
        fprintf(out, "  %s %d: history audit: FAIL: a hidden state: at the same input A (t = %g)"
                " output %d was %.17g, then %.17g %s: the output depends on earlier calls (a"
                " value kept between calls), which breaks implicit solvers, differencing and"
                " restarts\n", b->element, b->id, p.time[0], component + 1, first[component],
                again[component], after[failed_step]);
        return 1;
    }
    fprintf(out, "  %s %d: history audit: at the same input, bit-identical outputs repeated, after"
            " a call at another input, after a dflag call and after another time%s: pass\n",
            b->element, b->id, time_dependent ? " (the output depends on time)" : "");
    return 0;
}
