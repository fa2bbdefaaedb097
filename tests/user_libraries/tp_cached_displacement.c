/*
 * tp_cached_displacement.c -- test user library (GFOSUB,
 * Force_Vector_TwoBody).
 *
 * FAULTY ON PURPOSE. The stiffness of tp_good_sysfnc.c, but the damping is a
 * rate formed from a displacement cached at an earlier call:
 *     F_k = -K_k d_k - C_k (d_k - d_cached_k) / DT,   DT = 1e-3 (fixed)
 * with K = (1000, 2000, 3000, 50, 60, 70), C = (1, 2, 3, 0.1, 0.2, 0.3),
 * d = (DX, DY, DZ, AX, AY, AZ), USER(i_marker, j_marker). It reads only
 * DX..DZ (I,J,J) and AX..AZ (I,J) through c_sysfnc: six queries, the same in
 * both passes (no velocity queries at all).
 * Static d_cached[6] (zeros) and t_cached (initially "never"). Each call
 * computes the force with the cache as it stands, and THEN, only on an
 * ordinary call (iflag == 0 and dflag == 0) at a time strictly later than
 * t_cached, sets d_cached = d, t_cached = time. So the first ordinary call at
 * a new time uses the old cache, and a second call at the same state and time
 * sees the updated cache and returns a different force (whenever d moved).
 * A component that would not be finite is written as 0.
 *
 * A correct verifier must FAIL this library (element 1, GFOSUB) for hidden
 * state: the outputs at the same state and time differ between two calls (a
 * value kept from an earlier call).
 */
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "usrsub/solver_abi.h"

static const double K[6] = {1000.0, 2000.0, 3000.0, 50.0, 60.0, 70.0};
static const double C[6] = {1.0, 2.0, 3.0, 0.1, 0.2, 0.3};
static const double DT = 1e-3;

/* The hidden state. */
static double d_cached[6];
static double t_cached;
static int have_cached = 0; /* 0: t_cached is "never" */

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
    memset(result, 0, 6 * sizeof(double));

    int i_mk = marker_id(par, *npar, 0);
    int j_mk = marker_id(par, *npar, 1);
    if (*npar != 2 || i_mk == 0 || j_mk == 0) {
        char msg[200];
        snprintf(msg, sizeof msg,
                 "tp_cached_displacement: element %d: expected USER(i_marker, j_marker) "
                 "with two positive integer ids, got %d value(s)", *id, *npar);
        c_errmes(1, msg, *id, "STOP");
        return;
    }

    const int ij[2] = {i_mk, j_mk};
    const int ijj[3] = {i_mk, j_mk, j_mk};
    static const char *const dname[6] = {"DX", "DY", "DZ", "AX", "AY", "AZ"};

    double d[6];
    for (int k = 0; k < 3; ++k) d[k] = measure(dname[k], ijj, 3);
    for (int k = 3; k < 6; ++k) d[k] = measure(dname[k], ij, 2);

    /* the force with the cache as it stands */
    for (int k = 0; k < 6; ++k) {
        double f = -K[k] * d[k] - C[k] * (d[k] - d_cached[k]) / DT;
        result[k] = isfinite(f) ? f : 0.0;
    }

    /* then the cache moves on, on ordinary calls at a later time only */
    double t = *time;
    if (*iflag == 0 && *dflag == 0 && isfinite(t) && (!have_cached || t > t_cached)) {
        for (int k = 0; k < 6; ++k) d_cached[k] = d[k];
        t_cached = t;
        have_cached = 1;
    }
}
