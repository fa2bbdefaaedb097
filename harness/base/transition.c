/* STEP, STEP5 and HAVSIN (transition.h). */
#include "base/transition.h"

#include <math.h>

void hx_transition_shape_at(hx_transition_shape shape, double u, double s[3])
{
    switch (shape) {
    case HX_TRANSITION_STEP:
        s[0] = u * u * (3.0 - 2.0 * u), s[1] = 6.0 * u * (1.0 - u), s[2] = 6.0 - 12.0 * u;
        return;
    case HX_TRANSITION_STEP5:
        s[0] = u * u * u * (10.0 + u * (-15.0 + 6.0 * u));
        s[1] = 30.0 * u * u * (1.0 - u) * (1.0 - u);
        s[2] = 60.0 * u * (1.0 - u) * (1.0 - 2.0 * u);
        return;
    default:
        s[0] = 0.5 * (1.0 - cos(M_PI * u)), s[1] = 0.5 * M_PI * sin(M_PI * u);
        s[2] = 0.5 * M_PI * M_PI * cos(M_PI * u);
        return;
    }
}

/* The shape at x: zero before x0 (and at it), one from x1 on. */
static void shape_at_x(hx_transition_shape shape, double x, double x0, double x1, double s[3])
{
    s[0] = s[1] = s[2] = 0.0;
    if (x <= x0)
        return;
    if (x >= x1)
        s[0] = 1.0;
    else
        hx_transition_shape_at(shape, (x - x0) / (x1 - x0), s);
}

double hx_transition(hx_transition_shape shape, double x, double x0, double h0, double x1,
                     double h1, int iord)
{
    double s[3];
    shape_at_x(shape, x, x0, x1, s);
    if (iord == 0)
        return h0 + (h1 - h0) * s[0];
    const double length = x1 - x0;
    if (!(length > 0.0))
        return 0.0; /* a jump: flat on either side */
    return (h1 - h0) * s[iord] / (iord == 1 ? length : length * length);
}

void hx_transition_partials(hx_transition_shape shape, double x, double x0, double h0, double x1,
                            double h1, double d[5])
{
    double s[3];
    shape_at_x(shape, x, x0, x1, s);
    d[2] = 1.0 - s[0], d[4] = s[0];
    d[0] = d[1] = d[3] = 0.0;
    if (x <= x0 || x >= x1)
        return;
    /* u = (x - x0) / L: du/dx = 1/L, du/dx0 = (u - 1)/L, du/dx1 = -u/L */
    const double length = x1 - x0, u = (x - x0) / length, slope = (h1 - h0) * s[1] / length;
    d[0] = slope;
    d[1] = slope * (u - 1.0);
    d[3] = -slope * u;
}
