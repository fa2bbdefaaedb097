/*
 * IMPACT and BISTOP (docs/interface.md §5.2, §8.4): a stop's force, a power
 * law in the penetration plus damping that rises as a cubic STEP over the
 * first d of penetration, only ever pushing. The one implementation behind
 * the host's c_impact and c_bistop and the function expressions.
 */
#ifndef HX_BASE_IMPACT_H
#define HX_BASE_IMPACT_H

/* One side of a stop, the penetration p growing as x moves by dp_dx = -1 (a
 * lower stop) or +1 (an upper one): f[0] the force's size, f[1..2] its slopes
 * in x and xdot, f[3..5] its second derivatives (x x, x xdot, xdot xdot);
 * all zero where p <= 0 or the size would be negative (a stop only pushes).
 * The parameters are the caller's to check (k >= 0, e > 0, cmax >= 0,
 * d > 0). */
void hx_impact_side(double p, double dp_dx, double xdot, double k, double e, double cmax,
                    double d, double f[6]);

/* IMPACT(x, xdot, x1, k, e, cmax, d): max(0, k (x1 - x)^e - STEP(x, x1 - d,
 * cmax, x1, 0) xdot) for x < x1, else 0; with partials != NULL its partials
 * in the seven arguments (zero where the force is). */
double hx_impact(double x, double xdot, double x1, double k, double e, double cmax, double d,
                 double partials[7]);

/* BISTOP(x, xdot, x1, x2, k, e, cmax, d): IMPACT's force below x1, 0 between,
 * min(0, -k (x - x2)^e - STEP(x, x2, 0, x2 + d, cmax) xdot) above x2; with
 * partials != NULL its partials in the eight arguments. */
double hx_bistop(double x, double xdot, double x1, double x2, double k, double e, double cmax,
                 double d, double partials[8]);

#endif
