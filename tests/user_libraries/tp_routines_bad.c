/*
 * tp_routines_bad.c -- test user library: routines whose calls the host
 * must refuse or whose values it must not pass on.
 *   PEEKING_SWING (MOTSUB): a sin(w t) and its derivatives, but it also asks
 *       c_sysfnc for DX(i, j), which a motion may not (its value is a
 *       function of time); from t = t_nan on (when t_nan > 0) its
 *       acceleration is NaN, USER(a, w, i, j, t_nan);
 *   LOST_LAG (DIFSUB): -DIF(self) / tau, but it also asks DIF of a
 *       Control_Diff that does not exist and DIF with two ids; from t = t_nan
 *       on (when t_nan > 0) its value is NaN, USER(unknown_id, tau, t_nan).
 * Expected verdict: check names each refused query; run stops at the first
 * NaN, naming the routine.
 */
#include "usrsub/solver_abi.h"

#include <math.h>

USRSUB_EXPORT void STDCALL PEEKING_SWING(int *id, double *time, double *par, int *npar,
                                         int *iord, int *iflag, double *value);
USRSUB_EXPORT void STDCALL LOST_LAG(int *id, double *time, double *par, int *npar, int *dflag,
                                    int *iflag, double *value);

static double ask(const char *name, const int *ipar, int n)
{
    double value = 0.0;
    int err = 0;
    c_sysfnc(name, ipar, n, &value, &err);
    return err == 0 ? value : 0.0;
}

USRSUB_EXPORT void STDCALL PEEKING_SWING(int *id, double *time, double *par, int *npar,
                                         int *iord, int *iflag, double *value)
{
    (void)id, (void)iflag;
    if (*npar < 5)
        return;
    const int ipar[2] = {(int)par[2], (int)par[3]};
    const double a = par[0], w = par[1], t = *time, peek = ask("DX", ipar, 2);
    *value = *iord == 0 ? a * sin(w * t) : *iord == 1 ? a * w * cos(w * t) : -a * w * w * sin(w * t);
    if (*iord == 2 && par[4] > 0.0 && t >= par[4])
        *value = NAN;
    *value += 0.0 * peek;
}

USRSUB_EXPORT void STDCALL LOST_LAG(int *id, double *time, double *par, int *npar, int *dflag,
                                    int *iflag, double *value)
{
    (void)dflag, (void)iflag;
    if (*npar < 3)
        return;
    const int unknown = (int)par[0], both[2] = {*id, *id};
    *value = -ask("DIF", id, 1) / par[1] + 0.0 * ask("DIF", &unknown, 1) + 0.0 * ask("DIF", both, 2);
    if (par[2] > 0.0 && *time >= par[2])
        *value = NAN;
}
