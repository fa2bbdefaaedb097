/*
 * The one rule for the step of a central difference. Central differences of
 * a smooth f with step h err by about h^2 |f'''| / 6 (truncation) and by
 * DBL_EPSILON |f| / h (rounding); a step near cbrt(DBL_EPSILON) = 6e-6 of the
 * variable's size balances the two at about 1e-11 relative. The step is
 * relative (eps |x|) above `scale` and absolute (eps scale) below, where x is
 * counted zero: scale is the variable's size in its units (1 for a state of
 * order one, a unit's size otherwise). eps is the caller's, said where it is
 * chosen: 1e-5 for the Jacobian's partials (sim/jacobian/), 1e-6 for the
 * checks and rigs that compare analytic partials with differences.
 * CVODE's own forward differences (sim/ode/bdf.c) keep CVODE's rule.
 */
#ifndef HX_BASE_DIFFERENCE_STEP_H
#define HX_BASE_DIFFERENCE_STEP_H

#include <math.h>

static inline double hx_difference_step(double x, double eps, double scale)
{
    return eps * fmax(fabs(x), scale);
}

#endif
