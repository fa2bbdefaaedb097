/*
 * A coupler's partials (checks.h): COUXX against central differences of
 * COUSUB, then COUXX2 against central differences of COUXX, at a seeded set
 * of points in which each joint is sampled on its own across its term's data
 * (a Latin hypercube: every joint sweeps its whole range, in an order of its
 * own), so that a partial that reads the wrong joint cannot hide on the line
 * M1 = M2. COUXX2 is only judged against a COUXX that passed: a wrong COUXX is
 * reported as COUXX, whatever COUXX2 does.
 */
#include <math.h>
#include <stdio.h>

#include "host/invoke.h"
#include "base/finite.h"
#include "base/linalg.h"
#include "frames/measures.h"
#include "tools/check/checks.h"
#include "tools/check/coupler_ranges.h"
#include "tools/check/derivative_check.h"
#include "tools/check/element_samples.h"

#define COUPLER_POINTS 40

typedef struct coupler_sampler {
    hx_binding *b;
    const hx_frames *frames;
    int n, which;
} coupler_sampler;

static int sample(void *ctx, const double *x, double *out)
{
    const coupler_sampler *cs = ctx;
    hx_invoke_coupler(cs->b, cs->which, cs->frames, x, cs->n, 0, out, NULL);
    if (cs->b->messages != NULL && hx_messages_stopped(cs->b->messages))
        return -1;
    return hx_all_finite(out, cs->which == 0 ? 1 : cs->which == 1 ? cs->n : cs->n * cs->n) ? 0 : -1;
}

static void point_text(char *text, size_t size, const double *x, int n)
{
    size_t used = (size_t)snprintf(text, size, "(");
    for (int k = 0; k < n && used < size; ++k)
        used += (size_t)snprintf(text + used, size - used, k ? ", %.6g" : "%.6g", x[k]);
    if (used < size)
        snprintf(text + used, size - used, ")");
}

/* The points: joint i takes the strata of its range in a shuffled order. */
static void make_points(int n, const double lo[3], const double hi[3], double points[][3])
{
    unsigned seed = 20261123u;
    for (int i = 0; i < n; ++i) {
        int order[COUPLER_POINTS];
        for (int k = 0; k < COUPLER_POINTS; ++k)
            order[k] = k;
        for (int k = COUPLER_POINTS - 1; k > 0; --k) {
            seed = seed * 1664525u + 1013904223u;
            const int j = (int)((seed >> 8) % (unsigned)(k + 1));
            const int t = order[k];
            order[k] = order[j], order[j] = t;
        }
        for (int k = 0; k < COUPLER_POINTS; ++k) {
            const double u = (order[k] + 0.5 + 0.4 * hx_jitter(&seed)) / COUPLER_POINTS;
            points[k][i] = lo[i] + u * (hi[i] - lo[i]);
        }
    }
}

int hx_check_coupler(hx_session *s, hx_binding *b, FILE *out)
{
    const hx_coupler *c = &s->model->couplers[b->index];
    const int n = c->njoints;
    double q0[3] = {0}, lo[3] = {0}, hi[3] = {0}, points[COUPLER_POINTS][3];
    for (int i = 0; i < n; ++i)
        q0[i] = hx_joint_coordinate(&s->frames, c->joint[i], c->freedom[i]);
    const int layout = hx_coupler_ranges(s->model, b->par, b->npar, n, q0, lo, hi);
    make_points(n, lo, hi, points);
    coupler_sampler value = {b, &s->frames, n, 0}, slope = {b, &s->frames, n, 1};
    hx_worst first = {0}, second = {0};
    char worst_first_at[128] = "", worst_second_at[128] = "";
    for (int k = 0; k < COUPLER_POINTS; ++k) {
        double *x = points[k], grad[3];
        if (sample(&slope, x, grad) != 0) {
            fprintf(out, "  %s %d: %s did not return finite values at M = (%g, %g%s)\n",
                    b->element, b->id, b->names[1], x[0], x[1], n > 2 ? ", ..." : "");
            return 1;
        }
        const double floor1 = 1e-6 * fmax(hx_max_abs(grad, n), 1e-300);
        for (int j = 0; j < n; ++j) {
            const double h = 1e-5 * fmax(1.0, fabs(x[j]));
            const double e = hx_check_column(sample, &value, x, j, 1, &grad[j], &floor1, h, NULL);
            const double before = first.error;
            hx_worst_update(&first, e, "entry %d (dphi/dM%d)", j + 1, j + 1);
            if (first.compared == 1 || !(e <= before))
                point_text(worst_first_at, sizeof worst_first_at, x, n);
        }
    }
    fprintf(out, "  %s %d: %s against central differences of %s at %d points (each joint"
            " sampled on its own across %s): worst relative error %.2g at %s, M = %s: %s\n",
            b->element, b->id, b->names[1], b->names[0], COUPLER_POINTS,
            layout ? "its term's data" : "its initial coordinate +- 1", first.error, first.where,
            worst_first_at, first.failed ? "FAIL" : "pass");
    if (first.failed) {
        fprintf(out, "  %s %d: %s not judged: its reference, %s, is wrong\n", b->element, b->id,
                b->names[2], b->names[1]);
        return 1;
    }
    for (int k = 0; k < COUPLER_POINTS; ++k) {
        double *x = points[k], hess[9], grad[3];
        coupler_sampler curvature = {b, &s->frames, n, 2};
        if (sample(&curvature, x, hess) != 0 || sample(&slope, x, grad) != 0) {
            fprintf(out, "  %s %d: %s did not return finite values\n", b->element, b->id,
                    b->names[2]);
            return 1;
        }
        const double hmax = fmax(hx_max_abs(hess, n * n), hx_max_abs(grad, n));
        for (int j = 0; j < n; ++j) {
            double column[3], floors[3];
            for (int i = 0; i < n; ++i) {
                column[i] = hess[i + n * j];
                floors[i] = 1e-6 * fmax(hmax, 1e-300);
            }
            const double h = 1e-5 * fmax(1.0, fabs(x[j]));
            int row;
            const double e = hx_check_column(sample, &slope, x, j, n, column, floors, h, &row);
            const double before = second.error;
            hx_worst_update(&second, e, "row %d, column %d (d2phi/dM%d dM%d)", row + 1, j + 1,
                            row + 1, j + 1);
            if (second.compared == 1 || !(e <= before))
                point_text(worst_second_at, sizeof worst_second_at, x, n);
        }
    }
    fprintf(out, "  %s %d: %s against central differences of %s at the same points: worst"
            " relative error %.2g at %s, M = %s: %s\n", b->element, b->id, b->names[2],
            b->names[1], second.error, second.where, worst_second_at,
            second.failed ? "FAIL" : "pass");
    return second.failed ? 1 : 0;
}
