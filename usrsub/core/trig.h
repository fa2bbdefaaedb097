/*
 * atan2 and sincos within 3 and 2 units in the last place (nearly always 1),
 * and several times cheaper than the C library's correctly rounded ones:
 * the GFOSUB form turns the host's Euler angles into projection angles on
 * every call. Range reduction as in Cephes and fdlibm; the polynomial
 * coefficients are Chebyshev fits made with mpmath (error below 1e-17 on the
 * reduced ranges). Arguments outside |x| < 1e5, zeros, infinities and NaN go
 * to the C library. Inline: the GFOSUB form calls each three times a call,
 * and the calls' polynomials interleave when the compiler sees them.
 */
#ifndef USRSUB_TRIG_H
#define USRSUB_TRIG_H

#include <math.h>

#ifdef __cplusplus
extern "C" {
#endif

/* constants as a double and the rest (hi + lo), so sums keep their last bits */
#define USRSUB_TRIG_PI 3.141592653589793
#define USRSUB_TRIG_PI_LO 1.2246467991473532e-16
#define USRSUB_TRIG_PI_2 1.5707963267948966
#define USRSUB_TRIG_PI_2_LO 6.123233995736766e-17
#define USRSUB_TRIG_PI_6 0.5235987755982989
#define USRSUB_TRIG_PI_6_LO -5.360408832255455e-17
#define USRSUB_TRIG_TAN_PI_12 0.2679491924311227
#define USRSUB_TRIG_SQRT3 1.7320508075688772
#define USRSUB_TRIG_SQRT3_LO 1.0035084221806903e-16
#define USRSUB_TRIG_TWO_OVER_PI 0.6366197723675814
/* pi/2 in three parts (33 + 33 + 53 bits), so n * part is exact for |n| < 2^20 */
#define USRSUB_TRIG_PIO2_1 1.5707963267341256
#define USRSUB_TRIG_PIO2_2 6.077100506303966e-11
#define USRSUB_TRIG_PIO2_3 2.0222662487959506e-21
#define USRSUB_TRIG_ROUND_MAGIC 6755399441055744.0 /* 2^52 + 2^51: adding it rounds to an integer */

static inline double usrsub_atan2(double y, double x)
{
    if (y == 0.0 && x > 0.0)
        return y; /* +-0, keeping the sign of y */
    if (!isfinite(x) || !isfinite(y) || x == 0.0 || y == 0.0)
        return atan2(y, x); /* signed zeros, infinities, NaN: the C library's rules */
    const double ax = fabs(x), ay = fabs(y);
    const int swap = ay > ax;
    double t = swap ? ax / ay : ay / ax; /* in (0, 1] */
    double base = 0.0, base_lo = 0.0;
    if (t > USRSUB_TRIG_TAN_PI_12) { /* atan t = pi/6 + atan((t sqrt3 - 1) / (t + sqrt3)) */
        t = (fma(t, USRSUB_TRIG_SQRT3, -1.0) + t * USRSUB_TRIG_SQRT3_LO) / (t + USRSUB_TRIG_SQRT3);
        base = USRSUB_TRIG_PI_6, base_lo = USRSUB_TRIG_PI_6_LO;
    }
    const double z = t * t;
    const double p =
        -0.3333333333333333 +
        z * (0.1999999999999688 +
             z * (-0.14285714284553813 +
                  z * (0.11111110944516939 +
                       z * (-0.09090897081592211 +
                            z * (0.07691819638198708 +
                                 z * (-0.06654945053677658 +
                                      z * (0.05716329894442852 + z * -0.03957893591546196)))))));
    double a = base + (t + (t * z * p + base_lo));
    if (swap)
        a = (USRSUB_TRIG_PI_2 - a) + USRSUB_TRIG_PI_2_LO;
    if (x < 0.0)
        a = (USRSUB_TRIG_PI - a) + USRSUB_TRIG_PI_LO;
    return y < 0.0 ? -a : a;
}

static inline void usrsub_sincos(double x, double *s, double *c)
{
    if (!(fabs(x) < 1e5)) {
        *s = sin(x), *c = cos(x);
        return;
    }
    const double n = (x * USRSUB_TRIG_TWO_OVER_PI + USRSUB_TRIG_ROUND_MAGIC) - USRSUB_TRIG_ROUND_MAGIC;
    const double r = ((x - n * USRSUB_TRIG_PIO2_1) - n * USRSUB_TRIG_PIO2_2) - n * USRSUB_TRIG_PIO2_3; /* |r| <= pi/4 */
    const double z = r * r;
    const double sr =
        r + r * z *
                (-0.16666666666666666 +
                 z * (0.008333333333333331 +
                      z * (-0.00019841269841265065 +
                           z * (2.7557319219339167e-06 +
                                z * (-2.5052106232447578e-08 +
                                     z * (1.6058531618986147e-10 + z * -7.586697117706918e-13))))));
    const double cr =
        1.0 - 0.5 * z +
        z * z *
            (0.041666666666666664 +
             z * (-0.0013888888888888887 +
                  z * (2.4801587301584645e-05 +
                       z * (-2.7557319221402824e-07 +
                            z * (2.087675579108042e-09 +
                                 z * (-1.1470460887609959e-11 + z * 4.7458719020432915e-14))))));
    switch ((long)n & 3) {
    case 0: *s = sr, *c = cr; break;
    case 1: *s = cr, *c = -sr; break;
    case 2: *s = -sr, *c = -cr; break;
    default: *s = -cr, *c = sr; break;
    }
}


#ifdef __cplusplus
}
#endif

#endif
