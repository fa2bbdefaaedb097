/* Stiffness characteristics g(q) of a bushing direction (bushing.h). */
#include <stddef.h>

#include "usrsub/core/bushing.h"

/* c2, c3 with OF + OS u + c2 u^2 + c3 u^3 = f at u = a, slope s at u = b. */
static void fit_side(double of, double os, double a, double f, double b, double s,
                     double *c2, double *c3)
{
    const double r1 = f - of - os * a, r2 = s - os;
    const double det = a * a * b * (3.0 * b - 2.0 * a);
    *c2 = (3.0 * b * b * r1 - a * a * a * r2) / det;
    *c3 = (a * a * r2 - 2.0 * b * r1) / det;
}

int usrsub_cubic_fit(usrsub_cubic_characteristic *c, usrsub_message *msg)
{
    if (!(c->en < c->rn && c->rn < c->o && c->o < c->rp && c->rp < c->ep))
        return usrsub_fail(msg, "the cubic characteristic's points must satisfy EN < RN < O < RP"
                           " < EP (got EN %g, RN %g, O %g, RP %g, EP %g)", c->en, c->rn, c->o,
                           c->rp, c->ep);
    fit_side(c->of, c->os, c->rp - c->o, c->rpf, c->ep - c->o, c->eps, &c->c2p, &c->c3p);
    fit_side(c->of, c->os, c->rn - c->o, c->rnf, c->en - c->o, c->ens, &c->c2n, &c->c3n);
    const double up = c->ep - c->o, un = c->en - c->o;
    c->at_ep = c->of + up * (c->os + up * (c->c2p + up * c->c3p));
    c->at_en = c->of + un * (c->os + un * (c->c2n + un * c->c3n));
    return 0;
}

static double cubic(const usrsub_cubic_characteristic *c, double q, double *slope)
{
    if (q > c->ep) {
        *slope = c->eps;
        return c->at_ep + c->eps * (q - c->ep);
    }
    if (q < c->en) {
        *slope = c->ens;
        return c->at_en + c->ens * (q - c->en);
    }
    const double u = q - c->o;
    const double c2 = u >= 0.0 ? c->c2p : c->c2n, c3 = u >= 0.0 ? c->c3p : c->c3n;
    *slope = c->os + u * (2.0 * c2 + 3.0 * c3 * u);
    return c->of + u * (c->os + u * (c2 + u * c3));
}

double usrsub_characteristic(const usrsub_bushing_direction *d, double q, double *slope)
{
    double unused;
    switch (d->stiffness) {
    case USRSUB_STIFFNESS_CONSTANT:
        if (slope != NULL)
            *slope = d->k;
        return d->k * q;
    case USRSUB_STIFFNESS_SPLINE:
        return slope != NULL ? usrsub_spline_value_slope(&d->spline, q, slope)
                             : usrsub_spline_value(&d->spline, q);
    case USRSUB_STIFFNESS_CUBIC:
        return cubic(&d->cubic, q, slope != NULL ? slope : &unused);
    default:
        if (slope != NULL)
            *slope = 0.0;
        return 0.0;
    }
}
