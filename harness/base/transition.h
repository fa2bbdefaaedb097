/*
 * STEP, STEP5 and HAVSIN (docs/interface.md §3.6, §5.2, §8.4): a smooth
 * transition from (x0, h0) to (x1, h1), its derivatives in x and its
 * partials in every argument. The one implementation behind the host's
 * c_step, c_step5 and c_havsin, the model's time functions and the function
 * expressions.
 */
#ifndef HX_BASE_TRANSITION_H
#define HX_BASE_TRANSITION_H

typedef enum hx_transition_shape {
    HX_TRANSITION_STEP,   /* cubic u^2 (3 - 2u) */
    HX_TRANSITION_STEP5,  /* quintic u^3 (10 - 15u + 6u^2) */
    HX_TRANSITION_HAVSIN  /* haversine (1 - cos(pi u)) / 2 */
} hx_transition_shape;

/* The shape s(u) on u in [0, 1] (s(0) = 0, s(1) = 1) and its first two
 * derivatives into s[0..2]. */
void hx_transition_shape_at(hx_transition_shape shape, double u, double s[3]);

/* The iord-th derivative in x (iord 0, 1 or 2): h0 for x <= x0, h1 for
 * x >= x1, the shape scaled between. x1 == x0 is a jump at x0 (h0 at x0
 * itself) with zero derivatives; x1 < x0 is the caller's to refuse. */
double hx_transition(hx_transition_shape shape, double x, double x0, double h0, double x1,
                     double h1, int iord);

/* The partials of the value in x, x0, h0, x1 and h1 into d[0..4]. */
void hx_transition_partials(hx_transition_shape shape, double x, double x0, double h0, double x1,
                            double h1, double d[5]);

#endif
