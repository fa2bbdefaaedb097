/*
 * tp_array_gains.c -- test user library (GFOSUB, Force_Vector_TwoBody).
 *
 * A 6-direction linear spring-damper whose twelve gains come from the model,
 * as many real libraries take their tables:
 *     F_k = -K_k * d_k - C_k * v_k,   k = x, y, z, ax, ay, az
 * with (K_1..K_6, C_1..C_6) the last twelve numbers of an IC Reference_Array
 * of 12 to 64 (a table whose head holds other data), read with one
 * c_sysary("ARRAY");
 * d = (DX, DY, DZ, AX, AY, AZ) and v = (VX, VY, VZ, WX, WY, WZ) by c_sysfnc.
 * USER(i_marker, j_marker, array_id). The dependency pass makes the same
 * queries. No static state.
 *
 * A correct verifier must PASS this library; one that keeps a query's answer
 * in six numbers overruns its own buffer here.
 */
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "usrsub/solver_abi.h"

/* par[k] as a positive integer id; 0 when it is not one. */
static int id_at(const double *par, int npar, int k)
{
    if (k >= npar) return 0;
    double v = par[k];
    if (!isfinite(v) || v != floor(v) || v < 1.0 || v > (double)INT_MAX) return 0;
    return (int)v;
}

static double measure(const char *fnc, const int *ipar, int nsize)
{
    double value = 0.0;
    int errflg = 0;
    c_sysfnc(fnc, ipar, nsize, &value, &errflg);
    return (errflg == 0 && isfinite(value)) ? value : 0.0;
}

USRSUB_EXPORT void STDCALL GFOSUB(int *id, double *time, double *par, int *npar,
                                  int *dflag, int *iflag, double *result)
{
    (void)time;
    (void)dflag;
    (void)iflag;
    memset(result, 0, 6 * sizeof(double));
    const int i_mk = id_at(par, *npar, 0), j_mk = id_at(par, *npar, 1);
    const int array[1] = {id_at(par, *npar, 2)};
    if (*npar != 3 || i_mk == 0 || j_mk == 0 || array[0] == 0) {
        char msg[200];
        snprintf(msg, sizeof msg, "tp_array_gains: element %d: expected USER(i_marker, j_marker,"
                 " array_id), got %d value(s)", *id, *npar);
        c_errmes(1, msg, *id, "STOP");
        return;
    }
    double table[64] = {0};
    int count = 0, errflg = 0;
    c_sysary("ARRAY", array, 1, table, &count, &errflg);
    if (errflg != 0 || count < 12 || count > 64) {
        char msg[200];
        snprintf(msg, sizeof msg, "tp_array_gains: element %d: array %d must hold 12 to 64"
                 " numbers, got %d", *id, array[0], count);
        c_errmes(1, msg, *id, "STOP");
        return;
    }
    const double *gains = table + count - 12;
    const int ij[2] = {i_mk, j_mk}, ijj[3] = {i_mk, j_mk, j_mk};
    const int ijjj[4] = {i_mk, j_mk, j_mk, j_mk};
    static const char *const dname[6] = {"DX", "DY", "DZ", "AX", "AY", "AZ"};
    static const char *const vname[6] = {"VX", "VY", "VZ", "WX", "WY", "WZ"};
    for (int k = 0; k < 6; ++k) {
        const double d = measure(dname[k], k < 3 ? ijj : ij, k < 3 ? 3 : 2);
        const double v = measure(vname[k], k < 3 ? ijjj : ijj, k < 3 ? 4 : 3);
        result[k] = -gains[k] * d - gains[6 + k] * v;
    }
}
