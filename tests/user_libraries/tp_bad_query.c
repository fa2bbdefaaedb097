/*
 * tp_bad_query.c -- test user library (GFOSUB, Force_Vector_TwoBody).
 *
 * FAULTY ON PURPOSE (uses a measure outside the host's documented set).
 * The law of tp_good_sysfnc.c (F_k = -K_k d_k - C_k v_k, K = (1000, 2000,
 * 3000, 50, 60, 70), C = (1, 2, 3, 0.1, 0.2, 0.3), USER(i_marker, j_marker),
 * each component through c_sysfnc, same queries in both passes) plus an
 * "added mass" term on the relative acceleration, asked in both passes with
 *     c_sysary("ACC", {I, J, J, J}, 4, ...)
 * F_k += -MA_k * acc_k (MA = 0.001 for translations, 0.0001 for rotations) when
 * the host answers with errflg == 0 and six values; zeros otherwise.
 * docs/interface.md §5 lists the c_sysary measures a host provides (DISP,
 * TDISP, RDISP, VEL, TVEL, RVEL): ACC is not among them.
 *
 * A correct verifier must report the refused query: element 1 (GFOSUB) asked
 * c_sysary "ACC" (ipar 20, 10, 10, 10), which the host refused (errflg != 0).
 * It must not crash; the refusal must appear in its report (as a failure or
 * error for this element), not be silently swallowed.
 */
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "usrsub/solver_abi.h"

static const double K[6] = {1000.0, 2000.0, 3000.0, 50.0, 60.0, 70.0};
static const double C[6] = {1.0, 2.0, 3.0, 0.1, 0.2, 0.3};
static const double MA[6] = {1e-3, 1e-3, 1e-3, 1e-4, 1e-4, 1e-4};

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
                 "tp_bad_query: element %d: expected USER(i_marker, j_marker) with two "
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

    double acc[12] = {0};
    int nacc = 0, errflg = 0;
    c_sysary("ACC", ijjj, 4, acc, &nacc, &errflg);
    if (errflg != 0 || nacc < 6) memset(acc, 0, sizeof acc);

    for (int k = 0; k < 6; ++k) {
        double a = isfinite(acc[k]) ? acc[k] : 0.0;
        result[k] = -K[k] * d[k] - C[k] * v[k] - MA[k] * a;
    }
}
