/* usrsub-harness bench: cost per call, the harness's share, stability limits,
 * work-precision and long runs. */
#include <getopt.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "tools/bench/entry_cost.h"
#include "cmd/commands.h"
#include "cmd/crash_report.h"
#include "cmd/options.h"
#include "tools/bench/long_run.h"
#include "tools/bench/rhs_cost.h"
#include "session/session.h"
#include "tools/bench/stability.h"
#include "tools/bench/work_precision.h"

#define MAX_COMPARISONS 16

static void usage(FILE *f)
{
    fprintf(f, "usage: usrsub-harness bench MODEL.xml [options]\n"
               "\n"
               "Cost per call of every user-subroutine entry of the model, through the\n"
               "dlopen'd function pointer: median over N timed batches of about 2 ms after a\n"
               "warm-up, with the host calls per evaluation and in the dependency pass; the\n"
               "right-hand side against the entries it calls; the stability limits of the\n"
               "explicit integrators at the initial state.\n"
               "\n"
               "  --repeats N           timed batches (default 21)\n"
               "  --compare BASE,OTHER  the added cost of force element OTHER over BASE (ids,\n"
               "                        or vector:ID / field:ID): the median of their\n"
               "                        per-round differences\n"
               "  --work-precision      sweep every integrator against a reference to --end\n"
               "  --end T               horizon of the sweep (default 0.1)\n"
               "  --out PREFIX          PREFIX_work_precision.csv and its plots\n"
               "  --quick               a short sweep (seconds), for CI\n"
               "  --outputs ID[,ID..]   the slow outputs: errors of these bodies' states (default:\n"
               "                        every body; the error of all states is shown beside)\n"
               "  --atol-ratio R        adaptive methods' atol = R * rtol (default 1e-3)\n"
               "  --target E            the error at which the methods' costs are compared\n"
               "                        (default 1e-8)\n"
               "  --max-order Q         BDF's highest order in the sweep, 1 to 5 (default 5)\n"
               "  --long-run STEPS      STEPS fixed steps of symplectic Euler and RK4 at a\n"
               "                        fifth of the fastest mode's period / 2 pi (or --step)\n"
               "  --step H              the long runs' step\n");
}

typedef struct comparison {
    char text[64];
    int base, other; /* force indices */
} comparison;

static const hx_entry_cost *cost_of(const hx_entry_cost *costs, int n, int force_index)
{
    for (int k = 0; k < n; ++k)
        if (costs[k].force_index == force_index)
            return &costs[k];
    return NULL;
}

/* Resolves "BASE,OTHER" against the model. */
static int parse_comparison(const hx_model *m, comparison *c, hx_message *msg)
{
    char base[64];
    const char *comma = strchr(c->text, ',');
    if (comma == NULL || comma - c->text >= (long)sizeof base)
        return hx_fail(msg, "--compare %s: expected BASE,OTHER (two force element ids)",
                           c->text);
    memcpy(base, c->text, (size_t)(comma - c->text));
    base[comma - c->text] = '\0';
    if (hx_model_find_force(m, base, &c->base, msg) != 0 ||
        hx_model_find_force(m, comma + 1, &c->other, msg) != 0) {
        hx_message_prefix(msg, "--compare %s", c->text);
        return -1;
    }
    return 0;
}

typedef struct bench_options {
    int repeats;
    comparison compare[MAX_COMPARISONS];
    int ncompare;
    int work_precision, quick;
    double end, step;
    double atol_ratio, target;
    int noutputs, outputs[HX_WP_MAX_OUTPUTS];
    int max_order;
    long long_steps;
    const char *out;
} bench_options;

static int costs_section(hx_session *s, const bench_options *o)
{
    hx_message msg;
    if (hx_rhs_cost_supported(s, &msg) != 0) {
        /* the rest of bench still applies */
        printf("cost per call and right-hand side split: not measured: %s\n", msg.text);
        return 0;
    }
    hx_entry_cost *costs = calloc(256, sizeof *costs);
    hx_rhs_cost rc;
    int n = 0;
    if (costs == NULL || hx_measure_rhs_cost(s, o->repeats, costs, 256, &n, &rc, &msg) != 0) {
        fprintf(stderr, "usrsub-harness bench: %s\n", costs ? msg.text : "out of memory");
        free(costs);
        return 1;
    }
    printf("cost per call (median of %d batches):\n", o->repeats);
    hx_print_entry_costs(stdout, costs, n);
    char split[512];
    hx_rhs_cost_text(&rc, split, sizeof split);
    printf("%s\n", split);
    for (int k = 0; k < o->ncompare; ++k) {
        const hx_entry_cost *base = cost_of(costs, n, o->compare[k].base);
        const hx_entry_cost *other = cost_of(costs, n, o->compare[k].other);
        if (base == NULL || other == NULL) {
            printf("added cost %s: not a user element of the model\n", o->compare[k].text);
            continue;
        }
        printf("added cost of %s %s over %s %s: %.1f ns per call (median of per-round"
               " differences)\n", other->element, other->function, base->element,
               base->function, hx_added_cost(base, other, o->repeats));
    }
    hx_entry_costs_free(costs, n);
    free(costs);
    return 0;
}

static int stability_section(hx_session *s, hx_stability *st)
{
    hx_message msg = {.text = ""};
    hx_dynamics d;
    int status = hx_dynamics_init(&d, s, &msg);
    double *y = status == 0 ? calloc((size_t)d.n, sizeof(double)) : NULL;
    if (status == 0 && y == NULL)
        status = hx_fail(&msg, "out of memory");
    if (status == 0 && (hx_dynamics_initial_y(&d, y, &msg) != 0 ||
                        hx_estimate_stability(&d, 0.0, y, st, &msg) != 0))
        status = -1;
    if (status == 0) {
        char text[512];
        hx_stability_text(st, text, sizeof text);
        printf("stability at t = 0 (%d right-hand sides): %s\n", st->evaluations, text);
    } else {
        fprintf(stderr, "usrsub-harness bench: stability: %s\n", msg.text);
    }
    free(y);
    hx_dynamics_free(&d);
    return status == 0 ? 0 : 1;
}

/* Each series' cost at the target error, and what BDF with the elements'
 * partials gains over the best explicit method and over BDF with differences. */
static void work_at_target(const hx_wp_result *r, double target, int largest)
{
    printf("cost for an error of %.0e %s (right-hand sides, run time):", target,
           largest ? "over the whole trajectory" : "at the end");
    double best_explicit = INFINITY, bdf_seconds = 0.0, bdf_evaluations = 0.0, fd_evaluations = 0.0;
    const char *best = NULL;
    for (int k = 0; k < HX_WP_SERIES; ++k) {
        double e, t;
        const char *name = hx_wp_series_name((hx_wp_series)k);
        if (hx_wp_work_at(r, (hx_wp_series)k, target, largest, &e, &t) != 0) {
            int present = 0;
            for (int p = 0; p < r->npoints; ++p)
                present |= r->point[p].series == (hx_wp_series)k;
            if (present)
                printf("%s %s not reached", k ? "," : "", name);
            continue;
        }
        printf("%s %s %.0f, %.3g s", k ? "," : "", name, e, t);
        if (k == HX_WP_BDF)
            bdf_seconds = t, bdf_evaluations = e;
        else if (k == HX_WP_BDF_FD)
            fd_evaluations = e;
        else if (t < best_explicit)
            best_explicit = t, best = name;
    }
    printf("\n");
    if (bdf_seconds > 0.0 && best != NULL)
        printf("bdf with the elements' partials: %.3g times the speed of the best explicit method"
               " (%s)", best_explicit / bdf_seconds, best);
    if (bdf_evaluations > 0.0 && fd_evaluations > 0.0)
        printf("%s%.3g times fewer right-hand sides than bdf-fd", best != NULL ? "; " : "",
               fd_evaluations / bdf_evaluations);
    if (bdf_seconds > 0.0)
        printf("\n");
}

static int work_precision_section(hx_session *s, const bench_options *o, const char *model)
{
    hx_wp_options wo = {o->end, o->quick ? 1 : 3, o->quick, o->atol_ratio, o->noutputs, {0},
                        o->max_order};
    memcpy(wo.outputs, o->outputs, sizeof wo.outputs);
    hx_wp_result *r = calloc(1, sizeof *r);
    hx_message msg;
    if (r == NULL || hx_work_precision(s, &wo, r, &msg) != 0) {
        fprintf(stderr, "usrsub-harness bench: work-precision: %s\n", r ? msg.text : "out of memory");
        free(r);
        return 1;
    }
    hx_wp_print(stdout, r);
    work_at_target(r, o->target > 0.0 ? o->target : 1e-8, 0);
    work_at_target(r, o->target > 0.0 ? o->target : 1e-8, 1);
    int status = 0;
    if (o->out != NULL) {
        char prefix[4096], title[256];
        hx_session_path(s, o->out, prefix, sizeof prefix);
        const char *base = strrchr(model, '/');
        snprintf(title, sizeof title, "%s", base ? base + 1 : model);
        const int written = hx_wp_write(prefix, title, r);
        if (written < 0) {
            fprintf(stderr, "usrsub-harness bench: cannot write %s_work_precision.csv\n", prefix);
            status = 1;
        } else {
            printf("wrote %s_work_precision.csv%s\n", prefix,
                   written == 0 ? " and its plots (_error_time.png, _error_evaluations.png)"
                                : " (gnuplot is not installed: no plots)");
        }
    }
    free(r);
    return status;
}

/* "2,3": body ids of the slow outputs. */
static int parse_outputs(const char *text, bench_options *o)
{
    const char *p = text;
    o->noutputs = 0;
    while (*p != '\0') {
        char *end;
        const long id = strtol(p, &end, 10);
        if (end == p || (*end != ',' && *end != '\0') || o->noutputs == HX_WP_MAX_OUTPUTS ||
            id <= 0 || id > INT_MAX) {
            fprintf(stderr, "usrsub-harness bench: --outputs '%s': expected body ids separated by"
                    " commas (at most %d)\n", text, HX_WP_MAX_OUTPUTS);
            return -1;
        }
        o->outputs[o->noutputs++] = (int)id;
        p = *end == ',' ? end + 1 : end;
    }
    return 0;
}

static int long_run_section(hx_session *s, const bench_options *o, const hx_stability *st)
{
    double step = o->step;
    if (!(step > 0.0))
        step = st->magnitude > 0.0 ? 0.2 / st->magnitude : 1e-3;
    hx_long_run runs[2];
    static const hx_method methods[2] = {HX_METHOD_SYMPLECTIC_EULER, HX_METHOD_RK4};
    int status = 0;
    for (int k = 0; k < 2; ++k) {
        hx_message msg;
        if (hx_long_run_measure(s, methods[k], o->long_steps, step, &runs[k], &msg) != 0) {
            fprintf(stderr, "usrsub-harness bench: long run: %s\n", msg.text);
            status = 1;
        }
    }
    hx_long_run_print(stdout, runs, 2);
    return status;
}

/* The sweep's files, created before the sweep runs: a folder or a file that
 * cannot be written is said at once, not after minutes of work. */
static int prepare_outputs(hx_session *s, const bench_options *o, hx_message *msg)
{
    char prefix[4096], csv[4200];
    hx_session_path(s, o->out, prefix, sizeof prefix);
    snprintf(csv, sizeof csv, "%s_work_precision.csv", prefix);
    FILE *f = hx_open_output(csv, msg);
    if (f == NULL)
        return -1;
    fclose(f);
    return 0;
}

int hx_command_bench(int argc, char **argv)
{
    static const struct option options[] = {{"repeats", required_argument, NULL, 'r'},
                                            {"compare", required_argument, NULL, 'c'},
                                            {"work-precision", no_argument, NULL, 'w'},
                                            {"end", required_argument, NULL, 'e'},
                                            {"out", required_argument, NULL, 'o'},
                                            {"quick", no_argument, NULL, 'q'},
                                            {"long-run", required_argument, NULL, 'l'},
                                            {"step", required_argument, NULL, 's'},
                                            {"outputs", required_argument, NULL, 'O'},
                                            {"atol-ratio", required_argument, NULL, 'A'},
                                            {"target", required_argument, NULL, 'T'},
                                            {"max-order", required_argument, NULL, 'M'},
                                            {"help", no_argument, NULL, 'h'},
                                            {0, 0, 0, 0}};
    bench_options o = {.repeats = 21, .end = 0.1};
    int opt;
    optind = 1;
    while ((opt = getopt_long(argc, argv, "h", options, NULL)) != -1) {
        long count = 0;
        int bad = 0;
        switch (opt) {
        case 'r':
            bad = hx_option_count("bench", "repeats", optarg, 1, &count);
            o.repeats = (int)(count < 100000 ? count : 100000);
            break;
        case 'c':
            if (o.ncompare == MAX_COMPARISONS) {
                fprintf(stderr, "usrsub-harness bench: at most %d --compare\n", MAX_COMPARISONS);
                return 2;
            }
            snprintf(o.compare[o.ncompare++].text, sizeof o.compare[0].text, "%s", optarg);
            break;
        case 'w': o.work_precision = 1; break;
        case 'e': bad = hx_option_positive("bench", "end", optarg, &o.end); break;
        case 'o': o.out = optarg; break;
        case 'q': o.quick = 1; break;
        case 'l': bad = hx_option_count("bench", "long-run", optarg, 1, &o.long_steps); break;
        case 's': bad = hx_option_positive("bench", "step", optarg, &o.step); break;
        case 'O': bad = parse_outputs(optarg, &o); break;
        case 'A': bad = hx_option_positive("bench", "atol-ratio", optarg, &o.atol_ratio); break;
        case 'T': bad = hx_option_positive("bench", "target", optarg, &o.target); break;
        case 'M': bad = hx_option_max_order("bench", optarg, &o.max_order); break;
        case 'h': usage(stdout); return 0;
        default: usage(stderr); return 2;
        }
        if (bad)
            return 2;
    }
    if (optind != argc - 1) {
        fprintf(stderr, "usrsub-harness bench: expected one MODEL.xml (got %d)\n\n", argc - optind);
        usage(stderr);
        return 2;
    }
    if (o.quick && o.repeats == 21)
        o.repeats = 5;
    hx_session s;
    hx_message msg;
    if (hx_session_open(&s, argv[optind], stderr, &msg) != 0) {
        fprintf(stderr, "usrsub-harness bench: %s\n", msg.text);
        return 1;
    }
    if (o.work_precision && o.out != NULL && prepare_outputs(&s, &o, &msg) != 0) {
        fprintf(stderr, "usrsub-harness bench: %s\n", msg.text);
        hx_session_close(&s);
        return 1;
    }
    for (int k = 0; k < o.ncompare; ++k)
        if (parse_comparison(s.model, &o.compare[k], &msg) != 0) {
            fprintf(stderr, "usrsub-harness bench: %s\n", msg.text);
            hx_session_close(&s);
            return 2;
        }
    hx_stability st;
    memset(&st, 0, sizeof st);
    hx_crash_report_begin();
    int status = costs_section(&s, &o);
    status |= stability_section(&s, &st);
    if (o.work_precision)
        status |= work_precision_section(&s, &o, argv[optind]);
    if (o.long_steps > 0)
        status |= long_run_section(&s, &o, &st);
    hx_crash_report_end();
    const int stopped = hx_messages_stopped(&s.messages);
    hx_session_close(&s);
    return stopped ? 3 : status;
}
