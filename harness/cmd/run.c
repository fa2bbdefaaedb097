/* usrsub-harness run: integrate a model's dynamics. */
#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "cmd/commands.h"
#include "cmd/crash_report.h"
#include "cmd/options.h"
#include "sim/simulation.h"
#include "tools/bench/stability.h"

static void usage(FILE *f)
{
    fprintf(f,
            "usage: usrsub-harness run MODEL.xml --end T [options]\n"
            "\n"
            "  --end T             end time\n"
            "  --integrator NAME   dopri5 (default: adaptive, error-controlled) | rk4 |\n"
            "                      euler | symplectic-euler (fixed steps: give --step)\n"
            "  --step H            fixed step (dopri5: its first step; default automatic)\n"
            "  --out FILE.csv      joint coordinates, velocities, multipliers, element\n"
            "                      deformations and loads, energy and residuals\n"
            "  --output-interval DT  time between CSV rows (default: end/1000)\n"
            "  --rtol R, --atol A  dopri5 tolerances (default 1e-6, 1e-9)\n"
            "  --max-step H        dopri5's largest step\n"
            "  --quiet             no progress line\n");
}

static int stability_at_start(hx_dynamics *d, hx_stability *st)
{
    hx_message msg;
    double *y = calloc((size_t)d->n, sizeof(double));
    const int status = y != NULL && hx_dynamics_initial_state(d, y) == 0 &&
                               hx_estimate_stability(d, 0.0, y, st, &msg) == 0
                           ? 0
                           : -1;
    free(y);
    return status;
}

/* Reads the options into so; returns -1 (exit 2) on a bad one, 1 on --help. */
static int parse(int argc, char **argv, hx_simulation_options *so, const char **out,
                 int *fixed_step_given)
{
    static const struct option options[] = {
        {"integrator", required_argument, NULL, 'i'}, {"step", required_argument, NULL, 's'},
        {"end", required_argument, NULL, 'e'},        {"out", required_argument, NULL, 'o'},
        {"output-interval", required_argument, NULL, 'I'},
        {"rtol", required_argument, NULL, 'r'},       {"atol", required_argument, NULL, 'a'},
        {"max-step", required_argument, NULL, 'm'},   {"quiet", no_argument, NULL, 'q'},
        {"help", no_argument, NULL, 'h'},             {0, 0, 0, 0}};
    hx_integrator_options *io = &so->integration;
    int opt;
    optind = 1;
    while ((opt = getopt_long(argc, argv, "h", options, NULL)) != -1) {
        int bad = 0;
        switch (opt) {
        case 'i':
            if (hx_method_parse(optarg, &io->method) != 0) {
                fprintf(stderr, "usrsub-harness run: --integrator '%s' is not one of dopri5, rk4,"
                        " euler, symplectic-euler\n", optarg);
                bad = 1;
            }
            break;
        case 's': bad = hx_option_positive("run", "step", optarg, &io->step); *fixed_step_given = 1; break;
        case 'e': bad = hx_option_positive("run", "end", optarg, &io->t_end); break;
        case 'o': *out = optarg; break;
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
    if (!(io->t_end > 0.0)) {
        fprintf(stderr, "usrsub-harness run: --end T is needed\n");
        return -1;
    }
    if (io->method != HX_METHOD_DOPRI5 && !*fixed_step_given) {
        fprintf(stderr, "usrsub-harness run: %s takes fixed steps: give --step (or use the"
                " default dopri5, which chooses its own)\n", hx_method_name(io->method));
        return -1;
    }
    return 0;
}

int hx_command_run(int argc, char **argv)
{
    hx_simulation_options so = {0};
    hx_integrator_defaults(&so.integration);
    so.integration.method = HX_METHOD_DOPRI5;
    so.progress = 1;
    const char *out = NULL;
    int fixed_step_given = 0;
    const int parsed = parse(argc, argv, &so, &out, &fixed_step_given);
    if (parsed != 0)
        return parsed > 0 ? 0 : 2;
    if (so.integration.output_interval <= 0.0)
        so.integration.output_interval = so.integration.t_end / 1000.0;
    hx_session s;
    hx_message msg;
    if (hx_session_open(&s, argv[optind], stderr, &msg) != 0) {
        fprintf(stderr, "usrsub-harness run: %s\n", msg.text);
        return 1;
    }
    hx_dynamics d;
    char path[4096];
    if (hx_dynamics_init(&d, &s, &msg) != 0 ||
        (out != NULL && (so.csv = hx_open_output(hx_session_path(&s, out, path, sizeof path), &msg)) == NULL)) {
        fprintf(stderr, "usrsub-harness run: %s\n", msg.text);
        hx_dynamics_free(&d);
        hx_session_close(&s);
        return 1;
    }
    hx_crash_report_begin();
    /* a fixed step beyond the stability limit of the fastest mode: say so before */
    hx_stability st;
    const int fixed = so.integration.method != HX_METHOD_DOPRI5;
    const int limited = fixed && stability_at_start(&d, &st) == 0;
    const double limit = limited ? st.max_step[so.integration.method] : INFINITY;
    if (limited && so.integration.step > limit)
        fprintf(stderr, "run: warning: the step %g is above %s's stability limit %.3g for the"
                " model's fastest mode (lambda = %.4g + %.4gi at t = 0): expect the run to"
                " diverge\n", so.integration.step, hx_method_name(so.integration.method), limit,
                st.re, st.im);
    hx_simulation_result result;
    const int status = hx_simulate(&d, &so, NULL, &result);
    hx_simulation_summary(stdout, &d, &so, &result);
    if (result.status == HX_INTEGRATION_UNSTABLE && limited)
        printf("  the step %g %s the stability limit %.3g of %s at t = 0 (|lambda| = %.4g)\n",
               so.integration.step, so.integration.step > limit ? "exceeds" : "is within",
               limit, hx_method_name(so.integration.method), st.magnitude);
    hx_crash_report_end();
    if (so.csv != NULL)
        fclose(so.csv);
    hx_dynamics_free(&d);
    hx_session_close(&s);
    return status == 0 ? 0 : 1;
}
