/* usrsub-harness run: integrate a model's dynamics. */
#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <unistd.h>

#include "cmd/commands.h"
#include "cmd/crash_report.h"
#include "cmd/options.h"
#include "sim/dynamics/assembly.h"
#include "sim/dynamics/redundancy.h"
#include "sim/simulation/command_schedule.h"
#include "sim/simulation/simulation.h"
#include "tools/bench/stability.h"

static void usage(FILE *f)
{
    fprintf(f,
            "usage: usrsub-harness run MODEL.xml --end T [options]\n"
            "       usrsub-harness run MODEL.adm [options]   (follows MODEL.acf beside it)\n"
            "\n"
            "  --end T             end time (with a command file: the run cut there)\n"
            "  --acf FILE          follow this command file (SIMULATE/DYNAMIC segments,\n"
            "                      INTEGRATOR's ERROR); the options given override its values\n"
            "  --no-acf            do not follow MODEL.acf beside MODEL.adm\n"
            "  --static            start from the static equilibrium: the parts moved to where\n"
            "                      the loads balance, velocities zero (as SIMULATE/STATIC)\n"
            "  --integrator NAME   dopri5 (default: adaptive, error-controlled) |\n"
            "                      bdf (implicit, variable order and step: stiff models) |\n"
            "                      rk4 | euler | symplectic-euler (fixed steps: give --step) |\n"
            "                      dopri5-arkode (ARKODE's Dormand-Prince, for comparison)\n"
            "  --jacobian KIND     bdf's Newton matrix: analytic (default: the elements' own\n"
            "                      partials, assembled element by element) | fd (differences of\n"
            "                      the right-hand side, by column groups on the sparsity); and\n"
            "                      the static equilibrium's (analytic where it costs less)\n"
            "  --linear-solver S   bdf's Newton systems: auto (default: dense LU for one\n"
            "                      body, below 16 states; KLU sparse LU from 16 on) | dense |\n"
            "                      klu\n"
            "  --max-order Q       bdf's highest order, 1 to 5 (default 5)\n"
            "  --step H            fixed step (adaptive methods: the first step; default\n"
            "                      automatic)\n"
            "  --out FILE.csv      joint coordinates, velocities, multipliers, element\n"
            "                      deformations and loads, energy and residuals\n"
            "  --output-interval DT  time between CSV rows (default: end/1000)\n"
            "  --rtol R, --atol A  tolerances of the adaptive methods (default 1e-6, 1e-9)\n"
            "  --max-step H        the adaptive methods' largest step\n"
            "  --quiet             no progress line\n"
            "\n"
            "The summary says when the model is stiff for the run (its fastest mode against\n"
            "the end time) and recommends bdf then, or an explicit method when it is not.\n");
}

static int stability_at_start(const hx_dynamics *d, hx_stability *st)
{
    hx_message msg;
    double *y = calloc((size_t)d->n, sizeof(double));
    const int status = y != NULL && hx_dynamics_initial_y(d, y, &msg) == 0 &&
                               hx_estimate_stability(d, 0.0, y, st, &msg) == 0
                           ? 0
                           : -1;
    free(y);
    return status;
}

/* The model is stiff for a run when the stability limit of its fastest mode
 * alone would hold an explicit method to this many steps or more. */
#define STIFF_STEPS 500.0

/* The highest BDF order stable on a mode at any step: the order's A(alpha)
 * sector (90, 90, 86.0, 73.4, 51.8 degrees for orders 1 to 5) must hold the
 * mode's angle from the negative real axis. */
static int stable_bdf_order(double re, double im)
{
    static const double alpha[5] = {90.0, 90.0, 86.03, 73.35, 51.84};
    const double angle = atan2(fabs(im), -re) * 180.0 / M_PI;
    int q = 1;
    while (q < 5 && alpha[q] >= angle)
        ++q;
    return q;
}

/* Nothing chosen silently: whether the model is stiff for this run, with the
 * figures, and the integrator (and BDF order) that suits it. */
static void stiffness_advice(FILE *f, const hx_stability *st, const hx_integrator_options *io,
                             const hx_integrator_stats *stats)
{
    const double h = st->max_step[HX_METHOD_DOPRI5];
    if (!isfinite(h) || !(h > 0.0) || st->re > 0.0)
        return; /* a growing mode (re > 0) bounds accuracy, not stability: no advice */
    const double steps = io->t_end / h;
    const int stiff = steps >= STIFF_STEPS;
    const int order = stable_bdf_order(st->re, st->im);
    const int max_order = io->max_order > 0 ? io->max_order : 5;
    if (stiff && io->method != HX_METHOD_BDF)
        fprintf(f, "  stiff for this run: the fastest mode (lambda = %.4g + %.4gi, |lambda| = %.4g"
                " 1/s at t = 0) holds dopri5 to steps below %.3g s, at least %.0f steps (%.0f"
                " right-hand sides) to t = %g, however slow the motion of interest (this run: %ld"
                " steps); --integrator bdf is not bound by it (Newton matrix from the elements'"
                " partials)\n", st->re, st->im, st->magnitude, h, ceil(steps), 6.0 * ceil(steps),
                io->t_end, stats->steps);
    else if (stiff)
        fprintf(f, "  stiff for this run: the fastest mode (|lambda| = %.4g 1/s at t = 0) would hold"
                " dopri5 to steps below %.3g s, at least %.0f steps to t = %g; bdf took %ld\n",
                st->magnitude, h, ceil(steps), io->t_end, stats->steps);
    else if (io->method == HX_METHOD_BDF)
        fprintf(f, "  not stiff for this run: dopri5's stable step %.3g s (|lambda| = %.4g 1/s at"
                " t = 0) reaches t = %g in %.0f steps; an explicit method (--integrator dopri5)"
                " needs no Newton matrix and is likely cheaper here (bench --work-precision"
                " measures both)\n", h, st->magnitude, io->t_end, ceil(steps));
    if (stiff && order < 5 && (io->method != HX_METHOD_BDF || max_order > order))
        fprintf(f, "  the fastest mode is lightly damped (damping ratio %.3g): BDF above order %d"
                " is unstable on it at steps beyond about 1/|lambda|, and its error control then"
                " holds the step near that limit; --max-order %d keeps BDF stable on it at any"
                " step (a step beyond its period damps it away)\n",
                -st->re / st->magnitude, order, order);
}

/* How far the assembly moved the parts, each said once before the run (a
 * failed assembly is the run's failure, said by its summary). */
static void assembly_report(const hx_dynamics *d)
{
    hx_assembly_move *moves = malloc(sizeof *moves * ((size_t)d->m->nbodies + 1));
    hx_message msg;
    const int count = moves != NULL ? hx_assembly_moves(d, moves, &msg) : 0;
    for (int k = 0; k < count; ++k)
        fprintf(stderr, "run: note: the assembly moved PART/%d by %.3g (its centre of mass) and"
                " turned it by %.3g rad\n", d->m->bodies[moves[k].body].id,
                moves[k].translation, moves[k].rotation);
    free(moves);
}

/* What the command line says besides the options' values. */
typedef struct run_args {
    const char *out;
    const char *acf;  /* --acf FILE */
    int no_acf;       /* --no-acf */
    hx_command_overrides given; /* the values given, 0 where not */
} run_args;

/* Reads the options into so; returns -1 (exit 2) on a bad one, 1 on --help. */
static int parse(int argc, char **argv, hx_simulation_options *so, run_args *args)
{
    static const struct option options[] = {
        {"integrator", required_argument, NULL, 'i'}, {"step", required_argument, NULL, 's'},
        {"end", required_argument, NULL, 'e'},        {"out", required_argument, NULL, 'o'},
        {"output-interval", required_argument, NULL, 'I'},
        {"rtol", required_argument, NULL, 'r'},       {"atol", required_argument, NULL, 'a'},
        {"max-step", required_argument, NULL, 'm'},   {"quiet", no_argument, NULL, 'q'},
        {"jacobian", required_argument, NULL, 'j'},   {"max-order", required_argument, NULL, 'O'},
        {"linear-solver", required_argument, NULL, 'L'},
        {"acf", required_argument, NULL, 'A'},        {"no-acf", no_argument, NULL, 'N'},
        {"static", no_argument, NULL, 'S'},
        {"help", no_argument, NULL, 'h'},             {0, 0, 0, 0}};
    hx_integrator_options *io = &so->integration;
    int opt;
    optind = 1;
    while ((opt = getopt_long(argc, argv, "h", options, NULL)) != -1) {
        int bad = 0;
        switch (opt) {
        case 'i':
            if (hx_method_parse(optarg, &io->method) != 0) {
                fprintf(stderr, "usrsub-harness run: --integrator '%s' is not one of dopri5, bdf,"
                        " rk4, euler, symplectic-euler, dopri5-arkode\n", optarg);
                bad = 1;
            }
            break;
        case 'j':
            if (hx_jacobian_method_parse(optarg, &io->jacobian) != 0) {
                fprintf(stderr, "usrsub-harness run: --jacobian '%s' is not analytic or fd\n",
                        optarg);
                bad = 1;
            }
            break;
        case 'L':
            if (hx_linear_solver_parse(optarg, &io->linear_solver) != 0) {
                fprintf(stderr, "usrsub-harness run: --linear-solver '%s' is not auto, dense or"
                        " klu\n", optarg);
                bad = 1;
            }
            break;
        case 'O': bad = hx_option_max_order("run", optarg, &io->max_order); break;
        case 's': bad = hx_option_positive("run", "step", optarg, &io->step); break;
        case 'e': bad = hx_option_positive("run", "end", optarg, &io->t_end); break;
        case 'o': args->out = optarg; break;
        case 'A': args->acf = optarg; break;
        case 'N': args->no_acf = 1; break;
        case 'S': so->static_start = 1; break;
        case 'I': bad = hx_option_positive("run", "output-interval", optarg, &io->output_interval); break;
        case 'r': bad = hx_option_positive("run", "rtol", optarg, &io->rtol); break;
        case 'a': bad = hx_option_positive("run", "atol", optarg, &io->atol); break;
        case 'm': bad = hx_option_positive("run", "max-step", optarg, &io->max_step); break;
        case 'q': so->progress = 0; break;
        case 'h': usage(stdout); return 1;
        default: usage(stderr); return -1;
        }
        if (bad)
            return -1;
    }
    if (optind != argc - 1) {
        fprintf(stderr, "usrsub-harness run: expected one MODEL.xml (got %d)\n\n", argc - optind);
        usage(stderr);
        return -1;
    }
    if (args->acf != NULL && args->no_acf) {
        fprintf(stderr, "usrsub-harness run: --acf and --no-acf: one of them\n");
        return -1;
    }
    args->given = (hx_command_overrides){io->t_end, io->output_interval, io->rtol, io->atol};
    if (!hx_method_adaptive(io->method) && !(io->step > 0.0)) { /* --step takes only > 0 */
        fprintf(stderr, "usrsub-harness run: %s takes fixed steps: give --step (or use the"
                " default dopri5, which chooses its own)\n", hx_method_name(io->method));
        return -1;
    }
    return 0;
}

/* The command file the run follows: --acf's, else MODEL.acf beside an .adm
 * MODEL (the same name), unless --no-acf; NULL when none (docs/interface.md
 * §9.9). */
static const char *command_file_path(const char *model, const run_args *args, char *path,
                                     size_t size)
{
    if (args->no_acf)
        return NULL;
    if (args->acf != NULL)
        return args->acf;
    const size_t n = strlen(model);
    if (n < 4 || n >= size || strcasecmp(model + n - 4, ".adm") != 0)
        return NULL;
    snprintf(path, size, "%.*s.acf", (int)(n - 4), model);
    return access(path, F_OK) == 0 ? path : NULL;
}


int hx_command_run(int argc, char **argv)
{
    hx_simulation_options so = {0};
    hx_integrator_defaults(&so.integration);
    /* the tolerances given are told from the defaults: a command file's ERROR
     * stands unless they are */
    const double rtol = so.integration.rtol, atol = so.integration.atol;
    so.integration.rtol = so.integration.atol = 0.0;
    so.integration.method = HX_METHOD_DOPRI5;
    so.progress = 1;
    run_args args = {0};
    const int parsed = parse(argc, argv, &so, &args);
    if (parsed != 0)
        return parsed > 0 ? 0 : 2;
    const char *out = args.out;
    char acf_path[4096];
    const char *acf = command_file_path(argv[optind], &args, acf_path, sizeof acf_path);
    hx_command_schedule schedule = {0};
    hx_command_file *commands = NULL; /* read here: its path is the start folder's */
    hx_message msg;
    if (acf != NULL) {
        fprintf(stderr, "run: following the command file %s\n", acf);
        if ((commands = hx_command_file_read(acf, &msg)) == NULL) {
            fprintf(stderr, "usrsub-harness run: %s\n", msg.text);
            return 1;
        }
    } else if (!(so.integration.t_end > 0.0)) {
        fprintf(stderr, "usrsub-harness run: --end T is needed (or a command file: --acf FILE)\n");
        return 2;
    }
    hx_session s;
    if (hx_session_open(&s, argv[optind], stderr, &msg) != 0) {
        fprintf(stderr, "usrsub-harness run: %s\n", msg.text);
        hx_command_file_free(commands);
        return 1;
    }
    hx_dynamics d;
    memset(&d, 0, sizeof d); /* freed as it is when the schedule is refused */
    char path[4096];
    /* the command file's segments, its switches resolved on the model's loads */
    const int scheduled = commands == NULL ||
                          hx_command_schedule_make(commands, acf, s.model, argv[optind], rtol, atol,
                                                   &args.given, stderr, &schedule, &msg) == 0;
    hx_command_file_free(commands);
    if (schedule.nsegments > 0)
        so.integration.t_end = schedule.t_end;
    if (so.integration.rtol <= 0.0)
        so.integration.rtol = rtol;
    if (so.integration.atol <= 0.0)
        so.integration.atol = atol;
    if (so.integration.output_interval <= 0.0)
        so.integration.output_interval = so.integration.t_end / 1000.0;
    if (!scheduled || hx_dynamics_init(&d, &s, &msg) != 0 ||
        (out != NULL && (so.csv = hx_open_output(hx_session_path(&s, out, path, sizeof path), &msg)) == NULL)) {
        fprintf(stderr, "usrsub-harness run: %s\n", msg.text);
        hx_dynamics_free(&d);
        hx_session_close(&s);
        hx_command_schedule_free(&schedule);
        return 1;
    }
    /* the redundant constraint rows the set-up removed, each said once, after how the
     * assembly changed them */
    char no_longer[2048], now[2048];
    if (hx_redundancy_change(&d, no_longer, now, sizeof no_longer) > 0) {
        if (no_longer[0] != '\0')
            fprintf(stderr, "run: note: the assembly moved the parts to where %s, redundant"
                    " where the model places them, is not: kept\n", no_longer);
        if (now[0] != '\0')
            fprintf(stderr, "run: note: the assembly moved the parts to where %s, not redundant"
                    " where the model places them, is: removed\n", now);
    }
    for (int k = 0; k < d.nremoved; ++k) {
        char name[160];
        fprintf(stderr, "run: note: %s is redundant and removed\n",
                hx_redundancy_name_row(&d, d.removed[k], name, sizeof name));
    }
    assembly_report(&d);
    hx_crash_report_begin();
    /* the fastest mode at the start: a fixed step beyond its stability limit is
     * said before the run, and whether the model is stiff for it after */
    hx_stability st;
    if (schedule.nsegments > 0) /* under the first segment's switches: what it deactivates is
                                 * not called (the run sets them again and clears them) */
        hx_dynamics_switch(&d, schedule.segments[0].switched_off);
    const int known = stability_at_start(&d, &st) == 0;
    const int fixed = !hx_method_adaptive(so.integration.method);
    const int limited = fixed && known;
    const double limit = limited ? st.max_step[so.integration.method] : INFINITY;
    if (limited && so.integration.step > limit)
        fprintf(stderr, "run: warning: the step %g is above %s's stability limit %.3g for the"
                " model's fastest mode (lambda = %.4g + %.4gi at t = 0): expect the run to"
                " diverge\n", so.integration.step, hx_method_name(so.integration.method), limit,
                st.re, st.im);
    hx_simulation_result result;
    const int status = schedule.nsegments > 0
                           ? hx_simulate_segments(&d, &so, schedule.segments, schedule.nsegments,
                                                  NULL, &result)
                           : hx_simulate(&d, &so, NULL, &result);
    /* the rows a static equilibrium changed, as the set-up's changes are said */
    if (result.no_longer[0] != '\0')
        fprintf(stderr, "run: note: the static equilibrium at t = %g moved the parts to where"
                " %s, redundant before, is not: kept\n", result.t_redundancy, result.no_longer);
    if (result.now[0] != '\0')
        fprintf(stderr, "run: note: the static equilibrium at t = %g moved the parts to where"
                " %s, not redundant before, is: removed\n", result.t_redundancy, result.now);
    hx_simulation_summary(stdout, &d, &so, &result);
    if (result.status == HX_INTEGRATION_UNSTABLE && limited)
        printf("  the step %g %s the stability limit %.3g of %s at t = 0 (|lambda| = %.4g)\n",
               so.integration.step, so.integration.step > limit ? "exceeds" : "is within",
               limit, hx_method_name(so.integration.method), st.magnitude);
    if (known)
        stiffness_advice(stdout, &st, &so.integration, &result.stats);
    hx_crash_report_end();
    if (so.csv != NULL)
        fclose(so.csv);
    hx_dynamics_free(&d);
    hx_session_close(&s);
    hx_command_schedule_free(&schedule);
    return status == 0 ? 0 : 1;
}
