/* Long runs (long_run.h). */
#include "tools/bench/long_run.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sim/simulation/simulation.h"

#define SAMPLES 1000

typedef struct energy_trace {
    double e0;
    double t[SAMPLES + 1], e[SAMPLES + 1];
    double kinetic_max;
    int count;
} energy_trace;

static int observe(void *ctx, const hx_dynamics *d, hx_dynamics_data *dd, double t,
                   const double *y)
{
    energy_trace *tr = ctx;
    if (tr->count > SAMPLES)
        return 0;
    const hx_energy e = hx_energy_of(d, dd, t, y);
    if (tr->count == 0)
        tr->e0 = e.total;
    tr->kinetic_max = fmax(tr->kinetic_max, fabs(e.kinetic));
    tr->t[tr->count] = t;
    tr->e[tr->count++] = e.total;
    return 0;
}

int hx_long_run_measure(hx_session *s, hx_method method, long steps, double step,
                        hx_long_run *out, hx_message *msg)
{
    memset(out, 0, sizeof *out);
    out->method = method, out->steps = steps, out->step = step;
    hx_dynamics d;
    if (hx_dynamics_init(&d, s, msg) != 0)
        return -1;
    energy_trace *tr = calloc(1, sizeof *tr);
    if (tr == NULL) {
        hx_dynamics_free(&d);
        return hx_fail(msg, "out of memory");
    }
    hx_simulation_options so = {0};
    hx_integrator_defaults(&so.integration);
    so.integration.method = method;
    so.integration.step = step;
    so.integration.t_end = step * (double)steps;
    so.integration.output_interval = so.integration.t_end / SAMPLES;
    so.observer = observe;
    so.observer_ctx = tr;
    so.skip_energy = 1;
    hx_simulation_result result;
    hx_simulate(&d, &so, NULL, &result);
    out->status = result.status;
    out->seconds = result.seconds;
    out->max_phi = result.max_phi, out->max_phidot = result.max_phidot;
    out->scale = fmax(fabs(tr->e0), tr->kinetic_max);
    const double scale = out->scale > 0.0 ? out->scale : 1.0;
    /* the first and last tenth; the drift by least squares over all samples */
    double st = 0, se = 0, stt = 0, ste = 0;
    const int n = tr->count;
    for (int k = 0; k < n; ++k) {
        const double err = (tr->e[k] - tr->e0) / scale;
        if (k <= n / 10)
            out->error_first = fmax(out->error_first, fabs(err));
        if (k >= n - 1 - n / 10)
            out->error_last = fmax(out->error_last, fabs(err));
        st += tr->t[k], se += err, stt += tr->t[k] * tr->t[k], ste += tr->t[k] * err;
    }
    const double den = n * stt - st * st;
    out->drift = n > 1 && den > 0.0 ? (n * ste - st * se) / den : 0.0;
    free(tr);
    hx_dynamics_free(&d);
    if (result.status != HX_INTEGRATION_OK)
        return hx_fail(msg, "%s: %s", hx_method_name(method),
                           result.message[0] ? result.message : hx_status_text(result.status));
    return 0;
}

void hx_long_run_print(FILE *f, const hx_long_run *runs, int count)
{
    fprintf(f, "long runs (energy error relative to max(|E0|, largest kinetic energy)):\n");
    fprintf(f, "  %-17s %10s %10s %12s %12s %14s %10s %10s %10s\n", "method", "steps", "step",
            "first tenth", "last tenth", "drift per s", "|phi|", "|dphi/dt|", "run time s");
    for (int k = 0; k < count; ++k) {
        const hx_long_run *r = &runs[k];
        fprintf(f, "  %-17s %10ld %10.3g %12.3g %12.3g %14.3g %10.2g %10.2g %10.3g%s\n",
                hx_method_name(r->method), r->steps, r->step, r->error_first, r->error_last,
                r->drift, r->max_phi, r->max_phidot, r->seconds,
                r->status == HX_INTEGRATION_OK ? "" : "  (did not finish)");
    }
}
