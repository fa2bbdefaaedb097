/*
 * A Reference_Spline evaluated (docs/interface.md §7.11): Akima's or the
 * natural cubic spline in x on each curve, linear in z between the two
 * curves about z (the end two beyond them). The one implementation behind
 * the host's c_akispl and c_cubspl and the function expressions' AKISPL and
 * CUBSPL.
 */
#ifndef HX_MODEL_SPLINE_SURFACE_H
#define HX_MODEL_SPLINE_SURFACE_H

#include "model/model.h"

typedef enum hx_spline_method { HX_SPLINE_AKIMA, HX_SPLINE_CUBIC } hx_spline_method;

/* The spline at (x, z): f and its derivatives f_x f_z f_xx f_xz f_zz into
 * d[0..5]. One curve does not depend on z. */
void hx_spline_surface(const hx_spline *s, hx_spline_method method, double x, double z,
                       double d[6]);

/* The third derivatives f_xxx and f_xxz at (x, z) into d[0..1] (the
 * partials of the second derivative that AKISPL and CUBSPL answer with
 * order 2). */
void hx_spline_surface_third(const hx_spline *s, hx_spline_method method, double x, double z,
                             double d[2]);

#endif
