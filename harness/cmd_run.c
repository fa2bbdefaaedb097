/* usrsub-harness run: integrate a model's dynamics. */
#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "commands.h"
#include "simulation.h"
#include "stability.h"

static void usage(FILE *f)
{
    fprintf(f,
            "usage: usrsub-harness run MODEL.xml --end T [options]\n"
            "\n"
            "  --integrator NAME   euler | symplectic-euler | rk4 (default) | dopri5\n"
            "  --step H            fixed step (first step for dopri5; default: automatic)\n"
            "  --end T             end time\n"
            "  --out FILE.csv      joint coordinates, velocities, multipliers, element\n"
            "                      deformations and loads, energy and residuals\n"
            "  --output-interval DT  time between CSV rows (default: end/1000)\n"
            "  --rtol R, --atol A  dopri5 tolerances (default 1e-6, 1e-9)\n"
            "  --max-step H        dopri5's largest step\n"
            "  --quiet             no progress line\n");
}

static int stability_at_start(hx_dynamics *d, hx_stability *st)
{
    usrsub_message msg;
    double *y = calloc((size_t)d->n, sizeof(double));
    const int status = y != NULL && hx_dynamics_initial_state(d, y) == 0 &&
                               hx_estimate_stability(d, 0.0, y, st, &msg) == 0
                           ? 0
                           : -1;
    free(y);
    return status;
}

int hx_command_run(int argc, char **argv)
{
    static const struct option options[] = {
        {"integrator", required_argument, NULL, 'i'}, {"step", required_argument, NULL, 's'},
        {"end", required_argument, NULL, 'e'},        {"out", required_argument, NULL, 'o'},
        {"output-interval", required_argument, NULL, 'I'},
        {"rtol", required_argument, NULL, 'r'},       {"atol", required_argument, NULL, 'a'},
        {"max-step", required_argument, NULL, 'm'},   {"quiet", no_argument, NULL, 'q'},
        {"help", no_argument, NULL, 'h'},             {0, 0, 0, 0}};
    hx_simulation_options so = {0};
    hx_integrator_defaults(&so.integration);
    so.integration.t_end = -1.0;
    so.progress = 1;
    const char *out = NULL;
    int opt;
    optind = 1;
    while ((opt = getopt_long(argc, argv, "h", options, NULL)) != -1) {
        switch (opt) {
        case 'i':
            if (hx_method_parse(optarg, &so.integration.method) != 0) {
                fprintf(stderr, "run: unknown integrator '%s'\n", optarg);
                return 2;
            }
            break;
        case 's': so.integration.step = atof(optarg); break;
        case 'e': so.integration.t_end = atof(optarg); break;
        case 'o': out = optarg; break;
        case 'I': so.integration.output_interval = atof(optarg); break;
        case 'r': so.integration.rtol = atof(optarg); break;
        case 'a': so.integration.atol = atof(optarg); break;
        case 'm': so.integration.max_step = atof(optarg); break;
        case 'q': so.progress = 0; break;
        case 'h': usage(stdout); return 0;
        default: usage(stderr); return 2;
        }
    }
    if (optind != argc - 1 || !(so.integration.t_end > 0.0)) {
        usage(stderr);
        return 2;
    }
    if (so.integration.method != HX_METHOD_DOPRI5 && !(so.integration.step > 0.0)) {
        fprintf(stderr, "run: --step is needed for %s\n", hx_method_name(so.integration.method));
        return 2;
    }
    if (so.integration.output_interval <= 0.0)
        so.integration.output_interval = so.integration.t_end / 1000.0;
    hx_session s;
    usrsub_message msg;
    if (hx_session_open(&s, argv[optind], &msg) != 0) {
        fprintf(stderr, "usrsub-harness run: %s\n", msg.text);
        return 1;
    }
    hx_dynamics d;
    if (hx_dynamics_init(&d, &s, &msg) != 0) {
        fprintf(stderr, "usrsub-harness run: %s\n", msg.text);
        hx_session_close(&s);
        return 1;
    }
    char path[4096];
    if (out != NULL && (so.csv = fopen(hx_session_path(&s, out, path, sizeof path), "w")) == NULL) {
        fprintf(stderr, "usrsub-harness run: cannot write %s\n", path);
        hx_dynamics_free(&d);
        hx_session_close(&s);
        return 1;
    }
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
    if (so.csv != NULL)
        fclose(so.csv);
    hx_dynamics_free(&d);
    hx_session_close(&s);
    return status == 0 ? 0 : 1;
}
