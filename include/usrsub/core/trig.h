/*
 * atan2 and sincos within 3 and 2 units in the last place (nearly always 1),
 * and several times cheaper than the C library's correctly rounded ones:
 * the GFOSUB form turns the host's Euler angles into projection angles on
 * every call. Range reduction as in Cephes and fdlibm; the polynomial
 * coefficients are Chebyshev fits made with mpmath (error below 1e-17 on the
 * reduced ranges). Arguments outside |x| < 1e5, zeros, infinities and NaN go
 * to the C library.
 */
#ifndef USRSUB_TRIG_H
#define USRSUB_TRIG_H

#ifdef __cplusplus
extern "C" {
#endif

double usrsub_atan2(double y, double x);
void usrsub_sincos(double x, double *s, double *c);

#ifdef __cplusplus
}
#endif

#endif
