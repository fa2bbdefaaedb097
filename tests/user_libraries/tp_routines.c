/*
 * tp_routines.c -- test user library: the user routines that are not
 * forces, in the classic C form (every argument by address, upper-case
 * names), and a force on one body. Measured with c_sysfnc.
 *   ANCHOR (VFOSUB of a Force_Vector_OneBody, ForceOnly): a spring of
 *       stiffness k from marker I to the point (x0, 0, 0) of marker J's
 *       frame, USER(i, j, k, x0);
 *   SWING (MOTSUB of a Motion_Joint, val_type D): a sin(w t), its rate and
 *       acceleration for iord 0, 1, 2, USER(a, w);
 *   LAG (DIFSUB of a Control_Diff): (AZ(i, j) - DIF(self)) / tau, a lag of
 *       the joint's angle, USER(i, j, tau);
 *   SPEED (VARSUB): VX(i, j), USER(i, j);
 *   REPORT (REQSUB): DIF(d), DIF1(d), AZ(i, j), DX(k, l), USER(d, i, j, k, l).
 * Expected verdict: PASS; and the run follows the closed forms of
 * tp_routines.xml.
 */
#include "usrsub/solver_abi.h"

#include <math.h>

USRSUB_EXPORT void STDCALL ANCHOR(int *id, double *time, double *par, int *npar, int *dflag,
                                  int *iflag, double *result);
USRSUB_EXPORT void STDCALL SWING(int *id, double *time, double *par, int *npar, int *iord,
                                 int *iflag, double *value);
USRSUB_EXPORT void STDCALL LAG(int *id, double *time, double *par, int *npar, int *dflag,
                               int *iflag, double *value);
USRSUB_EXPORT void STDCALL SPEED(int *id, double *time, double *par, int *npar, int *dflag,
                                 int *iflag, double *value);
USRSUB_EXPORT void STDCALL REPORT(int *id, double *time, double *par, int *npar, int *iflag,
                                  double *result);

static double measure(const char *name, int i, int j)
{
    const int ipar[2] = {i, j};
    double value = 0.0;
    int err = 0;
    c_sysfnc(name, ipar, 2, &value, &err);
    return value;
}

static double diff_value(const char *name, int id)
{
    double value = 0.0;
    int err = 0;
    c_sysfnc(name, &id, 1, &value, &err);
    return value;
}

USRSUB_EXPORT void STDCALL ANCHOR(int *id, double *time, double *par, int *npar, int *dflag,
                                  int *iflag, double *result)
{
    (void)id, (void)time, (void)dflag, (void)iflag;
    if (*npar < 4)
        return;
    const int i = (int)par[0], j = (int)par[1];
    result[0] = -par[2] * (measure("DX", i, j) - par[3]);
    result[1] = -par[2] * measure("DY", i, j);
    result[2] = -par[2] * measure("DZ", i, j);
}

USRSUB_EXPORT void STDCALL SWING(int *id, double *time, double *par, int *npar, int *iord,
                                 int *iflag, double *value)
{
    (void)id, (void)iflag;
    if (*npar < 2)
        return;
    const double a = par[0], w = par[1], t = *time;
    *value = *iord == 0 ? a * sin(w * t) : *iord == 1 ? a * w * cos(w * t) : -a * w * w * sin(w * t);
}

USRSUB_EXPORT void STDCALL LAG(int *id, double *time, double *par, int *npar, int *dflag,
                               int *iflag, double *value)
{
    (void)time, (void)dflag, (void)iflag;
    if (*npar < 3)
        return;
    *value = (measure("AZ", (int)par[0], (int)par[1]) - diff_value("DIF", *id)) / par[2];
}

USRSUB_EXPORT void STDCALL SPEED(int *id, double *time, double *par, int *npar, int *dflag,
                                 int *iflag, double *value)
{
    (void)id, (void)time, (void)dflag, (void)iflag;
    if (*npar < 2)
        return;
    *value = measure("VX", (int)par[0], (int)par[1]);
}

USRSUB_EXPORT void STDCALL REPORT(int *id, double *time, double *par, int *npar, int *iflag,
                                  double *result)
{
    (void)id, (void)time, (void)iflag;
    if (*npar < 5)
        return;
    result[0] = diff_value("DIF", (int)par[0]);
    result[1] = diff_value("DIF1", (int)par[0]);
    result[2] = measure("AZ", (int)par[1], (int)par[2]);
    result[3] = measure("DX", (int)par[3], (int)par[4]);
    for (int k = 4; k < 8; ++k)
        result[k] = 0.0;
}
