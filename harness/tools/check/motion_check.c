/*
 * A MOTSUB's derivatives (checks.h): at the check's sample times over the
 * model's first second, its rate (iord 1) must be the time derivative of its
 * value (iord 0), and its acceleration (iord 2) that of its rate, as central
 * differences over 1e-4 and 2e-4 s, extrapolated (Richardson), see them:
 * good to 1e-5 of the magnitude for motions up to about 1000 rad/s. A solver
 * integrates with iord 1 and 2 and projects onto iord 0: a wrong one drives
 * the joint off its own motion.
 */
#include <math.h>
#include <stdio.h>

#include "host/invoke.h"
#include "tools/check/checks.h"
#include "tools/check/element_samples.h"

/* Order `iord` of the motion at time t; -1 when the routine stopped the run. */
static int motion_at(hx_binding *b, hx_frames *fr, double t, int iord, double *value)
{
    fr->time = t;
    hx_invoke_routine(b, fr, iord, 0, value, NULL);
    return hx_messages_stopped(b->messages) ? -1 : 0;
}

int hx_check_motion(hx_session *s, hx_binding *b, FILE *out)
{
    const hx_model *m = s->model;
    const double h = 1e-4 * hx_model_second(m);
    double worst[2] = {0, 0}, worst_time[2] = {0, 0}, size[2] = {0, 0}, at_worst[2][2] = {{0}};
    const double saved = s->frames.time;
    int failed = 0;
    for (int k = 1; k < HX_FORCE_SAMPLES && !failed; ++k) {
        const double t = hx_sample_time(m, k);
        for (int iord = 1; iord <= 2 && !failed; ++iord) {
            double exact, v[4]; /* at t - 2h, t - h, t + h, t + 2h */
            static const double at[4] = {-2.0, -1.0, 1.0, 2.0};
            failed = motion_at(b, &s->frames, t, iord, &exact) != 0;
            for (int i = 0; i < 4 && !failed; ++i)
                failed = motion_at(b, &s->frames, t + at[i] * h, iord - 1, &v[i]) != 0;
            if (failed)
                break;
            const double near = (v[2] - v[1]) / (2.0 * h), far = (v[3] - v[0]) / (4.0 * h);
            const double difference = (4.0 * near - far) / 3.0;
            const double error = fabs(exact - difference);
            size[iord - 1] = fmax(size[iord - 1], fmax(fabs(exact), fabs(difference)));
            if (!isnan(worst[iord - 1]) && !(error <= worst[iord - 1])) { /* a NaN stays */
                worst[iord - 1] = error;
                worst_time[iord - 1] = t;
                at_worst[iord - 1][0] = exact;
                at_worst[iord - 1][1] = difference;
            }
        }
    }
    s->frames.time = saved;
    if (failed)
        return 1;
    int failures = 0;
    static const char *const names[2] = {"rate (iord 1)", "acceleration (iord 2)"};
    static const char *const of[2] = {"value (iord 0)", "rate (iord 1)"};
    for (int i = 0; i < 2; ++i) {
        /* the extrapolated differences are good to about h^4 of the fifth
         * derivative: 1e-5 of the largest magnitude leaves room for that */
        const double tolerance = 1e-5 * size[i] + 1e-12;
        const int pass = worst[i] <= tolerance; /* NaN fails */
        failures += !pass;
        fprintf(out, "  %s %d: %s %s against differences in time of its %s at %d times:"
                " worst |error| %.3g at t = %g (%.9g, differences %.9g; tolerance %.3g): %s\n",
                b->element, b->id, hx_binding_routine(b, 0), names[i], of[i],
                HX_FORCE_SAMPLES - 1, worst[i], worst_time[i], at_worst[i][0], at_worst[i][1],
                tolerance, pass ? "pass" : "FAIL");
    }
    return failures;
}
