/*
 * The dependency audit of a routine that asks the host for the state
 * (checks.h): a GFOSUB (VFOSUB, VTOSUB, SFOSUB), REQSUB, VARSUB or DIFSUB. At
 * deformed, moving states spread over the first second of the model (every
 * term awake in some of them; a force's I marker moved relative to J, any
 * other routine's bodies all moved): every body state (position,
 * orientation, velocity, angular velocity) and Control_Diff state the
 * outputs depend on, by finite differences, must be reached by a query
 * declared in the dependency pass; every declared query must change the
 * outputs at one of the states at least when its answer changes. Two calls
 * in a row at the same state and time must give the same outputs: a routine
 * that does not keeps a value from an earlier call, and fails here.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/vecmath.h"
#include "host/invoke.h"
#include "host/element_call.h"
#include "sim/dynamics/element_at.h"
#include "frames/measures.h"
#include "tools/check/checks.h"
#include "tools/check/element_samples.h"

#define MAX_OUT 8

static int outputs_at(hx_binding *b, const hx_frames *fr, hx_call *call, double out[MAX_OUT])
{
    hx_call local;
    if (call == NULL) {
        hx_binding_call_init(b, &local, 0, fr, 0);
        call = &local;
    }
    if (b->kind == HX_BIND_FORCE)
        hx_invoke_force(b, fr, 0, 0, out, call);
    else
        hx_invoke_routine(b, fr, 0, 0, out, call);
    return hx_messages_stopped(b->messages) ? -1 : 0;
}

static int differs(const double *a, const double *b, int n, double tolerance)
{
    for (int k = 0; k < n; ++k)
        if (fabs(a[k] - b[k]) > tolerance * (1.0 + fabs(a[k])))
            return 1;
    return 0;
}

/* Moves one of a body's twelve states by delta. */
static void perturb_body(hx_frame *f, int c, double delta)
{
    double e[3] = {0, 0, 0};
    e[c % 3] = 1.0;
    if (c < 3) {
        f->p[c] += delta;
    } else if (c < 6) {
        double R[9];
        m3_axis_angle(R, e, delta);
        m3_mul(f->R, R, f->R);
    } else if (c < 9) {
        f->v[c - 6] += delta;
    } else {
        f->w[c - 9] += delta;
    }
}

typedef struct audit {
    hx_session *s;
    hx_binding *b;
    hx_frames base, moved;
    int nout;           /* outputs compared */
    const char *what;   /* "force", or "output" for the routines that are not forces */
    int failures, states, checked, influencing, unreached;
    int counts[HX_MAX_QUERIES];
    int capacity;              /* the most numbers any query answers (hx_query_capacity) */
    double *answer0, *answer1; /* capacity each */
    /* which components of query q move the outputs: used[q * capacity + c] */
    unsigned char *used;
    FILE *out;
} audit;

/* The name of value k a force routine returns, in its entry type's layout. */
static const char *value_name(const hx_binding *b, int k)
{
    static const char *const names[6] = {"Fx", "Fy", "Fz", "Tx", "Ty", "Tz"};
    switch (b->part) {
    case HX_OUTPUT_TORQUE: return names[3 + k];
    case HX_OUTPUT_SCALAR_FORCE: return "its force";
    case HX_OUTPUT_SCALAR_TORQUE: return "its torque";
    default: return names[k];
    }
}

/* Two calls in a row at one state and time that disagree. */
static void report_unrepeatable(const audit *a, const double *first, const double *second)
{
    static const char *const consequence = "the routine keeps a value from an earlier call (a"
                                           " hidden state), which breaks implicit solvers,"
                                           " differencing and restarts";
    int k = 0;
    while (k < a->nout - 1 && memcmp(&first[k], &second[k], sizeof first[k]) == 0)
        ++k;
    if (a->b->kind != HX_BIND_FORCE) {
        fprintf(a->out, "  %s %d: FAIL: two calls in a row at the same state and time t = %.9g"
                " return output %d = %.17g, then %.17g: %s\n", a->b->element, a->b->id,
                a->base.time, k + 1, first[k], second[k], consequence);
        return;
    }
    double disp[6], velo[6]; /* as the host measures them, J's motion included */
    hx_force_deformation(&a->base, a->b->index, disp, velo);
    fprintf(a->out, "  %s %d: FAIL: two calls in a row at the same state and time t = %.9g"
            " (deformation %.9g %.9g %.9g %.9g %.9g %.9g, rate %.9g %.9g %.9g %.9g %.9g %.9g of"
            " I relative to J) return %s = %.17g, then %.17g: %s\n", a->b->element, a->b->id,
            a->base.time, disp[0], disp[1], disp[2], disp[3], disp[4], disp[5], velo[0],
            velo[1], velo[2], velo[3], velo[4], velo[5], value_name(a->b, k), first[k],
            second[k], consequence);
}

/* An output that is not a number at the base state: named, 1; else 0. */
static int report_non_finite(const audit *a, const double *out)
{
    for (int k = 0; k < a->nout; ++k)
        if (!isfinite(out[k])) {
            fprintf(a->out, "  %s %d: FAIL: output %d is %g at t = %.9g (a sampled state): a"
                    " solver stops there\n", a->b->element, a->b->id, k + 1, out[k],
                    a->base.time);
            return 1;
        }
    return 0;
}

/* Whether a declared query's answer differs between the base and moved states. */
static int reached_by_declared(const audit *a)
{
    const hx_binding *b = a->b;
    for (int q = 0; q < b->deps.count; ++q) {
        const hx_query *dq = &b->deps.query[q];
        double *a0 = a->answer0, *a1 = a->answer1;
        const int n0 = hx_answer_query(&a->base, dq->fnc, dq->ipar, dq->nsize, dq->is_array, a0);
        const int n1 = hx_answer_query(&a->moved, dq->fnc, dq->ipar, dq->nsize, dq->is_array, a1);
        if (n0 > 0 && n0 == n1 && differs(a0, a1, n0, 1e-13))
            return 1;
    }
    return 0;
}

/* One change of the state (a->moved) that moves the outputs must be reached
 * by a declared query; `what` names the state changed. 0, or -1 (stopped). */
static int judge_change(audit *a, const double *out0, const char *what)
{
    double out1[MAX_OUT];
    char text[512];
    if (outputs_at(a->b, &a->moved, NULL, out1) != 0)
        return -1;
    ++a->checked;
    if (!differs(out0, out1, a->nout, 1e-11))
        return 0;
    ++a->influencing;
    if (!reached_by_declared(a)) {
        fprintf(a->out, "  %s %d: FAIL: the %s depends on %s, which no declared query (%s)"
                " reaches\n", a->b->element, a->b->id, a->what, what,
                hx_dependencies_text(&a->b->deps, text, sizeof text));
        ++a->unreached;
        ++a->failures;
    }
    return 0;
}

/* Body and Control_Diff states that move the outputs but no declared query. */
static int audit_states(audit *a, const double scale[12], const double *out0)
{
    static const char *const states[12] = {"x", "y", "z", "rotation about x", "rotation about y",
                                           "rotation about z", "vx", "vy", "vz", "wx", "wy", "wz"};
    const hx_model *m = a->s->model;
    char what[96];
    for (int k = 0; k < m->nbodies; ++k) {
        if (m->bodies[k].is_ground)
            continue;
        for (int c = 0; c < 12; ++c) {
            hx_frames_copy(&a->moved, &a->base);
            perturb_body(&a->moved.bodies[k], c, 1e-5 * scale[c < 3 ? 0 : c < 6 ? 3 : c < 9 ? 6 : 9]);
            hx_frames_update(&a->moved);
            snprintf(what, sizeof what, "body %d's %s", m->bodies[k].id, states[c]);
            if (judge_change(a, out0, what) != 0)
                return -1;
        }
    }
    for (int k = 0; k < m->nroutines; ++k) {
        const hx_routine *r = &m->routines[k];
        if (r->kind != HX_ROUTINE_DIFF)
            continue;
        hx_frames_copy(&a->moved, &a->base);
        double *value = &a->moved.diffs[2 * r->slot];
        *value += 1e-5 * (1.0 + fabs(*value));
        snprintf(what, sizeof what, "Control_Diff %d's state", r->id);
        if (judge_change(a, out0, what) != 0)
            return -1;
    }
    return 0;
}

/* Which components of each declared query move the outputs at the base state. */
static int audit_queries(audit *a, const double *out0)
{
    hx_binding *b = a->b;
    for (int q = 0; q < b->deps.count; ++q) {
        double *v = a->answer0;
        const hx_query *dq = &b->deps.query[q];
        a->counts[q] = hx_answer_query(&a->base, dq->fnc, dq->ipar, dq->nsize, dq->is_array, v);
        for (int c = 0; c < a->counts[q]; ++c) {
            hx_call call;
            double out1[MAX_OUT];
            hx_binding_call_init(b, &call, 0, &a->base, 0);
            call.perturb_query = q;
            call.perturb_component = c;
            call.perturb_delta = 1e-6 * (1.0 + fabs(v[c]));
            if (outputs_at(b, &a->base, &call, out1) != 0)
                return -1;
            if (differs(out0, out1, a->nout, 1e-12))
                a->used[(size_t)q * (size_t)a->capacity + (size_t)c] = 1;
        }
    }
    return 0;
}

/* Base state `sample`: a force's I marker moved relative to J, and J's body
 * moving too, to expose frame terms; any other routine's bodies all moved. */
static void place_sample(audit *a, int sample, double scale[12])
{
    hx_session *s = a->s;
    const hx_model *m = s->model;
    if (a->b->kind != HX_BIND_FORCE) {
        hx_sample_model_frames(s, sample, &a->base, scale);
        return;
    }
    const hx_force *f = &m->forces[a->b->index];
    double disp[6], velo[6];
    hx_sample_force_deformation(s, a->b->index, sample, disp, velo, scale);
    hx_place_relative(&s->frames, &a->base, f->i_marker, f->j_marker, disp, velo);
    for (int k = 0; k < m->nbodies; ++k)
        if (!m->bodies[k].is_ground && k != m->markers[f->i_marker].body)
            for (int c = 6; c < 12; ++c)
                perturb_body(&a->base.bodies[k], c, 0.3 * scale[c < 9 ? 6 : 9]);
    hx_frames_update(&a->base);
}

/* The closing line: what was declared, what moved the outputs, what was used. */
static void summarize(audit *a, double t_last)
{
    hx_binding *b = a->b;
    const hx_model *m = a->s->model;
    char declared[512], used_text[512] = "";
    size_t used_len = 0;
    for (int q = 0; q < b->deps.count; ++q) {
        char qt[64];
        hx_query_text(&b->deps.query[q], qt, sizeof qt);
        int used = 0;
        for (int c = 0; c < a->counts[q]; ++c)
            used += a->used[(size_t)q * (size_t)a->capacity + (size_t)c];
        if (used_len < sizeof used_text) /* else the line is cut short */
            used_len += (size_t)snprintf(used_text + used_len, sizeof used_text - used_len,
                                         "%s%s uses %d of %d", q ? ", " : "", qt, used,
                                         a->counts[q]);
        if (used == 0 && a->failures == 0) {
            fprintf(a->out, "  %s %d: FAIL: declares %s but its %s depends on it at none of the"
                    " %d states\n", b->element, b->id, qt, a->what, HX_FORCE_SAMPLES - 1);
            ++a->failures;
        }
    }
    hx_dependencies_text(&b->deps, declared, sizeof declared);
    char reach[160];
    if (a->influencing == 0)
        snprintf(reach, sizeof reach, "none moves the %s", a->what);
    else if (a->unreached == 0)
        snprintf(reach, sizeof reach, "all of them reached by a declared query");
    else
        snprintf(reach, sizeof reach, "%d of them reached by no declared query", a->unreached);
    fprintf(a->out, "  %s %d: dependency audit at %d states, t from %g to %g: declared %s; %d of"
            " %d state changes move the %s, %s; %s: %s\n", b->element, b->id, a->states,
            hx_sample_time(m, 1), t_last, declared, a->influencing, a->checked, a->what, reach,
            used_text[0] ? used_text : "no queries declared", a->failures ? "FAIL" : "pass");
}

static void audit_free(audit *a)
{
    hx_frames_free(&a->base);
    hx_frames_free(&a->moved);
    free(a->answer0);
    free(a->answer1);
    free(a->used);
}

int hx_audit_dependencies(hx_session *s, hx_binding *b, FILE *out)
{
    const hx_model *m = s->model;
    audit a;
    memset(&a, 0, sizeof a);
    a.s = s, a.b = b, a.out = out;
    /* the values the routine itself returns, in its entry type's layout: what
     * the harness makes of them (their axes, a scalar's direction) is its own */
    a.nout = hx_element_call_output_count(b);
    a.what = b->kind == HX_BIND_FORCE ? "force" : "output";
    a.capacity = hx_query_capacity(m);
    const size_t capacity = (size_t)a.capacity;
    a.answer0 = malloc(sizeof(double) * capacity);
    a.answer1 = malloc(sizeof(double) * capacity);
    a.used = calloc(HX_MAX_QUERIES * capacity, 1);
    if (a.answer0 == NULL || a.answer1 == NULL || a.used == NULL || hx_frames_clone(&a.base, &s->frames) != 0 ||
        hx_frames_clone(&a.moved, &s->frames) != 0) {
        fprintf(out, "  %s %d: FAIL: out of memory for the dependency audit\n", b->element, b->id);
        audit_free(&a);
        return 1;
    }
    double t_last = 0.0;
    for (int sample = 1; sample < HX_FORCE_SAMPLES && a.failures == 0; ++sample) {
        double scale[12], out0[MAX_OUT], again[MAX_OUT];
        ++a.states;
        place_sample(&a, sample, scale);
        a.base.time = t_last = hx_sample_time(m, sample);
        if (outputs_at(b, &a.base, NULL, out0) != 0 || outputs_at(b, &a.base, NULL, again) != 0) {
            ++a.failures;
            break;
        }
        if (report_non_finite(&a, out0) != 0) {
            ++a.failures;
            break;
        }
        if (memcmp(out0, again, sizeof(double) * (size_t)a.nout) != 0) {
            report_unrepeatable(&a, out0, again);
            audit_free(&a);
            return 1; /* nothing else can be judged of outputs that do not repeat */
        }
        if (audit_states(&a, scale, out0) != 0 || audit_queries(&a, out0) != 0) {
            ++a.failures;
            break;
        }
    }
    summarize(&a, t_last);
    audit_free(&a);
    return a.failures ? 1 : 0;
}
