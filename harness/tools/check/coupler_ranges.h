/*
 * Where to sample a coupler's joints. The harness learns a library's
 * elements as it would a third party's: when the USER list reads as the
 * documented layout (docs/interface.md §2), each spline term (codes 3 and 4)
 * is sampled across its knots and 10 % beyond; any other term, or a list in
 * another grammar, around the joint's initial coordinate +- 1.
 */
#ifndef HX_TOOLS_CHECK_COUPLER_RANGES_H
#define HX_TOOLS_CHECK_COUPLER_RANGES_H

#include "model/model.h"

/* lo, hi for each of the n joints; q0 the initial coordinates. Returns 1 when
 * the list read as the documented layout, else 0. */
int hx_coupler_ranges(const hx_model *m, const double *par, int npar, int n, const double *q0,
                      double lo[3], double hi[3]);

#endif
