/* IMPACT and BISTOP (impact.h). */
#include "base/impact.h"

#include <math.h>
#include <stddef.h>

#include "base/transition.h"

/* The damping coefficient at penetration p: cmax s(p/d) inside the ramp,
 * cmax beyond; its derivatives in p (first, second) and in d. */
static void damping(double p, double cmax, double d, double c[4])
{
    double s[3] = {1.0, 0.0, 0.0};
    if (p < d)
        hx_transition_shape_at(HX_TRANSITION_STEP, p / d, s);
    c[0] = cmax * s[0], c[1] = cmax * s[1] / d, c[2] = cmax * s[2] / (d * d);
    c[3] = -cmax * s[1] * p / (d * d);
}

void hx_impact_side(double p, double dp_dx, double xdot, double k, double e, double cmax,
                    double d, double f[6])
{
    for (int i = 0; i < 6; ++i)
        f[i] = 0.0;
    if (!(p > 0.0))
        return;
    double c[4];
    damping(p, cmax, d, c);
    const double dc_dx = c[1] * dp_dx;
    /* the damping opposes the penetration's rate, dp/dt = dp_dx xdot */
    const double rate = dp_dx * xdot;
    const double size = k * pow(p, e) + c[0] * rate;
    if (!(size > 0.0))
        return;
    f[0] = size;
    f[1] = k * e * pow(p, e - 1.0) * dp_dx + dc_dx * rate;
    f[2] = c[0] * dp_dx;
    f[3] = k * e * (e - 1.0) * pow(p, e - 2.0) + c[2] * rate;
    f[4] = dc_dx * dp_dx;
    f[5] = 0.0;
}

/* The side's size with its partials in p, xdot, k, e, cmax and d (g[0..5]),
 * all zero where the side does not push. */
static double side_partials(double p, double dp_dx, double xdot, double k, double e,
                            double cmax, double d, double g[6])
{
    for (int i = 0; i < 6; ++i)
        g[i] = 0.0;
    double f[6];
    hx_impact_side(p, dp_dx, xdot, k, e, cmax, d, f);
    if (!(f[0] > 0.0))
        return 0.0;
    double c[4], s[3] = {1.0, 0.0, 0.0};
    damping(p, cmax, d, c);
    if (p < d)
        hx_transition_shape_at(HX_TRANSITION_STEP, p / d, s);
    const double rate = dp_dx * xdot, power = pow(p, e);
    g[0] = f[1] * dp_dx; /* the slope in x times dx/dp (dp_dx is +-1) */
    g[1] = f[2];
    g[2] = power;
    g[3] = k * power * log(p);
    g[4] = s[0] * rate;
    g[5] = c[3] * rate;
    return f[0];
}

double hx_impact(double x, double xdot, double x1, double k, double e, double cmax, double d,
                 double partials[7])
{
    double g[6];
    const double size = side_partials(x1 - x, -1.0, xdot, k, e, cmax, d, g);
    if (partials != NULL) {
        partials[0] = -g[0], partials[1] = g[1], partials[2] = g[0];
        partials[3] = g[2], partials[4] = g[3], partials[5] = g[4], partials[6] = g[5];
    }
    return size;
}

double hx_bistop(double x, double xdot, double x1, double x2, double k, double e, double cmax,
                 double d, double partials[8])
{
    double g[6];
    if (x < x1) {
        const double size = side_partials(x1 - x, -1.0, xdot, k, e, cmax, d, g);
        if (partials != NULL) {
            partials[0] = -g[0], partials[1] = g[1], partials[2] = g[0], partials[3] = 0.0;
            partials[4] = g[2], partials[5] = g[3], partials[6] = g[4], partials[7] = g[5];
        }
        return size;
    }
    /* above: the force pushes back, negative */
    const double size = side_partials(x - x2, 1.0, xdot, k, e, cmax, d, g);
    if (partials != NULL) {
        partials[0] = -g[0], partials[1] = -g[1], partials[2] = 0.0, partials[3] = g[0];
        partials[4] = -g[2], partials[5] = -g[3], partials[6] = -g[4], partials[7] = -g[5];
    }
    return -size;
}
