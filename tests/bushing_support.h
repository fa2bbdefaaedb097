/* Bushings built by hand for the tests. */
#ifndef BUSHING_SUPPORT_H
#define BUSHING_SUPPORT_H

#include "usrsub/core/bushing.h"

/* All directions inactive, neutral preload/offset/scale, EPSILON 1e-9. */
void bushing_init(usrsub_bushing *b, int coupling);
/* g(d) = k1 d + k3 d^3 exactly on [-10, 10], through the cubic characteristic. */
void bushing_cubic(usrsub_bushing *b, int k, double k1, double k3);
void bushing_constant(usrsub_bushing *b, int k, double K);
void bushing_spline(usrsub_bushing *b, int k, int n, const double *x, const double *y);
void bushing_damping(usrsub_bushing *b, int k, double C);
/* Releases the splines. */
void bushing_release(usrsub_bushing *b);

#endif
