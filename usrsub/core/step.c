/* STEP and STEP5 with derivatives (docs/interface.md §3.6). */
#include "usrsub/core/step.h"

static usrsub_jet constant(double h)
{
    usrsub_jet j = {h, 0.0, 0.0};
    return j;
}

usrsub_jet usrsub_step(double x, double x0, double h0, double x1, double h1)
{
    if (x <= x0)
        return constant(h0);
    if (x >= x1)
        return constant(h1);
    const double span = x1 - x0;
    const double a = (x - x0) / span;
    const double dh = h1 - h0;
    usrsub_jet j;
    j.value = h0 + dh * a * a * (3.0 - 2.0 * a);
    j.d1 = dh * 6.0 * a * (1.0 - a) / span;
    j.d2 = dh * 6.0 * (1.0 - 2.0 * a) / (span * span);
    return j;
}

usrsub_jet usrsub_step5(double x, double x0, double h0, double x1, double h1)
{
    if (x <= x0)
        return constant(h0);
    if (x >= x1)
        return constant(h1);
    const double span = x1 - x0;
    const double a = (x - x0) / span;
    const double dh = h1 - h0;
    const double a2 = a * a;
    usrsub_jet j;
    j.value = h0 + dh * a2 * a * (10.0 - 15.0 * a + 6.0 * a2);
    /* d/da = 30 a^2 (1-a)^2,  d2/da2 = 60 a (1-a)(1-2a) */
    j.d1 = dh * 30.0 * a2 * (1.0 - a) * (1.0 - a) / span;
    j.d2 = dh * 60.0 * a * (1.0 - a) * (1.0 - 2.0 * a) / (span * span);
    return j;
}
