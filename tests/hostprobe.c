/*
 * A test-only user-subroutine library that probes its host. GFOSUB's par[0]
 * selects a probe; the others are marker ids:
 *   1 I J      result = c_sysary DISP(I,J,J)
 *   2 I J      result = c_sysfnc DX DY DZ (I,J,J) and AX AY AZ (I,J)
 *   3 I J      result = c_sysary VEL(I,J,J,J)
 *   4 I J      asks DISP only outside the dependency pass (an undeclared read)
 *   6 I J      result = (errflg, nstates) of c_sysary DISP(I,J,J) with a null array
 *   5 S        result[0] = length of Reference_String S, result[1..4] = c_gtunts scales
 *              (time, length, force, mass), result[5] = 1 when nothing past four
 *              sizes and twelve characters was written
 *   98         c_errmes(1, "probe asked to stop later", id, "STOP") at time > 0
 *   99         c_errmes(1, "probe asked to stop", id, "STOP")
 * COUSUB/COUXX/COUXX2: phi = sum of disp. There is deliberately no FIESUB.
 */
#include <string.h>

#include "usrsub/solver_abi.h"

void STDCALL GFOSUB(int *id, double *time, double *par, int *npar, int *dflag, int *iflag,
                    double *result)
{
    (void)dflag;
    memset(result, 0, 6 * sizeof(double));
    if (*npar < 1)
        return;
    const int probe = (int)par[0];
    const int ipar[4] = {*npar > 1 ? (int)par[1] : 0, *npar > 2 ? (int)par[2] : 0,
                         *npar > 2 ? (int)par[2] : 0, *npar > 2 ? (int)par[2] : 0};
    int n = 0, err = 0;
    switch (probe) {
    case 1: c_sysary("DISP", ipar, 3, result, &n, &err); break;
    case 2: {
        static const char *const names[6] = {"DX", "DY", "DZ", "AX", "AY", "AZ"};
        for (int k = 0; k < 6; ++k)
            c_sysfnc(names[k], ipar, k < 3 ? 3 : 2, &result[k], &err);
        break;
    }
    case 3: c_sysary("VEL", ipar, 4, result, &n, &err); break;
    case 4:
        if (!*iflag)
            c_sysary("DISP", ipar, 3, result, &n, &err);
        break;
    case 5: {
        char text[256];
        int nchars = (int)sizeof text - 1, istat = 0, exists = 0;
        c_gtstrg(ipar[0], text, &nchars, &istat);
        result[0] = istat == 0 ? nchars : -1;
        /* room for four sizes and twelve characters, then canaries the host
         * must leave alone */
        double scales[8] = {-7, -7, -7, -7, -7, -7, -7, -7};
        char units[16];
        memset(units, '#', sizeof units);
        c_gtunts(&exists, scales, units);
        for (int k = 0; k < 4 && exists; ++k)
            result[1 + k] = scales[k];
        int intact = 1;
        for (int k = 4; k < 8; ++k)
            intact &= scales[k] == -7;
        for (int k = 12; k < 16; ++k)
            intact &= units[k] == '#';
        result[5] = intact;
        break;
    }
    case 6:
        c_sysary("DISP", ipar, 3, NULL, &n, &err);
        result[0] = err;
        result[1] = n;
        break;
    case 98:
        if (*time > 0.0)
            c_errmes(1, "probe asked to stop later", *id, "STOP");
        break;
    case 99: c_errmes(1, "probe asked to stop", *id, "STOP"); break;
    default: break;
    }
}

static double sum(const double *disp, int n)
{
    double s = 0;
    for (int k = 0; k < n; ++k)
        s += disp[k];
    return s;
}

void STDCALL COUSUB(int *id, double *time, double *par, int *npar, double *disp, int *ndisp,
                    int *iflag, double *phi)
{
    (void)id, (void)time, (void)par, (void)npar, (void)iflag;
    *phi = sum(disp, *ndisp);
}

void STDCALL COUXX(int *id, double *time, double *par, int *npar, double *disp, int *ndisp,
                   int *iflag, double *dfda)
{
    (void)id, (void)time, (void)par, (void)npar, (void)iflag, (void)disp;
    for (int k = 0; k < *ndisp; ++k)
        dfda[k] = 1.0;
}

void STDCALL COUXX2(int *id, double *time, double *par, int *npar, double *disp, int *ndisp,
                    int *iflag, double *d2)
{
    (void)id, (void)time, (void)par, (void)npar, (void)iflag, (void)disp;
    memset(d2, 0, sizeof(double) * (size_t)(*ndisp * *ndisp));
}
