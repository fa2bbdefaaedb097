/* Simulations: integration, CSV output and summary (simulation.h). */
#include "sim/simulation/simulation.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>

#include "base/clock.h"
#include "sim/dynamics/bodies.h"
#include "sim/dynamics/constraints.h"
#include "sim/dynamics/joint_turns.h"
#include "sim/dynamics/redundancy.h"
#include "sim/dynamics/implicit_diffs.h"
#include "sim/jacobian/jacobian.h"
#include "sim/simulation/equilibrium.h"
#include "sim/simulation/equilibrium_matrix.h"

typedef struct run_context {
    hx_dynamics *d;           /* its redundant rows follow a static equilibrium */
    hx_dynamics_data *dd;     /* the run's evaluations */
    const hx_simulation_options *opt;
    hx_simulation_result *result;
    double started, last_progress;
    hx_jacobian *jacobian;    /* BDF: its sparsity, and with analytic partials J; a
                               * static equilibrium's Newton matrix (equilibrium.h) */
    const hx_variable_definitions *own; /* the model's variables, when a segment redefines
                                         * one (NULL: none does) */
} run_context;

static int rhs(void *ctx, double t, const double *y, double *ydot)
{
    run_context *rc = ctx;
    return hx_dynamics_rhs(rc->d, rc->dd, t, y, ydot);
}

static int project(void *ctx, double t, double *y)
{
    run_context *rc = ctx;
    if (hx_constraints_project(rc->d, rc->dd, t, y) != 0)
        return -1;
    return rc->d->nrows > 0 ? 1 : 0;
}

/* The Jacobian's data follows the run's turns (BDF's Newton matrices are
 * built at the states the run's steps reach). */
static void follow_turns(run_context *rc)
{
    if (rc->opt->integration.method == HX_METHOD_BDF)
        hx_joint_turns_copy(rc->d, &rc->jacobian->dd, rc->dd);
}

/* An accepted step: the rotations between moving bodies counted from it
 * (joint_turns.h), and the implicit Control_Diffs' Newton starting from its
 * rates (implicit_diffs.h; the step's last evaluation is at its end). */
static int accept(void *ctx, double t, const double *y)
{
    run_context *rc = ctx;
    if (hx_joint_turns_accept(rc->d, rc->dd, t, y) != 0)
        return -1;
    follow_turns(rc);
    hx_implicit_diffs_keep(rc->d, rc->dd);
    return 0;
}

/* The turns held at (t, y): the run's start, or a static equilibrium's state. */
static void start_turns(run_context *rc, double t, const double *y)
{
    hx_joint_turns_start(rc->d, rc->dd, t, y);
    follow_turns(rc);
}

static void advance(void *ctx, double *y, double h)
{
    hx_bodies_advance_positions(((run_context *)ctx)->d, y, h);
}

static int jacobian(void *ctx, double t, const double *y, const double *fy, double *values)
{
    return hx_jacobian_build(((run_context *)ctx)->jacobian, t, y, fy, values);
}

static int output_work(run_context *rc, double t, const double *y);

/* Output times: their work is timed apart from the integration's. */
static int output(void *ctx, double t, const double *y)
{
    run_context *rc = ctx;
    const double start = hx_seconds();
    const int status = output_work(rc, t, y);
    rc->result->output_seconds += hx_seconds() - start;
    rc->result->outputs++;
    return status;
}

static int output_work(run_context *rc, double t, const double *y)
{
    const hx_dynamics *d = rc->d;
    hx_dynamics_data *dd = rc->dd;
    hx_simulation_result *r = rc->result;
    if (!rc->opt->skip_energy || rc->opt->csv != NULL) {
        const hx_energy e = hx_energy_of(d, dd, t, y);
        r->energy_scale = fmax(r->energy_scale, fabs(e.kinetic));
        r->energy_error_max = fmax(r->energy_error_max, fabs(e.total - r->energy0.total));
        r->balance_error_max = fmax(r->balance_error_max, fabs(e.balance - r->energy0.balance));
        if (rc->opt->csv != NULL && hx_csv_row(rc->opt->csv, d, dd, t, y, &e, &r->energy0) != 0)
            return 1;
    }
    if (rc->opt->observer != NULL && rc->opt->observer(rc->opt->observer_ctx, d, dd, t, y) != 0)
        return 1;
    if (rc->opt->progress) {
        const double wall = hx_seconds();
        if (wall - rc->last_progress >= 1.0) {
            const double end = rc->opt->integration.t_end;
            fprintf(stderr, "\rrun: t = %.6g of %.6g (%.0f%%), %.1f s", t, end,
                    end > 0 ? 100.0 * t / end : 100.0, wall - rc->started);
            fflush(stderr);
            rc->last_progress = wall;
        }
    }
    return 0;
}

/* A later segment's counts added to the run's; its last step, order and
 * the rest of what describes the end taken. */
static void add_stats(hx_integrator_stats *run, const hx_integrator_stats *segment)
{
    const hx_integrator_stats before = *run;
    *run = *segment;
    run->steps += before.steps;
    run->rejected += before.rejected;
    run->evaluations += before.evaluations;
    run->newton_iterations += before.newton_iterations;
    run->jacobians += before.jacobians;
    run->error_test_failures += before.error_test_failures;
    run->convergence_failures += before.convergence_failures;
    run->fd_jacobian_evaluations += before.fd_jacobian_evaluations;
    run->partial_calls += before.partial_calls;
    run->jacobian_seconds += before.jacobian_seconds;
    if (before.stiff) { /* where it first seemed stiff */
        run->stiff = 1;
        run->t_stiff = before.t_stiff;
    }
}

/* The loads and force elements a segment switches off, its gravity and its
 * variables' definitions (docs/interface.md §9.9). */
static void switch_segment(const run_context *rc, const hx_segment *g)
{
    const hx_dynamics *d = rc->d;
    hx_dynamics_switch(d, g->switched_off);
    memcpy(d->gravity, g->gravity != NULL ? g->gravity : d->m->gravity, 3 * sizeof(double));
    if (rc->own != NULL)
        hx_variable_definitions_apply(g->variables != NULL ? g->variables : rc->own, d->m);
}

/* Whether segment g changes d's gravity or switches a load or force element. */
static int switches(const hx_dynamics *d, const hx_segment *g)
{
    const double *gravity = g->gravity != NULL ? g->gravity : d->m->gravity;
    if (memcmp(gravity, d->gravity, 3 * sizeof(double)) != 0)
        return 1;
    const int nloads = d->m->nloads;
    for (int k = 0; k < nloads; ++k)
        if (d->load_off[k] != (g->switched_off != NULL ? g->switched_off[k] : 0))
            return 1;
    for (int k = 0; k < d->m->nforces; ++k)
        if (d->force_off[k] != (g->switched_off != NULL ? g->switched_off[nloads + k] : 0))
            return 1;
    return 0;
}

/* names appended to text (size) after ", " when both have some. */
static void join_names(char *text, size_t size, const char *names)
{
    size_t used = strlen(text);
    if (names[0] == '\0')
        return;
    /* copied by hand: as snprintf would, cut at size, which some builds' -Wformat-truncation
     * refuses to see as meant */
    for (const char *p = used > 0 ? ", " : ""; *p != '\0' && used + 1 < size; ++p)
        text[used++] = *p;
    for (const char *p = names; *p != '\0' && used + 1 < size; ++p)
        text[used++] = *p;
    text[used] = '\0';
}

/* y moved to the static equilibrium at t (equilibrium.h) and the redundant
 * rows found again where it left the parts (redundancy.h): when the set
 * changes, the equilibrium again with the new set from there, as the
 * set-up's assembly does (up to HX_REDUNDANCY_PASSES times); the rows changed
 * named in the result. An equilibrium that does not converge is looked at
 * too: one leaving a pose where a row was redundant finds no step that keeps
 * it removed (docs/architecture.md, the constraint system). The energy
 * balance is counted from there. */
static int find_equilibrium(run_context *rc, double t, double *y)
{
    hx_simulation_result *result = rc->result;
    hx_message msg, failure;
    int status = 0;
    /* its Newton matrix from the Jacobian unless differences are asked for (BDF's
     * option) or cost less (equilibrium_matrix.h) */
    const int analytic = rc->opt->integration.jacobian == HX_JACOBIAN_ANALYTIC;
    hx_jacobian *jac = analytic && rc->jacobian->d != NULL &&
                               hx_equilibrium_jacobian_pays(rc->jacobian) ? rc->jacobian : NULL;
    for (int pass = 0; pass <= HX_REDUNDANCY_PASSES; ++pass) {
        char no_longer[sizeof result->no_longer], now[sizeof result->now];
        const int solved = hx_equilibrium_solve(rc->d, rc->dd, jac, t, y,
                                                &result->equilibrium, &failure) == 0;
        status = solved ? 0 : -1;
        if (rc->opt->keep_redundant || pass == HX_REDUNDANCY_PASSES)
            break;
        const int changed = hx_redundancy_reexamine(rc->d, rc->dd, t, y, no_longer, now,
                                                    sizeof now, &msg);
        if (changed < 0) {
            failure = msg, status = -1;
            break;
        }
        if (changed == 0)
            break;
        join_names(result->no_longer, sizeof result->no_longer, no_longer);
        join_names(result->now, sizeof result->now, now);
        result->redundancy_changes += changed;
        result->t_redundancy = t;
    }
    if (status != 0) {
        msg = failure;
        snprintf(result->message, sizeof result->message, "%s", msg.text);
        result->status = HX_INTEGRATION_FAILED;
        return -1;
    }
    result->statics++;
    start_turns(rc, t, y);
    result->energy0 = hx_energy_of(rc->d, rc->dd, t, y);
    return 0;
}

/* The run's work once its data is set up; the caller frees both. */
static int simulate(run_context *rc, const hx_segment *segments, int nsegments, double *y,
                    double *y_end)
{
    hx_dynamics *d = rc->d;
    hx_dynamics_data *dd = rc->dd;
    const hx_simulation_options *opt = rc->opt;
    hx_simulation_result *result = rc->result;
    if (hx_dynamics_initial_state(d, dd, y) != 0) {
        snprintf(result->message, sizeof result->message, "%s", dd->message);
        result->status = HX_INTEGRATION_FAILED;
        return -1;
    }
    start_turns(rc, 0.0, y);
    if (nsegments > 0)
        switch_segment(rc, &segments[0]);
    if ((opt->static_start || (nsegments > 0 && segments[0].equilibrium)) &&
        find_equilibrium(rc, 0.0, y) != 0)
        return -1;
    result->energy0 = hx_energy_of(d, dd, 0.0, y);
    result->energy_scale = fmax(fabs(result->energy0.total), fabs(result->energy0.kinetic));
    const int bdf = opt->integration.method == HX_METHOD_BDF;
    const int analytic = bdf && opt->integration.jacobian == HX_JACOBIAN_ANALYTIC;
    if (opt->csv != NULL) {
        hx_csv_header(opt->csv, d);
        if (hx_csv_row(opt->csv, d, dd, 0.0, y, &result->energy0, &result->energy0) != 0) {
            snprintf(result->message, sizeof result->message, "%s", dd->message);
            result->status = HX_INTEGRATION_FAILED;
            return -1;
        }
    }
    if (opt->observer != NULL)
        opt->observer(opt->observer_ctx, d, dd, 0.0, y);
    hx_ode ode = {d->n, d->nq, d->nu, 2 /* the work accumulators */, rhs, project, advance, rc,
                  analytic ? jacobian : NULL, bdf ? &rc->jacobian->pattern : NULL, accept};
    const double start = hx_seconds();
    double t = 0.0;
    for (int k = 0; k < nsegments; ++k) {
        /* each segment from the state the one before it ended in (docs/interface.md
         * §9.9): the integrator restarts there; its first output is after t */
        const int rebase = k > 0 && switches(d, &segments[k]);
        const hx_energy before = rebase ? hx_energy_of(d, dd, t, y) : result->energy0;
        switch_segment(rc, &segments[k]);
        if (rebase) { /* an ACCGRAV moves the potential's zero, a switched force element takes
                       * its stored energy along: neither is work done */
            const hx_energy after = hx_energy_of(d, dd, t, y);
            result->energy0.total += after.total - before.total;
            result->energy0.balance += after.balance - before.balance;
        }
        if (k > 0 && segments[k].equilibrium) { /* SIMULATE/STATIC between segments: its row */
            if (find_equilibrium(rc, t, y) != 0)
                break;
            if (opt->csv != NULL &&
                hx_csv_row(opt->csv, d, dd, t, y, &result->energy0, &result->energy0) != 0) {
                result->status = HX_INTEGRATION_FAILED;
                break;
            }
        }
        if (!(segments[k].t_end > t)) /* the equilibrium alone */
            continue;
        hx_integrator_options io = opt->integration;
        io.output = output;
        io.t_end = segments[k].t_end;
        io.output_interval = segments[k].output_interval;
        io.rtol = segments[k].rtol;
        io.atol = segments[k].atol;
        hx_integrator_stats stats;
        result->status = hx_integrate(&ode, t, y, &io, k == 0 ? &result->stats : &stats);
        if (k > 0)
            add_stats(&result->stats, &stats);
        if (result->status != HX_INTEGRATION_OK)
            break;
        t = segments[k].t_end;
    }
    result->seconds = hx_seconds() - start;
    if (bdf) {
        result->stats.partial_calls = rc->jacobian->partial_calls;
        result->stats.evaluations += rc->jacobian->evaluations;
        result->jacobian_outside = rc->jacobian->outside;
        if (analytic)
            hx_jacobian_describe(rc->jacobian, result->jacobian, sizeof result->jacobian);
    }
    if (opt->progress && result->seconds >= 1.0)
        fprintf(stderr, "\n");
    /* a failure's reason: the run's evaluation's, or the Jacobian's */
    const hx_dynamics_data *failed = dd->failed ? dd
                                     : bdf && rc->jacobian->dd.failed ? &rc->jacobian->dd
                                                                      : NULL;
    if (failed != NULL)
        snprintf(result->message, sizeof result->message, "%s", failed->message);
    else if (result->status != HX_INTEGRATION_OK)
        snprintf(result->message, sizeof result->message, "integration %s at t = %.6g",
                 hx_status_text(result->status), result->stats.t_reached);
    result->energy_end = hx_energy_of(d, dd, result->stats.t_reached, y);
    result->dissipated = hx_dissipated(&result->energy_end, &result->energy0);
    result->max_phi = dd->max_phi;
    result->max_phidot = dd->max_phidot;
    if (y_end != NULL)
        memcpy(y_end, y, sizeof(double) * (size_t)d->n);
    return result->status == HX_INTEGRATION_OK ? 0 : -1;
}

int hx_simulate(hx_dynamics *d, const hx_simulation_options *opt, double *y_end,
                hx_simulation_result *result)
{
    const hx_segment whole = {opt->integration.t_end, opt->integration.output_interval,
                              opt->integration.rtol, opt->integration.atol, NULL, NULL, 0, NULL};
    return hx_simulate_segments(d, opt, &whole, 1, y_end, result);
}

/* BDF's pattern widened to the dependencies of every segment's variables
 * (docs/interface.md §9.9), once before the run; the model's own back in
 * force after. 0, or -1 with msg. */
static int widen(hx_jacobian *jac, const hx_segment *segments, int nsegments,
                 const hx_variable_definitions *own, hx_message *msg)
{
    int status = 0;
    for (int k = 0; k < nsegments && status == 0; ++k) {
        if (segments[k].variables == NULL ||
            (k > 0 && segments[k].variables == segments[k - 1].variables))
            continue;
        hx_variable_definitions_apply(segments[k].variables, jac->d->m);
        status = hx_jacobian_widen(jac, msg);
    }
    if (own->program != NULL)
        hx_variable_definitions_apply(own, jac->d->m);
    return status;
}

int hx_simulate_segments(hx_dynamics *d, const hx_simulation_options *opt,
                         const hx_segment *segments, int nsegments, double *y_end,
                         hx_simulation_result *result)
{
    memset(result, 0, sizeof *result);
    result->n = d->n;
    hx_dynamics_data dd;
    hx_jacobian jac;
    hx_message msg;
    memset(&jac, 0, sizeof jac);
    double *y = malloc(sizeof(double) * (size_t)d->n);
    /* the redundant rows the run starts with: a static equilibrium may change them */
    const int nremoved = d->nremoved;
    int *removed = malloc(sizeof(int) * ((size_t)d->nremoved + 1));
    int status = -1;
    if (y == NULL || removed == NULL) {
        free(y), free(removed);
        snprintf(result->message, sizeof result->message, "out of memory");
        return -1;
    }
    memcpy(removed, d->removed, sizeof(int) * (size_t)nremoved);
    /* the model's own variables, kept when a segment redefines one */
    hx_variable_definitions own = {0};
    int redefines = 0, statics = opt->static_start;
    for (int k = 0; k < nsegments; ++k) {
        redefines |= segments[k].variables != NULL;
        statics |= segments[k].equilibrium;
    }
    /* the Jacobian for BDF, and for a static equilibrium's Newton matrix */
    const int jacobian = opt->integration.method == HX_METHOD_BDF ||
                         (statics && opt->integration.jacobian == HX_JACOBIAN_ANALYTIC);
    if ((redefines && hx_variable_definitions_of(&own, d->m, &msg) != 0) ||
        hx_dynamics_data_init(&dd, d, &msg) != 0 ||
        (jacobian &&
         (hx_jacobian_init(&jac, d, &msg) != 0 || widen(&jac, segments, nsegments, &own, &msg) != 0))) {
        snprintf(result->message, sizeof result->message, "%s", msg.text);
        result->status = HX_INTEGRATION_FAILED;
    } else {
        run_context rc = {d, &dd, opt, result, hx_seconds(), hx_seconds(), &jac,
                          redefines ? &own : NULL};
        status = simulate(&rc, segments, nsegments, y, y_end);
    }
    /* every load and force element on again, the model's gravity, variables and redundant rows, as the
     * set-up has them, however the run ended: the next run on d starts from the model */
    hx_dynamics_switch(d, NULL);
    if (result->redundancy_changes > 0 && hx_redundancy_use(d, removed, nremoved, &msg) != 0)
        status = -1; /* out of memory: the run's message stands */
    free(removed);
    memcpy(d->gravity, d->m->gravity, 3 * sizeof(double));
    if (redefines && own.program != NULL)
        hx_variable_definitions_apply(&own, d->m);
    hx_variable_definitions_free(&own);
    hx_jacobian_free(&jac);
    hx_dynamics_data_free(&dd);
    free(y);
    return status;
}

/* Newton iterations and Jacobians per step, and what the Newton matrix cost. */
static void bdf_summary(FILE *f, const hx_simulation_options *opt, const hx_simulation_result *r)
{
    const hx_integrator_stats *st = &r->stats;
    const double steps = st->steps > 0 ? (double)st->steps : 1.0;
    fprintf(f, "  bdf (CVODE, max order %d, last order %d): %ld Newton iterations (%.2f per step),"
            " %ld Jacobians (one per %.1f steps), %ld error-test and %ld convergence failures\n",
            opt->integration.max_order > 0 ? opt->integration.max_order : 5, st->last_order,
            st->newton_iterations, (double)st->newton_iterations / steps, st->jacobians,
            st->jacobians > 0 ? steps / (double)st->jacobians : 0.0, st->error_test_failures,
            st->convergence_failures);
    fprintf(f, "  linear solver: %s (%s; %ld nonzeros of %d x %d); Newton matrices took %.3g s\n",
            st->linear_solver == HX_LINEAR_KLU ? "KLU, sparse LU" : "dense LU",
            opt->integration.linear_solver != HX_LINEAR_AUTO ? "as asked"
            : st->linear_solver == HX_LINEAR_KLU ? "auto: a model this size"
                                                 : "auto: a model this small",
            st->nonzeros, r->n, r->n, st->jacobian_seconds);
    if (opt->integration.jacobian == HX_JACOBIAN_FD)
        fprintf(f, "  Jacobian by differences of the right-hand side in %d column groups: %ld"
                " of the %ld right-hand sides\n", st->column_groups, st->fd_jacobian_evaluations,
                st->evaluations);
    else
        fprintf(f, "  %s\n  its cost: %ld element calls for partials\n", r->jacobian,
                st->partial_calls);
}

void hx_simulation_summary(FILE *f, const hx_dynamics *d, const hx_simulation_options *opt,
                           const hx_simulation_result *r)
{
    fprintf(f, "run: %s with %s to t = %.6g\n", hx_status_text(r->status),
            hx_method_name(opt->integration.method), r->stats.t_reached);
    fprintf(f, "  steps %ld, rejected %ld, right-hand sides %ld, last step %.3g\n", r->stats.steps,
            r->stats.rejected, r->stats.evaluations, r->stats.last_step);
    const double stepping = r->seconds - r->output_seconds;
    fprintf(f, "  run time %.3f s: %.3f s stepping (%.3g us per right-hand side), %.3f s at %ld"
            " output times\n", r->seconds, stepping,
            r->stats.evaluations ? 1e6 * stepping / (double)r->stats.evaluations : 0.0,
            r->output_seconds, r->outputs);
    struct rusage usage;
    if (getrusage(RUSAGE_SELF, &usage) == 0)
        fprintf(f, "  peak memory %.1f MB (the whole process)\n", (double)usage.ru_maxrss / 1024.0);
    if (r->statics > 0)
        fprintf(f, "  static equilibri%s: %d; the last in %d Newton iterations (%ld right-hand"
                " sides, Newton matrix %s, %.3g s), unbalanced loads %.3g of the model's force"
                " %.6g\n", r->statics == 1 ? "um" : "a", r->statics, r->equilibrium.iterations,
                r->equilibrium.evaluations,
                r->equilibrium.analytic ? "from the Jacobian" : "by differences",
                r->equilibrium.seconds, r->equilibrium.residual, r->equilibrium.force_scale);
    if (d->nrows > 0)
        fprintf(f, "  largest constraint residual |phi| %.3g, |dphi/dt| %.3g\n", r->max_phi,
                r->max_phidot);
    const double scale = r->energy_scale > 0.0 ? r->energy_scale : 1.0;
    fprintf(f, "  energy (kinetic + potential + elastic - work of loads) %.10g -> %.10g\n",
            r->energy0.total, r->energy_end.total);
    fprintf(f, "  elements dissipated %.6g; largest energy change %.3g (%.3g relative)\n",
            r->dissipated, r->energy_error_max, r->energy_error_max / scale);
    fprintf(f, "  energy balance (dissipation counted): largest error %.3g (%.3g relative)\n",
            r->balance_error_max, r->balance_error_max / scale);
    fprintf(f, "  (relative to max(|E(0)|, largest kinetic energy) = %.6g)\n", r->energy_scale);
    if (opt->integration.method == HX_METHOD_BDF)
        bdf_summary(f, opt, r);
    if (r->stats.stiff)
        fprintf(f, "  dopri5: the problem seems to become stiff at t = %.6g\n", r->stats.t_stiff);
    if (r->stats.solver_message[0] != '\0' && r->status != HX_INTEGRATION_OK)
        fprintf(f, "  %s\n", r->stats.solver_message);
    if (r->message[0] != '\0')
        fprintf(f, "  %s\n", r->message);
}
