/*
 * tp_spline.c -- test user library: SFOSUB routines of
 * Force_Scalar_TwoBody elements whose laws are curves of the model, read
 * with the spline utilities from its Reference_Spline elements:
 *   SPLINE_SPRING (type FORCE): c_akispl(DM(I,J) - L0, 0, spline_id),
 *       USER(i, j, spline_id, L0): a spring along the line from J to I;
 *   SPLINE_TWIST (type TORQUE): c_cubspl(AZ(I,J), 0, spline_id),
 *       USER(i, j, spline_id): about J's z axis.
 * Each also asks for the curve's slope (iord 1, array[0] = dy/dx) and stops
 * the run through c_errmes when it is not the stiffness USER's last number
 * gives (par[4] for the spring, par[3] for the twist), or when a utility
 * sets errflg. Measured with c_sysfnc.
 * Expected verdict: PASS; the curves in tp_spline.xml are straight lines
 * (linear extrapolation beyond the spring's points), so each body oscillates
 * as a spring-mass does.
 */
#include <math.h>

#include "usrsub/solver_abi.h"

USRSUB_EXPORT void STDCALL SPLINE_SPRING(int *id, double *time, double *par, int *npar,
                                         int *dflag, int *iflag, double *value);
USRSUB_EXPORT void STDCALL SPLINE_TWIST(int *id, double *time, double *par, int *npar,
                                        int *dflag, int *iflag, double *value);

/* The curve's value at x, its slope checked against the stiffness k. */
static double curve(int id, int spline, int akima, double x, double k)
{
    double value[3] = {0, 0, 0}, slope[3] = {0, 0, 0};
    int err = 0, err_slope = 0;
    if (akima) {
        c_akispl(x, 0.0, spline, 0, value, &err);
        c_akispl(x, 0.0, spline, 1, slope, &err_slope);
    } else {
        c_cubspl(x, 0.0, spline, 0, value, &err);
        c_cubspl(x, 0.0, spline, 1, slope, &err_slope);
    }
    if (err || err_slope)
        c_errmes(1, "the spline utility set errflg", id, "STOP");
    else if (fabs(slope[0] - k) > 1e-9 * fabs(k) || slope[1] != 0.0)
        c_errmes(1, "the curve's slope is not the stiffness", id, "STOP");
    return value[0];
}

USRSUB_EXPORT void STDCALL SPLINE_SPRING(int *id, double *time, double *par, int *npar,
                                         int *dflag, int *iflag, double *value)
{
    (void)time, (void)dflag, (void)iflag;
    *value = 0.0;
    if (*npar < 5) {
        c_errmes(1, "USER(i, j, spline_id, L0, k) expected", *id, "STOP");
        return;
    }
    const int ipar[2] = {(int)par[0], (int)par[1]};
    double length = 0.0;
    int err = 0;
    c_sysfnc("DM", ipar, 2, &length, &err);
    *value = curve(*id, (int)par[2], 1, length - par[3], par[4]);
}

USRSUB_EXPORT void STDCALL SPLINE_TWIST(int *id, double *time, double *par, int *npar,
                                        int *dflag, int *iflag, double *value)
{
    (void)time, (void)dflag, (void)iflag;
    *value = 0.0;
    if (*npar < 4) {
        c_errmes(1, "USER(i, j, spline_id, k) expected", *id, "STOP");
        return;
    }
    const int ipar[2] = {(int)par[0], (int)par[1]};
    double angle = 0.0;
    int err = 0;
    c_sysfnc("AZ", ipar, 2, &angle, &err);
    *value = curve(*id, (int)par[2], 0, angle, par[3]);
}
