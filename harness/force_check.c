/* Partials and dependency checks of force elements (force_check.h). */
#include "force_check.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "derivative_check.h"
#include "element_probe.h"
#include "host.h"
#include "vecmath.h"

/* Deterministic numbers in [-1, 1]. */
static double jitter(unsigned *seed)
{
    *seed = *seed * 1664525u + 1013904223u;
    return ((*seed >> 8) & 0xffff) / 32767.5 - 1.0;
}

void hx_sample_element_state(const hx_session *s, int force, int k, double disp[6],
                             double velo[6], double scale[12])
{
    const hx_model *m = s->model;
    const double L = m->has_units ? m->unit_scales[USRSUB_UNIT_LENGTH] : 1e-3;
    const double T = m->has_units ? m->unit_scales[USRSUB_UNIT_TIME] : 1.0;
    const double A = m->has_units ? m->unit_scales[USRSUB_UNIT_ANGLE] : 1.0;
    const double length = 1e-3 / L, angle = 0.02 / A; /* 1 mm and 0.02 rad */
    for (int i = 0; i < 6; ++i) {
        scale[i] = i < 3 ? length : angle;
        scale[6 + i] = scale[i] / (0.01 / T); /* moved over 10 ms */
    }
    hx_element_state(s, force, disp, velo);
    if (k == 0)
        return;
    unsigned seed = 2654435761u * (unsigned)k;
    const double amplitude = 0.5 + 9.5 * (k - 1) / (HX_FORCE_SAMPLES - 2.0);
    for (int i = 0; i < 6; ++i) {
        disp[i] += amplitude * scale[i] * jitter(&seed);
        velo[i] += amplitude * scale[6 + i] * jitter(&seed);
    }
}

/* ---- FIESUB partials ------------------------------------------------------------ */

typedef struct field_sampler {
    hx_binding *b;
} field_sampler;

static int sample_field(void *ctx, const double *x, double *out)
{
    field_sampler *fs = ctx;
    double dfd[36], dfv[36];
    hx_call_fiesub(fs->b, 0.0, x, x + 6, 1, 0, out, dfd, dfv, NULL);
    if (hx_host_stop_requested())
        return -1;
    for (int k = 0; k < 6; ++k)
        if (!isfinite(out[k]))
            return -1;
    return 0;
}

int hx_check_field_partials(hx_session *s, hx_binding *b)
{
    static const char *const names[12] = {"x", "y", "z", "ax", "ay", "az",
                                          "vx", "vy", "vz", "wx", "wy", "wz"};
    hx_worst worst = {0};
    field_sampler fs = {b};
    for (int k = 0; k < HX_FORCE_SAMPLES; ++k) {
        double x[12], scale[12], F[6], J[72];
        hx_sample_element_state(s, b->index, k, x, x + 6, scale);
        hx_call_fiesub(b, 0.0, x, x + 6, 0, 0, F, J, J + 36, NULL);
        if (hx_host_stop_requested())
            return 1;
        for (int i = 0; i < 12; ++i) {
            double column[6], floor[6];
            for (int j = 0; j < 6; ++j) {
                column[j] = J[(i < 6 ? 0 : 36) + j + 6 * (i % 6)];
                double typical = 0.0; /* the largest change of F_j over typical steps */
                for (int c = 0; c < 12; ++c)
                    typical = fmax(typical, fabs(J[(c < 6 ? 0 : 36) + j + 6 * (c % 6)]) * scale[c]);
                floor[j] = fmax(1e-6 * typical / scale[i], 1e-300);
            }
            const double h = 1e-6 * fmax(fabs(x[i]), scale[i]);
            const double e = hx_check_column(sample_field, &fs, x, i, 6, column, floor, h);
            hx_worst_update(&worst, e, "d/d%s at sample %d", names[i], k);
        }
    }
    printf("  %s %d: dfddis and dfdvel against central differences of the field: worst relative"
           " error %.2g (%s), %d columns at %d states: %s\n", b->element, b->id, worst.error,
           worst.where, worst.compared, HX_FORCE_SAMPLES, worst.failed ? "FAIL" : "pass");
    return worst.failed ? 1 : 0;
}

/* ---- GFOSUB dependency audit ------------------------------------------------------ */

static int gfosub_with(hx_session *s, hx_binding *b, const hx_frame *frames, hx_call *call,
                       double out[6])
{
    hx_host_set_frames(frames, 0.0);
    hx_call_gfosub(b, 0.0, 0, 0, out, call);
    hx_host_set_frames(s->frames, 0.0);
    return hx_host_stop_requested() ? -1 : 0;
}

static int differs(const double *a, const double *b, int n, double tolerance)
{
    for (int k = 0; k < n; ++k)
        if (fabs(a[k] - b[k]) > tolerance * (1.0 + fabs(a[k])))
            return 1;
    return 0;
}

/* Moves one of body k's twelve states by delta. */
static void perturb_body(hx_frame *f, int c, double delta)
{
    double e[3] = {0, 0, 0};
    e[c % 3] = 1.0;
    if (c < 3)
        f->p[c] += delta;
    else if (c < 6) {
        double R[9];
        m3_axis_angle(R, e, delta);
        m3_mul(f->R, R, f->R);
    } else if (c < 9)
        f->v[c - 6] += delta;
    else
        f->w[c - 9] += delta;
}

/* Body states of the audit's frames that move the force but no declared
 * query; returns the failures, counting what moves the force. */
static int audit_states(hx_session *s, hx_binding *b, const hx_frame *base, hx_frame *moved,
                        const double scale[12], const double out0[6], int *influencing,
                        int *checked)
{
    static const char *const states[12] = {"x", "y", "z", "rotation about x", "rotation about y",
                                           "rotation about z", "vx", "vy", "vz", "wx", "wy", "wz"};
    const hx_model *m = s->model;
    int failures = 0;
    char text[512];
    for (int k = 0; k < m->nbodies; ++k) {
        if (m->bodies[k].is_ground)
            continue;
        for (int c = 0; c < 12; ++c) {
            memcpy(moved, base, sizeof *moved * (size_t)m->nbodies);
            perturb_body(&moved[k], c, 1e-5 * scale[c < 3 ? 0 : c < 6 ? 3 : c < 9 ? 6 : 9]);
            hx_call call;
            double out1[6];
            hx_binding_call_init(b, &call, 0);
            if (gfosub_with(s, b, moved, &call, out1) != 0)
                return failures + 1;
            ++*checked;
            if (!differs(out0, out1, 6, 1e-11))
                continue;
            ++*influencing;
            int reached = 0;
            for (int q = 0; q < b->deps.count && !reached; ++q) {
                const hx_query *dq = &b->deps.query[q];
                double a0[6], a1[6];
                const int n0 = hx_answer_query(m, base, dq->fnc, dq->ipar, dq->nsize, a0);
                const int n1 = hx_answer_query(m, moved, dq->fnc, dq->ipar, dq->nsize, a1);
                reached = n0 > 0 && n0 == n1 && differs(a0, a1, n0, 1e-13);
            }
            if (!reached) {
                printf("  %s %d: FAIL: the force depends on body %d's %s, which no declared query"
                       " (%s) reaches\n", b->element, b->id, m->bodies[k].id, states[c],
                       hx_dependencies_text(&b->deps, text, sizeof text));
                ++failures;
            }
        }
    }
    return failures;
}

int hx_audit_dependencies(hx_session *s, hx_binding *b)
{
    const hx_model *m = s->model;
    const hx_force *f = &m->forces[b->index];
    const int nb = m->nbodies;
    hx_frame *base = malloc(sizeof *base * (size_t)nb), *moved = malloc(sizeof *moved * (size_t)nb);
    int failures = 0, checked = 0, influencing = 0;
    unsigned used[HX_MAX_QUERIES] = {0};
    int counts[HX_MAX_QUERIES] = {0};
    char text[512];
    /* deformed, moving states reaching 10 mm and 0.2 rad, so that every term
     * (contacts beyond gaps included) is awake in some of them */
    for (int sample = 1; sample < HX_FORCE_SAMPLES && failures == 0; ++sample) {
        double disp[6], velo[6], scale[12], out0[6], out1[6];
        hx_sample_element_state(s, b->index, sample, disp, velo, scale);
        hx_place_relative(m, s->frames, base, f->i_marker, f->j_marker, disp, velo);
        for (int k = 0; k < nb; ++k) /* J's body moves too, to expose frame terms */
            if (!m->bodies[k].is_ground && k != m->markers[f->i_marker].body)
                for (int c = 6; c < 12; ++c)
                    perturb_body(&base[k], c, 0.3 * scale[c < 9 ? 6 : 9]);
        hx_call call;
        hx_binding_call_init(b, &call, 0);
        if (gfosub_with(s, b, base, &call, out0) != 0) {
            ++failures;
            break;
        }
        if (call.undeclared > 0) {
            char q[64];
            printf("  %s %d: FAIL: reads %s outside the dependencies it declared (%s)\n",
                   b->element, b->id, hx_query_text(&call.first_undeclared, q, sizeof q),
                   hx_dependencies_text(&b->deps, text, sizeof text));
            ++failures;
        }
        failures += audit_states(s, b, base, moved, scale, out0, &influencing, &checked);
        for (int q = 0; q < b->deps.count; ++q) {
            double a[6];
            const hx_query *dq = &b->deps.query[q];
            counts[q] = hx_answer_query(m, base, dq->fnc, dq->ipar, dq->nsize, a);
            for (int c = 0; c < counts[q]; ++c) {
                hx_binding_call_init(b, &call, 0);
                call.perturb_query = q;
                call.perturb_component = c;
                call.perturb_delta = 1e-6 * (1.0 + fabs(a[c]));
                if (gfosub_with(s, b, base, &call, out1) != 0) {
                    ++failures;
                    break;
                }
                if (differs(out0, out1, 6, 1e-12))
                    used[q] |= 1u << c;
            }
        }
    }
    char used_text[512] = "";
    size_t used_len = 0;
    for (int q = 0; q < b->deps.count; ++q) {
        char qt[64];
        hx_query_text(&b->deps.query[q], qt, sizeof qt);
        used_len += (size_t)snprintf(used_text + used_len, sizeof used_text - used_len,
                                     "%s%s uses %d of %d", q ? ", " : "", qt,
                                     __builtin_popcount(used[q]), counts[q]);
        if (used[q] == 0) {
            printf("  %s %d: FAIL: declares %s but its force depends on it at none of the %d"
                   " states\n", b->element, b->id, qt, HX_FORCE_SAMPLES - 1);
            ++failures;
        }
    }
    printf("  %s %d: dependency audit at %d states: declared %s; %d of %d body-state changes"
           " move the force, all reached by a declared query; %s: %s\n", b->element, b->id,
           HX_FORCE_SAMPLES - 1, hx_dependencies_text(&b->deps, text, sizeof text), influencing,
           checked, used_text[0] ? used_text : "no queries", failures ? "FAIL" : "pass");
    hx_host_set_frames(s->frames, 0.0);
    free(base);
    free(moved);
    return failures || hx_host_stop_requested() ? 1 : 0;
}
