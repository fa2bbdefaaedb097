/*
 * STEP and STEP5 (docs/interface.md §3.6), with first and second derivatives
 * with respect to x.
 *   STEP:  h0 + (h1-h0) a^2 (3 - 2a)                  (C1)
 *   STEP5: h0 + (h1-h0) a^3 (10 - 15a + 6a^2)         (C2)
 * with a = (x - x0)/(x1 - x0), h0 for x <= x0, h1 for x >= x1.
 * x1 == x0 is a jump at x0 (h0 at x0 itself), with zero derivatives.
 */
#ifndef USRSUB_STEP_H
#define USRSUB_STEP_H

#include "usrsub/core/jet.h"

#ifdef __cplusplus
extern "C" {
#endif

usrsub_jet usrsub_step(double x, double x0, double h0, double x1, double h1);
usrsub_jet usrsub_step5(double x, double x0, double h0, double x1, double h1);

#ifdef __cplusplus
}
#endif

#endif
