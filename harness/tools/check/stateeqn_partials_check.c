/*
 * A Force_StateEqn's partial routines (checks.h): YFOXX, YFOXU, YFOYX and
 * YFOYU against central differences of YFOSUB, column by column (every state
 * and every input varied on its own), at the element's initial state and at
 * the sampled states around it; each routine judged on its own, naming its
 * worst entry by row and column and the sample it was found at. A column that
 * fails at the usual steps (h, h/10, h/100) is tried at up to 10^4 h too: a
 * wrong partial is wrong at every step. A routine the
 * library does not export is said, not failed: the harness differences
 * YFOSUB in its place.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "host/invoke.h"
#include "base/finite.h"
#include "tools/check/checks.h"
#include "tools/check/derivative_check.h"
#include "tools/check/element_samples.h"

enum { XX, XU, YX, YU };

static const char *const matrix_names[4] = {"pxxmat", "pxumat", "pyxmat", "pyumat"};
static const char *const output_names[6] = {"Fx", "Fy", "Fz", "Tx", "Ty", "Tz"};

typedef struct state_sampler {
    hx_session *session;
    hx_binding *b;
    hx_frames *frames;
    int ns, ni;
    int outputs;         /* 0: the rates (stated), 1: the outputs */
    double *copy, *rates, out[6];
} state_sampler;

/* YFOSUB at v = (states, inputs): the rates or the outputs. */
static int sample_stateeqn(void *ctx, const double *v, double *out)
{
    state_sampler *ss = ctx;
    memcpy(ss->copy, v, sizeof(double) * (size_t)(ss->ns + ss->ni)); /* it may write there */
    hx_invoke_stateeqn(ss->b, ss->frames, ss->copy, ss->copy + ss->ns, 1, 0, ss->rates, ss->out, NULL);
    if (hx_messages_stopped(ss->b->messages) || !hx_all_finite(ss->rates, ss->ns) ||
        !hx_all_finite(ss->out, 6))
        return -1;
    memcpy(out, ss->outputs ? ss->out : ss->rates,
           sizeof(double) * (size_t)(ss->outputs ? 6 : ss->ns));
    return 0;
}

/* The whole Jacobian at v, rows (stated, outputs), columns (states, inputs):
 * the library's blocks where it exports them, central differences of YFOSUB
 * for the others (those are not judged; they set the typical sizes). */
static int jacobian_at(state_sampler *ss, double *v, const double *scale, double *J)
{
    const int ns = ss->ns, ni = ss->ni, rows = ns + 6;
    double matrix[4][64 * 64];
    for (int r = 0; r < 4; ++r) {
        if (ss->b->fn.stateeqn.partial[r] == NULL)
            continue;
        memcpy(ss->copy, v, sizeof(double) * (size_t)(ns + ni));
        hx_invoke_stateeqn_partial(ss->b, r, ss->frames, ss->copy, ss->copy + ns, matrix[r], NULL);
        const int size = (r < YX ? ns : 6) * (r == XX || r == YX ? ns : ni);
        if (hx_messages_stopped(ss->b->messages) || !hx_all_finite(matrix[r], size))
            return -1 - r;
    }
    for (int c = 0; c < ns + ni; ++c) {
        double up[70], down[70];
        const double keep = v[c], h = 1e-6 * fmax(fabs(keep), scale[c]);
        for (int side = 0; side < 2; ++side) {
            v[c] = keep + (side ? -h : h);
            for (ss->outputs = 0; ss->outputs < 2; ++ss->outputs)
                if (sample_stateeqn(ss, v, (side ? down : up) + (ss->outputs ? ns : 0)) != 0) {
                    v[c] = keep;
                    return -5;
                }
        }
        v[c] = keep;
        const int state = c < ns, j = state ? c : c - ns;
        for (int i = 0; i < rows; ++i) {
            const int r = i < ns ? (state ? XX : XU) : (state ? YX : YU);
            const int row = i < ns ? i : i - ns, height = i < ns ? ns : 6;
            J[i + rows * c] = ss->b->fn.stateeqn.partial[r] != NULL ? matrix[r][row + height * j]
                                                              : (up[i] - down[i]) / (2.0 * h);
        }
    }
    return 0;
}

static void describe_entry(char *text, size_t size, const hx_model *m, const hx_stateeqn *f,
                           int r, int row, int column, int sample, double t)
{
    char output[32], input[48];
    if (r < YX)
        snprintf(output, sizeof output, "dstated%d", row + 1);
    else
        snprintf(output, sizeof output, "d%s", output_names[row]);
    if (r == XX || r == YX)
        snprintf(input, sizeof input, "dstate%d", column + 1);
    else {
        const hx_variable *v = &m->variables[f->inputs[column]];
        snprintf(input, sizeof input, "dinput%d (%s)", column + 1,
                 v->varsub ? "a VARSUB" : v->program != NULL ? "an expression"
                 : v->function[0] != '\0' ? v->function : "a number");
    }
    snprintf(text, size, "%s[%d + %d*%d] = %s/%s at sample %d (t = %g)", matrix_names[r], row,
             r < YX ? f->nstate : 6, column, output, input, sample, t);
}

/* One sample: every column of every exported routine against differences. */
static int check_sample(state_sampler *ss, const hx_model *m, const hx_stateeqn *f, int k,
                        hx_worst worst[4])
{
    const int ns = ss->ns, ni = ss->ni, rows = ns + 6;
    double v[64], scale[64], J[70 * 64];
    hx_sample_stateeqn_states(ss->session, ss->b->index, k, v, v + ns, scale);
    ss->frames->time = hx_sample_time(m, k);
    const int status = jacobian_at(ss, v, scale, J);
    if (status != 0)
        return status;
    for (int c = 0; c < ns + ni; ++c)
        for (ss->outputs = 0; ss->outputs < 2; ++ss->outputs) {
            const int r = ss->outputs ? (c < ns ? YX : YU) : (c < ns ? XX : XU);
            const int first = ss->outputs ? ns : 0, height = ss->outputs ? 6 : ns;
            if (ss->b->fn.stateeqn.partial[r] == NULL || height == 0)
                continue;
            double column[64], floor[64];
            for (int i = 0; i < height; ++i) {
                column[i] = J[first + i + rows * c];
                double typical = 0.0; /* the largest change of this output over typical steps */
                for (int cc = 0; cc < ns + ni; ++cc)
                    typical = fmax(typical, fabs(J[first + i + rows * cc]) * scale[cc]);
                floor[i] = fmax(1e-6 * typical / scale[c], 1e-300);
            }
            const double h = 1e-6 * fmax(fabs(v[c]), scale[c]);
            int row, wide_row;
            double e = hx_check_column(sample_stateeqn, ss, v, c, height, column, floor, h, &row);
            /* an output that is a difference of larger terms (the friction torque's,
             * a state equation's internal balance) carries more rounding than the
             * 4 eps the column's noise floor allows for: wider steps too */
            for (double wide = 100.0 * h; !(e <= HX_DERIVATIVE_TOLERANCE) && wide <= 1e4 * h;
                 wide *= 100.0) {
                const double e_wide = hx_check_column(sample_stateeqn, ss, v, c, height, column,
                                                      floor, wide, &wide_row);
                if (e_wide < e)
                    e = e_wide, row = wide_row;
            }
            char where[256];
            describe_entry(where, sizeof where, m, f, r, row, c < ns ? c : c - ns, k, ss->frames->time);
            hx_worst_update(&worst[r], e, "%s", where);
        }
    return 0;
}

int hx_check_state_partials(hx_session *s, hx_binding *b, FILE *out)
{
    const hx_model *m = s->model;
    const hx_stateeqn *f = &m->stateeqns[b->index];
    static const char *const meaning[4] = {"d stated/d states", "d stated/d inputs",
                                           "d outputs/d states", "d outputs/d inputs"};
    if (f->nstate + f->ninput > 64) {
        fprintf(out, "  %s %d: %d states and %d inputs: the partial routines are checked up to 64"
                " in all: FAIL\n", b->element, b->id, f->nstate, f->ninput);
        return 1;
    }
    hx_frames sample;
    double copy[64], rates[64];
    if (hx_frames_clone(&sample, &s->frames) != 0)
        return 1;
    state_sampler ss = {s, b, &sample, f->nstate, f->ninput, 0, copy, rates, {0}};
    hx_worst worst[4];
    memset(worst, 0, sizeof worst);
    int failures = 0, status = 0, k = 0;
    for (; k < HX_FORCE_SAMPLES && status == 0; ++k)
        status = check_sample(&ss, m, f, k, worst);
    hx_frames_free(&sample);
    if (status != 0) {
        fprintf(out, "  %s %d: %s returned non-finite values or stopped the run at sample %d:"
                " FAIL\n", b->element, b->id, status >= -4 ? b->names[-status] : b->names[0],
                k - 1);
        ++failures;
    }
    for (int r = 0; r < 4; ++r) {
        const int empty = (r != YU && f->nstate == 0) || (r % 2 == 1 && f->ninput == 0);
        if (b->fn.stateeqn.partial[r] == NULL)
            fprintf(out, "  %s %d: %s (%s): not exported; the harness differences %s in its"
                    " place\n", b->element, b->id, b->names[1 + r], meaning[r], b->names[0]);
        else if (empty)
            fprintf(out, "  %s %d: %s (%s): empty (%s), nothing to compare\n", b->element, b->id,
                    b->names[1 + r], meaning[r], f->nstate == 0 ? "no states" : "no inputs");
        else if (status == 0) {
            fprintf(out, "  %s %d: %s (%s) against central differences of %s: worst relative"
                    " error %.2g at %s, %d columns at %d states: %s\n", b->element, b->id,
                    b->names[1 + r], meaning[r], b->names[0], worst[r].error, worst[r].where,
                    worst[r].compared, HX_FORCE_SAMPLES, worst[r].failed ? "FAIL" : "pass");
            failures += worst[r].failed != 0;
        }
    }
    return failures;
}
