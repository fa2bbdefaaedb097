/*
 * A model's curve (model.h's hx_curve, docs/interface.md §8.4): checked,
 * fitted through points on it (Adams' CURVE_POINTS), and evaluated with its
 * derivatives in alpha as the CURVE function answers them.
 */
#ifndef HX_MODEL_CURVE_H
#define HX_MODEL_CURVE_H

#include "base/message.h"
#include "model/model.h"

/* 0, or -1 with what is wrong in msg: the order outside 2 to 8, too few
 * points for it, a closed curve whose last point is not its first, a
 * coordinate that is not finite. */
int hx_curve_check(const hx_curve *c, hx_message *msg);

/* Makes c (id, order, closed set) the curve through the n points (3 n
 * numbers, x y z of each; closed: the last repeats the first), passing
 * through point j at alpha = -1 + 2 j / (n - 1) when closed, at the
 * Greville abscissae of its knots when open (both ends at alpha = -1 and 1):
 * its control points solved for and set (c->points allocated; c->points is
 * overwritten). Returns 0, or -1 with msg. */
int hx_curve_through(hx_curve *c, const double *points, int n, hx_message *msg);

/* Component (1, 2, 3: x, y, z) of the curve at alpha and its first three
 * derivatives in alpha into d[0..3]. An open curve's alpha is the caller's
 * to keep in [-1, 1]; a closed curve repeats with period 2. */
void hx_curve_at(const hx_curve *c, double alpha, int component, double d[4]);

#endif
