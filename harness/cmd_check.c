/*
 * usrsub-harness check: every user element gets its dependency pass and one
 * evaluation at the model's initial state, printed as a table.
 */
#include <getopt.h>
#include <libgen.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "binding.h"
#include "commands.h"
#include "derivative_check.h"
#include "force_check.h"
#include "usrsub/coupler.h"
#include "host.h"
#include "session.h"

typedef struct check_row {
    char element[64];
    char functions[96];
    char outputs[512];
    int finite;
} check_row;

static void format_values(char *text, size_t size, const double *v, int n)
{
    size_t used = 0;
    text[0] = '\0';
    for (int k = 0; k < n && used < size; ++k)
        used += (size_t)snprintf(text + used, size - used, k ? " %.6g" : "%.6g", v[k]);
}

static double hx_max_abs_values(const double *v, int n)
{
    double m = 0.0;
    for (int k = 0; k < n; ++k)
        m = fmax(m, fabs(v[k]));
    return m;
}

static int all_finite(const double *v, int n)
{
    for (int k = 0; k < n; ++k)
        if (!isfinite(v[k]))
            return 0;
    return 1;
}

/* Coupled joints' coordinates at the current frames. */
static int coupler_disp(const hx_session *s, int coupler, double disp[3])
{
    const hx_coupler *c = &s->model->couplers[coupler];
    for (int k = 0; k < c->njoints; ++k)
        disp[k] = hx_joint_coordinate(s->model, s->frames, c->joint[k]);
    return c->njoints;
}

static void field_inputs(const hx_session *s, const hx_binding *b, double disp[6], double velo[6])
{
    const hx_force *f = &s->model->forces[b->index];
    hx_frame I, J;
    hx_marker_frame(s->model, s->frames, f->i_marker, &I);
    hx_marker_frame(s->model, s->frames, f->j_marker, &J);
    hx_field_state(&I, &J, disp, velo);
}

/* Dependency pass then one evaluation. */
static void evaluate(hx_session *s, hx_binding *b, check_row *row)
{
    double out[64] = {0};
    int nout = 0;
    snprintf(row->element, sizeof row->element, "%s %d", b->element, b->id);
    if (b->kind == HX_BIND_COUPLER) {
        double disp[3];
        const int n = coupler_disp(s, b->index, disp);
        snprintf(row->functions, sizeof row->functions, "%s %s %s", b->names[0], b->names[1],
                 b->names[2]);
        for (int pass = 1; pass >= 0; --pass) {
            hx_call_coupler(b, 0, 0.0, disp, n, pass, out, NULL);
            hx_call_coupler(b, 1, 0.0, disp, n, pass, out + 1, NULL);
            hx_call_coupler(b, 2, 0.0, disp, n, pass, out + 1 + n, NULL);
        }
        nout = 1 + n + n * n;
    } else if (b->kind == HX_BIND_GFOSUB) {
        snprintf(row->functions, sizeof row->functions, "%s", b->names[0]);
        hx_call_gfosub(b, 0.0, 0, 1, out, NULL);
        hx_call_gfosub(b, 0.0, 0, 0, out, NULL);
        nout = 6;
    } else {
        double disp[6], velo[6], dfd[36], dfv[36];
        field_inputs(s, b, disp, velo);
        snprintf(row->functions, sizeof row->functions, "%s", b->names[0]);
        hx_call_fiesub(b, 0.0, disp, velo, 0, 1, out, dfd, dfv, NULL);
        hx_call_fiesub(b, 0.0, disp, velo, 0, 0, out, dfd, dfv, NULL);
        nout = 6;
    }
    row->finite = all_finite(out, nout);
    format_values(row->outputs, sizeof row->outputs, out, nout);
}

/* ---- couplers: COUXX against differences of COUSUB, COUXX2 against COUXX ---- */

#define COUPLER_SAMPLES 25

typedef struct coupler_sampler {
    hx_binding *b;
    int n, which;
} coupler_sampler;

static int sample_coupler(void *ctx, const double *x, double *out)
{
    const coupler_sampler *cs = ctx;
    hx_call_coupler(cs->b, cs->which, 0.0, x, cs->n, 0, out, NULL);
    if (hx_host_stop_requested())
        return -1;
    return all_finite(out, cs->which == 0 ? 1 : cs->n) ? 0 : -1;
}

/* Sampling intervals: each term's data (spline knots, 10 % beyond both ends,
 * to cover the linear extension), else the initial coordinate +- 1. The USER
 * list is read with the library's own grammar (include/usrsub/coupler.h); a
 * list in another grammar falls back to the initial coordinates. */
static void coupler_ranges(const hx_session *s, const hx_binding *b, int n, const double *q0,
                           double lo[3], double hi[3])
{
    usrsub_coupler c;
    usrsub_message msg;
    const int decoded =
        usrsub_coupler_decode(&c, b->par, b->npar, n, hx_model_string_copy, s->model, &msg) == 0;
    for (int i = 0; i < n; ++i) {
        double a, z;
        if (decoded && usrsub_coupler_term_range(&c.term[i], &a, &z)) {
            lo[i] = a - 0.1 * (z - a);
            hi[i] = z + 0.1 * (z - a);
        } else {
            lo[i] = q0[i] - 1.0;
            hi[i] = q0[i] + 1.0;
        }
    }
    if (decoded)
        usrsub_coupler_free(&c);
}

static int check_coupler_derivatives(hx_session *s, hx_binding *b)
{
    double q0[3], lo[3], hi[3];
    const int n = coupler_disp(s, b->index, q0);
    coupler_ranges(s, b, n, q0, lo, hi);
    hx_worst first = {0}, second = {0};
    for (int k = 0; k < COUPLER_SAMPLES; ++k) {
        double x[3], phi, grad[3], hess[9];
        for (int i = 0; i < n; ++i)
            x[i] = lo[i] + (k + 0.5) / COUPLER_SAMPLES * (hi[i] - lo[i]);
        coupler_sampler value = {b, n, 0}, slope = {b, n, 1};
        if (sample_coupler(&value, x, &phi) != 0 || sample_coupler(&slope, x, grad) != 0)
            return -1;
        hx_call_coupler(b, 2, 0.0, x, n, 0, hess, NULL);
        const double gmax = hx_max_abs_values(grad, n);
        const double hmax = fmax(hx_max_abs_values(hess, n * n), gmax);
        for (int i = 0; i < n; ++i) {
            const double h = 1e-5 * fmax(1.0, fabs(x[i]));
            const double floor1 = 1e-6 * fmax(gmax, 1e-300);
            const double e1 = hx_check_column(sample_coupler, &value, x, i, 1, &grad[i], &floor1, h);
            char at[96];
            format_values(at, sizeof at, x, n);
            hx_worst_update(&first, e1, "dphi/dM%d at M = (%s)", i + 1, at);
            double column[3], floors[3];
            for (int j = 0; j < n; ++j) {
                column[j] = hess[j + n * i];
                floors[j] = 1e-6 * fmax(hmax, 1e-300);
            }
            const double e2 = hx_check_column(sample_coupler, &slope, x, i, n, column, floors, h);
            hx_worst_update(&second, e2, "d2phi/dM dM%d at M = (%s)", i + 1, at);
        }
    }
    printf("  %s %d: %s against central differences of %s: worst relative error %.2g (%s), %d"
           " values at %d points across the terms' data: %s\n", b->element, b->id, b->names[1],
           b->names[0], first.error, first.where, first.compared, COUPLER_SAMPLES,
           first.failed ? "FAIL" : "pass");
    printf("  %s %d: %s against central differences of %s: worst relative error %.2g (%s), %d"
           " values: %s\n", b->element, b->id, b->names[2], b->names[1], second.error,
           second.where, second.compared * n, second.failed ? "FAIL" : "pass");
    return first.failed || second.failed ? 1 : 0;
}

static void usage(FILE *f)
{
    fprintf(f, "usage: usrsub-harness check MODEL.xml\n"
               "\n"
               "For every user-subroutine element: the dependency pass (iflag = 1) and one\n"
               "evaluation at the initial state, printed as a table (element, library,\n"
               "functions, declared dependencies, outputs). Exits non-zero when an element\n"
               "reports an error, returns a non-finite value, or fails a check.\n");
}

int hx_command_check(int argc, char **argv)
{
    static const struct option options[] = {{"help", no_argument, NULL, 'h'}, {0, 0, 0, 0}};
    int opt;
    optind = 1;
    while ((opt = getopt_long(argc, argv, "h", options, NULL)) != -1) {
        if (opt == 'h') {
            usage(stdout);
            return 0;
        }
        usage(stderr);
        return 2;
    }
    if (optind != argc - 1) {
        usage(stderr);
        return 2;
    }
    hx_session s;
    usrsub_message msg;
    if (hx_session_open(&s, argv[optind], &msg) != 0) {
        fprintf(stderr, "usrsub-harness check: %s\n", msg.text);
        return 1;
    }
    int failures = 0;
    printf("%-28s %-16s %-22s %-34s %s\n", "element", "library", "functions",
           "declared dependencies", "outputs");
    for (int k = 0; k < s.bindings.count && !hx_host_stop_requested(); ++k) {
        hx_binding *b = &s.bindings.items[k];
        check_row row;
        evaluate(&s, b, &row);
        char deps[512], lib[256];
        snprintf(lib, sizeof lib, "%s", b->library);
        printf("%-28s %-16s %-22s %-34s %s\n", row.element, basename(lib), row.functions,
               hx_dependencies_text(&b->deps, deps, sizeof deps), row.outputs);
        if (!row.finite) {
            fprintf(stderr, "check: %s returned a non-finite value\n", row.element);
            ++failures;
        }
    }
    if (!hx_host_stop_requested() && failures == 0) {
        printf("\nderivative checks (tolerance %g):\n", HX_DERIVATIVE_TOLERANCE);
        for (int k = 0; k < s.bindings.count && !hx_host_stop_requested(); ++k) {
            hx_binding *b = &s.bindings.items[k];
            if (b->kind == HX_BIND_COUPLER && check_coupler_derivatives(&s, b) != 0)
                ++failures;
            if (b->kind == HX_BIND_FIESUB && hx_check_field_partials(&s, b) != 0)
                ++failures;
            if (b->kind == HX_BIND_GFOSUB && hx_audit_dependencies(&s, b) != 0)
                ++failures;
        }
    }
    if (hx_host_stop_requested()) {
        fprintf(stderr, "usrsub-harness check: stopped by c_errmes STOP: %s\n",
                hx_host_stop_message());
        hx_session_close(&s);
        return 3;
    }
    hx_session_close(&s);
    return failures ? 1 : 0;
}
