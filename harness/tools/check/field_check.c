/*
 * A FIESUB element's partials (checks.h): dfddis and dfdvel against central
 * differences of the field, column by column, at the element's state and at
 * the sampled states around it, naming the worst entry by its output (row)
 * and input (column) and the sample it was found at.
 */
#include <math.h>
#include <stdio.h>

#include "host/invoke.h"
#include "base/finite.h"
#include "tools/check/checks.h"
#include "tools/check/derivative_check.h"
#include "tools/check/element_samples.h"

typedef struct field_sampler {
    hx_binding *b;
    hx_frames *frames;
} field_sampler;

static int sample_field(void *ctx, const double *x, double *out)
{
    field_sampler *fs = ctx;
    double dfd[36], dfv[36];
    hx_invoke_field(fs->b, fs->frames, x, x + 6, 1, 0, out, dfd, dfv, NULL);
    if (hx_messages_stopped(fs->b->messages))
        return -1;
    return hx_all_finite(out, 6) ? 0 : -1;
}

int hx_check_field_partials(hx_session *s, hx_binding *b, FILE *out)
{
    static const char *const inputs[12] = {"x", "y", "z", "ax", "ay", "az",
                                           "vx", "vy", "vz", "wx", "wy", "wz"};
    static const char *const outputs[6] = {"Fx", "Fy", "Fz", "Tx", "Ty", "Tz"};
    hx_worst worst = {0};
    hx_frames sample;
    if (hx_frames_clone(&sample, &s->frames) != 0)
        return 1;
    field_sampler fs = {b, &sample};
    int failures = 0;
    for (int k = 0; k < HX_FORCE_SAMPLES && failures == 0; ++k) {
        double x[12], scale[12], F[6], J[72];
        hx_sample_force_deformation(s, b->index, k, x, x + 6, scale);
        sample.time = hx_sample_time(s->model, k);
        hx_invoke_field(b, &sample, x, x + 6, 1, 0, F, J, J + 36, NULL); /* dflag: partials wanted */
        if (hx_messages_stopped(b->messages) || !hx_all_finite(J, 72)) {
            fprintf(out, "  %s %d: %s returned non-finite partials at sample %d\n", b->element,
                    b->id, b->names[0], k);
            ++failures;
            break;
        }
        for (int i = 0; i < 12; ++i) {
            double column[6], floor[6];
            for (int j = 0; j < 6; ++j) {
                column[j] = J[(i < 6 ? 0 : 36) + j + 6 * (i % 6)];
                double typical = 0.0; /* the largest change of F_j over typical steps */
                for (int c = 0; c < 12; ++c)
                    typical = fmax(typical, fabs(J[(c < 6 ? 0 : 36) + j + 6 * (c % 6)]) * scale[c]);
                floor[j] = fmax(1e-6 * typical / scale[i], 1e-300);
            }
            const double h = 1e-6 * fmax(fabs(x[i]), scale[i]);
            int row;
            const double e = hx_check_column(sample_field, &fs, x, i, 6, column, floor, h, &row);
            hx_worst_update(&worst, e, "%s[%d + 6*%d] = d%s/d%s at sample %d (t = %g)",
                            i < 6 ? "dfddis" : "dfdvel", row, i % 6, outputs[row], inputs[i], k,
                            sample.time);
        }
    }
    hx_frames_free(&sample);
    fprintf(out, "  %s %d: dfddis and dfdvel against central differences of the field: worst"
            " relative error %.2g at %s, %d columns at %d states: %s\n", b->element, b->id,
            worst.error, worst.where, worst.compared, HX_FORCE_SAMPLES,
            worst.failed || failures ? "FAIL" : "pass");
    return worst.failed || failures ? 1 : 0;
}
