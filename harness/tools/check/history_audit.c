/*
 * The history audit (checks.h): a solver calls an element in any order, at
 * trial states it throws away, differencing with dflag set, going back in
 * time after a rejected step, and again after a restart; an element whose
 * outputs depend on what it was called with before (a value kept from an
 * earlier call) breaks every implicit solver. So the outputs at one input A
 * and time T must be bit-identical whatever came before.
 *
 * Each history (a few calls, then A at T) runs in a process of its own,
 * forked from this one, so that every history starts from the same library
 * state and the outputs at A and T are compared across histories, not along
 * one sequence. The times lie beyond any the element has been called at (the
 * check runs this audit first, after the calls at t = 0, so that they stay in
 * the model's first second), so that a cache refreshed only when time
 * advances is refreshed here. What the host notes in a history (a read
 * outside the declared dependencies, a refused query, a STOP) comes back to
 * this process. Whether the output depends on time is said, not judged.
 */
#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <string.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include "sim/dynamics/element_at.h"
#include "frames/measures.h"
#include "host/element_call.h"
#include "tools/check/checks.h"
#include "tools/check/coupler_ranges.h"
#include "tools/check/element_samples.h"

#define MAX_OUT 81
#define MAX_IN 64

enum { INPUT_A, INPUT_B };
enum { EARLIER, AUDITED, LATER, TIMES };

typedef struct probe {
    hx_session *s;
    hx_binding *b;
    hx_frames frames;
    /* A and B: joint displacements, deformation and rate, or a state
     * equation's states and inputs */
    double input[2][MAX_IN];
    int ninput;
    double time[TIMES];
    int nout;
} probe;

typedef struct call_step {
    int input, time, dflag;
} call_step;

/* Calls made before the audited one, A at time[AUDITED]. */
typedef struct history {
    const char *what;
    int nsteps;
    call_step step[2];
} history;

static const history histories[] = {
    {"as the first call at its time", 0, {{0}}},
    {"repeated at once", 1, {{INPUT_A, AUDITED, 0}}},
    {"after a call at input B at the same time", 1, {{INPUT_B, AUDITED, 0}}},
    {"after a call at input B at an earlier time", 1, {{INPUT_B, EARLIER, 0}}},
    {"after a call at A at an earlier time, then one at B at its time", 2,
     {{INPUT_A, EARLIER, 0}, {INPUT_B, AUDITED, 0}}},
    {"after a dflag call at input B at the same time", 1, {{INPUT_B, AUDITED, 1}}},
    {"after calls at a later time (as after a rejected step)", 2,
     {{INPUT_A, LATER, 0}, {INPUT_B, LATER, 0}}},
    {"after a call at A at an earlier time", 1, {{INPUT_A, EARLIER, 0}}},
};
#define HISTORIES ((int)(sizeof histories / sizeof histories[0]))

/* Every output of the element at input `which`, at time t; dflag as given
 * (couplers have none). A Force_Vector_TwoBody's input is its I marker's
 * place relative to J, set in the state its queries are answered from. */
static int evaluate(probe *p, int which, double t, int dflag, double *out)
{
    hx_binding *b = p->b;
    memset(out, 0, sizeof(double) * MAX_OUT);
    if (b->kind == HX_BIND_FORCE) {
        const hx_force *f = &p->s->model->forces[b->index];
        hx_place_relative(&p->s->frames, &p->frames, f->i_marker, f->j_marker, p->input[which],
                          p->input[which] + 6);
    } else if (b->kind >= HX_BIND_REQUEST) { /* the whole model's state is its input */
        double scale[12];
        hx_sample_model_frames(p->s, which == INPUT_A ? 3 : 8, &p->frames, scale);
    }
    double copy[MAX_IN]; /* a state equation may write into its arguments */
    memcpy(copy, p->input[which], sizeof copy);
    p->frames.time = t;
    hx_element_call(b, &p->frames, copy, 0, dflag, out);
    return hx_messages_stopped(b->messages) ? -1 : 0;
}

/* Times past every time the element was called at, spread as the checks'
 * samples 3, 5 and 8 are. */
static void choose_times(probe *p)
{
    static const int samples[TIMES] = {3, 5, 8};
    for (int k = 0; k < TIMES; ++k)
        p->time[k] = p->b->latest_time + hx_sample_time(p->s->model, samples[k]);
}

static void choose_inputs(probe *p)
{
    const hx_model *m = p->s->model;
    hx_binding *b = p->b;
    if (b->kind == HX_BIND_COUPLER) {
        const hx_coupler *c = &m->couplers[b->index];
        double q0[3] = {0}, lo[3] = {0}, hi[3] = {0};
        for (int i = 0; i < c->njoints; ++i)
            q0[i] = hx_joint_coordinate(&p->s->frames, c->joint[i], c->freedom[i]);
        hx_coupler_ranges(m, b->par, b->npar, c->njoints, q0, lo, hi);
        for (int i = 0; i < c->njoints; ++i) {
            p->input[INPUT_A][i] = lo[i] + 0.31 * (hi[i] - lo[i]);
            p->input[INPUT_B][i] = lo[i] + (0.77 - 0.1 * i) * (hi[i] - lo[i]);
        }
        p->ninput = c->njoints;
        return;
    }
    double scale[MAX_IN];
    if (b->kind >= HX_BIND_REQUEST) {
        p->ninput = 0; /* evaluate() sets the model's state A or B */
        return;
    }
    if (b->kind == HX_BIND_STATEEQN) {
        const hx_stateeqn *f = &m->stateeqns[b->index];
        hx_sample_stateeqn_states(p->s, b->index, 3, p->input[INPUT_A], p->input[INPUT_A] + f->nstate,
                                scale);
        hx_sample_stateeqn_states(p->s, b->index, 8, p->input[INPUT_B], p->input[INPUT_B] + f->nstate,
                                scale);
        p->ninput = f->nstate + f->ninput;
        return;
    }
    hx_sample_force_deformation(p->s, b->index, 3, p->input[INPUT_A], p->input[INPUT_A] + 6, scale);
    hx_sample_force_deformation(p->s, b->index, 8, p->input[INPUT_B], p->input[INPUT_B] + 6, scale);
    p->ninput = 12;
}

/* What a history produced: the outputs at A and time[AUDITED], those of its
 * first call, and what the host noted of the element meanwhile. */
typedef struct result {
    double audited[MAX_OUT], first[MAX_OUT];
    enum { RAN, STOPPED, SIGNALLED, EXITED } outcome;
    int code; /* the signal or the exit status */
    hx_noted_queries undeclared, refused;
    unsigned long long unoffered, misused;
    char stop_message[HX_TEXT_MAX];
} result;

static void run_history(probe *p, const history *h, result *r)
{
    hx_binding *b = p->b;
    memset(r, 0, sizeof *r);
    int stopped = 0;
    for (int k = 0; k < h->nsteps && !stopped; ++k) {
        const call_step *c = &h->step[k];
        stopped = evaluate(p, c->input, p->time[c->time], c->dflag,
                           k == 0 ? r->first : r->audited) != 0;
    }
    if (!stopped)
        stopped = evaluate(p, INPUT_A, p->time[AUDITED], 0, r->audited) != 0;
    if (!stopped && h->nsteps == 0)
        memcpy(r->first, r->audited, sizeof r->first);
    r->outcome = stopped ? STOPPED : RAN;
    r->undeclared = b->reported_undeclared;
    r->refused = b->reported_refused;
    r->unoffered = b->reported_unoffered, r->misused = b->reported_misused;
    if (stopped)
        snprintf(r->stop_message, sizeof r->stop_message, "%s", b->messages->stop_message);
}

static int read_all(int fd, void *buffer, size_t size)
{
    char *at = buffer;
    while (size > 0) {
        const ssize_t n = read(fd, at, size);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            return -1;
        at += n, size -= (size_t)n;
    }
    return 0;
}

/* The history in a process forked from this one, so that every history
 * starts from the same library state; once no process can be had, in this
 * one (isolated turns 0). What the host noted, and a STOP, are taken over. */
static void run_isolated(probe *p, const history *h, result *r, int *isolated)
{
    int fds[2] = {-1, -1};
    pid_t child = -1;
    fflush(stdout);
    fflush(stderr);
    if (*isolated && pipe(fds) == 0 && (child = fork()) < 0) {
        close(fds[0]);
        close(fds[1]);
    }
    if (child < 0) {
        *isolated = 0;
        run_history(p, h, r); /* in this process: what it notes is noted here */
        return;
    }
    if (child == 0) {
        close(fds[0]);
        prctl(PR_SET_PDEATHSIG, SIGKILL); /* a hang dies with the check that waits */
        run_history(p, h, r);
        const ssize_t n = write(fds[1], r, sizeof *r);
        _exit(n == (ssize_t)sizeof *r ? 0 : 1);
    }
    close(fds[1]);
    const int got = read_all(fds[0], r, sizeof *r);
    close(fds[0]);
    int status = 0;
    while (waitpid(child, &status, 0) < 0 && errno == EINTR)
        ;
    if (WIFSIGNALED(status)) {
        r->outcome = SIGNALLED, r->code = WTERMSIG(status);
    } else if (got != 0) {
        r->outcome = EXITED, r->code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    } else {
        hx_binding *b = p->b; /* the next history starts from what this one noted */
        b->reported_undeclared = r->undeclared;
        b->reported_refused = r->refused;
        b->reported_unoffered = r->unoffered, b->reported_misused = r->misused;
        if (r->outcome == STOPPED)
            hx_messages_adopt_stop(b->messages, r->stop_message);
    }
}

static const char *input_name(const hx_binding *b)
{
    switch (b->kind) {
    case HX_BIND_COUPLER: return "joint displacements";
    case HX_BIND_STATEEQN: return "states, then inputs";
    case HX_BIND_REQUEST:
    case HX_BIND_VARIABLE:
    case HX_BIND_DIFF:
    case HX_BIND_MOTION: return "a sampled state of the model's bodies and Control_Diff states";
    default: return "deformation and rate of I relative to J";
    }
}

int hx_audit_history(hx_session *s, hx_binding *b, FILE *out)
{
    probe p = {.s = s, .b = b};
    if (b->kind == HX_BIND_STATEEQN) {
        const hx_stateeqn *f = &s->model->stateeqns[b->index];
        if (f->nstate + f->ninput > MAX_IN || f->nstate + 6 > MAX_OUT) {
            fprintf(out, "  %s %d: history audit: %d states and %d inputs are more than it"
                    " compares (%d): FAIL\n", b->element, b->id, f->nstate, f->ninput, MAX_IN);
            return 1;
        }
    }
    if (hx_frames_clone(&p.frames, &s->frames) != 0)
        return 1;
    choose_inputs(&p);
    choose_times(&p);
    p.nout = hx_element_call_output_count(b);
    result r[HISTORIES];
    int isolated = 1, failed = -1, component = 0;
    for (int h = 0; h < HISTORIES && failed < 0; ++h) {
        run_isolated(&p, &histories[h], &r[h], &isolated);
        if (r[h].outcome != RAN) {
            failed = h;
            break;
        }
        for (int k = 0; h > 0 && k < p.nout && failed < 0; ++k)
            if (memcmp(&r[0].audited[k], &r[h].audited[k], sizeof(double)) != 0)
                failed = h, component = k;
    }
    hx_frames_free(&p.frames);
    if (failed >= 0 && r[failed].outcome == STOPPED) {
        fprintf(out, "  %s %d: history audit: the element stopped the run in the calls %s\n",
                b->element, b->id, histories[failed].what);
        return 1;
    }
    if (failed >= 0 && r[failed].outcome == SIGNALLED) {
        fprintf(out, "  %s %d: history audit: FAIL: the element crashed with signal %d (%s) in"
                " the calls %s\n", b->element, b->id, r[failed].code, strsignal(r[failed].code),
                histories[failed].what);
        return 1;
    }
    if (failed >= 0 && r[failed].outcome == EXITED) {
        fprintf(out, "  %s %d: history audit: FAIL: the process ended (exit status %d) in the"
                " calls %s: the library exits instead of returning\n", b->element, b->id,
                r[failed].code, histories[failed].what);
        return 1;
    }
    char input[1024] = "";
    if (p.ninput > 0) {
        input[0] = ':', input[1] = ' ';
        hx_format_values(input + 2, sizeof input - 2, p.input[INPUT_A], p.ninput, 9);
    }
    if (failed >= 0) {
        fprintf(out, "  %s %d: history audit: FAIL: a hidden state: at the same input A (%s%s)"
                " and time t = %.9g, output %d was %.17g %s, and %.17g %s: the outputs depend on"
                " earlier calls (a value kept from an earlier call), which breaks implicit"
                " solvers, differencing and restarts\n", b->element, b->id, input_name(b), input,
                p.time[AUDITED], component + 1, r[0].audited[component], histories[0].what,
                r[failed].audited[component], histories[failed].what);
        return 1;
    }
    const int last = HISTORIES - 1; /* its first call: A at the earlier time */
    const int time_dependent =
        memcmp(r[last].first, r[0].audited, sizeof(double) * (size_t)p.nout) != 0;
    fprintf(out, "  %s %d: history audit: at input A and t = %.9g, bit-identical outputs after %d"
            " different histories (repeated, after calls at another input, at earlier and"
            " later times, with dflag)%s%s: pass\n", b->element, b->id, p.time[AUDITED],
            HISTORIES, isolated ? ", each from the same start in a process of its own"
                                : ", one after another in this process",
            time_dependent ? "; the output depends on time" : "");
    return 0;
}
