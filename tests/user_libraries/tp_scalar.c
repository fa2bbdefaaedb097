/*
 * tp_scalar.c -- test user library: SFOSUB routines of
 * Force_Scalar_TwoBody elements, one value each, named by usrsub_fnc_name:
 *   LINE_SPRING (type FORCE):  -k (DM(I,J) - L0), USER(i, j, k, L0): a spring
 *       along the line from J to I, positive pushing I away;
 *   TWIST_SPRING (type TORQUE): -k AZ(I,J), USER(i, j, k): about J's z axis;
 *   SPRING_DAMPER (type FORCE): -k (DM(I,J) - L0) - c VR(I,J),
 *       USER(i, j, k, L0, c): the law of the bundled spring_damper.xml's
 *       expression, compiled (its twin in tests/test_expr_loads.c and the
 *       expressions' measurement in docs/performance.md).
 * Measured with c_sysfnc. Expected verdict: PASS; and each body oscillates
 * as a spring-mass does.
 */
#include "usrsub/solver_abi.h"

/* the entries, as the solver's documentation gives them */
USRSUB_EXPORT void STDCALL LINE_SPRING(int *id, double *time, double *par, int *npar,
                                       int *dflag, int *iflag, double *value);
USRSUB_EXPORT void STDCALL TWIST_SPRING(int *id, double *time, double *par, int *npar,
                                        int *dflag, int *iflag, double *value);
USRSUB_EXPORT void STDCALL SPRING_DAMPER(int *id, double *time, double *par, int *npar,
                                         int *dflag, int *iflag, double *value);

USRSUB_EXPORT void STDCALL LINE_SPRING(int *id, double *time, double *par, int *npar,
                                       int *dflag, int *iflag, double *value)
{
    (void)id, (void)time, (void)dflag, (void)iflag;
    *value = 0.0;
    if (*npar < 4)
        return;
    const int ipar[2] = {(int)par[0], (int)par[1]};
    double length = 0.0;
    int err = 0;
    c_sysfnc("DM", ipar, 2, &length, &err);
    *value = -par[2] * (length - par[3]);
}

USRSUB_EXPORT void STDCALL TWIST_SPRING(int *id, double *time, double *par, int *npar,
                                        int *dflag, int *iflag, double *value)
{
    (void)id, (void)time, (void)dflag, (void)iflag;
    *value = 0.0;
    if (*npar < 3)
        return;
    const int ipar[2] = {(int)par[0], (int)par[1]};
    double angle = 0.0;
    int err = 0;
    c_sysfnc("AZ", ipar, 2, &angle, &err);
    *value = -par[2] * angle;
}

USRSUB_EXPORT void STDCALL SPRING_DAMPER(int *id, double *time, double *par, int *npar,
                                         int *dflag, int *iflag, double *value)
{
    (void)id, (void)time, (void)dflag, (void)iflag;
    *value = 0.0;
    if (*npar < 5)
        return;
    const int ipar[2] = {(int)par[0], (int)par[1]};
    double length = 0.0, rate = 0.0;
    int err = 0;
    c_sysfnc("DM", ipar, 2, &length, &err);
    c_sysfnc("VR", ipar, 2, &rate, &err);
    *value = -par[2] * (length - par[3]) - par[4] * rate;
}
