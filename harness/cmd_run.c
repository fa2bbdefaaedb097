/* usrsub-harness run: integrate a model's dynamics. */
#include <getopt.h>
#include <stdio.h>
#include <stdlib.h>

#include "commands.h"
#include "simulation.h"

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
    hx_simulation_result result;
    const int status = hx_simulate(&d, &so, NULL, &result);
    hx_simulation_summary(stdout, &d, &so, &result);
    if (so.csv != NULL)
        fclose(so.csv);
    hx_dynamics_free(&d);
    hx_session_close(&s);
    return status == 0 ? 0 : 1;
}
