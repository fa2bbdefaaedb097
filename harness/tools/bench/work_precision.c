/* Work-precision sweeps (work_precision.h). */
#include "tools/bench/work_precision.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "tools/bench/entry_cost.h"
#include "tools/bench/linear_reference.h"
#include "tools/plot.h"
#include "sim/simulation/simulation.h"

/* A fixed-step sweep stops halving past this many right-hand sides a run:
 * on a stiff model the stable steps alone cost millions. */
#define FIXED_STEP_BUDGET 3e6
/* Runs longer than this are timed once: their timing noise is small. */
#define LONG_RUN_SECONDS 0.5

const char *hx_wp_series_name(hx_wp_series series)
{
    static const char *const names[HX_WP_SERIES] = {
        "euler", "symplectic-euler", "rk4", "dopri5", "dopri5-arkode", "bdf", "bdf-fd"};
    return series < HX_WP_SERIES ? names[series] : "?";
}

static hx_method method_of(hx_wp_series series)
{
    static const hx_method methods[HX_WP_SERIES] = {
        HX_METHOD_EULER, HX_METHOD_SYMPLECTIC_EULER, HX_METHOD_RK4, HX_METHOD_DOPRI5,
        HX_METHOD_DOPRI5_ARKODE, HX_METHOD_BDF, HX_METHOD_BDF};
    return methods[series];
}

/* ---- kinds of state, for errors that never mix units ---------------------------------- */

enum { KIND_POSITION, KIND_ROTATION, KIND_JOINT_ANGLE, KIND_JOINT_SLIDE, KIND_VELOCITY,
       KIND_ANGULAR_VELOCITY, KIND_JOINT_RATE, KIND_JOINT_SPEED, KIND_COUNT };

typedef struct reference_grid {
    int m;                 /* compared components: positions and velocities */
    int *kind;             /* per component */
    unsigned char *slow;   /* per component: a state of a slow-output body */
    double scale[KIND_COUNT];     /* over the slow outputs */
    double all_scale[KIND_COUNT]; /* over every state */
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

/* The slow outputs: the states of the bodies named (every body without names). */
static int assign_outputs(const hx_dynamics *d, const hx_wp_options *o, unsigned char *slow,
                          hx_message *msg)
{
    const hx_model *m = d->m;
    for (int b = 0; b < m->nbodies; ++b) {
        const hx_body_dof *dof = &d->dof[b];
        int chosen = o->noutputs == 0;
        for (int k = 0; k < o->noutputs; ++k)
            chosen |= m->bodies[b].id == o->outputs[k];
        if (!chosen || dof->kind == HX_DOF_GROUND)
            continue;
        const int free = dof->kind == HX_DOF_FREE;
        for (int i = 0; i < (free ? 7 : 1); ++i)
            slow[dof->q + i] = 1;
        for (int i = 0; i < (free ? 6 : 1); ++i)
            slow[d->nq + dof->u + i] = 1;
    }
    for (int k = 0; k < o->noutputs; ++k) {
        int found = 0;
        for (int b = 0; b < m->nbodies; ++b)
            found |= m->bodies[b].id == o->outputs[k] && !m->bodies[b].is_ground;
        if (!found)
            return hx_fail(msg, "--outputs: no moving Body_Rigid with id %d", o->outputs[k]);
    }
    return 0;
}

/* Per kind: the largest excursion (positions) or value (velocities), over
 * the slow outputs and over every state. */
static void grid_scales(reference_grid *g, int nq)
{
    memset(g->scale, 0, sizeof g->scale);
    memset(g->all_scale, 0, sizeof g->all_scale);
    for (int r = 0; r <= HX_WP_GRID; ++r)
        for (int i = 0; i < g->m; ++i) {
            const double v = g->y[r * g->m + i];
            const double size = i < nq ? fabs(v - g->y[i]) : fabs(v);
            g->all_scale[g->kind[i]] = fmax(g->all_scale[g->kind[i]], size);
            if (g->slow[i])
                g->scale[g->kind[i]] = fmax(g->scale[g->kind[i]], size);
        }
    double largest = 0.0, all_largest = 0.0;
    for (int k = 0; k < KIND_COUNT; ++k) {
        largest = fmax(largest, g->scale[k]);
        all_largest = fmax(all_largest, g->all_scale[k]);
    }
    for (int k = 0; k < KIND_COUNT; ++k) { /* kinds that do not move are not compared */
        if (g->scale[k] <= 1e-12 * largest)
            g->scale[k] = 0.0;
        if (g->all_scale[k] <= 1e-12 * all_largest)
            g->all_scale[k] = 0.0;
    }
}

/* The error of a state at a grid row: of the slow outputs, or of every state. */
static double state_error(const reference_grid *g, int row, const double *y, int all)
{
    const double *scale = all ? g->all_scale : g->scale;
    double e = 0.0;
    for (int i = 0; i < g->m; ++i) {
        const double s = scale[g->kind[i]];
        if (s > 0.0 && (all || g->slow[i]))
            e = fmax(e, fabs(y[i] - g->y[row * g->m + i]) / s);
    }
    return e;
}

/* ---- runs ----------------------------------------------------------------------------------- */

typedef struct observed {
    const reference_grid *g;
    double *store;      /* non-NULL: keep the states here (reference runs) */
    double end_error, max_error, all_error;
    int rows;
    double t_end;
} observed;

static int observe(void *ctx, const hx_dynamics *d, hx_dynamics_data *dd, double t,
                   const double *y)
{
    (void)d, (void)dd;
    observed *o = ctx;
    const int row = (int)lround(t / o->t_end * HX_WP_GRID);
    if (row < 0 || row > HX_WP_GRID)
        return 0;
    if (o->store != NULL)
        memcpy(o->store + row * o->g->m, y, sizeof(double) * (size_t)o->g->m);
    else {
        const double e = state_error(o->g, row, y, 0);
        o->max_error = fmax(o->max_error, e);
        o->all_error = fmax(o->all_error, state_error(o->g, row, y, 1));
        if (row == HX_WP_GRID)
            o->end_error = e;
    }
    o->rows++;
    return 0;
}

static int simulate(hx_dynamics *d, hx_wp_series series, double setting, double atol_ratio,
                    int max_order, double t_end, observed *obs, hx_simulation_result *result)
{
    hx_simulation_options so = {0};
    hx_integrator_defaults(&so.integration);
    so.integration.method = method_of(series);
    so.integration.max_order = max_order;
    so.integration.jacobian = series == HX_WP_BDF_FD ? HX_JACOBIAN_FD : HX_JACOBIAN_ANALYTIC;
    so.integration.t_end = t_end;
    so.integration.output_interval = t_end / HX_WP_GRID;
    if (hx_method_adaptive(so.integration.method)) {
        so.integration.rtol = setting;
        so.integration.atol = setting * atol_ratio;
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
                          hx_wp_series series, double setting, hx_wp_point *p)
{
    observed obs = {g, NULL, INFINITY, 0.0, 0.0, 0, o->t_end};
    hx_simulation_result result;
    double seconds[15];
    const double atol_ratio = o->atol_ratio > 0.0 ? o->atol_ratio : 1e-3;
    const int repeats = o->repeats < 1 ? 1 : o->repeats > 15 ? 15 : o->repeats;
    simulate(d, series, setting, atol_ratio, o->max_order, o->t_end, &obs, &result);
    const int ok = result.status == HX_INTEGRATION_OK;
    memset(p, 0, sizeof *p);
    p->series = series;
    p->method = method_of(series);
    p->setting = setting;
    p->status = result.status;
    p->evaluations = result.stats.evaluations;
    p->steps = result.stats.steps;
    p->newton_iterations = result.stats.newton_iterations;
    p->jacobians = result.stats.jacobians;
    p->fd_evaluations = result.stats.fd_jacobian_evaluations;
    p->jacobian_seconds = result.stats.jacobian_seconds;
    p->partial_calls = result.stats.partial_calls;
    p->end_error = ok ? obs.end_error : INFINITY;
    p->max_error = ok ? obs.max_error : INFINITY;
    p->all_error = ok ? obs.all_error : INFINITY;
    seconds[0] = result.seconds;
    int timed = 1;
    for (; timed < repeats && ok && result.seconds < LONG_RUN_SECONDS; ++timed) {
        simulate(d, series, setting, atol_ratio, o->max_order, o->t_end, NULL, &result);
        seconds[timed] = result.seconds;
    }
    p->seconds = hx_median(seconds, timed);
}

/* ---- the reference ----------------------------------------------------------------------- */

/* A tight run of a series into a grid of states. */
static int reference_run(hx_dynamics *d, const hx_wp_options *o, reference_grid *g,
                         hx_wp_series series, double rtol, double *into, hx_message *msg)
{
    observed run = {g, into, 0, 0, 0, 0, o->t_end};
    hx_simulation_result result;
    /* the sweep's absolute tolerances, and no tighter than atol = rtol for BDF:
     * below that a stiff model's error estimates drown in rounding */
    const double ratio = o->atol_ratio > 0.0 ? o->atol_ratio : 1e-3;
    const double atol_ratio = series == HX_WP_BDF ? fmax(ratio, 1.0) : ratio;
    if (simulate(d, series, rtol, atol_ratio, 0, o->t_end, &run, &result) != 0)
        return hx_fail(msg, "the reference run (%s at %g) failed: %s", hx_wp_series_name(series),
                       rtol, result.message);
    return 0;
}

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
    /* numerical: DOPRI5 at 1e-13, confirmed by DOPRI5 and by BDF at 1e-12 */
    const size_t size = (size_t)((HX_WP_GRID + 1) * g->m);
    double *dopri5 = malloc(sizeof(double) * size), *bdf = malloc(sizeof(double) * size);
    int status = dopri5 && bdf ? 0 : hx_fail(msg, "out of memory");
    if (status == 0)
        status = reference_run(d, o, g, HX_WP_DOPRI5, 1e-13, g->y, msg);
    if (status == 0)
        status = reference_run(d, o, g, HX_WP_DOPRI5, 1e-12, dopri5, msg);
    if (status == 0)
        status = reference_run(d, o, g, HX_WP_BDF, 1e-12, bdf, msg);
    if (status == 0) {
        grid_scales(g, d->nq);
        double by_dopri5 = 0.0, by_bdf = 0.0;
        for (int row = 0; row <= HX_WP_GRID; ++row) {
            by_dopri5 = fmax(by_dopri5, state_error(g, row, dopri5 + row * g->m, 1));
            by_bdf = fmax(by_bdf, state_error(g, row, bdf + row * g->m, 1));
        }
        snprintf(r->reference, sizeof r->reference, "numerical: DOPRI5 at tolerance 1e-13, within"
                 " %.2g of DOPRI5 and %.2g of BDF at 1e-12 (%.700s)", by_dopri5, by_bdf, why.text);
    }
    free(dopri5);
    free(bdf);
    return status;
}

/* ---- the sweep --------------------------------------------------------------------------- */

static void fixed_step_sweep(hx_dynamics *d, const reference_grid *g, const hx_wp_options *o,
                             hx_wp_result *r, hx_wp_series series, double h0)
{
    const int halvings = o->quick ? 4 : 9;
    static const int stages[3] = {1, 1, 4};
    for (int k = 0; k < halvings && r->npoints < HX_WP_MAX_POINTS; ++k) {
        const double h = h0 / (double)(1L << k);
        if (k > 0 && stages[series] * o->t_end / h > FIXED_STEP_BUDGET)
            break;
        measure_point(d, g, o, series, h, &r->point[r->npoints++]);
    }
}

static void tolerance_sweep(hx_dynamics *d, const reference_grid *g, const hx_wp_options *o,
                            hx_wp_result *r, hx_wp_series series)
{
    /* explicit: 1e-3 down to 1e-12; BDF from 1e-2 (it is the loose end that
     * stiff models run at) down to 1e-10 */
    const int implicit = method_of(series) == HX_METHOD_BDF;
    const int count = o->quick ? 4 : implicit ? 9 : 10;
    const double first = implicit ? (o->quick ? 1e-3 : 1e-2) : 1e-3;
    for (int k = 0; k < count && r->npoints < HX_WP_MAX_POINTS; ++k)
        measure_point(d, g, o, series, first * pow(10.0, -(o->quick ? 2 : 1) * k),
                      &r->point[r->npoints++]);
}

int hx_work_precision(hx_session *s, const hx_wp_options *o, hx_wp_result *r,
                      hx_message *msg)
{
    memset(r, 0, sizeof *r);
    hx_dynamics d;
    if (hx_dynamics_init(&d, s, msg) != 0)
        return -1;
    reference_grid g = {d.nq + d.nu, NULL, NULL, {0}, {0}, NULL};
    g.kind = calloc((size_t)g.m + 1, sizeof(int));
    g.slow = calloc((size_t)g.m + 1, 1);
    g.y = calloc((size_t)((HX_WP_GRID + 1) * g.m + 1), sizeof(double));
    double *y0 = calloc((size_t)d.n, sizeof(double));
    int status = g.kind && g.slow && g.y && y0 ? 0 : hx_fail(msg, "out of memory");
    if (status == 0) {
        assign_kinds(&d, g.kind);
        status = assign_outputs(&d, o, g.slow, msg);
        r->restricted = o->noutputs > 0;
    }
    if (status == 0 && (hx_dynamics_initial_y(&d, y0, msg) != 0 ||
                        hx_estimate_stability(&d, 0.0, y0, &r->stability, msg) != 0))
        status = -1;
    if (status == 0)
        status = build_reference(&d, o, &g, r, msg);
    if (status == 0) {
        /* fixed steps: from the output spacing (or half RK4's stable step, when
         * smaller), halving; each step divides the output spacing */
        double h0 = o->t_end / HX_WP_GRID;
        const double limit = r->stability.max_step[HX_METHOD_RK4];
        while (isfinite(limit) && h0 > 0.5 * limit)
            h0 /= 2.0;
        for (int k = HX_WP_EULER; k <= HX_WP_RK4; ++k)
            fixed_step_sweep(&d, &g, o, r, (hx_wp_series)k, h0);
        for (int k = HX_WP_DOPRI5; k < HX_WP_SERIES; ++k)
            tolerance_sweep(&d, &g, o, r, (hx_wp_series)k);
    }
    free(g.kind);
    free(g.slow);
    free(g.y);
    free(y0);
    hx_dynamics_free(&d);
    return status;
}

int hx_wp_work_at(const hx_wp_result *r, hx_wp_series series, double target, int largest,
                  double *evaluations, double *seconds)
{
    /* the series' points in order of work; the first crossing of the target */
    const hx_wp_point *previous = NULL;
    double previous_error = 0.0;
    for (int k = 0; k < r->npoints; ++k) {
        const hx_wp_point *p = &r->point[k];
        const double error = largest ? p->max_error : p->end_error;
        if (p->series != series || p->status != HX_INTEGRATION_OK || !(error > 0.0))
            continue;
        if (error <= target) {
            double e = (double)p->evaluations, s = p->seconds;
            if (previous != NULL && isfinite(previous_error) && previous_error > target) {
                const double f = (log(target) - log(previous_error)) /
                                 (log(error) - log(previous_error));
                e = exp(log((double)previous->evaluations) +
                        f * (log((double)p->evaluations) - log((double)previous->evaluations)));
                s = exp(log(previous->seconds) + f * (log(p->seconds) - log(previous->seconds)));
            }
            if (evaluations != NULL)
                *evaluations = e;
            if (seconds != NULL)
                *seconds = s;
            return 0;
        }
        previous = p;
        previous_error = error;
    }
    return -1;
}

double hx_wp_evaluations_at(const hx_wp_result *r, hx_method method, double target)
{
    for (int k = 0; k < HX_WP_SERIES; ++k)
        if (method_of((hx_wp_series)k) == method) {
            double e = 0.0;
            return hx_wp_work_at(r, (hx_wp_series)k, target, 0, &e, NULL) == 0 ? e : 0.0;
        }
    return 0.0;
}

void hx_wp_print(FILE *f, const hx_wp_result *r)
{
    fprintf(f, "work-precision against the reference (%s)\n", r->reference);
    fprintf(f, "  errors of the %s; 'all states' is the largest over the trajectory of every"
            " state\n", r->restricted ? "slow outputs (the bodies named by --outputs)" : "states");
    fprintf(f, "  %-17s %-9s %9s %11s %10s %10s %10s %10s  %s\n", "method", "step/rtol", "steps",
            "evaluations", "run time s", "end error", "max error", "all states",
            "Newton it./step, Jacobians (right-hand sides in them | their time, element calls)");
    for (int k = 0; k < r->npoints; ++k) {
        const hx_wp_point *p = &r->point[k];
        fprintf(f, "  %-17s %-9.3g %9ld %11ld %10.3g %10.3g %10.3g %10.3g", hx_wp_series_name(p->series),
                p->setting, p->steps, p->evaluations, p->seconds, p->end_error, p->max_error,
                p->all_error);
        if (p->method == HX_METHOD_BDF && p->steps > 0) {
            fprintf(f, "  %.2f, %ld", (double)p->newton_iterations / (double)p->steps,
                    p->jacobians);
            if (p->series == HX_WP_BDF_FD)
                fprintf(f, " (%ld)", p->fd_evaluations);
            else
                fprintf(f, " (%.2g s, %ld)", p->jacobian_seconds, p->partial_calls);
        }
        fprintf(f, "%s\n", p->status == HX_INTEGRATION_OK ? "" : "  (failed or unstable)");
    }
}

int hx_wp_write(const char *prefix, const char *title, const hx_wp_result *r)
{
    char csv[4096], script_path[4096];
    snprintf(csv, sizeof csv, "%s_work_precision.csv", prefix);
    FILE *f = fopen(csv, "w");
    if (f == NULL)
        return -1;
    fprintf(f, "method,setting,steps,evaluations,seconds,end_error,max_error,status,all_error,"
               "newton_iterations,jacobians,fd_evaluations,jacobian_seconds,partial_calls\n");
    int present[HX_WP_SERIES] = {0};
    for (int k = 0; k < r->npoints; ++k) {
        const hx_wp_point *p = &r->point[k];
        present[p->series] = 1;
        fprintf(f, "%s,%.6g,%ld,%ld,%.6g,%.6g,%.6g,%s,%.6g,%ld,%ld,%ld,%.6g,%ld\n",
                hx_wp_series_name(p->series), p->setting, p->steps, p->evaluations, p->seconds,
                p->end_error, p->max_error, p->status == HX_INTEGRATION_OK ? "ok" : "unstable",
                p->all_error, p->newton_iterations, p->jacobians, p->fd_evaluations,
                p->jacobian_seconds, p->partial_calls);
    }
    fclose(f);
    /* one series per method: end-point error (solid) and largest error (dashed) */
    char script[16384];
    int n = snprintf(script, sizeof script,
                     "set datafile separator ','\nset terminal pngcairo size 900,650 font ',11'\n"
                     "set logscale xy\nset grid\nset key outside right noenhanced\nset format y '10^{%%L}'\n"
                     "set format x '10^{%%L}'\n"
                     "set ylabel 'relative error%s'\n",
                     r->restricted ? " of the slow outputs" : "");
    static const char *const axes[2][3] = {{"error_time", "run time (s)", "5"},
                                           {"error_evaluations", "right-hand-side evaluations", "4"}};
    for (int a = 0; a < 2 && n > 0 && (size_t)n < sizeof script; ++a) {
        n += snprintf(script + n, sizeof script - (size_t)n,
                      "set output '%s_%s.png'\nset title '%s: error against %s' noenhanced\n"
                      "set xlabel '%s'\n"
                      "plot", prefix, axes[a][0], title, axes[a][1], axes[a][1]);
        int plotted = 0;
        for (int m = 0; m < HX_WP_SERIES && n > 0 && (size_t)n < sizeof script; ++m) {
            if (!present[m])
                continue;
            const char *name = hx_wp_series_name((hx_wp_series)m);
            n += snprintf(script + n, sizeof script - (size_t)n,
                          "%s '%s' using (strcol(1) eq '%s' && strcol(8) eq 'ok' ? $%s : 1/0):6"
                          " with linespoints lw 2 lc %d title '%s, end',"
                          " '%s' using (strcol(1) eq '%s' && strcol(8) eq 'ok' ? $%s : 1/0):7"
                          " with lines dt 2 lc %d title '%s, largest'",
                          plotted++ ? "," : "", csv, name, axes[a][2], m + 1, name, csv, name,
                          axes[a][2], m + 1, name);
        }
        n += snprintf(script + n, sizeof script - (size_t)n, "\n");
    }
    if (n < 0 || (size_t)n >= sizeof script)
        return -1;
    snprintf(script_path, sizeof script_path, "%s_work_precision.gp", prefix);
    return hx_gnuplot(script_path, script);
}
