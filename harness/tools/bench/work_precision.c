/* Work-precision sweeps (work_precision.h). */
#include "tools/bench/work_precision.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "tools/bench/call_cost.h"
#include "tools/bench/linear_reference.h"
#include "tools/plot.h"
#include "sim/simulation.h"

/* ---- kinds of state, for errors that never mix units ---------------------------------- */

enum { KIND_POSITION, KIND_ROTATION, KIND_JOINT_ANGLE, KIND_JOINT_SLIDE, KIND_VELOCITY,
       KIND_ANGULAR_VELOCITY, KIND_JOINT_RATE, KIND_JOINT_SPEED, KIND_COUNT };

typedef struct reference_grid {
    int m;                 /* compared components: positions and velocities */
    int *kind;             /* per component */
    double scale[KIND_COUNT];
    double *y;             /* (HX_WP_GRID + 1) x m reference states */
} reference_grid;

static void assign_kinds(const hx_dynamics *d, int *kind)
{
    for (int b = 0; b < d->m->nbodies; ++b) {
        const hx_body_dof *dof = &d->dof[b];
        switch (dof->kind) {
        case HX_DOF_GROUND:
            break;
        case HX_DOF_FREE:
            for (int i = 0; i < 7; ++i)
                kind[dof->q + i] = i < 3 ? KIND_POSITION : KIND_ROTATION;
            for (int i = 0; i < 6; ++i)
                kind[d->nq + dof->u + i] = i < 3 ? KIND_VELOCITY : KIND_ANGULAR_VELOCITY;
            break;
        case HX_DOF_REVOLUTE:
            kind[dof->q] = KIND_JOINT_ANGLE;
            kind[d->nq + dof->u] = KIND_JOINT_RATE;
            break;
        case HX_DOF_SLIDER:
            kind[dof->q] = KIND_JOINT_SLIDE;
            kind[d->nq + dof->u] = KIND_JOINT_SPEED;
            break;
        }
    }
}

/* Per kind: the largest excursion (positions) or value (velocities). */
static void grid_scales(reference_grid *g, int nq)
{
    memset(g->scale, 0, sizeof g->scale);
    for (int r = 0; r <= HX_WP_GRID; ++r)
        for (int i = 0; i < g->m; ++i) {
            const double v = g->y[r * g->m + i];
            const double size = i < nq ? fabs(v - g->y[i]) : fabs(v);
            g->scale[g->kind[i]] = fmax(g->scale[g->kind[i]], size);
        }
    double largest = 0.0;
    for (int k = 0; k < KIND_COUNT; ++k)
        largest = fmax(largest, g->scale[k]);
    for (int k = 0; k < KIND_COUNT; ++k) /* kinds that do not move are not compared */
        if (g->scale[k] <= 1e-12 * largest)
            g->scale[k] = 0.0;
}

static double state_error(const reference_grid *g, int row, const double *y)
{
    double e = 0.0;
    for (int i = 0; i < g->m; ++i) {
        const double s = g->scale[g->kind[i]];
        if (s > 0.0)
            e = fmax(e, fabs(y[i] - g->y[row * g->m + i]) / s);
    }
    return e;
}

/* ---- runs ----------------------------------------------------------------------------------- */

typedef struct observed {
    const reference_grid *g;
    double *store;      /* non-NULL: keep the states here (reference runs) */
    double end_error, max_error;
    int rows;
    double t_end;
} observed;

static int observe(void *ctx, hx_dynamics *d, double t, const double *y)
{
    observed *o = ctx;
    (void)d;
    const int row = (int)lround(t / o->t_end * HX_WP_GRID);
    if (row < 0 || row > HX_WP_GRID)
        return 0;
    if (o->store != NULL)
        memcpy(o->store + row * o->g->m, y, sizeof(double) * (size_t)o->g->m);
    else {
        const double e = state_error(o->g, row, y);
        o->max_error = fmax(o->max_error, e);
        if (row == HX_WP_GRID)
            o->end_error = e;
    }
    o->rows++;
    return 0;
}

static int simulate(hx_dynamics *d, hx_method method, double setting, double t_end,
                    observed *obs, hx_simulation_result *result)
{
    hx_simulation_options so = {0};
    hx_integrator_defaults(&so.integration);
    so.integration.method = method;
    so.integration.t_end = t_end;
    so.integration.output_interval = t_end / HX_WP_GRID;
    if (method == HX_METHOD_DOPRI5) {
        so.integration.rtol = setting;
        so.integration.atol = setting * 1e-3;
        so.integration.max_steps = 50000000;
    } else {
        so.integration.step = setting;
    }
    so.observer = obs != NULL ? observe : NULL;
    so.observer_ctx = obs;
    so.skip_energy = 1;
    return hx_simulate(d, &so, NULL, result);
}

static void measure_point(hx_dynamics *d, const reference_grid *g, const hx_wp_options *o,
                          hx_method method, double setting, hx_wp_point *p)
{
    observed obs = {g, NULL, INFINITY, 0.0, 0, o->t_end};
    hx_simulation_result result;
    double seconds[15];
    const int repeats = o->repeats < 1 ? 1 : o->repeats > 15 ? 15 : o->repeats;
    simulate(d, method, setting, o->t_end, &obs, &result);
    p->method = method;
    p->setting = setting;
    p->status = result.status;
    p->evaluations = result.stats.evaluations;
    p->steps = result.stats.steps;
    p->end_error = result.status == HX_INTEGRATION_OK ? obs.end_error : INFINITY;
    p->max_error = result.status == HX_INTEGRATION_OK ? obs.max_error : INFINITY;
    seconds[0] = result.seconds;
    for (int k = 1; k < repeats && result.status == HX_INTEGRATION_OK; ++k) {
        simulate(d, method, setting, o->t_end, NULL, &result);
        seconds[k] = result.seconds;
    }
    const int timed = result.status == HX_INTEGRATION_OK ? repeats : 1;
    p->seconds = hx_median(seconds, timed);
}

/* ---- the reference ----------------------------------------------------------------------- */

static int build_reference(hx_dynamics *d, const hx_wp_options *o, reference_grid *g,
                           hx_wp_result *r, hx_message *msg)
{
    hx_linear_reference lin;
    hx_message why;
    if (hx_linear_reference_build(d, &lin, &why) == 0) {
        double *y = malloc(sizeof(double) * (size_t)d->n);
        if (y == NULL)
            return hx_fail(msg, "out of memory");
        for (int row = 0; row <= HX_WP_GRID; ++row) {
            memcpy(y, lin.y0, sizeof(double) * (size_t)d->n);
            hx_linear_reference_state(&lin, o->t_end * row / HX_WP_GRID, y);
            memcpy(g->y + row * g->m, y, sizeof(double) * (size_t)g->m);
        }
        int len = snprintf(r->reference, sizeof r->reference, "closed form: %d linear"
                           " direction%s, z'' = f - k z - c z' with", lin.modes,
                           lin.modes == 1 ? "" : "s");
        for (int k = 0; k < lin.modes && k < 3 && len > 0 && (size_t)len < sizeof r->reference; ++k)
            len += snprintf(r->reference + len, sizeof r->reference - (size_t)len,
                            "%s k = %.4g, c = %.4g", k ? ";" : "", lin.k[k], lin.c[k]);
        free(y);
        hx_linear_reference_free(&lin);
        r->analytic = 1;
        grid_scales(g, d->nq);
        return 0;
    }
    /* numerical: DOPRI5 at 1e-12, confirmed by 1e-13 */
    double *second = malloc(sizeof(double) * (size_t)((HX_WP_GRID + 1) * g->m));
    if (second == NULL)
        return hx_fail(msg, "out of memory");
    observed a = {g, g->y, 0, 0, 0, o->t_end}, b = {g, second, 0, 0, 0, o->t_end};
    hx_simulation_result ra, rb;
    if (simulate(d, HX_METHOD_DOPRI5, 1e-12, o->t_end, &a, &ra) != 0 ||
        simulate(d, HX_METHOD_DOPRI5, 1e-13, o->t_end, &b, &rb) != 0) {
        free(second);
        return hx_fail(msg, "the reference run failed: %s", ra.message[0] ? ra.message : rb.message);
    }
    grid_scales(g, d->nq);
    r->reference_error = 0.0;
    for (int row = 0; row <= HX_WP_GRID; ++row)
        r->reference_error = fmax(r->reference_error, state_error(g, row, second + row * g->m));
    /* the finer run is the reference */
    memcpy(g->y, second, sizeof(double) * (size_t)((HX_WP_GRID + 1) * g->m));
    free(second);
    snprintf(r->reference, sizeof r->reference, "numerical: DOPRI5 at tolerance 1e-13, within %.2g"
             " of the run at 1e-12 (%.700s)", r->reference_error, why.text);
    return 0;
}

/* ---- the sweep --------------------------------------------------------------------------- */

int hx_work_precision(hx_session *s, const hx_wp_options *o, hx_wp_result *r,
                      hx_message *msg)
{
    memset(r, 0, sizeof *r);
    hx_dynamics d;
    if (hx_dynamics_init(&d, s, msg) != 0)
        return -1;
    reference_grid g = {d.nq + d.nu, NULL, {0}, NULL};
    g.kind = calloc((size_t)g.m + 1, sizeof(int));
    g.y = calloc((size_t)((HX_WP_GRID + 1) * g.m + 1), sizeof(double));
    double *y0 = calloc((size_t)d.n, sizeof(double));
    int status = g.kind && g.y && y0 ? 0 : hx_fail(msg, "out of memory");
    if (status == 0)
        assign_kinds(&d, g.kind);
    if (status == 0 && (hx_dynamics_initial_state(&d, y0) != 0 ||
                        hx_estimate_stability(&d, 0.0, y0, &r->stability, msg) != 0))
        status = msg->text[0] ? -1 : hx_fail(msg, "%s", d.message);
    if (status == 0)
        status = build_reference(&d, o, &g, r, msg);
    if (status == 0) {
        /* fixed steps: from the output spacing (or half RK4's stable step, when
         * smaller), halving; each step divides the output spacing */
        double h0 = o->t_end / HX_WP_GRID;
        const double limit = r->stability.max_step[HX_METHOD_RK4];
        while (isfinite(limit) && h0 > 0.5 * limit)
            h0 /= 2.0;
        const int halvings = o->quick ? 4 : 9;
        static const hx_method fixed[3] = {HX_METHOD_EULER, HX_METHOD_SYMPLECTIC_EULER,
                                           HX_METHOD_RK4};
        for (int m = 0; m < 3; ++m)
            for (int k = 0; k < halvings && r->npoints < HX_WP_MAX_POINTS; ++k)
                measure_point(&d, &g, o, fixed[m], h0 / (double)(1L << k),
                              &r->point[r->npoints++]);
        const int tolerances = o->quick ? 4 : 10;
        for (int k = 0; k < tolerances && r->npoints < HX_WP_MAX_POINTS; ++k)
            measure_point(&d, &g, o, HX_METHOD_DOPRI5, pow(10.0, -3.0 - (o->quick ? 2 : 1) * k),
                          &r->point[r->npoints++]);
    }
    free(g.kind);
    free(g.y);
    free(y0);
    hx_dynamics_free(&d);
    return status;
}

double hx_wp_evaluations_at(const hx_wp_result *r, hx_method method, double target)
{
    /* the method's points in order of work; the first crossing of the target */
    const hx_wp_point *previous = NULL;
    for (int k = 0; k < r->npoints; ++k) {
        const hx_wp_point *p = &r->point[k];
        if (p->method != method || p->status != HX_INTEGRATION_OK || !(p->end_error > 0.0))
            continue;
        if (p->end_error <= target) {
            if (previous == NULL || !isfinite(previous->end_error))
                return (double)p->evaluations;
            const double x0 = log((double)previous->evaluations), x1 = log((double)p->evaluations);
            const double e0 = log(previous->end_error), e1 = log(p->end_error);
            return exp(x0 + (x1 - x0) * (log(target) - e0) / (e1 - e0));
        }
        previous = p;
    }
    return 0.0;
}

void hx_wp_print(FILE *f, const hx_wp_result *r)
{
    fprintf(f, "work-precision against the reference (%s)\n", r->reference);
    fprintf(f, "  %-17s %-11s %10s %12s %12s %12s %12s\n", "method", "step/rtol", "steps",
            "evaluations", "run time s", "end error", "max error");
    for (int k = 0; k < r->npoints; ++k) {
        const hx_wp_point *p = &r->point[k];
        fprintf(f, "  %-17s %-11.3g %10ld %12ld %12.3g %12.3g %12.3g%s\n",
                hx_method_name(p->method), p->setting, p->steps, p->evaluations, p->seconds,
                p->end_error, p->max_error,
                p->status == HX_INTEGRATION_OK ? "" : "  (unstable)");
    }
}

int hx_wp_write(const char *prefix, const char *title, const hx_wp_result *r)
{
    char csv[4096], script_path[4096];
    snprintf(csv, sizeof csv, "%s_work_precision.csv", prefix);
    FILE *f = fopen(csv, "w");
    if (f == NULL)
        return -1;
    fprintf(f, "method,setting,steps,evaluations,seconds,end_error,max_error,status\n");
    for (int k = 0; k < r->npoints; ++k) {
        const hx_wp_point *p = &r->point[k];
        fprintf(f, "%s,%.6g,%ld,%ld,%.6g,%.6g,%.6g,%s\n", hx_method_name(p->method), p->setting,
                p->steps, p->evaluations, p->seconds, p->end_error, p->max_error,
                p->status == HX_INTEGRATION_OK ? "ok" : "unstable");
    }
    fclose(f);
    /* one series per method: end-point error (solid) and largest error (dashed) */
    char script[8192];
    int n = snprintf(script, sizeof script,
                     "set datafile separator ','\nset terminal pngcairo size 900,650 font ',11'\n"
                     "set logscale xy\nset grid\nset key outside right noenhanced\nset format y '10^{%%L}'\n"
                     "set format x '10^{%%L}'\n"
                     "set ylabel 'relative error'\n");
    static const char *const axes[2][3] = {{"error_time", "run time (s)", "5"},
                                           {"error_evaluations", "right-hand-side evaluations", "4"}};
    for (int a = 0; a < 2 && n > 0 && (size_t)n < sizeof script; ++a) {
        n += snprintf(script + n, sizeof script - (size_t)n,
                      "set output '%s_%s.png'\nset title '%s: error against %s' noenhanced\n"
                      "set xlabel '%s'\n"
                      "plot", prefix, axes[a][0], title, axes[a][1], axes[a][1]);
        for (int m = 0; m < HX_METHOD_COUNT && n > 0 && (size_t)n < sizeof script; ++m) {
            const char *name = hx_method_name((hx_method)m);
            n += snprintf(script + n, sizeof script - (size_t)n,
                          "%s '%s' using (strcol(1) eq '%s' && strcol(8) eq 'ok' ? $%s : 1/0):6"
                          " with linespoints lw 2 lc %d title '%s, end',"
                          " '%s' using (strcol(1) eq '%s' && strcol(8) eq 'ok' ? $%s : 1/0):7"
                          " with lines dt 2 lc %d title '%s, largest'",
                          m ? "," : "", csv, name, axes[a][2], m + 1, name, csv, name, axes[a][2],
                          m + 1, name);
        }
        n += snprintf(script + n, sizeof script - (size_t)n, "\n");
    }
    if (n < 0 || (size_t)n >= sizeof script)
        return -1;
    snprintf(script_path, sizeof script_path, "%s_work_precision.gp", prefix);
    return hx_gnuplot(script_path, script);
}
