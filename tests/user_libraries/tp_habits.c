/*
 * tp_habits.c -- test user library (GFOSUB, Force_Vector_TwoBody) with
 * two habits real user code has and a real solver tolerates:
 *   - it never writes result[4] (TY): the solver zeroes the outputs;
 *   - its law divides by DX (a stiffness scaled by DX / DX), so its
 *     dependency pass, where the host answers zeros, returns NaN.
 * Elsewhere it is a linear spring-damper in x and z:
 *   F = -1000 DX (DX / DX) - 2 VX,  Fz = -3000 DZ - 3 VZ,  T = 0 (TY unwritten).
 * Expected verdict: PASS, with a note naming the unwritten output and a
 * warning about the dependency pass.
 */
#include "usrsub/solver_abi.h"

USRSUB_EXPORT void STDCALL GFOSUB(int *id, double *time, double *par, int *npar,
                                  int *dflag, int *iflag, double *result)
{
    (void)id, (void)time, (void)dflag, (void)iflag;
    if (*npar < 2)
        return;
    const int ipar[4] = {(int)par[0], (int)par[1], (int)par[1], (int)par[1]};
    double dx = 0, dz = 0, vx = 0, vz = 0;
    int err = 0;
    c_sysfnc("DX", ipar, 3, &dx, &err);
    c_sysfnc("DZ", ipar, 3, &dz, &err);
    c_sysfnc("VX", ipar, 4, &vx, &err);
    c_sysfnc("VZ", ipar, 4, &vz, &err);
    result[0] = -1000.0 * dx * (dx / dx) - 2.0 * vx;
    result[1] = 0.0;
    result[2] = -3000.0 * dz - 3.0 * vz;
    result[3] = 0.0;
    result[5] = 0.0;
}
