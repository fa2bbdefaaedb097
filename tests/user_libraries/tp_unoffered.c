/*
 * tp_unoffered.c -- test user library (GFOSUB, Force_Vector_TwoBody)
 * that reads its spring's curve with c_quispl (quintic interpolation of a
 * Reference_Spline), a utility the harness does not offer. It loads (the
 * harness defines every utility); the verdict must FAIL it, naming c_quispl.
 */
#include <string.h>

#include "usrsub/solver_abi.h"

USRSUB_EXPORT void STDCALL GFOSUB(int *id, double *time, double *par, int *npar,
                                  int *dflag, int *iflag, double *result)
{
    (void)id, (void)time, (void)dflag, (void)iflag;
    memset(result, 0, 6 * sizeof(double));
    if (*npar < 3)
        return;
    const int ipar[3] = {(int)par[0], (int)par[1], (int)par[1]};
    double dx = 0.0, curve[3] = {0, 0, 0};
    int err = 0;
    c_sysfnc("DX", ipar, 3, &dx, &err);
    c_quispl(dx, 0.0, (int)par[2], 0, curve, &err);
    result[0] = err ? -1000.0 * dx : curve[0];
}
