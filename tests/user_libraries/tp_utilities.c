/*
 * tp_utilities.c -- test user library (GFOSUB, Force_Vector_TwoBody),
 * written against the Adams-compatible C utilities, upper-case entry name.
 *
 * USER(i_marker, j_marker, array_id): a mount with
 *   - a force along z from c_impact: a stop at z = 0 (k = 2000 N/mm, e = 1.5,
 *     cmax = 5, d = 0.2) pushing I up when it sinks below J;
 *   - a force along x from c_poly: -(k1 dx + k3 dx^3), k1 and k3 read with
 *     c_gtaray from the IC Reference_Array array_id, faded in over the first
 *     0.1 s with c_step on c_getstm's time;
 *   - a torque from the rotation: DISP's Euler angles turned into direction
 *     cosines by c_rcnvrt, T = -kt (a32 - a23, a13 - a31, a21 - a12) / 2.
 * Every state it reads comes from c_sysary DISP and c_sysfnc VZ, asked the
 * same way in the dependency pass. c_timget's time is checked against the
 * call's (an error through c_errmes when they differ).
 *
 * A correct verifier must PASS this library.
 */
#include <math.h>
#include <string.h>

#include "usrsub/solver_abi.h"

USRSUB_EXPORT void STDCALL GFOSUB(int *id, double *time, double *par, int *npar,
                                  int *dflag, int *iflag, double *result)
{
    (void)dflag, (void)iflag;
    memset(result, 0, 6 * sizeof(double));
    if (*npar < 3)
        return;
    const int ipar[3] = {(int)par[0], (int)par[1], (int)par[1]};
    double disp[6] = {0, 0, 0, 0, 0, 0}, vz = 0.0;
    int n = 0, err = 0;
    c_sysary("DISP", ipar, 3, disp, &n, &err);
    const int vpar[4] = {ipar[0], ipar[1], ipar[1], ipar[1]};
    c_sysfnc("VZ", vpar, 4, &vz, &err);

    double stop[3] = {0, 0, 0};
    c_impact(disp[2], vz, 0.0, 2000.0, 1.5, 5.0, 0.2, 0, stop, &err);
    result[2] = stop[0];

    double k[2] = {0, 0}, now = 0.0, then = 0.0, fade = 0.0, spring = 0.0;
    int count = 2, istat = 0;
    c_gtaray((int)par[2], k, &count, &istat);
    c_getstm(&now);
    c_timget(&then);
    if (then != now || now != *time)
        c_errmes(1, "c_timget and c_getstm disagree with the call's time", *id, "STOP");
    c_step(now, 0.0, 0.0, 0.1, 1.0, 0, &fade, &err);
    const double coefficients[4] = {0.0, k[0], 0.0, k[1]};
    c_poly(disp[0], 0.0, coefficients, 4, 0, &spring, &err);
    result[0] = -fade * spring;

    double a[9];
    c_rcnvrt("EULER", disp + 3, "COSINES", a, &istat);
    const double kt = 500.0; /* a[row + 3 column], column by column */
    result[3] = -kt * (a[2 + 3 * 1] - a[1 + 3 * 2]) / 2.0;
    result[4] = -kt * (a[0 + 3 * 2] - a[2 + 3 * 0]) / 2.0;
    result[5] = -kt * (a[1 + 3 * 0] - a[0 + 3 * 1]) / 2.0;
}
