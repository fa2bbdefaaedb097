/*
 * tp_routines_faults.c -- test user library: the routines that are
 * not forces, each with a planted fault check must name.
 *   BAD_SWING (MOTSUB): a sin(w t), but its acceleration (iord 2) has the
 *       wrong sign, USER(a, w);
 *   SLY_LAG (DIFSUB): (AZ(i, j) - DIF(self)) / tau, but it asks for AZ and
 *       DIF only when iflag is not set, so the dependency pass learns of
 *       neither the body nor its own state, USER(i, j, tau);
 *   COUNTER (VARSUB): DX(i, j) plus a count of its calls (a hidden state),
 *       USER(i, j);
 *   SHORT_REPORT (REQSUB): writes only its first five values, USER(i, j).
 * Expected verdict: FAIL for the first three; a note for the fourth.
 */
#include "usrsub/solver_abi.h"

#include <math.h>

USRSUB_EXPORT void STDCALL BAD_SWING(int *id, double *time, double *par, int *npar, int *iord,
                                     int *iflag, double *value);
USRSUB_EXPORT void STDCALL SLY_LAG(int *id, double *time, double *par, int *npar, int *dflag,
                                   int *iflag, double *value);
USRSUB_EXPORT void STDCALL COUNTER(int *id, double *time, double *par, int *npar, int *dflag,
                                   int *iflag, double *value);
USRSUB_EXPORT void STDCALL SHORT_REPORT(int *id, double *time, double *par, int *npar,
                                        int *iflag, double *result);

static double measure(const char *name, const int *ipar, int n)
{
    double value = 0.0;
    int err = 0;
    c_sysfnc(name, ipar, n, &value, &err);
    return value;
}

USRSUB_EXPORT void STDCALL BAD_SWING(int *id, double *time, double *par, int *npar, int *iord,
                                     int *iflag, double *value)
{
    (void)id, (void)iflag;
    if (*npar < 2)
        return;
    const double a = par[0], w = par[1], t = *time;
    *value = *iord == 0 ? a * sin(w * t) : *iord == 1 ? a * w * cos(w * t) : a * w * w * sin(w * t);
}

USRSUB_EXPORT void STDCALL SLY_LAG(int *id, double *time, double *par, int *npar, int *dflag,
                                   int *iflag, double *value)
{
    (void)time, (void)dflag;
    if (*npar < 3)
        return;
    const int ipar[2] = {(int)par[0], (int)par[1]};
    const double angle = *iflag ? 0.0 : measure("AZ", ipar, 2);
    const double lagged = *iflag ? 0.0 : measure("DIF", id, 1);
    *value = (angle - lagged) / par[2];
}

USRSUB_EXPORT void STDCALL COUNTER(int *id, double *time, double *par, int *npar, int *dflag,
                                   int *iflag, double *value)
{
    (void)id, (void)time, (void)dflag, (void)iflag;
    static long calls;
    if (*npar < 2)
        return;
    const int ipar[2] = {(int)par[0], (int)par[1]};
    *value = measure("DX", ipar, 2) + 1e-3 * (double)++calls;
}

USRSUB_EXPORT void STDCALL SHORT_REPORT(int *id, double *time, double *par, int *npar,
                                        int *iflag, double *result)
{
    (void)id, (void)time, (void)iflag;
    if (*npar < 2)
        return;
    const int ipar[2] = {(int)par[0], (int)par[1]};
    for (int k = 0; k < 5; ++k)
        result[k] = (k + 1) * measure("DX", ipar, 2);
}
