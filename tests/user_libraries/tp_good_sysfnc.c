/*
 * tp_good_sysfnc.c -- test user library (GFOSUB, Force_Vector_TwoBody).
 *
 * Linear spring-damper on the deformation of I relative to J, in J axes:
 *     F_k = -K_k * d_k - C_k * v_k,   k = x, y, z, ax, ay, az
 * with K = (1000, 2000, 3000, 50, 60, 70), C = (1, 2, 3, 0.1, 0.2, 0.3),
 * d = (DX, DY, DZ, AX, AY, AZ), v = (VX, VY, VZ, WX, WY, WZ).
 * USER(i_marker, j_marker). Every component is measured with one c_sysfnc
 * call: DX..DZ (I,J,J), AX..AZ (I,J), VX..VZ (I,J,J,J), WX..WZ (I,J,J).
 * The dependency pass (iflag != 0) makes exactly the same twelve queries and
 * evaluates the same law on the zeros the host returns. No static state.
 *
 * A correct verifier must PASS this library: declared dependencies cover every
 * read, output is a pure function of the state, no crash.
 */
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "usrsub/solver_abi.h"

static const double K[6] = {1000.0, 2000.0, 3000.0, 50.0, 60.0, 70.0};
static const double C[6] = {1.0, 2.0, 3.0, 0.1, 0.2, 0.3};

/* par[k] as a marker id; 0 when it is missing or not a positive integer. */
static int marker_id(const double *par, int npar, int k)
{
    if (k >= npar) return 0;
    double v = par[k];
    if (!isfinite(v) || v != floor(v) || v < 1.0 || v > (double)INT_MAX) return 0;
    return (int)v;
}

/* One scalar measure; 0 when the host refuses it. */
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
    (void)iflag; /* the same queries and law in both passes */
    memset(result, 0, 6 * sizeof(double));

    int i_mk = marker_id(par, *npar, 0);
    int j_mk = marker_id(par, *npar, 1);
    if (*npar != 2 || i_mk == 0 || j_mk == 0) {
        char msg[200];
        snprintf(msg, sizeof msg,
                 "tp_good_sysfnc: element %d: expected USER(i_marker, j_marker) with two "
                 "positive integer ids, got %d value(s)", *id, *npar);
        c_errmes(1, msg, *id, "STOP");
        return;
    }

    const int ij[2] = {i_mk, j_mk};
    const int ijj[3] = {i_mk, j_mk, j_mk};
    const int ijjj[4] = {i_mk, j_mk, j_mk, j_mk};
    static const char *const dname[6] = {"DX", "DY", "DZ", "AX", "AY", "AZ"};
    static const char *const vname[6] = {"VX", "VY", "VZ", "WX", "WY", "WZ"};

    double d[6], v[6];
    for (int k = 0; k < 3; ++k) d[k] = measure(dname[k], ijj, 3);
    for (int k = 3; k < 6; ++k) d[k] = measure(dname[k], ij, 2);
    for (int k = 0; k < 3; ++k) v[k] = measure(vname[k], ijjj, 4);
    for (int k = 3; k < 6; ++k) v[k] = measure(vname[k], ijj, 3);

    for (int k = 0; k < 6; ++k) result[k] = -K[k] * d[k] - C[k] * v[k];
}
